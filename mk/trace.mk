# Looking inside a pixel (README.md, "For students"; docs/tracing.md): the
# tracer's tests, the reference traces and make trace-step N [X Y], the
# report and its check in a browser. (The per-term reference images are
# tools/figures/images.sh's.)

TRACE_DIFF := $(BUILD)/bin/trace-diff
$(TRACE_DIFF): $(BUILD)/obj/tools/loop/trace-diff.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

# The reference traces tests/traces/STEP/X_Y.json: the pixels of each step's
# manifest (TRACE_X_Y lines), traced by the solution; make regen rewrites them.

# make trace-step N [X Y]: step N's traces against the references, the first
# line that differs for each pixel (or only pixel X Y).
ifeq (trace-step,$(firstword $(MAKECMDGOALS)))
  N ?= $(word 2,$(MAKECMDGOALS))
  TRACE_XY := $(wordlist 3,4,$(MAKECMDGOALS))
  $(foreach w,$(wordlist 2,4,$(MAKECMDGOALS)),$(eval $(w):;@:))
endif
trace-step: $(TRACE_DIFF) $(if $(filter $(STEP_N),$(PRESENT)),$(BUILD)/bin/$(STEP_N))
	@if [ -z "$(N)" ]; then echo "usage: make trace-step N [X Y]   (N = 1 .. 8)"; exit 2; fi
	@if [ -z "$(filter $(STEP_N),$(PRESENT))" ]; then \
	  echo "make trace-step: there is no step '$(N)' (steps are 1 .. 8)"; exit 2; fi
	@tools/figures/traces.sh compare $(BUILD) $(STEP_N) $(TRACE_XY)

# CI: the solution's traces are the references (make regen after a change
# that moves them on purpose).
check-traces: $(TRACE_DIFF) $(BINS)
	@status=0; for s in $(PRESENT); do \
	  tools/figures/traces.sh compare $(BUILD) $$s > $(BUILD)/check-traces.log 2>&1 || { \
	    cat $(BUILD)/check-traces.log; status=1; }; done; \
	if [ $$status = 0 ]; then echo "check-traces: every reference trace agrees with the solution"; \
	else echo "check-traces: the traces above are stale: run make regen (if the change is meant)"; fi; \
	exit $$status

.PHONY: trace-step check-traces

# The tests of --trace and --aov (tests/test_trace.c): they run every step's
# binary, so they are a test binary of their own, run by make test.
TRACE_TESTBIN := $(BUILD)/tests/trace
$(BUILD)/obj/tests/trace/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (trace)"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -DBUILD_DIR='"$(BUILD)"' -c $< -o $@
$(TRACE_TESTBIN): $(BUILD)/obj/tests/trace/test_trace.o $(LIBCOMMON) $(BINS)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $(filter %.o %.a,$^) $(LDLIBS) -lcriterion -o $@
test-build: $(TRACE_TESTBIN)

# The report (tools/loop/report.c, its look in tools/loop/report.html): make test and
# make test-step N write build/report/index.html from the results files and
# the image tests' pictures.
REPORT := $(BUILD)/bin/report
$(REPORT): tools/loop/report.c tools/loop/json.h | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<"
	@$(CC) $(CFLAGS) $< -o $@
report: $(REPORT)
	@mkdir -p $(BUILD)/report
	@$(REPORT) $(BUILD) tools/loop/report.html
.PHONY: report

# What the Makefile's test and test-step recipes run after the tests (their
# exit status kept): the report.
REPORT_AFTER_TEST = mkdir -p $(BUILD)/report && $(REPORT) $(BUILD) tools/loop/report.html
REPORT_AFTER_STEP = mkdir -p $(BUILD)/report && $(REPORT) $(BUILD) tools/loop/report.html $(STEP_N)
test-build: $(REPORT)
test-step: $(REPORT)

# make check-report (part of make check): the report make test wrote, and a
# scratch one, in headless Chromium (tests/report.sh; chromium is installed
# when make runs as root, else the check says SKIP).
DEB_REPORT := chromium
report-deps:
	-@$(call need_debs,$(DEB_REPORT))
check-report: report-deps $(REPORT) $(BUILD)/bin/report-check $(BUILD)/tests/03-camera \
              $(BUILD)/tests/04-phong $(BUILD)/bin/04-phong
	@if [ ! -d $(BUILD)/results ]; then \
	  echo "check-report: no test results in $(BUILD)/results: run make test first"; exit 1; fi
	@$(REPORT_AFTER_TEST) && tests/report.sh $(BUILD)
.PHONY: report-deps check-report
$(BUILD)/bin/report-check: $(BUILD)/obj/tools/check/report-check.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

# The trace lines of the step docs' "Seeing the mistake" sections
# (tools/figures/trace-mistakes.sh; on purpose only, minutes; their pictures, which
# land in build/ here, are make regen's, through tools/figures/docimg.sh).
trace-mistakes: $(BINS)
	@OUT=$(BUILD)/trace-mistakes-img tools/figures/trace-mistakes.sh $(BUILD)
.PHONY: trace-mistakes
