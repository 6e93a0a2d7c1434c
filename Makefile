# matcap-kiosk: one build, every dependency through pkg-config.
#   make            build ./matcap-kiosk
#   make test       every test (unit, golden images, malformed input under ASan)
#   make bench      speed figures (printed, never asserted)
#   make install    PREFIX=/usr/local DESTDIR= (staging)
#   make deps       install what building and running need, under the names
#                   this Debian release gives them (12 bookworm or 13 trixie;
#                   through sudo unless root)
#   make deps-test  add the test bench (make test says so when it is missing)
#   make test-trixie  make deps, make deps-test and make test in a Debian 13 chroot
#   make test-ansible the Ansible role (contrib/ansible) applied to a fresh root

VERSION    := 0.1.0
PREFIX     ?= /usr/local
BINDIR     ?= $(PREFIX)/bin
DATADIR    ?= $(PREFIX)/share/matcap-kiosk
MANDIR     ?= $(PREFIX)/share/man
SYSCONFDIR ?= /etc
DESTDIR    ?=
# systemd and udev search these under /usr/local as under /usr. A package
# for /usr may take the unit folder from systemd itself:
#   make install PREFIX=/usr SYSTEMD_UNITDIR=$(pkg-config --variable=systemdsystemunitdir systemd)
SYSTEMD_UNITDIR ?= $(PREFIX)/lib/systemd/system
SYSUSERSDIR     ?= $(PREFIX)/lib/sysusers.d
UDEVRULESDIR    ?= $(PREFIX)/lib/udev/rules.d

CC      ?= cc
CXX     ?= c++
PKG_CONFIG ?= pkg-config
BUILD   ?= build

# libOSMesa is opened with dlopen and libGLESv2 is never linked: every gl*
# call goes through the table in src/render/gl.c (the README, "How it is put
# together"). Their headers are still found through pkg-config.
# Debian 12's libunibreak-dev (1.1) is not multiarch: its .pc and .so lie
# in /usr/lib, where a cross pkg-config (dpkg-buildpackage -a, the
# sysroots) never looks, so it is linked by name there; the cross linker
# and the loader both search /usr/lib. Debian 13's has a .pc pkg-config finds.
UNIBREAK_PC  := $(shell $(PKG_CONFIG) --exists libunibreak && echo libunibreak)
UNIBREAK_LIB := $(if $(UNIBREAK_PC),,-lunibreak)
PKGS_LINK    := egl gbm libdrm libudev libpng libturbojpeg libwebp tinygltf libsystemd libgpiod libevdev \
		libcamera draco freetype2 harfbuzz fribidi fontconfig libmosquitto \
		$(UNIBREAK_PC)
# Mesa 25.1 and later have no OSMesa: without its headers the osmesa
# backend is left out (OSMESA=0 leaves it out by hand) and offscreen
# rendering, the tests' included, goes through egl-headless.
OSMESA ?= $(if $(shell $(PKG_CONFIG) --exists osmesa && echo y),1,0)
PKGS_HEADERS := glesv2 $(if $(filter 1,$(OSMESA)),osmesa)
OFFSCREEN_BACKEND ?= $(if $(filter 1,$(OSMESA)),osmesa,egl-headless)
export OFFSCREEN_BACKEND
# libgpiod 2 (Debian 13) is a new API: one backend file per API, the one
# pkg-config's version asks for.
GPIOD_API ?= $(if $(filter 0 1,$(firstword $(subst ., ,$(shell $(PKG_CONFIG) \
	--modversion libgpiod)))),v1,v2)

PKG_CFLAGS := $(shell $(PKG_CONFIG) --cflags $(PKGS_LINK) $(PKGS_HEADERS))
PKG_LIBS   := $(shell $(PKG_CONFIG) --libs $(PKGS_LINK))

