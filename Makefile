# Ray-tracing course: build every step, render it, test it, measure it.
# `make` builds and renders all steps; `make test` tests them (`make check`: the course); `make help`
# lists the other targets. GNU make 4, gcc or clang, the libraries from
# pkg-config (tools/build/deps.sh installs them on Debian as root).

SHELL := /bin/bash
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:
.SUFFIXES:

BUILD ?= build
STEPS := 01-film 02-intersection 03-camera 04-phong 05-shadows 06-ambient \
         07-antialiasing 08-area-lights
PRESENT := $(filter $(STEPS),$(notdir $(wildcard steps/[0-9][0-9]-*)))

# Each step's manifest, steps/NN-name/step.mk (docs/instructors.md, "A step's
# manifest"): its KEY = value lines read here as NN-name.KEY (the scene
# compiled into its program, NN-name.SCENE; its unit tests tests/test_NAME.c,
# NN-name.TESTS; ...). tools/build/manifest.sh reads the same files for the shell
# tools and writes the header of the step's Step fields.
MANIFEST_KEYS := SUMMARY FEATURES SAMPLER ADAPTIVE SCENE TESTS IMAGE_SIZE IMAGE_ARGS IMAGE_TOL \
                 IMAGE_TERMS TRACE_ARGS
define read_manifest
include steps/$(1)/step.mk
$$(foreach k,$$(MANIFEST_KEYS),$$(eval $(1).$$(k) := $$$$($$(k)))$$(eval undefine $$(k)))
$$(foreach k,$$(filter TRACE_%,$$(.VARIABLES)),$$(eval undefine $$(k)))
endef
$(foreach s,$(PRESENT),$(eval $(call read_manifest,$(s))))

# The shapes of the registry (common/shapes.h, one X(NAME, name, ...) line
# each) that have a test of their own, tests/test_<name>.c: the word SHAPES
# in a manifest's TESTS stands for them (step 02 runs them, beside the
# conformance suite, tests/test_shapes.c, that checks all).
SHAPE_NAMES := $(shell sed -n 's/^ *X.[A-Z0-9_]*, *\([a-z0-9_]*\),.*/\1/p' common/shapes.h)
SHAPE_TESTS := $(foreach s,$(SHAPE_NAMES),$(if $(wildcard tests/test_$(s).c),$(s)))
$(foreach s,$(PRESENT),$(eval $(s).TESTS := $(patsubst SHAPES,$(SHAPE_TESTS),$($(s).TESTS))))
STRESS_TESTS := $(patsubst tests/%.c,%,$(wildcard tests/stress_*.c))

# ---------------------------------------------------------------- flags
# The compiler is Make's CC (cc unless given: make CC=clang). tools/build/deps.sh
# probes it once per build folder into $(BUILD)/config.mk: gcc or clang, its
# OpenMP flags, LTO, and the libraries' flags from pkg-config.
CONFIG := $(BUILD)/config.mk
# Goals that need no compiler: they run without probing it.
NO_CONFIG_GOALS := clean help deps bench-deps grade-deps clang-deps valgrind-deps dist
ifneq ($(MAKECMDGOALS),)
  ifeq ($(filter-out $(NO_CONFIG_GOALS),$(MAKECMDGOALS)),)
    SKIP_CONFIG := 1
  endif
endif
ifndef SKIP_CONFIG
  -include $(CONFIG)
endif

