# The starter tree as a student meets it, and the checks that the tree says
# what it does (docs/instructors.md, "Checks of the starter").
#   make check-starter  the starter builds, fails exactly the unwritten steps,
#                       and passes steps 1..K once a student wrote them
#   make check-refs     every file and doc section a source or test cites exists
#   make check-images   the reference images are what make regen renders now
#   make dist [N=K]     the tarball an instructor hands out: the starter (steps
#                       below K solved), no .git, both licenses

# FULL=1: every step's test at every stage (the default: step K and K+1).
check-starter:
	@tools/check/check-starter.sh $(BUILD)/check-starter $(if $(FULL),--full)

check-refs:
	@tools/check/check-refs.sh

check-images: $(BINS) $(BUILD)/bin/imgcmp
	@tools/figures/images.sh check $(BUILD) $(PRESENT)
$(BUILD)/bin/imgcmp: $(BUILD)/obj/tools/loop/imgcmp.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

# The tarball an instructor hands out (docs/instructors.md, "Handing out the
# starter"): $(BUILD)/dist/$(DIST_NAME).tar.gz, one folder $(DIST_NAME)/ that
# builds, tests and grades without git.
DIST_NAME ?= raytracer-starter
dist:
	@tools/check/starter.sh $(BUILD)/dist/$(DIST_NAME) $(N) >/dev/null
	@for f in LICENSE docs/LICENSE; do [ -f $(BUILD)/dist/$(DIST_NAME)/$$f ] || \
	  { echo "dist: $$f is missing from the starter"; exit 1; }; done
	@tar -czf $(BUILD)/dist/$(DIST_NAME).tar.gz -C $(BUILD)/dist --sort=name --owner=0 --group=0 \
	  --numeric-owner $(DIST_NAME)
	@echo "dist: wrote $(BUILD)/dist/$(DIST_NAME).tar.gz ($$(du -h $(BUILD)/dist/$(DIST_NAME).tar.gz | cut -f1);" \
	  "$$(tar -tzf $(BUILD)/dist/$(DIST_NAME).tar.gz | grep -c '[^/]$$') files, every step $(if $(N),from $(N) on )stubbed):" \
	  "unpacked anywhere, make builds it, make test tests it, make grade SUBMISSIONS=DIR grades a class"

.PHONY: check-starter check-refs check-images dist
