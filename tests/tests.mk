# Tests: included from the top-level Makefile (tests/README.md says more).
#   make test          every test (tests/run.sh), ending in one "N passed,
#                      N failed" line; VM_E2E=0 leaves the virtual board out
#   make unit          the unit tests alone, built with ASan and UBSan
#   make quick         the unit tests and the golden images, no sanitizer
#                      (build/quick): the inner loop, "N passed, N failed"
#   make check T=NAME  one test or group by name (tests/check.sh; T= lists them)
#   make golden        regenerate tests/golden/*.png and tests/readme/first.png on
#                      purpose (then look at them)
#   make bench         speed figures (printed, never asserted); make report

UNIT_TESTS  := options mesh image gltf gltf_ext shading app app_clock button content service
UNIT_TESTS  += tangent subdivide material mesh_cache mesh_cache_content
UNIT_TESTS  += camera_math camera_proto camera_texture
UNIT_TESTS  += stability fp16 lod lod_threads
UNIT_TESTS  += base_color draw_list material_light
UNIT_TESTS  += drm gesture touch_decode schedule power cec backlight
UNIT_TESTS  += touch_device app_touch
UNIT_TESTS  += model_list gltf_words settings_files
UNIT_TESTS  += status poster file metrics background framing
UNIT_TESTS  += kiosk_reload kiosk_matcap app_frame model_settings render_scale
UNIT_TESTS  += kiosk_coarse
UNIT_TESTS  += anim anim_palette anim_play kiosk_anim anim_frames gltf_bake
UNIT_TESTS  += caption import gltf_depth load_guard caption_wrap lang_text lang kiosk_lang
UNIT_TESTS  += ini stranger_settings normals
UNIT_TESTS  += textures
UNIT_TESTS  += variants vertex_alpha
UNIT_TESTS  += precedence model_name
UNIT_TESTS  += knob visits
UNIT_TESTS  += remote
UNIT_TESTS  += hotspot hotspot_settings hotspot_place hotspot_node
UNIT_TESTS  += output_view
UNIT_TESTS  += wall
TOOLS_DIR   := $(BUILD)/tools
ASAN_BUILD  := $(BUILD)/asan
# MK_TEST_HOOKS: the test hooks (MK_TEST_PREPARE_DELAY_MS, src/app/reload.c)
# exist in the sanitizer builds alone, never in the program installed.
SANITIZE    := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all \
	       -fno-omit-frame-pointer -DMK_TEST_HOOKS
TSAN_BUILD  := $(BUILD)/tsan
TSANITIZE   := -O1 -g -fsanitize=thread -fno-omit-frame-pointer -DMK_TEST_HOOKS
TEST_LIBS   = $(shell $(PKG_CONFIG) --libs cmocka zlib) $(LDLIBS) -lstdc++
TEST_CFLAGS = $(ALL_CFLAGS) -Itests -Itests/tools
# The C mirror of the shaders: the tests' reference, never in the program.
ORACLE_OBJS := $(BUILD)/oracle/fp16.o $(BUILD)/oracle/shading_double.o $(BUILD)/oracle/anim_mirror.o \
	       $(BUILD)/oracle/shading_float.o

$(BUILD)/oracle/%.o: tests/oracle/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -MMD -MP -c -o $@ $<

