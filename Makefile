# Ray-tracing course: build every step, render it, test it, measure it.
# `make` builds and renders all steps; `make test` runs every test; `make help`
# lists the other targets. GNU make 4, gcc, Debian packages (installed below).

SHELL := /bin/bash
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:
.SUFFIXES:

BUILD ?= build
STEPS := 01-film 02-intersection 03-camera 04-phong 05-shadows 06-ambient \
         07-antialiasing 08-area-lights
PRESENT := $(filter $(STEPS),$(notdir $(wildcard steps/[0-9][0-9]-*)))

# Each step's default scene (compiled into its binary; none for 01-film).
SCENE_01-film         := scenes/film.scene
SCENE_02-intersection := scenes/spheres.scene
SCENE_03-camera       := scenes/spheres.scene
SCENE_04-phong        := scenes/spheres.scene
SCENE_05-shadows      := scenes/spheres.scene
SCENE_06-ambient      := scenes/ambient.scene
SCENE_07-antialiasing := scenes/antialiasing.scene
SCENE_08-area-lights  := scenes/area-lights.scene

# Each step's unit tests: tests/test_<name>.c (make test-step N runs them).
TESTS_01-film           := film export image
TESTS_02-intersection   := ray sphere plane scene vec
TESTS_03-camera         := camera parser cli
TESTS_04-phong          := light phong
# Steps 05-08 carry step 04's Phong region in their shade.c: they run its tests too.
TESTS_05-shadows        := shadows shadows_lecture phong
TESTS_06-ambient        := ambient phong
TESTS_07-antialiasing   := sampler antialiasing phong
TESTS_08-area-lights    := area_light phong
STRESS_TESTS := $(patsubst tests/%.c,%,$(wildcard tests/stress_*.c))

# ---------------------------------------------------------------- flags
# No -ffast-math and no fused multiply-add contraction: results must not change
# with the optimiser's mood (docs/accuracy.md).
CC      := gcc
# -flto=auto: link-time optimisation inlines camera_ray, film_sample and the
# shape tests into each step's pixel function (about 30 % faster, pictures
# byte-identical; docs/performance.md). Fat objects: tools/ and bench/ link
# build/libcommon.a with plain gcc, without -flto.
OPT     ?= -O3 -march=native -flto=auto -ffat-lto-objects
CFLAGS  := -std=c11 $(OPT) -g -fopenmp -ffp-contract=off -fno-math-errno \
           -D_POSIX_C_SOURCE=200809L \
           -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
           -Wmissing-prototypes -Werror -MMD -MP -Icommon
# TRACE_OFF=1: the trace hooks compiled out (make bench's comparison build;
# --trace and --aov then record nothing).
CFLAGS  += $(if $(TRACE_OFF),-DTRACE_COMPILED_OUT)
# pkg-config runs when a recipe needs it, after the dependency check below.
PKG_CFLAGS = $(shell pkg-config --cflags cglm stb libpng zlib)
LDLIBS  := -fopenmp -lpng -lz -lstb -lm
# Link flags only: with -flto, gcc 12 re-runs its warnings at link time and
# reports false -Wmaybe-uninitialized / -Wuninitialized on `Hit hit;` in the
# steps (scene_intersect fills it whenever it returns true; gcc follows a path
# where instance_hit_fill's switch matches no shape). Each file's compile step
# keeps both warnings.
LDFLAGS := -Wno-maybe-uninitialized -Wno-uninitialized
SAN ?=
# Any report ends the program, so a test that meets one fails. The clang
# build of make sanitize passes its fuller set (mk/reliability.mk).
SAN_FLAGS ?= -fsanitize=address,undefined -fno-sanitize-recover=all
ifneq ($(SAN),)
  CFLAGS  += $(SAN_FLAGS) -fno-omit-frame-pointer
  LDLIBS  += $(SAN_FLAGS)
endif

# ---------------------------------------------------------------- dependencies
# Debian packages the build, the tests and the benchmark need. Run as root, the
# Makefile installs what is missing; otherwise it prints the command to run.
DEB_BUILD := gcc make pkg-config libc6-dev libstb-dev libcglm-dev libpng-dev zlib1g-dev \
             libcriterion-dev libmpfr-dev
