# The shapes and the statement table (docs/extending.md, "Adding a shape").
#   make regen-statements  rewrite the files generated from the parser's
#                          statement table (tests/bad/scenes/*.err lists,
#                          tests/statements.h, tests/fuzz/scene.dict's words);
#                          make regen runs it
#   make check-statements  those files are up to date ("run make regen" if not)
#   make check-tracked     every source file is tracked by git (make starter
#                          copies only those)
# The lists are read from the messages of a step's program.
STATEMENTS_BIN := $(firstword $(BINS))

regen-statements: $(STATEMENTS_BIN)
	@tools/figures/statements.sh $<

check-statements: $(STATEMENTS_BIN)
	@tools/figures/statements.sh --check $<

check-tracked:
	@tools/check/check-tracked.sh

# Where they run: with the derived files' checks, before the bad-input
# suite compares the messages, and before a starter is made.
check-derived: check-statements
test-reliability: check-statements
check-starter: check-tracked
starter: check-tracked

.PHONY: regen-statements check-statements check-tracked
