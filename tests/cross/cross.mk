# Cross builds for the Raspberry Pi's architectures, tested under qemu-user
# (included from the top-level Makefile):
#   make deps-cross ARCH=arm64   Debian's cross toolchain, qemu-user and a sysroot
#   make test-cross ARCH=arm64   build into build/cross-arm64, then the unit tests and
#                                the golden images under qemu-user; ARCH=armhf likewise
#
# The other architecture's -dev packages are Debian's multiarch ones, unpacked
# with their dependencies into a sysroot (build/sysroot-ARCH) rather than
# installed beside the host's with dpkg --add-architecture: Multi-Arch: same
# packages must then have one version on every architecture, so one security
# update that reached amd64's index before armhf's blocks the install, and
# every later upgrade of the host is tied to them.

CROSS_TRIPLET_arm64 := aarch64-linux-gnu
CROSS_TRIPLET_armhf := arm-linux-gnueabihf
CROSS_QEMU_arm64    := qemu-aarch64-static
CROSS_QEMU_armhf    := qemu-arm-static
CROSS_TRIPLET       := $(CROSS_TRIPLET_$(ARCH))
CROSS_QEMU          := $(CROSS_QEMU_$(ARCH))
CROSS_SYSROOT       := $(CURDIR)/build/sysroot-$(ARCH)
CROSS_BUILD         := build/cross-$(ARCH)
# The sysroot follows the host's release, as the cross toolchain does.
CROSS_SUITE  ?= $(shell . /etc/os-release 2>/dev/null && echo $$VERSION_CODENAME)
CROSS_MIRROR ?= http://deb.debian.org/debian
CROSS_EMPTY  :=
CROSS_SPACE  := $(CROSS_EMPTY) $(CROSS_EMPTY)
CROSS_COMMA  := ,
CROSS_SUDO   := $(if $(filter 0,$(shell id -u)),,sudo)

# What the program, its unit tests and the offscreen renders link or open:
# DEBIAN_PACKAGES' libraries, less the virtual board, clang and the tools;
# Noto CJK as make deps-test brings it: a caption's fallback font (the
# Japanese golden, test_caption's fallback cases) is found in the sysroot.
CROSS_PACKAGES := libc6 libstdc++6 libgcc-s1 libubsan1 libegl-dev libgles-dev libosmesa6-dev \
	libosmesa6 libgbm-dev libdrm-dev libtinygltf-dev nlohmann-json3-dev libpng-dev \
	libturbojpeg0-dev libwebp-dev libcmocka-dev libudev-dev libsystemd-dev libgpiod-dev \
	libevdev-dev libcamera-dev libmeshoptimizer-dev libdraco-dev zlib1g-dev \
	libfreetype-dev libharfbuzz-dev libfribidi-dev fonts-dejavu-core \
	libfontconfig-dev libunibreak-dev libmosquitto-dev fonts-noto-cjk
CROSS_HOST_PACKAGES := gcc-$(CROSS_TRIPLET) g++-$(CROSS_TRIPLET) qemu-user-static mmdebstrap \
	pkg-config make

# pkg-config reads the sysroot's .pc files and prefixes their paths with it.
CROSS_PKG_CONFIG := env PKG_CONFIG_LIBDIR=$(CROSS_SYSROOT)/usr/lib/$(CROSS_TRIPLET)/pkgconfig:$(CROSS_SYSROOT)/usr/share/pkgconfig \
	PKG_CONFIG_SYSROOT_DIR=$(CROSS_SYSROOT) $(PKG_CONFIG)
# UBSan runs under qemu-user and catches what a 32-bit size_t or long, or
# a misaligned access, would break; ASan does not (its leak checker stops
# with a fatal error under qemu-user), so the cross tests go without it.
CROSS_SANITIZE := -fsanitize=undefined -fno-sanitize-recover=all
# GCC's note that armhf passes some C++ arguments differently since GCC 7.1
# concerns only code built with GCC 6 and older, none of it here.
CROSS_CXXFLAGS_armhf := -Wno-psabi
CROSS_MAKE = $(MAKE) --no-print-directory BUILD=$(CROSS_BUILD) KIOSK=$(CROSS_BUILD)/matcap-kiosk \
	CXXFLAGS="$(CROSS_CXXFLAGS_$(ARCH))" \
	CC="$(CROSS_TRIPLET)-gcc --sysroot=$(CROSS_SYSROOT)" AR=$(CROSS_TRIPLET)-ar \
	CXX="$(CROSS_TRIPLET)-g++ --sysroot=$(CROSS_SYSROOT)" PKG_CONFIG="$(CROSS_PKG_CONFIG)"

cross-arch:
	@test -n "$(CROSS_TRIPLET)" || { echo "ARCH must be arm64 or armhf (ARCH=$(ARCH))"; exit 2; }

deps-cross: cross-arch
	$(CROSS_SUDO) apt-get -o DPkg::Lock::Timeout=600 update -qq
	$(CROSS_SUDO) env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq \
		--no-install-recommends $(CROSS_HOST_PACKAGES)
	$(MAKE) --no-print-directory $(CROSS_SYSROOT)/.complete

