# Fuzzing (docs/reliability.md, "Fuzzing"): libFuzzer targets built by
# Debian's clang with AddressSanitizer and UBSan, float-cast-overflow and
# float-divide-by-zero included:
#   fuzz-scene   the scene reader, scene_prepare, accel_build (the index's
#                answers checked against the plain loop's)
#   fuzz-cli     the command line
#   fuzz-render  a tiny render of the parsed scene through step 08's shading
# make fuzz runs each for FUZZ_SECONDS (default 10); make fuzz-scene (-cli,
# -render) runs one. Seeds: scenes/, tests/bad/, tests/fuzz/seeds/ and the
# regression corpus tests/fuzz/regressions/TARGET/ (every input that ever
# crashed: copy a new crash there; make test replays them all). The corpus
# grown so far stays in build/fuzz/corpus/TARGET, crashes land in
# build/fuzz/crashes/TARGET/, the last run's figures in build/fuzz/TARGET.log.

FUZZ_SECONDS ?= 10
FUZZ_BUILD   := $(BUILD)/fuzz
FUZZ_TARGETS := scene cli render
FUZZ_SAN     := -fsanitize=address,undefined,float-cast-overflow,float-divide-by-zero \
                -fsanitize-ignorelist=tests/fuzz/ubsan-ignore.txt \
                -fno-sanitize-recover=all
FUZZ_CFLAGS   = -std=c11 -O1 -g -fno-omit-frame-pointer -fopenmp -ffp-contract=off \
                -fno-math-errno -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic \
                -Wshadow -Wstrict-prototypes -Wmissing-prototypes $(WARN_FLAGS_clang) -Werror -MMD -MP -Icommon -Ifast \
                -Itests/fuzz $(FUZZ_SAN) $(PKG_CFLAGS)
FUZZ_STEP    := steps/08-area-lights
# Step 08's main, renamed: its app_run call hands the step's description to
# the targets (tests/fuzz/fuzz.h).
FUZZ_STEP_MAIN := -Dmain=fuzz_step08_main -Dapp_run=fuzz_app_run -include tests/fuzz/fuzz.h \
                  -I$(FUZZ_STEP)
FUZZ_LIB_SRC := $(filter-out common/app/app.c,$(COMMON_SRC)) \
                tests/fuzz/targets.c
FUZZ_LIB_OBJ := $(FUZZ_LIB_SRC:%.c=$(FUZZ_BUILD)/obj/%.o) $(FUZZ_BUILD)/obj/step08-main.o

$(FUZZ_BUILD)/obj/%.o: %.c tests/fuzz/ubsan-ignore.txt | clang-deps $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (fuzz)"
	@clang $(FUZZ_CFLAGS) -I$(FUZZ_STEP) -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_BUILD)/obj/step08-main.o: $(FUZZ_STEP)/main.c tests/fuzz/fuzz.h tests/fuzz/ubsan-ignore.txt \
                                 $(BUILD)/gen/08-area-lights/step_manifest.h | clang-deps $(BUILD)/.deps
	@mkdir -p $(@D)
	@clang $(FUZZ_CFLAGS) -I$(BUILD)/gen/08-area-lights -include step_manifest.h $(FUZZ_STEP_MAIN) \
	  -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_BUILD)/obj/entry-%.o: tests/fuzz/libfuzzer.c tests/fuzz/fuzz.h tests/fuzz/ubsan-ignore.txt | clang-deps $(BUILD)/.deps
	@mkdir -p $(@D)
	@clang $(FUZZ_CFLAGS) -DFUZZ_ENTRY=fuzz_$* -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_BUILD)/fuzz-%: $(FUZZ_BUILD)/obj/entry-%.o $(FUZZ_LIB_OBJ)
	@echo "LD $@"
	@clang $(FUZZ_CFLAGS) -fsanitize=fuzzer $^ $(LDLIBS) -o $@

# The seeds of each target, gathered into build/fuzz/seeds/TARGET: command
# lines are cli.cases' "$ ARGS" lines with NULs between the words.
$(FUZZ_BUILD)/seeds/%: FORCE
	@rm -rf $@ && mkdir -p $@
	@if [ $* = cli ]; then \
	  n=0; sed -n 's/^\$$ //p' tests/bad/cli.cases | while IFS= read -r line; do \
	    n=$$((n + 1)); printf '%s' "$$line" | tr ' ' '\0' > $@/case-$$n; done; \
	else \
	  cp scenes/*.scene tests/bad/scenes/*.scene tests/fuzz/seeds/*.scene $@/; \
	fi
	@cp tests/fuzz/regressions/$*/* $@/ 2>/dev/null || true

FUZZ_DICT_scene  := tests/fuzz/scene.dict
FUZZ_DICT_render := tests/fuzz/scene.dict
FUZZ_DICT_cli    := tests/fuzz/cli.dict

# fuzz-TARGET: FUZZ_SECONDS of libFuzzer; the summary line (executions,
# coverage, corpus) printed and kept in build/fuzz/TARGET.log.
$(FUZZ_TARGETS:%=fuzz-%): fuzz-%: $(FUZZ_BUILD)/fuzz-% $(FUZZ_BUILD)/seeds/%
	@mkdir -p $(FUZZ_BUILD)/corpus/$* $(FUZZ_BUILD)/crashes/$*
	@tools/build/omp-stale.sh
	@echo "fuzz-$*: $(FUZZ_SECONDS) s (build/fuzz/crashes/$*/ keeps what crashes)"
	@$(FUZZ_BUILD)/fuzz-$* -max_total_time=$(FUZZ_SECONDS) -timeout=10 -close_fd_mask=3 \
	  -print_final_stats=1 -dict=$(FUZZ_DICT_$*) \
	  -artifact_prefix=$(FUZZ_BUILD)/crashes/$*/ \
	  $(FUZZ_BUILD)/corpus/$* $(FUZZ_BUILD)/seeds/$* > $(FUZZ_BUILD)/$*.log 2>&1; \
	  rc=$$?; grep -E '^#[0-9]+[[:space:]]+DONE|^stat::(number_of_executed_units|average_exec_per_sec|new_units_added)' \
	    $(FUZZ_BUILD)/$*.log | sed 's/^/  /'; \
	  if [ $$rc -ne 0 ]; then tail -n 40 $(FUZZ_BUILD)/$*.log; \
	    echo "fuzz-$*: FOUND A CRASH (exit $$rc): see build/fuzz/crashes/$*/"; exit 1; fi

fuzz: $(FUZZ_TARGETS:%=fuzz-%)
fuzz-build: $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/fuzz-%)

-include $(shell find $(FUZZ_BUILD)/obj -name '*.d' 2>/dev/null)

FORCE:
.SECONDARY: $(FUZZ_LIB_OBJ) $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/obj/entry-%.o)
.PHONY: fuzz fuzz-build FORCE $(FUZZ_TARGETS:%=fuzz-%)
