# The starter tree as a student meets it, and the checks that the tree says
# what it does (docs/instructors.md, "Checks of the starter").
#   make check-starter  the starter builds, fails exactly the unwritten steps,
#                       and passes steps 1..K once a student wrote them
#   make check-refs     every file and doc section a source or test cites exists
#   make check-images   the reference images are what make regen renders now

# FULL=1: every step's test at every stage (the default: step K and K+1).
check-starter:
	@tools/check-starter.sh $(BUILD)/check-starter $(if $(FULL),--full)

check-refs:
	@tools/check-refs.sh

check-images: $(BINS) $(BUILD)/bin/imgcmp
	@tools/images.sh check $(BUILD) $(PRESENT)
$(BUILD)/bin/imgcmp: $(BUILD)/obj/tools/imgcmp.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

.PHONY: check-starter check-refs check-images