# Results must not change with the optimiser's mood (docs/accuracy.md): no
# -ffast-math, no fused multiply-add contraction, on every compiler. FP_FLAGS_gcc
# and FP_FLAGS_clang take what one compiler alone needs.
FP_FLAGS       := -ffp-contract=off -fno-math-errno
FP_FLAGS_gcc   :=
FP_FLAGS_clang :=
# The default build runs on every x86-64 or arm64 machine (no -march); make
# NATIVE=1 tunes for this CPU (-march=native: a binary that may not run on
# another machine). gcc adds link-time optimisation with fat objects (CC_LTO):
# LTO inlines camera_ray, film_sample and the shape tests into each step's
# pixel function (docs/performance.md); the tests and tools link the same
# objects without it.
# -mno-fma (x86-64): cglm's SIMD code calls fused multiply-add intrinsics
# where the target has FMA (camera_ray's glms_mat4_mulv3), which
# -ffp-contract=off does not reach; without them NATIVE=1 draws the default
# build's pictures bit for bit.
NATIVE_FLAGS := -march=native $(if $(filter x86_64% amd64%,$(CC_MACHINE)),-mno-fma)
OPT     ?= -O3 $(if $(NATIVE),$(NATIVE_FLAGS)) $(CC_LTO)
# -Werror where the warnings are known clean (gcc 12 to 14, clang 14); a
# compiler of another version may warn where these do not: make WERROR= keeps
# its warnings warnings.
WERROR  ?= -Werror
# clang's -Wpedantic flags an `inline` function with external linkage that
# calls cglm's static functions (the steps' shade_phong_light); its header's
# plain declaration makes the definition an external one, which C11 allows.
WARN_FLAGS_clang := -Wno-static-in-inline
# OpenMP where the compiler has it; without it (or with OPENMP=0) one thread,
# the same pictures (common/threads.h).
ifndef OPENMP
  OPENMP := $(if $(OMP_CFLAGS),1,0)
endif
ifeq ($(OPENMP),0)
  OMP_CFLAGS := -Wno-unknown-pragmas
  OMP_LIBS   :=
endif
# stb as the system ships it: Debian's compiled libstb (pkg-config stb, -lstb),
# or headers only, compiled in by common/app/stb_impl.c. STB=headers takes the
# headers even where libstb is; STB_CFLAGS=-I/dir names a folder of them.
STB_CFLAGS ?= $(STB_CFLAGS_FOUND)
STB_LIBS   ?= $(if $(filter command,$(origin STB_CFLAGS)),,$(STB_LIBS_FOUND))
STB_IMPL   := $(if $(STB_LIBS),,1)

CFLAGS  := -std=c11 $(OPT) -g $(OMP_CFLAGS) $(FP_FLAGS) $(FP_FLAGS_$(CC_KIND)) \
           -D_POSIX_C_SOURCE=200809L $(SYS_CFLAGS) \
           -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
           -Wmissing-prototypes $(WARN_FLAGS_$(CC_KIND)) $(WERROR) -MMD -MP -Icommon -Ifast
PKG_CFLAGS = $(LIB_CFLAGS) $(STB_CFLAGS) $(filter -I%,$(TEST_CFLAGS))
LDLIBS  := $(OMP_LIBS) $(LIB_LIBS) $(STB_LIBS) -lm
# Every link but the steps' programs: without LTO (the fat objects' code),
# so that a test or tool links in a moment. gcc 12 with -flto re-runs its
# warnings at link time and reports false -Wmaybe-uninitialized /
# -Wuninitialized on `Hit hit;` in the steps (scene_intersect fills it
# whenever it returns true; gcc follows a path where instance_hit_fill's
# switch matches no shape): the programs' link leaves them out. Each file's
# compile step keeps both warnings.
LDFLAGS := $(if $(CC_LTO),-fno-lto) $(filter -L%,$(TEST_LIBS))
# Files no LTO link reads (the tests', common/app's): compiled without LTO's
# second copy.
TEST_OBJ_FLAGS := $(if $(CC_LTO),-fno-lto)
PROG_LDFLAGS = $(filter-out -fno-lto,$(LDFLAGS)) \
               $(if $(filter -flto%,$(CFLAGS)),-Wno-maybe-uninitialized -Wno-uninitialized)
SAN ?=
# Any report ends the program, so a test that meets one fails. The clang
# build of make sanitize passes its fuller set (mk/reliability.mk).
SAN_FLAGS ?= -fsanitize=address,undefined -fno-sanitize-recover=all
ifneq ($(SAN),)
  CFLAGS  += $(SAN_FLAGS) -fno-omit-frame-pointer
  LDLIBS  += $(SAN_FLAGS)
endif

# A change of compiler or flags rebuilds everything: $(BUILD)/.flags holds
# the last set, and every object depends on it (at the end of this file).
FLAGS_SIG := $(CC) $(CFLAGS) $(PKG_CFLAGS) | $(LDFLAGS) $(LDLIBS)
ifndef SKIP_CONFIG
  ifneq ($(FLAGS_SIG),$(shell cat $(BUILD)/.flags 2>/dev/null))
    $(shell mkdir -p $(BUILD) && printf '%s\n' '$(FLAGS_SIG)' > $(BUILD)/.flags)
  endif