WARN      := -Wall -Wextra -Werror
OPT       ?= -O2 -g
CFLAGS    ?=
CXXFLAGS  ?=
# 64-bit file offsets on 32-bit ARM too: without them readdir() and stat()
# fail (EOVERFLOW) where a filesystem hands out 64-bit inodes or cookies.
ALL_CFLAGS   = -std=c11 -D_GNU_SOURCE -D_FILE_OFFSET_BITS=64 $(OPT) $(WARN) -Isrc -I$(BUILD) \
	       $(PKG_CFLAGS) $(if $(filter 1,$(OSMESA)),-DMK_HAVE_OSMESA) \
	       -DMK_VERSION='"$(VERSION)"' -DMK_MATCAP_DIR='"$(DATADIR)/matcaps"' $(CFLAGS)
# The C++ shims share structs and calls with the C side (file_read_at's
# off_t): the same file offset size, or a 32-bit build (armhf) passes a
# 32-bit offset where C reads 64 bits.
ALL_CXXFLAGS = -std=c++17 -D_FILE_OFFSET_BITS=64 $(OPT) $(WARN) -Isrc $(PKG_CFLAGS) $(CXXFLAGS)
# meshoptimizer (Debian's 0.18) ships no .pc file; it is C++, and the link
# already brings libstdc++.
LDLIBS    = $(PKG_LIBS) $(UNIBREAK_LIB) -lmeshoptimizer -ldl -lm

# The program's sources, minus app/main.c (tests link the same objects),
# one folder per layer: each includes only the layers listed after it
# (tests/tools/layers.sh checks that).
SRC_APP     := app/kiosk_models app/kiosk app/kiosk_anim app/kiosk_variant app/kiosk_lang app/kiosk_caption app/kiosk_clock app/kiosk_visits app/kiosk_content app/kiosk_report app/kiosk_remote app/reload app/preview \
	       app/signals
SRC_OPS     := ops/check ops/check_text ops/import ops/import_copy ops/import_ini ops/metrics ops/mqtt ops/mqtt_ha ops/screen ops/service ops/status
SRC_CONTENT := content/content content/load_guard content/content_cache content/content_look content/content_view content/content_fit content/content_caption content/content_hotspot content/content_play content/content_deform content/matcap_set content/matcap_job content/model_list \
	       content/model_loader content/worker
SRC_CONTENT += content/content_coarse content/refine_job
SRC_CONFIG  := config/options config/options_file config/model_settings config/settings config/settings_table config/settings_origin config/settings_text config/lang_text config/hotspot_settings
SRC_STATE   := state/app state/app_pose state/steps state/view state/power state/schedule state/visits state/remote state/lang state/hotspot
SRC_DISPLAY := display/backlight display/cec display/cec_link display/display display/display_egl display/display_kms display/kms_egl display/kms_output display/kms_scale \
	       display/display_osmesa \
	       display/drm display/drm_atomic display/drm_legacy display/egl_util display/hotplug \
	       display/kms_fb display/kms_overlay
SRC_INPUT   := input/action input/button input/gesture input/touch_decode input/gpio \
	       input/gpio_$(GPIOD_API) input/keyboard input/touch input/knob input/knob_device
SRC_CAMERA  := camera/camera_feed camera/camera_link camera/camera_math camera/camera_proto \
	       camera/camera_texture
SRC_RENDER  := render/background render/bake render/draw_list render/framing render/gl render/poster render/render_scale render/render_caption \
	       render/caption render/hotspot_gl render/render_hotspot render/render render/render_draw render/render_live render/render_skin render/render_morph render/render_variant render/shader render/shading
SRC_SCENE   := scene/mesh/lod scene/mesh/lod_seams scene/mesh/lod_split scene/mesh/material scene/mesh/mesh scene/mesh/mesh_cache scene/mesh/mesh_cache_anim scene/mesh/mesh_cache_nest scene/mesh/mesh_cache_fields scene/mesh/mesh_cache_key scene/mesh/mesh_gen scene/mesh/mesh_node scene/mesh/mesh_pack scene/mesh/subdivide scene/mesh/tangent \
	       scene/mesh/texture scene/text/caption scene/text/caption_text scene/text/model_name scene/text/caption_font scene/text/caption_wrap