# mmdebstrap's extract variant unpacks the packages and their dependencies
# and runs none of their scripts, so nothing of the other architecture runs.
$(CROSS_SYSROOT)/.complete: | cross-arch
	rm -rf $(CROSS_SYSROOT)
	mmdebstrap --quiet --variant=extract --architectures=$(ARCH) \
		--include="$(subst $(CROSS_SPACE),$(CROSS_COMMA),$(strip $(CROSS_PACKAGES)))" \
		$(CROSS_SUITE) $(CROSS_SYSROOT) "deb $(CROSS_MIRROR) $(CROSS_SUITE) main"
	touch $@

cross-tools: cross-arch
	@for t in $(CROSS_TRIPLET)-gcc $(CROSS_TRIPLET)-g++ $(CROSS_QEMU) mmdebstrap; do \
		command -v $$t >/dev/null || { echo "$$t not found: run make deps-cross ARCH=$(ARCH)"; \
		exit 1; }; done

# The program as shipped (-O2) and, with UBSan and the test hooks (a
# reload held by MK_TEST_PREPARE_DELAY_MS: test_kiosk_reload), the unit
# tests and tools.
cross-build: cross-tools $(CROSS_SYSROOT)/.complete
	+$(CROSS_MAKE) OPT="-O2 -g" $(CROSS_BUILD)/matcap-kiosk
	+$(CROSS_MAKE) BUILD=$(CROSS_BUILD)/ubsan OPT="-O2 -g $(CROSS_SANITIZE) -DMK_TEST_HOOKS" \
		LDFLAGS="$(CROSS_SANITIZE)" KIOSK=$(CROSS_BUILD)/ubsan/matcap-kiosk unit-tests \
		$(CROSS_BUILD)/ubsan/matcap-kiosk $(CROSS_BUILD)/ubsan/tools/mkmodels

# The host's program and tools draw the same scenes for comparison.
test-cross: cross-build $(KIOSK) $(TOOLS_DIR)/mkmodels $(TOOLS_DIR)/imgdiff $(TOOLS_DIR)/stitch
	sh tests/cross/run.sh $(ARCH) $(CROSS_BUILD) $(CROSS_SYSROOT) $(CROSS_QEMU) ./$(KIOSK) \
		$(TOOLS_DIR)

.PHONY: cross-arch deps-cross cross-tools cross-build test-cross

# The Debian package, from config/debian (debhelper):
#   make deps-pkg               what a native `make deb` needs, nothing for roots or
#                               cross builds (a Pi building its own package)
#   make deps-deb               what the package targets need on this machine, the
#                               roots' mmdebstrap and qemu-user-static included
#   make dist                   build/matcap-kiosk-VERSION.tar.gz, the source tarball
#   make test-pi-quickstart     the README's quick start in a fresh Debian 13 arm64 root
#   make deb                    matcap-kiosk_VERSION_ARCH.deb for this machine, built
#                               here, then lintian (no error allowed): in build/deb/ on
#                               Debian 13, build/deb/bookworm/ on 12
#   make deb ARCH=arm64         the same for arm64 (or armhf, or amd64), cross-built by
#                               Debian's recipe in a fresh Debian 13 root that has only the
#                               Build-Depends (DEB_SUITE=bookworm: Debian 12, into
#                               build/deb/bookworm/), lintian there (tests/cross/deb-build.sh)
#   make test-deb               amd64, arm64 and armhf built that way on Debian 13, amd64 on
#                               Debian 12 (one root per release; DEB_OTHER_ARCHS="arm64 armhf"
#                               builds those on 12 too), the Debian 13 ones and Debian 12's
#                               amd64 installed into fresh roots of their own architecture
#                               and run there (qemu-user binfmt); ARCH=arm64 (or armhf) for
#                               one, DEB_SUITES=trixie for one release (tests/cross/deb-test.sh)
# Roots are made by mmdebstrap as root; the host gets no foreign
# architecture. Downloaded packages are kept in build/deb-cache for the
# next root.
DEB_BUILD   := build/deb
DEB_SRC     := build/deb-src/matcap-kiosk-$(VERSION)
DEB_TREE    := Makefile README.md LICENSE src shaders matcaps config systemd tests
DEB_SUITE   ?= trixie
DEB_SUITES  ?= trixie bookworm
DEB_ARCHS   ?= $(or $(ARCH),arm64 armhf)
# The other architectures are installed on Debian 13 (what Pi OS is);
# on 12 they are built and lintian-checked, amd64 installed (each qemu
# root costs minutes of CI).
DEB_INSTALL ?= $(foreach a,$(DEB_ARCHS),trixie:$(a))
DEB_OTHER_ARCHS ?=
DEB_HOST_ARCH := $(shell dpkg --print-architecture 2>/dev/null)
# build/deb/ holds Debian 13's packages, build/deb/SUITE/ another release's.
DEB_OUT     := $(if $(filter trixie,$(DEB_SUITE)),$(DEB_BUILD),$(DEB_BUILD)/$(DEB_SUITE))
DEB_HOST_OUT = $(if $(filter trixie,$(OS_CODENAME)),$(DEB_BUILD),$(DEB_BUILD)/$(OS_CODENAME))
DEB_SUDO_ROOT := $(if $(filter 0,$(shell id -u)),,sudo)