endif

$(BUILD)/.flags: ;

# make test-step builds on every core unless make was given -j.
NPROC = $(shell nproc 2>/dev/null || sysctl -n hw.ncpu 2>/dev/null || echo 2)
JOBS_FLAG = $(if $(findstring -j,$(MAKEFLAGS)),,-j$(NPROC))

# make print-flags: the flags as shell assignments, for the scripts that
# compile a tool against $(BUILD)/libcommon.a (cglm's types follow -march).
BUILD_KIND = $(if $(filter -march=native,$(CFLAGS)),native (make NATIVE=1: -march=native),portable (no -march)), $(CC_KIND)$(if $(filter -flto%,$(CFLAGS)), with LTO)$(if $(filter 0,$(OPENMP)), without OpenMP)
print-flags:
	@printf "CC='%s'\nCFLAGS='%s'\nLDFLAGS='%s'\nLDLIBS='%s'\nBUILD_KIND='%s'\n" '$(CC)' \
	  '$(strip $(filter-out -MMD -MP,$(CFLAGS)) $(PKG_CFLAGS))' '$(strip $(LDFLAGS))' '$(strip $(LDLIBS))' '$(BUILD_KIND)'

# ---------------------------------------------------------------- dependencies
# tools/build/deps.sh check: the build's libraries through pkg-config. As root on
# Debian/Ubuntu it installs what is missing (apt-get); elsewhere it prints the
# one install command of the system (dnf, brew, pacman).
$(BUILD)/.deps: Makefile tools/build/deps.sh
	@mkdir -p $(@D)
	@tools/build/deps.sh check '$(CC)'
	@touch $@

$(CONFIG): $(BUILD)/.deps tools/build/deps.sh
	@tools/build/deps.sh config '$(CC)' $(STB) > $@.tmp && mv $@.tmp $@
ifndef SKIP_CONFIG
  ifneq ($(CONFIG_CC) $(CONFIG_STB),$(CC) $(STB))
    $(CONFIG): FORCE
  endif
endif
FORCE:

# Debian packages of the optional targets (the benchmark here, grading and
# the sanitizers in mk/): installed as root, else the apt-get command.
need_debs = tools/build/deps.sh debs $(1)
DEB_BENCH := gnuplot-nox povray hyperfine

deps: $(BUILD)/.deps
bench-deps:
	@$(call need_debs,$(DEB_BENCH))