SRC_SCENE   += scene/gltf/gltf_json_depth scene/gltf/gltf_features
SRC_SCENE   += scene/mesh/lod_coarse
SRC_RENDER  += render/wall render/output_view
SRC_CONFIG  += config/wall_settings config/output_settings
SRC_SCENE   += scene/anim/anim scene/anim/anim_sampler scene/anim/anim_palette scene/anim/anim_play scene/anim/anim_play_gpu scene/anim/anim_play_split scene/anim/anim_play_morph
SRC_UTIL    := util/file util/folder_watch util/image util/ini util/log util/math3d
LIB_C  := $(SRC_APP) $(SRC_OPS) $(SRC_CONTENT) $(SRC_CONFIG) $(SRC_STATE) $(SRC_DISPLAY) $(SRC_INPUT) $(SRC_CAMERA) $(SRC_RENDER) $(SRC_SCENE) $(SRC_UTIL)
# The C++ shims, each behind a C header (gltf_ext.h is internal to the glTF one).
LIB_CC := scene/gltf/gltf scene/gltf/gltf_mesh scene/gltf/gltf_accessor scene/gltf/gltf_fs scene/gltf/gltf_material scene/gltf/gltf_ext scene/gltf/gltf_files scene/gltf/gltf_pose \
	  scene/gltf/gltf_draco camera/camera
LIB_CC += scene/gltf/gltf_words scene/gltf/gltf_anim scene/gltf/gltf_fit scene/gltf/gltf_name scene/gltf/gltf_play scene/gltf/gltf_flat
LIB_CC += scene/gltf/gltf_variants
SHADERS := shaders/mapping.glsl shaders/morph.glsl shaders/matcap.vert shaders/matcap.frag shaders/material.glsl
SHADERS += shaders/camera.vert shaders/camera.frag
SHADERS += shaders/poster.vert shaders/poster.frag
SHADERS += shaders/scale.vert shaders/scale.frag
SHADERS += shaders/background.vert shaders/background.frag
SHADERS += shaders/caption.vert shaders/caption.frag
SHADERS += shaders/hotspot.vert shaders/hotspot.frag

LIB_OBJS := $(LIB_C:%=$(BUILD)/%.o) $(LIB_CC:%=$(BUILD)/%.o) $(BUILD)/shaders_embedded.o
# The tests and tools link the same objects from an archive, so that each
# binary takes only the objects it calls (tests/tests.mk).
LIB_ARCHIVE := $(BUILD)/libkiosk.a

KIOSK ?= matcap-kiosk

all: $(KIOSK)

$(KIOSK): $(BUILD)/app/main.o $(LIB_OBJS)
	$(CXX) -o $@ $^ $(LDFLAGS) $(LDLIBS)

$(BUILD)/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/%.o: src/%.cc
	@mkdir -p $(@D)
	$(CXX) $(ALL_CXXFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/shaders_embedded.c: shaders/embed.sh $(SHADERS) | $(BUILD)
	sh shaders/embed.sh $(SHADERS) > $@

$(BUILD)/shaders_embedded.o: $(BUILD)/shaders_embedded.c
	$(CC) $(ALL_CFLAGS) -c -o $@ $<

$(LIB_ARCHIVE): $(LIB_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD):
	mkdir -p $@

# Every tree's dependency files (the plain build, the sanitizers', make
# quick's, the cross builds': each a folder with app/ in it), to the depth
# of scene/gltf/*.d, so that an object rebuilds when a header it includes
# changes. The cross sysroots and the Ansible test's root beside them hold
# folders named *.d (etc/binfmt.d): left out.
DEP_TREES := $(patsubst %/app,%,$(wildcard $(BUILD)/app $(BUILD)/*/app))
-include $(filter-out $(BUILD)/sysroot-% $(BUILD)/ansible-root/%,$(foreach t,$(DEP_TREES),$(wildcard $(t)/*.d $(t)/*/*.d $(t)/*/*/*.d)))

# The matcap baker: regenerates matcaps/*.png byte for byte.
$(BUILD)/bake: matcaps/bake.c $(BUILD)/render/bake.o $(BUILD)/util/image.o $(BUILD)/util/file.o $(BUILD)/util/log.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm

