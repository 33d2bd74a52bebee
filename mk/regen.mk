# make regen (docs/instructors.md, "Derived files"): every file derived from
# the sources rebuilt, and written only where its content changed beyond its
# check's tolerance (tools/figures/regen.sh); a clean tree regenerates to no change.
# It then lists what it wrote and the hand-written places that name what
# changed (tools/figures/regen-places.sh). REGEN_BENCH=1: make bench too.
#   make images, make traces, make diffs, make docimg: one part alone.

# The generators of other derived files, run by make regen after its own
# parts: make targets, each rewriting a file only when its content changes
# and printing "regen: wrote FILE" (or "TOOL: rewrote FILE") for each file it
# writes (make regen lists those lines). regen-statements: the lists of
# statements in the expected messages, tests/statements.h and the fuzzing
# dictionary (mk/shapes.mk); diagnoses: the mutants' fingerprints,
# tests/diagnoses.tsv (mk/mutants.mk).
REGEN_HOOKS := regen-statements diagnoses

# What the parts run: the steps' programs, the picture comparison, the trace
# comparison, the docs' pictures' programs (tools/figures/docimg.sh; the
# stress tests write the scaled scenes of docs/accuracy.md's pictures).
REGEN_NEEDS = $(BINS) $(BUILD)/bin/imgcmp $(BUILD)/bin/trace-diff $(BUILD)/bin/mistakes $(STRESSBIN)
regen: $(REGEN_NEEDS)
	@REGEN_HOOKS='$(strip $(REGEN_HOOKS))' REGEN_BENCH='$(REGEN_BENCH)' \
	  tools/figures/regen.sh $(BUILD) $(PRESENT)
images traces diffs docimg: $(REGEN_NEEDS)
	@REGEN_ONLY=$@ tools/figures/regen.sh $(BUILD) $(PRESENT)

# The docs' pictures against what their generators render now.
check-docimg: $(REGEN_NEEDS)
	@tools/figures/docimg.sh check $(BUILD)

.PHONY: regen images traces diffs docimg check-docimg