# systemd.pc and udev.pc (where units and rules go) are in systemd-dev from
# Debian 13 on, in systemd and udev before: `apt-get build-dep` picks the
# alternative config/debian/control names for this release, and brings
# build-essential (make, the compilers, dpkg-dev) with the Build-Depends.
# It reads ./config as an unpacked source (config/debian/control): nothing
# needs to exist before it but apt. lintian checks what `make deb` wrote.
deps-pkg:
	$(APT_GET) update -qq
	$(APT_GET) build-dep -y -qq --no-install-recommends ./config
	$(APT_GET) install -y -qq --no-install-recommends lintian

# deps-deb: what the package targets need here, the roots' mmdebstrap,
# qemu-user-static's binfmt handlers and arch-test included (the roots
# install the Build-Depends themselves; systemd-dev, or systemd and udev
# before Debian 13, for a native `make deb`).
deps-deb:
	$(CROSS_SUDO) apt-get -o DPkg::Lock::Timeout=600 update -qq
	sd=$$(apt-cache show systemd-dev >/dev/null 2>&1 && echo systemd-dev || echo systemd udev); \
	$(CROSS_SUDO) env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq \
		--no-install-recommends build-essential debhelper lintian dpkg-dev mmdebstrap file \
		qemu-user-static arch-test $$sd

# The source tree the package is built from: the project's files and
# config/debian as debian/ (no caches: the Debian 13 chroot's root is
# one).
deb-src:
	@v=$$(dpkg-parsechangelog -l config/debian/changelog -SVersion); [ "$$v" = "$(VERSION)" ] || \
		{ echo "config/debian/changelog: version $$v, the Makefile says $(VERSION)"; exit 1; }
	rm -rf $(dir $(DEB_SRC))
	mkdir -p $(DEB_SRC)
	tar -c --exclude=tests/out --exclude=tests/vm/cache --exclude=tests/trixie/cache $(DEB_TREE) | tar -x -C $(DEB_SRC)
	cp -r config/debian $(DEB_SRC)/debian
	cp systemd/matcap-kiosk.sysusers $(DEB_SRC)/debian/matcap-kiosk.sysusers

# The release's source: what the package is built from, with the
# documents and contrib/ (a Pi OS Lite has tar, not git).
DIST_TREE := $(DEB_TREE) docs contrib .clang-format
dist:
	mkdir -p build
	tar -czf build/matcap-kiosk-$(VERSION).tar.gz --exclude=tests/out --exclude=tests/vm/cache \
		--exclude=tests/trixie/cache --exclude='*.o' --transform='s,^,matcap-kiosk-$(VERSION)/,' \
		$(DIST_TREE)

# A native build uses every core (a Pi 4 or 5 has four) unless
# DEB_BUILD_OPTIONS says otherwise; debian/rules passes parallel=N to make.
deb: deb-src
ifeq ($(ARCH),)
	cd $(DEB_SRC) && DEB_BUILD_OPTIONS="$${DEB_BUILD_OPTIONS-parallel=$$(nproc)}" \
		dpkg-buildpackage --build=binary --no-sign
	mkdir -p $(DEB_HOST_OUT)
	mv $(dir $(DEB_SRC))matcap-kiosk*_$(VERSION)_$(DEB_HOST_ARCH).deb $(DEB_HOST_OUT)/
	lintian --fail-on error $(DEB_HOST_OUT)/matcap-kiosk_$(VERSION)_$(DEB_HOST_ARCH).deb
else
	$(if $(filter 0,$(shell id -u)),,sudo) sh tests/cross/deb-build.sh $(DEB_SUITE) $(ARCH) \
		$(DEB_SRC) $(DEB_OUT)
endif

# Builds, installs and renders in roots (as root: they are chroots). The
# host's imgdiff compares the renders.
test-deb: deb-src $(TOOLS_DIR)/imgdiff
	$(DEB_SUDO_ROOT) env DEB_OTHER_ARCHS="$(DEB_OTHER_ARCHS)" sh tests/cross/deb-test.sh $(DEB_SRC) $(TOOLS_DIR)/imgdiff "$(DEB_SUITES)" \
		"$(DEB_ARCHS)" "$(DEB_INSTALL)"

# The README's quick start, verbatim, in a fresh Debian 13 arm64 root
# under qemu-user: the package built natively there, installed, rendering
# (tests/cross/pi-quickstart.sh; as root; long under emulation, not in
# .ci/run). At the lowest priority: the machine is shared.
test-pi-quickstart: dist
	$(DEB_SUDO_ROOT) nice -n 19 ionice -c3 sh tests/cross/pi-quickstart.sh \
		build/matcap-kiosk-$(VERSION).tar.gz build/pi-quickstart

.PHONY: deps-pkg deps-deb deb-src dist deb test-deb test-pi-quickstart