matcaps: $(BUILD)/bake
	$(BUILD)/bake matcaps 256

run: matcap-kiosk
	./matcap-kiosk

# The manual pages, matcap-kiosk(1) and kiosk.ini(5), are written from the
# settings table and the exit statuses (src/config/settings_man.c, through
# tests/tools/mkman): `make man` writes them into config/, where they are
# kept and from where they are installed. A cross build (the package for
# arm64, built on amd64) cannot run a program it builds, so the build does
# not write them; `make test` writes them again into build/man/ and fails
# when they differ from config/'s (test_man): they cannot drift. Dated by
# the package's changelog, so that only a release changes the date; their
# paths are @SYSCONFDIR@ and @DATADIR@, which make install fills in.
MAN_DATE  := $(shell sed -n 's/^ -- .*>  //p' config/debian/changelog | head -1 | \
		xargs -r -I{} date -u -d {} +%F)
MKMAN     := $(BUILD)/mkman
MAN_PAGES := config/matcap-kiosk.1 config/kiosk.ini.5
MAN_BUILT := $(BUILD)/man/matcap-kiosk.1 $(BUILD)/man/kiosk.ini.5
MAN_OBJS  := $(BUILD)/config/settings_man.o $(BUILD)/config/settings_man_cli.o

$(BUILD)/mkman.o: tests/tools/mkman.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

$(MKMAN): $(BUILD)/mkman.o $(MAN_OBJS) $(LIB_ARCHIVE)
	$(CXX) -o $@ $^ $(LDFLAGS) $(LDLIBS)

$(BUILD)/man/matcap-kiosk.1: $(MKMAN) config/debian/changelog
	@mkdir -p $(@D)
	$(MKMAN) 1 $(VERSION) $(MAN_DATE) @SYSCONFDIR@ @DATADIR@ >$@.tmp && mv $@.tmp $@

$(BUILD)/man/kiosk.ini.5: $(MKMAN) config/debian/changelog
	@mkdir -p $(@D)
	$(MKMAN) 5 $(VERSION) $(MAN_DATE) @SYSCONFDIR@ @DATADIR@ >$@.tmp && mv $@.tmp $@

man: $(MAN_BUILT)
	cp $(MAN_BUILT) config/

.PHONY: man

include tests/tests.mk
-include tests/vm/vm.mk
-include tests/cross/cross.mk
-include tests/cross/ansible.mk

# Package names differ between releases: clang (and its runtime for the
# fuzzers) is 14 on Debian 12 and 19 on Debian 13; OSMesa only while Mesa
# has it. apt-get runs through sudo unless make already runs as root.
OS_CODENAME   := $(shell . /etc/os-release 2>/dev/null && echo $$VERSION_CODENAME)
CLANG_VERSION ?= $(if $(filter bookworm,$(OS_CODENAME)),14,19)
# apt waits up to ten minutes for another apt (an unattended upgrade on a
# fresh Pi) rather than fail at once.
APT_GET       := $(if $(filter 0,$(shell id -u)),,sudo) env DEBIAN_FRONTEND=noninteractive apt-get \
	-o DPkg::Lock::Timeout=600
# make deps: what building and running need, nothing more (a Pi gets no
# test bench). procps brings /bin/kill, which the unit's ExecReload names
# (a minimal Debian 13 has none); libcamera-ipa runs the camera matcap;
# FreeType, HarfBuzz and FriBidi shape [caption]'s text, in DejaVu Sans
# (fonts-dejavu-core) unless [caption] font names another; fontconfig finds
# a fallback font for characters it lacks; libunibreak breaks lines (UAX
# #14, CJK too); libmosquitto is [mqtt]'s client (off unless set).
DEBIAN_PACKAGES := make gcc g++ pkg-config libegl-dev libgles-dev \
	libegl-mesa0 libgl1-mesa-dri libgbm-dev libdrm-dev libtinygltf-dev nlohmann-json3-dev \
	libpng-dev libturbojpeg0-dev libwebp-dev libudev-dev libsystemd-dev \
	libgpiod-dev libevdev-dev libcamera-dev libcamera-ipa libmeshoptimizer-dev libdraco-dev \
	libfreetype-dev libharfbuzz-dev libfribidi-dev fonts-dejavu-core procps \
	libfontconfig-dev libunibreak-dev libmosquitto-dev
