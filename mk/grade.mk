# Grading a class (docs/grading.md): make grade SUBMISSIONS=DIR [HIDDEN=DIR]
# [POINTS=FILE] [JOBS=N] [SSHLOGIN=HOSTS] [SLURM=1]; the Gradescope
# autograder; the sample class and the grader's own tests.

# Debian packages the grader needs: jq (Gradescope's results.json), parallel
# (submissions side by side, and on other hosts), bubblewrap (the sandbox);
# chromium for the pages' test, slurm-wlm and munge for the Slurm test. As
# root they are installed, each install announced first with what it is for
# (DEPS_INSTALL=0: named, not installed).
DEB_GRADE       := jq parallel bubblewrap zip unzip
DEB_GRADE_PAGES := chromium
DEB_GRADE_SLURM := slurm-wlm munge

grade-deps: $(BUILD)/.deps
	@DEBS_FOR="the grader (jq: results, parallel: submissions side by side, bubblewrap: the sandbox, zip/unzip: archives)" \
	  $(call need_debs,$(DEB_GRADE))

# The grader's picture comparison, linked with the instructor's library.
$(BUILD)/bin/grade-compare: $(BUILD)/obj/tools/grading/compare.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

GRADE_VARS := SUBMISSIONS HIDDEN POINTS JOBS OUT SSHLOGIN SLURM SLURM_ARGS KEEP
grade: grade-deps $(BUILD)/bin/grade-compare
	@tools/grading/grade $(foreach v,$(GRADE_VARS),$(if $($(v)),$(v)='$($(v))'))

# The autograder to upload to Gradescope: $(BUILD)/gradescope/autograder.zip.
gradescope: grade-deps
	@tools/grading/gradescope/zip.sh $(BUILD)/gradescope/autograder.zip $(HIDDEN) $(POINTS)

# The sample class (tools/grading/sample-class.txt) in $(BUILD)/sample-class.
sample-class:
	@tools/grading/sample-class.sh $(BUILD)/sample-class

# make test-grade (part of make check) grades the sample class (in parallel,
# with the sample hidden scenes), checks every verdict against
# sample-class.txt, the pages in Chromium and the Gradescope autograder on one
# submission (with GRADE_TEST_MIN=3, as the class: it reuses the class's
# results). A test's limit is at least 3 s there, not 5 (docs/grading.md,
# "The sample class").
GRADE_TEST := $(BUILD)/grade-test
GRADE_SAMPLE_HIDDEN := tools/grading/sample-hidden
grade-test-deps: grade-deps
	-@DEBS_FOR="make test-grade's look at the grading pages in headless Chromium" $(call need_debs,$(DEB_GRADE_PAGES))
test-grade: grade-test-deps $(BUILD)/bin/grade-compare $(BUILD)/bin/report-check
	@if [ ! -x tools/check/mutate.sh ]; then \
	  echo "SKIP  grading the sample class: tools/check/mutate.sh (make mutants) is not in this tree"; exit 0; fi; \
	t0=$$(date +%s); export GRADE_TEST_MIN=3; \
	tools/grading/sample-class.sh $(GRADE_TEST)/class >/dev/null && \
	tools/grading/grade SUBMISSIONS=$(GRADE_TEST)/class HIDDEN=$(GRADE_SAMPLE_HIDDEN) \
	  OUT=$(GRADE_TEST)/out $(if $(JOBS),JOBS=$(JOBS)) >$(GRADE_TEST)/grade.log 2>&1 || { cat $(GRADE_TEST)/grade.log; exit 1; }; \
	tools/grading/check-class.sh $(GRADE_TEST)/out | sed 's/^check-class: /      /' > $(GRADE_TEST)/check.log; \
	st=$${PIPESTATUS[0]}; \
	if [ $$st = 0 ]; then echo "PASS  grading the sample class: every verdict as expected ($$(($$(date +%s) - t0)) s," \
	  "load $$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null))"; \
	else echo "FAIL  grading the sample class:"; cat $(GRADE_TEST)/check.log; exit 1; fi; \
	REPORT_CHECK=$(BUILD)/bin/report-check tools/grading/page-test.sh $(GRADE_TEST)/out correct larger-root && \
	tools/grading/gradescope/test.sh $(GRADE_TEST)/class $(GRADE_TEST)/out area-no-cos && \
	echo "      make test-grade: $$(($$(date +%s) - t0)) s in all"

# The same class through a Slurm job array on a one-node Slurm started for
# the test (as root), compared with the local grading. Not in make check.
test-grade-slurm: test-grade
	-@DEBS_FOR="a one-node Slurm for make test-grade-slurm" $(call need_debs,$(DEB_GRADE_SLURM))
	@tools/grading/slurm-test.sh $(GRADE_TEST)/class $(GRADE_SAMPLE_HIDDEN) $(GRADE_TEST)/out

# Two submissions through GNU parallel --sshlogin on two host names, with a
# stand-in for ssh; compared with the local grading. Not in make check.
test-grade-ssh: test-grade
	@tools/grading/ssh-test.sh $(GRADE_TEST)/class $(GRADE_SAMPLE_HIDDEN) $(GRADE_TEST)/out

.PHONY: grade grade-deps gradescope sample-class grade-test-deps test-grade test-grade-slurm \
        test-grade-ssh
