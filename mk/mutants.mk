# The mutation run (docs/testing-the-tests.md): realistic student bugs and
# correct alternatives from tools/check/mutants/, each applied alone to a scratch
# tree and put through every step's tests; docs/mutants.md is the result.

# make mutants [MUTANTS=pattern]: the whole set writes docs/mutants.md, a
# pattern (grep -E on the IDs) writes build/mutants/mutants.md.
mutants:
	@tools/check/mutants.sh $(if $(MUTANTS),'$(MUTANTS)')

# make check-mutants: every mutant still applies to the code (no build; seconds).
check-mutants:
	@tools/check/mutants.sh --check

.PHONY: mutants check-mutants

# The diagnosis of a failing check (docs/mutants.md, "Diagnosis"): the
# signature of each bug's failing checks at its own step, in
# tests/diagnoses.tsv, which tests/run.sh reads. make diagnoses rewrites it
# (minutes; written only when it changes; DIAGNOSES=pattern: those mutants
# alone, to build/diagnoses/); make check-diagnoses says when it is stale;
# make measure-diagnoses puts every mutant through the student's build and
# counts the verdicts that name their mistake (build/diagnoses/measure.md).
diagnoses:
	@tools/check/diagnoses.sh write $(if $(DIAGNOSES),'$(DIAGNOSES)')
check-diagnoses:
	@tools/check/diagnoses.sh check
measure-diagnoses:
	@tools/check/diagnoses.sh measure $(if $(DIAGNOSES),'$(DIAGNOSES)')

.PHONY: diagnoses check-diagnoses measure-diagnoses
