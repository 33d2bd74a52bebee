# Grading a class (docs/grading.md): make grade SUBMISSIONS=DIR [HIDDEN=DIR]
# [POINTS=FILE] [JOBS=N] [SSHLOGIN=HOSTS] [SLURM=1]; the sample class and its
# tests; the Gradescope autograder.

# Debian packages the grader needs: jq reads Criterion's reports, parallel
# runs submissions side by side (and on other hosts), bubblewrap is the
# sandbox; chromium only for the page tests, slurm for its own test.
DEB_GRADE        := jq parallel bubblewrap
DEB_GRADE_PAGES  := chromium
DEB_GRADE_SLURM  := slurm-wlm munge

grade-deps: $(BUILD)/.deps
	@$(call need_debs,$(DEB_GRADE))

# The grader's picture comparison, linked with the instructor's library.
$(BUILD)/bin/grade-compare: $(BUILD)/obj/tools/grading/compare.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

GRADE_VARS := SUBMISSIONS HIDDEN POINTS JOBS OUT SSHLOGIN SLURM SLURM_ARGS KEEP
grade: grade-deps $(BUILD)/bin/grade-compare
	@tools/grade $(foreach v,$(GRADE_VARS),$(if $($(v)),$(v)='$($(v))'))

.PHONY: grade grade-deps
