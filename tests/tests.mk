# Tests: included from the top-level Makefile.
#   make test     everything below, ending in one "N passed, N failed" line
#   make golden   regenerate tests/golden/*.png on purpose (then look at them)

UNIT_TESTS  := options mesh image gltf shading
TOOLS_DIR   := $(BUILD)/tools
ASAN_BUILD  := $(BUILD)/asan
SANITIZE    := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all \
	       -fno-omit-frame-pointer
TEST_LIBS   = $(shell $(PKG_CONFIG) --libs cmocka zlib) $(LDLIBS) -lstdc++

$(BUILD)/tests/test_%: tests/unit/test_%.c tests/gltf_write.c tests/gltf_write.h $(LIB_OBJS)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Itests $(LDFLAGS) -o $@ $< tests/gltf_write.c $(LIB_OBJS) $(TEST_LIBS)

unit-tests: $(UNIT_TESTS:%=$(BUILD)/tests/test_%)

$(TOOLS_DIR)/mkmodels: tests/mkmodels.c tests/gltf_write.c $(LIB_OBJS)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Itests -o $@ $< tests/gltf_write.c $(LIB_OBJS) $(TEST_LIBS)

$(TOOLS_DIR)/imgdiff: tests/imgdiff.c $(BUILD)/image.o $(BUILD)/log.o
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm

test-tools: $(TOOLS_DIR)/mkmodels $(TOOLS_DIR)/imgdiff $(BUILD)/bake

# The unit tests and a second kiosk binary, built with AddressSanitizer and
# UndefinedBehaviorSanitizer: malformed input must not crash either.
asan:
	$(MAKE) --no-print-directory BUILD=$(ASAN_BUILD) OPT="$(SANITIZE)" \
		LDFLAGS="$(SANITIZE)" KIOSK=$(ASAN_BUILD)/matcap-kiosk \
		$(ASAN_BUILD)/matcap-kiosk unit-tests

test: $(KIOSK) test-tools asan
	KIOSK=./$(KIOSK) ASAN_KIOSK=$(ASAN_BUILD)/matcap-kiosk UNIT_DIR=$(ASAN_BUILD)/tests \
		TOOLS=$(TOOLS_DIR) BAKE=$(BUILD)/bake sh tests/run.sh

golden: $(KIOSK) test-tools
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/golden.sh tests/golden

.PHONY: unit-tests test-tools asan test golden

bench: $(KIOSK) test-tools
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench.sh

.PHONY: bench
