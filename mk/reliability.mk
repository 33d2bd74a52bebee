# Reliability tests (docs/reliability.md): the bad-input suite (tests/bad/,
# run through a step binary), the number reader against strtof, output files
# under signals and umasks, and the replay of the fuzzing regression corpus.
# `make test` runs them with the other test binaries.

REL_STEP := 08-area-lights
REL_SRC  := tests/test_bad_input.c tests/test_number.c tests/test_outfile.c
REL_OBJ  := $(REL_SRC:tests/%.c=$(BUILD)/obj/tests/rel/%.o)

$(BUILD)/obj/tests/rel/%.o: tests/%.c | $(BUILD)/.deps
	@mkdir -p $(@D)
	@echo "CC $<  (reliability)"
	@$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -DBUILD_DIR='"$(BUILD)"' \
	  -DREL_STEP='"$(REL_STEP)"' -c $< -o $@

$(BUILD)/tests/reliability: $(REL_OBJ) $(LIBCOMMON) $(BUILD)/bin/$(REL_STEP)
	@mkdir -p $(@D)
	@echo "LD $@"
	@$(CC) $(CFLAGS) $(LDFLAGS) $(filter %.o %.a,$^) $(LDLIBS) -lcriterion -o $@

TESTBIN += $(BUILD)/tests/reliability
test: $(BUILD)/tests/reliability

# make test-reliability: this binary alone, verbose.
test-reliability: $(BUILD)/tests/reliability
	@tests/run.sh --verbose $<

.PHONY: test-reliability
