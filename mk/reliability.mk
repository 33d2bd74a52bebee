# Reliability tests (docs/reliability.md): the bad-input suite (tests/bad/,
# run through a step binary), the number reader against strtof, output files
# under signals and umasks, and the replay of the fuzzing regression corpus.
# `make test` runs them with the other test binaries.

REL_STEP := 08-area-lights
REL_SRC  := tests/test_bad_input.c tests/test_number.c tests/test_outfile.c \
            tests/test_fuzz_corpus.c tests/fuzz/targets.c
REL_OBJ  := $(REL_SRC:tests/%.c=$(BUILD)/obj/tests/rel/%.o) \
            $(BUILD)/obj/tests/rel/step08-main.o

$(BUILD)/obj/tests/rel/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (reliability)"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -Itests/fuzz -DBUILD_DIR='"$(BUILD)"' \
	  -DREL_STEP='"$(REL_STEP)"' -c $< -o $@

# Step 08's main renamed for the fuzzing targets (tests/fuzz/fuzz.h).
$(BUILD)/obj/tests/rel/step08-main.o: steps/$(REL_STEP)/main.c tests/fuzz/fuzz.h | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (reliability: step 08 for the fuzzing targets)"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Isteps/$(REL_STEP) -Itests/fuzz -Dmain=fuzz_step08_main \
	  -Dapp_run=fuzz_app_run -include tests/fuzz/fuzz.h -c $< -o $@

$(BUILD)/tests/reliability: $(REL_OBJ) $($(REL_STEP)_LIB) $(LIBCOMMON) $(BUILD)/bin/$(REL_STEP)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $(filter %.o %.a,$^) $(LDLIBS) -lcriterion -o $@

TESTBIN += $(BUILD)/tests/reliability
test: $(BUILD)/tests/reliability

# make test-reliability: this binary alone, verbose.
test-reliability: $(BUILD)/tests/reliability
	@tests/run.sh --verbose $<

.PHONY: test-reliability

# ---------------------------------------------------------------- sanitizers
# make sanitize runs the suite built by gcc (the Makefile), then by clang with
# its fuller UBSan: float-cast-overflow (in clang's "undefined"), float
# division by zero and local array bounds besides. Debian's clang, libomp for
# OpenMP. docs/reliability.md, "Sanitizers".
ifneq ($(SAN),)
  export LSAN_OPTIONS := suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0
endif
DEB_CLANG := clang libclang-rt-dev libomp-dev llvm
CLANG_SAN_FLAGS := -fsanitize=address,undefined,float-divide-by-zero,local-bounds \
                   -fsanitize-ignorelist=tests/fuzz/ubsan-ignore.txt \
                   -fno-sanitize-recover=all
clang-deps:
	@$(call need_debs,$(DEB_CLANG))
sanitize-clang: clang-deps
	@if [ tests/fuzz/ubsan-ignore.txt -nt build/san-clang/.ignorelist ]; then \
	  rm -rf build/san-clang/obj; mkdir -p build/san-clang; touch build/san-clang/.ignorelist; fi
	$(MAKE) BUILD=build/san-clang CC=clang SAN=1 SAN_FLAGS='$(CLANG_SAN_FLAGS)' \
	  OPT='-O1' LDFLAGS= test

.PHONY: clang-deps sanitize-clang