DEB_BENCH := gnuplot-nox povray hyperfine

define need_debs
missing=$$(for p in $(1); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null \
    | grep -q 'install ok installed' || echo $$p; done); \
if [ -n "$$missing" ]; then \
  if [ "$$(id -u)" = 0 ]; then \
    echo "make: installing Debian packages:" $$missing; \
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive \
      apt-get install -y -qq --no-install-recommends $$missing >/dev/null \
      || { echo "make: apt-get install failed"; exit 1; }; \
  else \
    echo "make: missing Debian packages. Install them with:"; \
    echo "  sudo apt-get update && sudo apt-get install -y" $$missing; exit 1; \
  fi; \
fi
endef

$(BUILD)/.deps: Makefile
	@mkdir -p $(@D)
	@$(call need_debs,$(DEB_BUILD))
	@touch $@

deps: $(BUILD)/.deps
bench-deps:
	@$(call need_debs,$(DEB_BENCH))

# ---------------------------------------------------------------- common library
COMMON_SRC := $(wildcard common/*.c common/*/*.c)
COMMON_OBJ := $(COMMON_SRC:%.c=$(BUILD)/obj/%.o)
LIBCOMMON  := $(BUILD)/libcommon.a

$(BUILD)/obj/%.o: %.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -c $< -o $@

$(LIBCOMMON): $(COMMON_OBJ)
	@rm -f $@
	@ar rcs $@ $^