# ---------------------------------------------------------------- common library
# common/app/stb_impl.c: stb compiled in, where the system has its headers only.
# The speed pack (fast/) is archived with the core; FAST=0 links the plain
# answers of common/app/pack.c in place of the pack's (fast/fast.c), so that
# no step binary takes any of it (same pictures: docs/performance.md).
FAST ?= 1
PACK_SRC   := $(if $(filter 0,$(FAST)),common/app/pack.c,fast/fast.c)
COMMON_SRC := $(filter-out common/app/pack.c $(if $(STB_IMPL),,common/app/stb_impl.c),\
                $(wildcard common/*.c common/*/*.c)) $(wildcard fast/*/*.c) $(PACK_SRC)
COMMON_OBJ := $(COMMON_SRC:%.c=$(BUILD)/obj/%.o)
LIBCOMMON  := $(BUILD)/libcommon.a

$(BUILD)/obj/%.o: %.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -c $< -o $@

# The program around the lessons (command line, scene reader, image files,
# traces, render loop) has nothing to inline into a pixel function: compiled
# without LTO, which shortens the programs' link (pictures the same, renders
# as fast: docs/performance.md, "Build flags").
$(BUILD)/obj/common/app/%.o: CFLAGS += $(TEST_OBJ_FLAGS)
# The speed pack's compiler hints for the shading (fast/hints.h), read
# ahead of common/shade.c so that the student's file holds none.
$(BUILD)/obj/common/shade.o: CFLAGS += $(if $(filter 0,$(FAST)),,-include fast/hints.h)
# stb's own code, not ours: its warnings are not the course's.
$(BUILD)/obj/common/app/stb_impl.o: CFLAGS += -w
$(LIBCOMMON): $(COMMON_OBJ)
	@rm -f $@
	@$(AR) rcs $@ $^

# ---------------------------------------------------------------- steps
# step_rules(step): binary build/bin/STEP from steps/STEP/*.c, the default
# scene turned into a C string, and the common library; its render in
# build/out; its test binary build/tests/STEP.
define step_rules
$(1)_SRC := $$(wildcard steps/$(1)/*.c)
$(1)_OBJ := $$($(1)_SRC:%.c=$(BUILD)/obj/%.o)
$(1)_LIB := $$(filter-out %/main.o,$$($(1)_OBJ))
$(BUILD)/obj/steps/$(1)/%.o: CFLAGS += -Isteps/$(1)

$(BUILD)/gen/$(1)-scene.c: $($(1).SCENE) tools/build/scene2c.sh steps/$(1)/step.mk
	@mkdir -p $$(@D)
	@tools/build/scene2c.sh $($(1).SCENE) > $$@

# main.c's Step fields (STEP_MANIFEST) and the image test's reference size,
# options and tolerance, from the manifest.
$(BUILD)/gen/$(1)/step_manifest.h: steps/$(1)/step.mk tools/build/manifest.sh
	@mkdir -p $$(@D)
	@tools/build/manifest.sh header $(1) > $$@.tmp && mv $$@.tmp $$@
$(BUILD)/obj/steps/$(1)/main.o: CFLAGS += -I$(BUILD)/gen/$(1) -include step_manifest.h
$(BUILD)/obj/steps/$(1)/main.o: $(BUILD)/gen/$(1)/step_manifest.h

$(BUILD)/bin/$(1): $$($(1)_OBJ) $(BUILD)/obj/gen/$(1)-scene.o $(LIBCOMMON)
	@mkdir -p $$(@D)
	@echo "LD $$@"
	@$(CC) $(CFLAGS) $(PROG_LDFLAGS) $$^ $(LDLIBS) -o $$@

$(BUILD)/out/$(1).png: $(BUILD)/bin/$(1)
	@mkdir -p $$(@D)
	@$(BUILD)/bin/$(1) -o $$@

$(1)_TOBJ := $$(patsubst %,$(BUILD)/obj/tests/$(1)/test_%.o,$$($(1).TESTS)) \
             $(BUILD)/obj/tests/$(1)/image_test.o
$(BUILD)/obj/tests/$(1)/image_test.o: $(BUILD)/gen/$(1)/step_manifest.h
$(BUILD)/obj/tests/$(1)/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $$(@D)
	@echo "CC $$<  ($(1) test)"
	@$(CC) $(CFLAGS) $(TEST_OBJ_FLAGS) $$(PKG_CFLAGS) $(TEST_CFLAGS) -Isteps/$(1) -I$(BUILD)/gen/$(1) -Itests \
	  -DSTEP_NAME='"$(1)"' -DBUILD_DIR='"$(BUILD)"' -c $$< -o $$@
$(BUILD)/tests/$(1): $$($(1)_TOBJ) $$($(1)_LIB) $(LIBCOMMON) $(BUILD)/bin/$(1)
	@mkdir -p $$(@D)
	@echo "LD $$@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $$(filter %.o %.a,$$^) $(LDLIBS) $(TEST_LIBS) -o $$@
endef
$(foreach s,$(PRESENT),$(eval $(call step_rules,$(s))))

$(BUILD)/obj/gen/%.o: $(BUILD)/gen/%.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@$(CC) $(CFLAGS) -c $< -o $@

BINS    := $(PRESENT:%=$(BUILD)/bin/%)
RENDERS := $(PRESENT:%=$(BUILD)/out/%.png)
TESTBIN := $(PRESENT:%=$(BUILD)/tests/%)

all: $(BINS) $(RENDERS)
build: $(BINS)

# ---------------------------------------------------------------- tests
STRESS_OBJ := $(STRESS_TESTS:%=$(BUILD)/obj/tests/stress/%.o)
$(BUILD)/obj/tests/stress/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (stress)"
	@$(CC) $(CFLAGS) $(TEST_OBJ_FLAGS) $(PKG_CFLAGS) $(TEST_CFLAGS) -Itests -DBUILD_DIR='"$(BUILD)"' -c $< -o $@
$(BUILD)/tests/stress: $(STRESS_OBJ) $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) $(TEST_LIBS) -o $@
STRESSBIN := $(if $(STRESS_TESTS),$(BUILD)/tests/stress)

# make test: the student's command (README.md, "For students: the loop").
# Every present step's unit and image tests, the stress, reliability and
# trace tests, then the report; nothing that checks the course rather than
# the student's code (that is make check, below).
# make test-build: what make test runs, built and not run (make -j2
# test-build builds it two at a time; CI does, before make test).
test-build: $(TESTBIN) $(STRESSBIN) $(BUILD)/bin/04-phong $(BUILD)/bin/05-shadows \
            $(BUILD)/bin/mistakes
test: test-build
	@tests/run.sh $(TESTBIN) $(STRESSBIN) $(TRACE_TESTBIN); status=$$?; \
	  $(REPORT_AFTER_TEST) || status=1; \
	  exit $$status

# The stress tests of steps 01 .. K (tests/stress.h, stress_step): make stress
# N=K, or by default the steps written so far, up to the first step whose
# TODO(step NN) a starter tree still holds (all eight in a solved tree). Those
# of step 05 render through steps 04, 05 and tools/figures/mistakes.c (docs/accuracy.md).
STRESS_TODO = $(shell grep -rhoE 'TODO\(step [0-9]+\)' common steps 2>/dev/null | \
                grep -oE '[0-9]+' | sort -n | head -1)
STRESS_UPTO = $(if $(N),$(N_PAD),$(if $(STRESS_TODO),$(shell printf %02d \
                $$(( 10#$(STRESS_TODO) - 1 ))),08))
stress_bins = $(STRESSBIN) $(if $(filter 05 06 07 08,$(1)),$(BUILD)/bin/04-phong \
                $(BUILD)/bin/05-shadows $(BUILD)/bin/mistakes)
stress:
	@$(MAKE) --no-print-directory $(call stress_bins,$(STRESS_UPTO))
	@echo "make stress: the stress tests of steps 01 .. $(STRESS_UPTO)"
	@RT_STRESS_STEPS=$(STRESS_UPTO) tests/run.sh --verbose $(STRESSBIN)

# make test-step N  (or N=3): one step's unit tests and image test.
ifeq (test-step,$(firstword $(MAKECMDGOALS)))
  N ?= $(word 2,$(MAKECMDGOALS))
  $(eval $(word 2,$(MAKECMDGOALS)):;@:)
endif
N_NUM = $(shell expr '$(N)' + 0 2>/dev/null)
N_PAD = $(if $(N_NUM),$(shell printf %02d '$(N_NUM)' 2>/dev/null))
STEP_N = $(filter $(N_PAD)-%,$(STEPS))
# With the stress tests of steps 01 .. N; TEST_STEP_STRESS=0: the step's own
# tests alone (tools/check/check-regions.sh and tools/check/mutants.sh run those apart).
TEST_STEP_STRESS ?= 1
TEST_STEP_STRESSBIN = $(if $(filter 1,$(TEST_STEP_STRESS)),$(call stress_bins,$(N_PAD)))
test-step:
	@if [ -z "$(N)" ]; then echo "usage: make test-step N   (N = 1 .. 8)"; exit 2; fi
	@if [ -z "$(STEP_N)" ]; then echo "make test-step: there is no step '$(N)' (steps are 1 .. 8)"; exit 2; fi
	@if [ -z "$(filter $(STEP_N),$(PRESENT))" ]; then \
	  echo "make test-step: step $(STEP_N) does not exist yet (no steps/$(STEP_N)/)"; exit 1; fi
	@$(MAKE) --no-print-directory $(JOBS_FLAG) $(BUILD)/tests/$(STEP_N) $(TEST_STEP_STRESSBIN)
	@RT_STRESS_STEPS=$(N_PAD) tests/run.sh --verbose $(BUILD)/tests/$(STEP_N) \
	  $(filter $(STRESSBIN),$(TEST_STEP_STRESSBIN)); status=$$?; $(REPORT_AFTER_STEP); exit $$status

# Both suites: one after the other, or side by side under make -j2 (CI runs
# make -j2 -Orecurse sanitize, each suite's lines printed together).
sanitize: sanitize-gcc sanitize-clang
sanitize-gcc:
	$(MAKE) BUILD=build/san SAN=1 OPT=-O1 test

# ---------------------------------------------------------------- images, diffs
# The reference images, traces, diffs and the docs' pictures are derived
# files: make regen (mk/regen.mk) rewrites those that changed.

# The pictures of shadow and ambient mistakes in docs/05-shadows.md and
# docs/06-ambient.md: tools/figures/mistakes.c renders them (make regen, through
# tools/figures/docimg.sh).
$(BUILD)/bin/mistakes: $(BUILD)/obj/tools/figures/mistakes.o $(BUILD)/obj/gen/05-shadows-scene.o \
                       $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@
check-diffs:
	@tools/figures/diffs.sh check $(PRESENT)

# ---------------------------------------------------------------- benchmark
bench: bench-deps $(BINS) bench-accuracy
	@bench/run.sh

# The cost of the robust geometry (docs/accuracy.md, "Cost"): step 05's frame
# with common/'s geometry and with tests/textbook.h's, in one process. Linked
# without LTO: each side keeps its own functions (docs/accuracy.md says why).
$(BUILD)/obj/bench/robust-cost.o: CFLAGS += -Itests
$(BUILD)/bin/robust-cost: $(BUILD)/obj/bench/robust-cost.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) -fno-lto $(LDFLAGS) $^ $(LDLIBS) -o $@
bench-accuracy: $(BUILD)/bin/robust-cost
	@$(BUILD)/bin/robust-cost $${BENCH_COST_RUNS:-21} 1 | tee $(BUILD)/robust-cost.md

clean:
	rm -rf $(BUILD)

# ---------------------------------------------------------------- the course's checks
# make check: the instructor's command (docs/instructors.md, "make check"):
# make test, then every check of the course rather than of a student's code,
# stage by stage, each stage's time printed. A failed stage does not stop the
# next ones; make check fails at the end, naming the stages that failed. make -j2 check runs
# two jobs at a time inside a stage, each job's lines printed together.
# .ci/run runs the same stages one by one (with check-regions-ci).
CHECK_REGIONS ?= check-regions
# A stage's targets joined by '+'.
CHECK_STAGES = test check-derived check-report check-compilers test-grade check-starter+$(CHECK_REGIONS) sanitize fuzz
check:
	@bad=; for s in $(CHECK_STAGES); do s=$${s//+/ }; t0=$$(date +%s); \
	  echo "==== make check: $$s"; \
	  $(MAKE) --no-print-directory -Orecurse $$s || bad="$$bad, $$s"; \
	  echo "==== make check: $$s ($$(($$(date +%s) - t0)) s)"; done; \
	if [ -n "$$bad" ]; then echo "make check: FAILED: $${bad#, }"; exit 1; fi; \
	echo "make check: every stage passed"

# The files derived from the sources are up to date, every citation exists.
# A stale one says "run make regen".
check-derived: check-diffs check-refs check-mutants check-diagnoses check-images check-traces check-docimg
.PHONY: check check-derived

help:
	@echo "For students (README.md; their tools in tools/loop/)"
	@echo "  make              build every step and render its default scene to $(BUILD)/out/"
	@echo "  make test         every present step's unit and image tests, the stress, reliability and trace tests, the report"
	@echo "  make test-step N  step N's unit tests and image test, and the stress tests of steps 1 .. N (N = 1 .. 8);"
	@echo "                    a result nothing has changed since it passed is reused (RT_CACHE=0: run all)"
	@echo "  make trace-step N [X Y]  step N's traces against the solution's: the first line that differs"
	@echo "  make report       write $(BUILD)/report/index.html from the last test results"
	@echo "  make stress [N=K] the numerical stress tests of the steps written so far (or of steps 1 .. K)"
	@echo "  make test-reliability  the bad-input suite, the number reader, output files, fuzz corpus"
	@echo "  make test-build   build what make test runs, without running it (make -j2 test-build: two at a time)"
	@echo "Building (README.md, \"Set up\"; docs/performance.md, \"Build flags\"; tools/build/)"
	@echo "  make deps         check the libraries; as root on Debian, install the missing ones"
	@echo "  make CC=clang     build with clang (BUILD=build/clang keeps both builds)"
	@echo "  make NATIVE=1     tune for this CPU (the programs may not run on another machine)"
	@echo "  make OPENMP=0     one thread, without OpenMP (the same pictures)"
	@echo "  make print-flags  the compiler and flags in use"
	@echo "For instructors (docs/instructors.md; the course checks in tools/check/)"
	@echo "  make check        make test, then every check of the course, stage by stage:"
	@echo "    make check-derived   check-diffs, check-refs, check-mutants, check-diagnoses, check-images, check-traces, check-docimg, check-statements"
	@echo "    make check-report    the report in headless Chromium"
	@echo "    make check-compilers clang, gcc without OpenMP and gcc -march=native draw this build's floats"
	@echo "    make test-grade      grade the sample class and check every verdict, the pages, Gradescope"
	@echo "    make check-starter   play a student through the starter, step by step, then make test"
	@echo "    make check-regions   stub each solution region alone: its step and later pictures must fail"
	@echo "    make sanitize        the whole suite under AddressSanitizer + UBSan, gcc's and clang's"
	@echo "    make fuzz            fuzz the scene reader, the command line and a render, FUZZ_SECONDS each"
	@echo "  make check-regions-ci  check-regions for the intersection, camera, film and shading regions (CI)"
	@echo "  make regions      list the solution regions"
	@echo "  make starter      write the student starter tree to $(BUILD)/starter (N=5: steps 1-4 stay solved)"
	@echo "  make dist         the starter as handed out: $(BUILD)/dist/raytracer-starter.tar.gz (no git needed to build, test, grade)"
	@echo "  make mutants      run the realistic student bugs through every step, write docs/mutants.md"
	@echo "  make diagnoses    the known mistakes' signatures the verdict lines name (tests/diagnoses.tsv; check-diagnoses, measure-diagnoses)"
	@echo "  make valgrind     the whole suite under valgrind"
	@echo "Grading (docs/grading.md; tools/grading/)"
	@echo "  make grade SUBMISSIONS=DIR [HIDDEN=DIR] [POINTS=FILE] [JOBS=N]  grade a class into $(BUILD)/grade/"
	@echo "  make gradescope   pack the grader for Gradescope ($(BUILD)/gradescope/autograder.zip)"
	@echo "  make sample-class write the sample class of submissions to $(BUILD)/sample-class"
	@echo "  make test-grade-slurm, make test-grade-ssh  the sample class through a one-node Slurm / parallel --sshlogin"
	@echo "  make platforms    build, test and render in fresh Debian 12/13 trees, arm64 (qemu), clang (as root)"
	@echo "Performance (docs/benchmarks.md, docs/performance.md)"
	@echo "  make bench        measure speed and error against POV-Ray, write docs/benchmarks.md"
	@echo "  make bench-accuracy  time step 05's frame, robust vs textbook geometry (docs/accuracy.md)"
	@echo "Derived files (docs/instructors.md, \"Derived files\"; tools/figures/)"
	@echo "  make regen        rebuild every derived file, write those that changed, list the places to re-read"
	@echo "                    (REGEN_BENCH=1: make bench too); steps/NN-name/step.mk is each step's manifest"
	@echo "  make images, make traces, make diffs, make docimg  one part of make regen: images/, tests/traces/,"
	@echo "                    docs/diffs/, docs/img/"
	@echo "  make trace-mistakes  the trace lines of the docs' mistakes (their pictures: make docimg)"
	@echo "  make clean        remove $(BUILD)/"

starter:
	@tools/check/starter.sh $(BUILD)/starter $(N)

.PHONY: all build deps bench-deps test test-build stress test-step sanitize sanitize-gcc \
        check-diffs bench bench-accuracy clean help starter

# Each tool's rules (fuzzing, grading, region checks, ...) in a file of its own.
include $(wildcard mk/*.mk)

DEPFILES := $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
-include $(DEPFILES)
# Every object built before depends on the flags it was built with.
$(DEPFILES:.d=.o): $(BUILD)/.flags