-include $(wildcard $(BUILD)/oracle/*.d)

# The test helpers (tests/tools, and the C mirror above), compiled once and
# archived beside the program's objects (LIB_ARCHIVE): a test or tool takes
# only the objects it calls. Each test compiled the helpers again and
# linked every object, 39 MB an ASan test and 1.8 GB the unit tests, and a
# CI machine ran out of disk.
TEST_HELPERS := gltf_write gltf_parts gltf_morph gltf_joints maps parts_models gltf_variants
TESTKIT      := $(BUILD)/libtestkit.a
TEST_LINK     = $(TESTKIT) $(LIB_ARCHIVE) $(TEST_LIBS)

$(BUILD)/testkit/%.o: tests/tools/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -MMD -MP -c -o $@ $<

-include $(wildcard $(BUILD)/testkit/*.d)

$(TESTKIT): $(TEST_HELPERS:%=$(BUILD)/testkit/%.o) $(ORACLE_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/tests/test_%: tests/unit/test_%.c tests/tools/gltf_write.h tests/tools/gltf_parts.h \
		tests/tools/gltf_joints.h $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) $(LDFLAGS) -o $@ $< $(TEST_LINK)

unit-tests: $(UNIT_TESTS:%=$(BUILD)/tests/test_%)

$(TOOLS_DIR)/mkmodels: tests/tools/mkmodels.c $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(TEST_LINK)

$(TOOLS_DIR)/imgdiff: tests/tools/imgdiff.c $(BUILD)/util/image.o $(BUILD)/util/file.o $(BUILD)/util/log.o
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm

# Which colour-bar hues a picture shows (the camera's, in tests/e2e/camera.sh).
$(TOOLS_DIR)/hues: tests/tools/hues.c $(BUILD)/util/image.o $(BUILD)/util/file.o $(BUILD)/util/log.o
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm
test-tools: $(TOOLS_DIR)/hues
# A wall's screens side by side (tests/golden wall-2x2, the seam test).
$(TOOLS_DIR)/stitch: tests/tools/stitch.c $(BUILD)/util/image.o $(BUILD)/util/file.o $(BUILD)/util/log.o
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm
test-tools: $(TOOLS_DIR)/stitch
# The manual pages as the settings table writes them now (test_man compares
# them with config/'s).
test-tools: $(MAN_BUILT)

# Sends CEC power messages through src/display/cec.c (tests/e2e/cec.sh).
$(TOOLS_DIR)/cec_power: tests/tools/cec_power.c $(BUILD)/display/cec.o $(BUILD)/util/log.o
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^
test-tools: $(TOOLS_DIR)/cec_power

# Sets the board's clock and its synchronised flag (tests/e2e/power.sh).
$(TOOLS_DIR)/clock_set: tests/tools/clock_set.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^
test-tools: $(TOOLS_DIR)/clock_set

# A uinput touchscreen that drags, pinches and taps (tests/e2e/touch.sh).
$(TOOLS_DIR)/touch_inject: tests/tools/touch_inject.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^
test-tools: $(TOOLS_DIR)/touch_inject

# A uinput rotary knob that turns and presses (tests/e2e/knob-board.sh).
$(TOOLS_DIR)/knob_inject: tests/tools/knob_inject.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^
test-tools: $(TOOLS_DIR)/knob_inject

# Whether a model with no reference image shows (tests/corpus/run.sh).
$(TOOLS_DIR)/silhouette: tests/corpus/silhouette.c $(BUILD)/util/image.o $(BUILD)/util/file.o $(BUILD)/util/log.o
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm
test-tools: $(TOOLS_DIR)/silhouette

# Stands in for systemd's notify socket in tests/e2e/live.sh.
$(TOOLS_DIR)/notify_listen: tests/tools/notify_listen.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -o $@ $<

# What each material feature compiles, uploads and binds.
$(TOOLS_DIR)/program_check: tests/golden/program_check.c $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(LIB_ARCHIVE) $(TEST_LIBS)

test-tools: $(TOOLS_DIR)/mkmodels $(TOOLS_DIR)/imgdiff $(BUILD)/bake $(TOOLS_DIR)/notify_listen \
	$(TOOLS_DIR)/soak
test-tools: $(TOOLS_DIR)/program_check

# The renderer against the C mirror of the shaders, pixel by pixel.
$(TOOLS_DIR)/mirror_check: tests/oracle/mirror_check.c $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(TEST_LINK)

test-tools: $(TOOLS_DIR)/mirror_check

# The glTF base colour, loaded and drawn, against a reference from the specs.
$(TOOLS_DIR)/base_color_check: tests/oracle/base_color_check.c $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(TEST_LINK)

test-tools: $(TOOLS_DIR)/base_color_check

# Speed against error, for `make bench` and `make report`.
$(TOOLS_DIR)/bench_quality: tests/bench/bench_quality.c tests/bench/bench_quality_report.c \
		tests/bench/bench_quality.h tests/bench/bench_clock.h $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< tests/bench/bench_quality_report.c $(TEST_LINK)

test-tools: $(TOOLS_DIR)/bench_quality

# The caption's cost a frame, for `make bench`.
$(TOOLS_DIR)/bench_caption: tests/bench/bench_caption.c tests/bench/bench_clock.h tests/bench/bench_display.h $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(LIB_ARCHIVE) $(TEST_LIBS)

test-tools: $(TOOLS_DIR)/bench_caption

# Live playback's cost a frame, for `make bench`.
$(TOOLS_DIR)/bench_anim_live: tests/bench/bench_anim_live.c tests/bench/bench_clock.h tests/bench/bench_display.h $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(LIB_ARCHIVE) $(TEST_LIBS)

test-tools: $(TOOLS_DIR)/bench_anim_live

# The level of detail's time on 1, 2, 4 threads (issue 34).
$(TOOLS_DIR)/bench_lod_threads: tests/bench/bench_lod_threads.c tests/bench/bench_clock.h $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(LIB_ARCHIVE) $(TEST_LIBS)

test-tools: $(TOOLS_DIR)/bench_lod_threads

# What its paths cost in error (the C mirror of the vertex shader).
$(TOOLS_DIR)/bench_anim_error: tests/bench/bench_anim_error.c $(TESTKIT) $(LIB_ARCHIVE)
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(TEST_LINK)

test-tools: $(TOOLS_DIR)/bench_anim_error

# The unit tests and a second kiosk binary, built with AddressSanitizer and
# UndefinedBehaviorSanitizer in a build folder of their own: malformed
# input must not crash either. asan-unit, asan-kiosk and asan-test_NAME
# build a part of it (for make unit and make check).
ASAN_MAKE = $(MAKE) --no-print-directory BUILD=$(ASAN_BUILD) OPT="$(SANITIZE)" \
	    LDFLAGS="$(SANITIZE)" KIOSK=$(ASAN_BUILD)/matcap-kiosk
asan:
	+$(ASAN_MAKE) $(ASAN_BUILD)/matcap-kiosk unit-tests
asan-kiosk:
	+@$(ASAN_MAKE) $(ASAN_BUILD)/matcap-kiosk
asan-unit:
	+@$(ASAN_MAKE) unit-tests
asan-test_%:
	+@$(ASAN_MAKE) $(ASAN_BUILD)/tests/test_$*

# make quick: the unit tests and the golden images from one plain -O1 build
# of their own (build/quick), no sanitizer: the ASan tree alone takes over 3
# minutes on two cores from clean, this all of it under 2. The test hooks
# are in (test_kiosk_reload needs them); it is never installed. It catches
# a wrong answer, not a memory error: make unit and make test still do.
# Run in parallel on every core unless make was given -j already.
QUICK_BUILD := $(BUILD)/quick
QUICK_MAKE   = $(MAKE) --no-print-directory BUILD=$(QUICK_BUILD) OPT="-O1 -DMK_TEST_HOOKS" \
	       KIOSK=$(QUICK_BUILD)/matcap-kiosk
QUICK_ENV    = KIOSK=$(QUICK_BUILD)/matcap-kiosk UNIT_DIR=$(QUICK_BUILD)/tests \
	       UNIT_TESTS="$(UNIT_TESTS)" TOOLS=$(QUICK_BUILD)/tools
quick:
	+@case " $$MAKEFLAGS " in *" -j"* | *jobserver*) j= ;; *) j=-j$$(nproc) ;; esac; \
		$(QUICK_MAKE) $$j $(QUICK_BUILD)/matcap-kiosk unit-tests \
		$(QUICK_BUILD)/tools/mkmodels $(QUICK_BUILD)/tools/imgdiff $(QUICK_BUILD)/tools/stitch
	@$(QUICK_ENV) sh -c 'out=tests/out/quick; . tests/suite.sh; test_unit; test_golden; summary'

# The same with ThreadSanitizer (the content worker and the loop share
# jobs, the log level and the last error): tests/suite.sh's tsan group.
TSAN_MAKE = $(MAKE) --no-print-directory BUILD=$(TSAN_BUILD) OPT="$(TSANITIZE)" \
	    LDFLAGS="-fsanitize=thread" KIOSK=$(TSAN_BUILD)/matcap-kiosk
tsan:
	+@$(TSAN_MAKE) $(TSAN_BUILD)/matcap-kiosk unit-tests

# What every test script reads: the binaries and tools to run.
TEST_ENV = KIOSK=./$(KIOSK) ASAN_KIOSK=$(ASAN_BUILD)/matcap-kiosk UNIT_DIR=$(ASAN_BUILD)/tests \
	   TSAN_KIOSK=$(TSAN_BUILD)/matcap-kiosk TSAN_UNIT_DIR=$(TSAN_BUILD)/tests \
	   UNIT_TESTS="$(UNIT_TESTS)" TOOLS=$(TOOLS_DIR) BAKE=$(BUILD)/bake FUZZ_DIR=$(FUZZ_BUILD) \
	   FUZZ_SECONDS=$(FUZZ_SECONDS) TSAN=$(TSAN) MKMAN=$(MKMAN) MAN_DIR=$(BUILD)/man

# TSAN=0 leaves the ThreadSanitizer build and group out (make test-trixie:
# the threads are proven once, on the host's build; the chroot's run would
# add ~8 minutes of CI for the same code).
TSAN ?= 1
test: $(KIOSK) test-tools asan $(if $(filter 0,$(TSAN)),,tsan) fuzzers
	$(TEST_ENV) sh tests/run.sh

unit: asan-unit
	@$(TEST_ENV) sh tests/check.sh unit

# One test by name: tests/check.sh says which targets it needs (and lists
# the names when T is empty or unknown), those are built, then it runs.
check:
	@needs=$$($(TEST_ENV) sh tests/check.sh --needs '$(T)') || exit 2; \
		[ -z "$$needs" ] || $(MAKE) --no-print-directory $$needs
	@$(TEST_ENV) sh tests/check.sh '$(T)'

golden: $(KIOSK) test-tools
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/golden/golden.sh tests/golden
	$(MAKE) readme

# The README's first picture: what `make run` draws with no settings on a
# machine with no display (the frame it writes), through the offscreen backend.
readme: $(KIOSK)
	./$(KIOSK) -q --backend $(OFFSCREEN_BACKEND) --output tests/readme/first.png
	sh tests/readme/tour.sh ./$(KIOSK) $(OFFSCREEN_BACKEND) tests/readme/tour.png

.PHONY: unit-tests test-tools asan asan-kiosk asan-unit tsan test unit quick check golden readme

include tests/fuzz/fuzz.mk
include tests/soak/soak.mk

bench: $(KIOSK) test-tools
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_startup.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_prepare.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_gltf.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_parts.sh
	KIOSK=./$(KIOSK) sh tests/bench/bench_camera.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_materials.sh
	KIOSK=./$(KIOSK) sh tests/bench/bench_input.sh
	KIOSK=./$(KIOSK) sh tests/bench/bench_in_step.sh
	KIOSK=./$(KIOSK) sh tests/bench/bench_kms.sh
	KIOSK=./$(KIOSK) sh tests/bench/bench_outputs.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_models.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_anim.sh
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_quality.sh tests/out/report --frames 7

# Speed against error, regenerated into tests/bench/report (checked in, with
# the machine it was measured on): the table and the plot in the README.
report: $(KIOSK) test-tools
	KIOSK=./$(KIOSK) TOOLS=$(TOOLS_DIR) sh tests/bench/bench_quality.sh tests/bench/report

.PHONY: bench report