# make deps-test: the test bench on top. The unit tests' cmocka and zlib;
# systemd-analyze for the unit; clang for the fuzzers; valgrind for the
# soak; gnuplot for make report; the virtual board (qemu, busybox, kernel
# modules, kmscube, the DRM, camera, GPIO and V4L2 tools); the model
# corpus (Draco's and gltfpack's tools, assimp's sample files); the
# board's USB stick images (FAT with files put in by mtools, ext2 by
# mke2fs -d; no root or loop device needed); rsync for content by sync
# (tests/e2e/sync.sh: real rsync into a live kiosk's folder); [status]
# metrics scraped from a real node_exporter (tests/e2e/metrics.sh); the
# Ansible role applied to a fresh root (tests/cross/ansible.sh); a real
# mosquitto broker for [mqtt] (tests/e2e/mqtt.sh) and Noto CJK for the
# captions' fallback font (a Japanese caption's golden).
DEBIAN_TEST_PACKAGES := libcmocka-dev zlib1g-dev systemd \
	clang-$(CLANG_VERSION) libclang-rt-$(CLANG_VERSION)-dev valgrind gnuplot-nox \
	qemu-system-x86 busybox-static lz4 cpio kmod udev xz-utils kmscube libdrm-tests \
	libcamera-tools gpiod v4l-utils \
	draco gltfpack assimp-testmodels \
	dosfstools mtools e2fsprogs rsync time \
	prometheus-node-exporter curl ansible mmdebstrap man-db groff-base bsdextrautils \
	mosquitto mosquitto-clients fonts-noto-cjk

deps:
	$(APT_GET) update -qq
	osmesa=$$(apt-cache show libosmesa6-dev >/dev/null 2>&1 && echo libosmesa6-dev libosmesa6); \
	$(APT_GET) install -y -qq --no-install-recommends $(DEBIAN_PACKAGES) $$osmesa

deps-test:
	$(APT_GET) update -qq
	$(APT_GET) install -y -qq --no-install-recommends $(DEBIAN_TEST_PACKAGES)

# The test targets say what is missing before anything is built (one
# dpkg-query, read only when such a target is asked for).
TEST_GOALS := $(filter test unit quick check golden bench,$(MAKECMDGOALS))
ifneq ($(TEST_GOALS),)
DEPS_INSTALLED := $(shell dpkg-query -W -f='$${db:Status-Abbrev} $${Package}\n' \
	$(DEBIAN_PACKAGES) $(DEBIAN_TEST_PACKAGES) 2>/dev/null | sed -n 's/^ii *//p')
DEPS_MISSING   := $(filter-out $(DEPS_INSTALLED),$(DEBIAN_PACKAGES))
TEST_MISSING   := $(filter-out $(DEPS_INSTALLED),$(DEBIAN_TEST_PACKAGES))
ifneq ($(DEPS_MISSING),)
$(error make $(TEST_GOALS) needs $(DEPS_MISSING): run make deps, then make deps-test)
endif
ifneq ($(TEST_MISSING),)
$(error make $(TEST_GOALS) needs the test bench ($(TEST_MISSING) missing): run make deps-test)
endif
endif

# The tests on Debian 13 in a chroot made from Debian's archive (root:
# debootstrap, mount and chroot; tests/trixie/chroot.sh says more).
test-trixie:
	$(if $(filter 0,$(shell id -u)),,sudo) tests/trixie/chroot.sh

