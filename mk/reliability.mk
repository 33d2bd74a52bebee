# Reliability tests (docs/reliability.md): the bad-input suite (tests/bad/,
# run through a step binary), the number reader against strtof, output files
# under signals and umasks, and the replay of the fuzzing regression corpus.
# `make test` runs them with the other test binaries.

REL_STEP := 08-area-lights
REL_SRC  := tests/test_bad_input.c tests/test_huge_input.c tests/test_number.c \
            tests/test_outfile.c tests/test_fast_reader.c tests/test_large_scene.c \
            tests/test_scene_parts.c tests/test_fuzz_corpus.c tests/fuzz/targets.c
REL_OBJ  := $(REL_SRC:tests/%.c=$(BUILD)/obj/tests/rel/%.o) \
            $(BUILD)/obj/tests/rel/step08-main.o

$(BUILD)/obj/tests/rel/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (reliability)"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -Itests/fuzz -DBUILD_DIR='"$(BUILD)"' \
	  -DREL_STEP='"$(REL_STEP)"' -c $< -o $@

# Step 08's main renamed for the fuzzing targets (tests/fuzz/fuzz.h).
$(BUILD)/obj/tests/rel/step08-main.o: steps/$(REL_STEP)/main.c tests/fuzz/fuzz.h \
                                      $(BUILD)/gen/$(REL_STEP)/step_manifest.h | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (reliability: step 08 for the fuzzing targets)"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Isteps/$(REL_STEP) -I$(BUILD)/gen/$(REL_STEP) -include step_manifest.h \
	  -Itests/fuzz -Dmain=fuzz_step08_main \
	  -Dapp_run=fuzz_app_run -include tests/fuzz/fuzz.h -c $< -o $@

$(BUILD)/tests/reliability: $(REL_OBJ) $($(REL_STEP)_LIB) $(LIBCOMMON) $(BUILD)/bin/$(REL_STEP)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $(filter %.o %.a,$^) $(LDLIBS) -lcriterion -o $@

TESTBIN += $(BUILD)/tests/reliability
test-build: $(BUILD)/tests/reliability

# make test-reliability: this binary alone, verbose.
test-reliability: $(BUILD)/tests/reliability
	@tests/run.sh --verbose $<

.PHONY: test-reliability

# ---------------------------------------------------------------- sanitizers
# make sanitize runs the suite built by gcc (the Makefile), then by clang with
# its fuller UBSan: float-cast-overflow (in clang's "undefined"), float
# division by zero and local array bounds besides. Debian's clang, libomp for
# OpenMP (whose empty files of dead processes in /dev/shm would kill a
# program with the same PID: tools/build/omp-stale.sh removes them first).
# docs/reliability.md, "Sanitizers".
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
	@tools/build/omp-stale.sh
	@if [ tests/fuzz/ubsan-ignore.txt -nt build/san-clang/.ignorelist ]; then \
	  rm -rf build/san-clang/obj; mkdir -p build/san-clang; touch build/san-clang/.ignorelist; fi
	$(MAKE) BUILD=build/san-clang CC=clang SAN=1 SAN_FLAGS='$(CLANG_SAN_FLAGS)' \
	  OPT='-O1' LDFLAGS= test

.PHONY: clang-deps sanitize-clang

# ---------------------------------------------------------------- valgrind
# make valgrind: the whole suite under valgrind's memcheck. valgrind 3.19
# does not know AVX-512, which -march=native emits here: this build targets
# x86-64-v3 (AVX2), whose pictures are the native build's bit for bit
# (docs/reliability.md, "Valgrind"). Every process the tests start (the step
# binaries too) runs under memcheck; an error or a definite leak makes that
# process exit 99, which fails its test. Logs: build/vg/valgrind/PID.log (the
# processes a test ends with a file-size limit or a signal leave theirs cut).
VG_BUILD := build/vg
# valgrind computes x87 long double in double precision: the one test whose
# long double reference then no longer holds is left out (the other long
# double references keep enough margin).
VG_SKIP  := !(scene/closest_hit_among_many_spheres_matches_brute_force)
VG_FLAGS := --trace-children=yes --error-exitcode=99 --leak-check=full \
            --show-leak-kinds=definite --errors-for-leak-kinds=definite \
            --suppressions=$(CURDIR)/tests/valgrind.supp \
            --log-file=$(CURDIR)/$(VG_BUILD)/valgrind/%p.log
# Every test binary of make test, built in VG_BUILD.
VG_TESTBIN = $(patsubst $(BUILD)/%,$(VG_BUILD)/%,$(TESTBIN) $(STRESSBIN) $(TRACE_TESTBIN))
valgrind-deps:
	@$(call need_debs,valgrind)
valgrind: valgrind-deps
	$(MAKE) BUILD=$(VG_BUILD) OPT='-O3 -march=x86-64-v3 -flto=auto -ffat-lto-objects' \
	  $(VG_TESTBIN) $(VG_BUILD)/bin/mistakes $(VG_BUILD)/bin/04-phong
	@rm -rf $(VG_BUILD)/valgrind && mkdir -p $(VG_BUILD)/valgrind
	@VALGRIND='valgrind $(VG_FLAGS)' CRITERION_TEST_PATTERN='$(VG_SKIP)' \
	  tests/run.sh $(VG_TESTBIN); rc=$$?; \
	  bad=$$(grep -l 'ERROR SUMMARY: [1-9]' $(VG_BUILD)/valgrind/*.log | wc -l); \
	  echo "valgrind: $$(ls $(VG_BUILD)/valgrind | wc -l) processes, $$bad with errors"; \
	  [ $$rc -eq 0 ] && [ $$bad -eq 0 ]

.PHONY: valgrind valgrind-deps
