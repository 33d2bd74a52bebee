# Verdicts of the tests (docs/testing.md): every doc section a test message
# cites must exist.
check-test-docs:
	@tools/check-test-docs.sh

.PHONY: check-test-docs