install: matcap-kiosk
	install -D -m 0755 matcap-kiosk $(DESTDIR)$(BINDIR)/matcap-kiosk
	install -d $(DESTDIR)$(DATADIR)/matcaps
	install -m 0644 matcaps/*.png $(DESTDIR)$(DATADIR)/matcaps/
	install -D -m 0644 config/kiosk.ini $(DESTDIR)$(DATADIR)/kiosk.ini.example
	install -D -m 0644 systemd/mqtt.conf $(DESTDIR)$(DATADIR)/mqtt.conf.example
	install -d $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man5
	for p in $(MAN_PAGES); do \
		sed -e 's|@SYSCONFDIR@|$(SYSCONFDIR)|g' -e 's|@DATADIR@|$(DATADIR)|g' $$p \
			>$(DESTDIR)$(MANDIR)/man$${p##*.}/$${p##*/} && \
		chmod 0644 $(DESTDIR)$(MANDIR)/man$${p##*.}/$${p##*/} || exit 1; \
	done
	# Settings in pieces: packages and Ansible roles drop *.ini files here.
	install -d $(DESTDIR)$(SYSCONFDIR)/matcap-kiosk/kiosk.ini.d
	# An edited config survives a reinstall.
	test -e $(DESTDIR)$(SYSCONFDIR)/matcap-kiosk/kiosk.ini || \
		install -D -m 0644 config/kiosk.ini $(DESTDIR)$(SYSCONFDIR)/matcap-kiosk/kiosk.ini
	# The service, its user and groups, and the GPIO chips for that group.
	install -d $(DESTDIR)$(SYSTEMD_UNITDIR)
	sed -e 's|/usr/local/bin/matcap-kiosk|$(BINDIR)/matcap-kiosk|' \
		-e 's|/etc/matcap-kiosk/|$(SYSCONFDIR)/matcap-kiosk/|' systemd/matcap-kiosk.service \
		>$(DESTDIR)$(SYSTEMD_UNITDIR)/matcap-kiosk.service
	chmod 0644 $(DESTDIR)$(SYSTEMD_UNITDIR)/matcap-kiosk.service
	install -D -m 0644 systemd/matcap-kiosk.sysusers $(DESTDIR)$(SYSUSERSDIR)/matcap-kiosk.conf
	install -D -m 0644 systemd/60-matcap-kiosk-gpio.rules \
		$(DESTDIR)$(UDEVRULESDIR)/60-matcap-kiosk-gpio.rules
	# Content from a USB stick: the rule and the unit it starts.
	sed -e 's|/usr/local/bin/matcap-kiosk|$(BINDIR)/matcap-kiosk|' \
		-e 's|/etc/matcap-kiosk/|$(SYSCONFDIR)/matcap-kiosk/|' \
		systemd/matcap-kiosk-import@.service \
		>$(DESTDIR)$(SYSTEMD_UNITDIR)/matcap-kiosk-import@.service
	chmod 0644 $(DESTDIR)$(SYSTEMD_UNITDIR)/matcap-kiosk-import@.service
	install -m 0644 systemd/61-matcap-kiosk-usb.rules \
		$(DESTDIR)$(UDEVRULESDIR)/61-matcap-kiosk-usb.rules

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/matcap-kiosk
	rm -f $(DESTDIR)$(MANDIR)/man1/matcap-kiosk.1 $(DESTDIR)$(MANDIR)/man5/kiosk.ini.5
	rm -rf $(DESTDIR)$(DATADIR)
	rm -f $(DESTDIR)$(SYSTEMD_UNITDIR)/matcap-kiosk.service \
		$(DESTDIR)$(SYSTEMD_UNITDIR)/matcap-kiosk-import@.service \
		$(DESTDIR)$(SYSUSERSDIR)/matcap-kiosk.conf \
		$(DESTDIR)$(UDEVRULESDIR)/60-matcap-kiosk-gpio.rules \
		$(DESTDIR)$(UDEVRULESDIR)/61-matcap-kiosk-usb.rules

format:
	clang-format -i $(wildcard src/*/*.c src/*/*.h src/*/*.cc matcaps/*.c tests/*/*.c tests/*/*.h)

clean:
	rm -rf $(BUILD) matcap-kiosk tests/out

.PHONY: all run matcaps deps deps-test test-trixie install uninstall format clean