# ---------------------------------------------------------------- steps
# step_rules(step): binary build/bin/STEP from steps/STEP/*.c, the default
# scene turned into a C string, and the common library; its render in
# build/out; its test binary build/tests/STEP.
define step_rules
$(1)_SRC := $$(wildcard steps/$(1)/*.c)
$(1)_OBJ := $$($(1)_SRC:%.c=$(BUILD)/obj/%.o)
$(1)_LIB := $$(filter-out %/main.o,$$($(1)_OBJ))
$(BUILD)/obj/steps/$(1)/%.o: CFLAGS += -Isteps/$(1)

$(BUILD)/gen/$(1)-scene.c: $(SCENE_$(1)) tools/scene2c.sh
	@mkdir -p $$(@D)
	@tools/scene2c.sh $(SCENE_$(1)) > $$@

$(BUILD)/bin/$(1): $$($(1)_OBJ) $(BUILD)/obj/gen/$(1)-scene.o $(LIBCOMMON)
	@mkdir -p $$(@D)
	@echo "LD $$@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $$^ $(LDLIBS) -o $$@

$(BUILD)/out/$(1).png: $(BUILD)/bin/$(1)
	@mkdir -p $$(@D)
	@$(BUILD)/bin/$(1) -o $$@

$(1)_TOBJ := $$(patsubst %,$(BUILD)/obj/tests/$(1)/test_%.o,$$(TESTS_$(1))) \
             $(BUILD)/obj/tests/$(1)/image_test.o
$(BUILD)/obj/tests/$(1)/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $$(@D)
	@echo "CC $$<  ($(1) test)"
	@$(CC) $(CFLAGS) $$(PKG_CFLAGS) -Isteps/$(1) -Itests \
	  -DSTEP_NAME='"$(1)"' -DBUILD_DIR='"$(BUILD)"' -c $$< -o $$@
$(BUILD)/tests/$(1): $$($(1)_TOBJ) $$($(1)_LIB) $(LIBCOMMON) $(BUILD)/bin/$(1)
	@mkdir -p $$(@D)
	@echo "LD $$@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $$(filter %.o %.a,$$^) $(LDLIBS) -lcriterion -lmpfr -lgmp -o $$@
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
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -DBUILD_DIR='"$(BUILD)"' -c $< -o $@
$(BUILD)/tests/stress: $(STRESS_OBJ) $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -lcriterion -lmpfr -lgmp -o $@
STRESSBIN := $(if $(STRESS_TESTS),$(BUILD)/tests/stress)

# make test-build: what make test runs, built and not run (make -j2
# test-build builds it two at a time; CI does, before make test).
test-build: $(TESTBIN) $(STRESSBIN) $(BUILD)/bin/04-phong $(BUILD)/bin/05-shadows \
            $(BUILD)/bin/mistakes
test: test-build
	@tests/run.sh $(TESTBIN) $(STRESSBIN) $(TRACE_TESTBIN); status=$$?; \
	  $(REPORT_AFTER_TEST) || status=1; \
	  $(if $(SAN),,$(foreach t,$(TEST_AFTER),$(MAKE) --no-print-directory $(t) || status=1;)) \
	  exit $$status

# The stress tests render through steps 04, 05 and tools/mistakes.c (docs/accuracy.md).
stress: $(STRESSBIN) $(BUILD)/bin/04-phong $(BUILD)/bin/05-shadows $(BUILD)/bin/mistakes
	@tests/run.sh --verbose $(STRESSBIN)

# make test-step N  (or N=3): one step's unit tests and image test.
ifeq (test-step,$(firstword $(MAKECMDGOALS)))
  N ?= $(word 2,$(MAKECMDGOALS))
  $(eval $(word 2,$(MAKECMDGOALS)):;@:)
endif
N_NUM = $(shell expr '$(N)' + 0 2>/dev/null)
N_PAD = $(if $(N_NUM),$(shell printf %02d '$(N_NUM)' 2>/dev/null))
STEP_N = $(filter $(N_PAD)-%,$(STEPS))
test-step:
	@if [ -z "$(N)" ]; then echo "usage: make test-step N   (N = 1 .. 8)"; exit 2; fi
	@if [ -z "$(STEP_N)" ]; then echo "make test-step: there is no step '$(N)' (steps are 1 .. 8)"; exit 2; fi
	@if [ -z "$(filter $(STEP_N),$(PRESENT))" ]; then \
	  echo "make test-step: step $(STEP_N) does not exist yet (no steps/$(STEP_N)/)"; exit 1; fi
	@$(MAKE) --no-print-directory $(BUILD)/tests/$(STEP_N)
	@tests/run.sh --verbose $(BUILD)/tests/$(STEP_N); status=$$?; \
	  $(REPORT_AFTER_STEP); exit $$status

# Both suites: one after the other, or side by side under make -j2 (CI runs
# make -j2 -Orecurse sanitize, each suite's lines printed together).
sanitize: sanitize-gcc sanitize-clang
sanitize-gcc:
	$(MAKE) BUILD=build/san SAN=1 OPT=-O1 test

# ---------------------------------------------------------------- images, diffs
# Reference images: each step's default scene at the reference size, with the
# image test's options (tools/images.sh). Only on purpose: they are what the
# image tests compare against (make check-images says when they are stale).
images: $(BINS)
	@tools/images.sh write $(BUILD) $(PRESENT)

# The pictures of shadow and ambient mistakes in docs/05-shadows.md and
# docs/06-ambient.md: tools/mistakes.c renders them (on purpose only).
$(BUILD)/bin/mistakes: $(BUILD)/obj/tools/mistakes.o $(BUILD)/obj/gen/05-shadows-scene.o \
                       $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@
mistakes: $(BUILD)/bin/mistakes $(BUILD)/bin/05-shadows $(BUILD)/bin/06-ambient
	@tools/mistakes.sh $(BUILD)/bin

diffs:
	@tools/diffs.sh write $(PRESENT)
check-diffs:
	@tools/diffs.sh check $(PRESENT)

# ---------------------------------------------------------------- benchmark
bench: bench-deps $(BINS) bench-accuracy
	@bench/run.sh

# The cost of the robust geometry (docs/accuracy.md, "Cost"): step 05's frame
# with common/'s geometry and with tests/textbook.h's, in one process. Linked
# without LTO: each side keeps its own functions (docs/accuracy.md says why).
$(BUILD)/obj/bench/robust-cost.o: CFLAGS += -Itests -Isteps/05-shadows
$(BUILD)/bin/robust-cost: $(BUILD)/obj/bench/robust-cost.o \
                          $(BUILD)/obj/steps/05-shadows/shade.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) -fno-lto $(LDFLAGS) $^ $(LDLIBS) -o $@
bench-accuracy: $(BUILD)/bin/robust-cost
	@$(BUILD)/bin/robust-cost $${BENCH_COST_RUNS:-21} 1 | tee $(BUILD)/robust-cost.md

clean:
	rm -rf $(BUILD)

help:
	@echo "Build and test"
	@echo "  make              build every step and render its default scene to $(BUILD)/out/"
	@echo "  make test         every unit, stress, image, reliability and trace test, the report, the sample class graded"
	@echo "  make test-build   build what make test runs, without running it (make -j2 test-build: two at a time)"
	@echo "  make test-step N  step N's unit tests and image test, one verdict line per check (N = 1 .. 8)"
	@echo "  make stress       the numerical stress tests alone"
	@echo "  make test-reliability  the bad-input suite, the number reader, output files, fuzz corpus"
	@echo "Seeing why (docs/tracing.md)"
	@echo "  make trace-step N [X Y]  step N's traces against the solution's: the first line that differs"
	@echo "  make report       write $(BUILD)/report/index.html from the last test results"
	@echo "  make traces       rewrite the reference traces tests/traces/ (on purpose only)"
	@echo "  make trace-mistakes  the pictures and traces of the docs' 'Seeing the mistake' (on purpose only)"
	@echo "Students and instructors (README, docs/grading.md)"
	@echo "  make starter      write the student starter tree to $(BUILD)/starter (N=5: steps 1-4 stay solved)"
	@echo "  make carry N      in a starter tree: copy your code of the steps below N into steps N to 8"
	@echo "  make grade SUBMISSIONS=DIR [HIDDEN=DIR] [POINTS=FILE] [JOBS=N]  grade a class into $(BUILD)/grade/"
	@echo "  make gradescope   pack the grader for Gradescope ($(BUILD)/gradescope/autograder.zip)"
	@echo "  make sample-class write the sample class of submissions to $(BUILD)/sample-class"
	@echo "  make test-grade   grade the sample class and check every verdict (part of make test)"
	@echo "  make test-grade-slurm, make test-grade-ssh  the same through a one-node Slurm / parallel --sshlogin"
	@echo "Checks that keep the course honest (docs/testing-the-tests.md; CI runs most)"
	@echo "  make check-starter  play a student through the starter, step by step"
	@echo "  make check-regions  stub each solution region alone: its step and later pictures must fail"
	@echo "  make check-regions-ci  the same for the intersection, camera, film and shading regions"
	@echo "  make regions      list the solution regions"
	@echo "  make mutants      run the realistic student bugs through every step, write docs/mutants.md"
	@echo "  make check-mutants  every mutant still applies to the code"
	@echo "  make check-diffs, check-refs, check-images, check-traces  derived files and citations up to date"
	@echo "Reliability (docs/reliability.md)"
	@echo "  make sanitize     the whole suite under AddressSanitizer + UBSan, gcc's and clang's"
	@echo "  make valgrind     the whole suite under valgrind (an x86-64-v3 build in build/vg)"
	@echo "  make fuzz         fuzz the scene reader, the command line and a render, FUZZ_SECONDS each"
	@echo "Performance (docs/benchmarks.md, docs/performance.md)"
	@echo "  make bench        measure speed and error against POV-Ray, write docs/benchmarks.md"
	@echo "  make bench-accuracy  time step 05's frame, robust vs textbook geometry (docs/accuracy.md)"
	@echo "Generated files (on purpose only)"
	@echo "  make images       regenerate the reference images in images/"
	@echo "  make diffs        write docs/diffs/NN-name.diff (each step against the previous)"
	@echo "  make mistakes     render the shadow/ambient mistake pictures into docs/img/"
	@echo "  make clean        remove $(BUILD)/"

starter:
	@tools/starter.sh $(BUILD)/starter $(N)

.PHONY: all build deps bench-deps test test-build stress test-step sanitize sanitize-gcc images diffs \
        check-diffs bench bench-accuracy clean help starter mistakes

# Each tool's rules (fuzzing, grading, region checks, ...) in a file of its own.
include $(wildcard mk/*.mk)

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
