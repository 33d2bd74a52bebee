# The solution regions and the check that the tests cannot be fooled
# (docs/testing-the-tests.md): tools/check/regions.sh, tools/check/check-regions.sh.

# make regions: every region, its step, function and hash.
regions:
	@tools/check/regions.sh list

# make check-regions [REGIONS=pattern]: copies of a region in several step
# folders are identical, and stubbing any one region fails the step that
# introduces it and the image test of every later step that uses it.
check-regions:
	@tools/check/regions.sh same
	@tools/check/check-regions.sh $(if $(REGIONS),'$(REGIONS)')

.PHONY: regions check-regions

# The CI subset, should the whole check grow too long for CI: the
# intersection, camera, film and Phong regions (21 of 38 today).
check-regions-ci:
	@tools/check/regions.sh same
	@tools/check/check-regions.sh '^common/(sphere|plane|camera|film)\.c |shade_phong'

.PHONY: check-regions-ci
