# make platforms: the course built, tested and rendered on other platforms,
# every render compared with images/ and with this machine's (tools/build/platforms.sh;
# root, the Debian mirror reachable). PLATFORMS picks some of host (gcc and
# clang here), bookworm and trixie (Debian 12 and 13 from debootstrap: make,
# make test-step 1 .. 8, FULL=1 make test) and arm64 (cross-built, run under
# qemu-user). Results in $(BUILD)/platforms/summary.txt.
PLATFORMS ?= host bookworm trixie arm64

platforms: $(BINS) $(BUILD)/bin/pfmdiff
	@BUILD=$(BUILD) tools/build/platforms.sh $(PLATFORMS)

# make check-compilers: the host platform alone (no root): clang, gcc without
# OpenMP and gcc -march=native built beside this build, each drawing every
# reference render, and steps 07-08 with every sampler, float for float as
# this build does (one float that differs fails).
check-compilers: clang-deps $(BINS) $(BUILD)/bin/pfmdiff
	@BUILD=$(BUILD) tools/build/platforms.sh host

$(BUILD)/bin/pfmdiff: $(BUILD)/obj/tools/build/pfmdiff.o $(LIBCOMMON)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

.PHONY: platforms check-compilers
