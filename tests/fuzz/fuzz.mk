# libFuzzer harnesses (clang, AddressSanitizer + UndefinedBehaviorSanitizer)
# for the parsers that read what a user, or anyone with the SD card, hands
# the kiosk: glTF/GLB models, PNG/JPEG matcaps and kiosk.ini. Included from
# tests/tests.mk.
#   make fuzzers     build them (build/fuzz/fuzz_*)
#   make fuzz        each for FUZZ_SECONDS (20) from tests/fuzz/corpus, then
#                    replay tests/fuzz/regressions (make test does this too)
#   make fuzz-long   FUZZ_SECONDS=1800 with FUZZ_JOBS=2 workers each
#   make fuzz-seeds  write the glTF and image seeds again (tests/fuzz/mkseeds.c)

# clang 14 on Debian 12, 19 on Debian 13 (CLANG_VERSION: the Makefile reads the release).
FUZZ_CC      ?= clang-$(CLANG_VERSION)
FUZZ_CXX     ?= clang++-$(CLANG_VERSION)
FUZZ_BUILD   := $(BUILD)/fuzz
FUZZ_SECONDS ?= 20
FUZZ_JOBS    ?= 1
FUZZERS      := gltf image config mesh_cache remote
FUZZ_SANITIZE := -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all \
		 -fno-omit-frame-pointer

# Every object of the program, compiled by clang with coverage for the
# fuzzer, in a build folder of its own (as `make asan` does). Warnings are
# gcc's to enforce (-Werror there); clang's may differ, so they do not stop
# this build. tinygltf comes from tests/fuzz/tinygltf_impl.cc, not the
# library, so that its parser is instrumented as well.
fuzzers:
	$(MAKE) --no-print-directory BUILD=$(FUZZ_BUILD) CC=$(FUZZ_CC) CXX=$(FUZZ_CXX) \
		OPT="$(FUZZ_SANITIZE) -fsanitize=fuzzer-no-link" WARN="-Wall -Wextra" \
		$(FUZZERS:%=$(FUZZ_BUILD)/fuzz_%)

# Its stubs follow the header's signatures, which 2.9 (Debian 13) changed.
TINYGLTF_MINOR := $(word 2,$(subst ., ,$(shell $(PKG_CONFIG) --modversion tinygltf)))
$(BUILD)/tinygltf_impl.o: tests/fuzz/tinygltf_impl.cc | $(BUILD)
	$(CXX) $(ALL_CXXFLAGS) -DMK_TINYGLTF_MINOR=$(TINYGLTF_MINOR) -w -c -o $@ $<

# -MMD: rebuilt when a header it reads changes (struct options grows).
$(BUILD)/fuzz_%.o: tests/fuzz/fuzz_%.c | $(BUILD)
	$(CC) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

.PRECIOUS: $(BUILD)/fuzz_%.o

# Linked by clang++, which brings UBSan's C++ runtime (vptr checks).
$(BUILD)/fuzz_%: $(BUILD)/fuzz_%.o $(LIB_OBJS) $(BUILD)/tinygltf_impl.o
	$(CXX) $(FUZZ_SANITIZE) -fsanitize=fuzzer -o $@ $^ $(filter-out -ltinygltf,$(LDLIBS))

fuzz: fuzzers
	FUZZ_DIR=$(FUZZ_BUILD) FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_JOBS=$(FUZZ_JOBS) \
		sh tests/fuzz/run.sh

fuzz-long:
	$(MAKE) fuzz FUZZ_SECONDS=1800 FUZZ_JOBS=2

$(TOOLS_DIR)/mkseeds: tests/fuzz/mkseeds.c $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(TEST_LINK)

fuzz-seeds: $(TOOLS_DIR)/mkseeds
	$(TOOLS_DIR)/mkseeds tests/fuzz/corpus

.PHONY: fuzzers fuzz fuzz-long fuzz-seeds
