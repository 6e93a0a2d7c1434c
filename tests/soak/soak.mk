# The soak test: tests/soak/soak.c drives the live loop through OSMesa with
# matcap changes and reloads, and checks that memory stays flat; valgrind
# runs a shorter version for leaks. Included from tests/tests.mk.
#   make soak    a longer run than make test's: 500,000 frames at 64x64, a
#                matcap change every 100 frames, a reload every 10,000; then
#                valgrind on 1,000 frames (a reload every 50)
# `make test` runs 100,000 frames (a reload every 10,000) and valgrind on 400.

$(TOOLS_DIR)/soak: tests/soak/soak.c $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(TEST_LINK)

soak: $(TOOLS_DIR)/soak
	SOAK=$(TOOLS_DIR)/soak SOAK_FRAMES=500000 SOAK_RELOAD_EVERY=10000 \
		SOAK_VALGRIND_FRAMES=1000 sh tests/soak/soak.sh

.PHONY: soak
