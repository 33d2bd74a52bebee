# The mutation run (docs/testing-the-tests.md): realistic student bugs and
# correct alternatives from tools/mutants/, each applied alone to a scratch
# tree and put through every step's tests; docs/mutants.md is the result.

# make mutants [MUTANTS=pattern]: the whole set writes docs/mutants.md, a
# pattern (grep -E on the IDs) writes build/mutants/mutants.md.
mutants:
	@tools/mutants.sh $(if $(MUTANTS),'$(MUTANTS)')

# make check-mutants: every mutant still applies to the code (no build; seconds).
check-mutants:
	@tools/mutants.sh --check

.PHONY: mutants check-mutants
