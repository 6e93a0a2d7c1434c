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
# DEBIAN_PACKAGES' libraries, less the virtual board, clang and the tools.
CROSS_PACKAGES := libc6 libstdc++6 libgcc-s1 libubsan1 libegl-dev libgles-dev libosmesa6-dev \
	libosmesa6 libgbm-dev libdrm-dev libtinygltf-dev nlohmann-json3-dev libpng-dev \
	libturbojpeg0-dev libcmocka-dev libinih-dev libudev-dev libsystemd-dev libgpiod-dev \
	libevdev-dev libcamera-dev libmeshoptimizer-dev libdraco-dev zlib1g-dev
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
	CC="$(CROSS_TRIPLET)-gcc --sysroot=$(CROSS_SYSROOT)" \
	CXX="$(CROSS_TRIPLET)-g++ --sysroot=$(CROSS_SYSROOT)" PKG_CONFIG="$(CROSS_PKG_CONFIG)"

cross-arch:
	@test -n "$(CROSS_TRIPLET)" || { echo "ARCH must be arm64 or armhf (ARCH=$(ARCH))"; exit 2; }

deps-cross: cross-arch
	$(CROSS_SUDO) apt-get update -qq
	$(CROSS_SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
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

# The program as shipped (-O2) and, with UBSan, the unit tests and tools.
cross-build: cross-tools $(CROSS_SYSROOT)/.complete
	+$(CROSS_MAKE) OPT="-O2 -g" $(CROSS_BUILD)/matcap-kiosk
	+$(CROSS_MAKE) BUILD=$(CROSS_BUILD)/ubsan OPT="-O2 -g $(CROSS_SANITIZE)" \
		LDFLAGS="$(CROSS_SANITIZE)" KIOSK=$(CROSS_BUILD)/ubsan/matcap-kiosk unit-tests \
		$(CROSS_BUILD)/ubsan/matcap-kiosk $(CROSS_BUILD)/ubsan/tools/mkmodels

# The host's program and tools draw the same scenes for comparison.
test-cross: cross-build $(KIOSK) $(TOOLS_DIR)/mkmodels $(TOOLS_DIR)/imgdiff
	sh tests/cross/run.sh $(ARCH) $(CROSS_BUILD) $(CROSS_SYSROOT) $(CROSS_QEMU) ./$(KIOSK) \
		$(TOOLS_DIR)

.PHONY: cross-arch deps-cross cross-tools cross-build test-cross

# The Debian package, from config/debian (debhelper), built in a copy of the
# tree under build/deb: `make deb` for this machine's architecture.
#   make deps-deb   build-essential, debhelper and lintian
#   make deb        build/deb/matcap-kiosk_VERSION_ARCH.deb, then lintian (no error allowed)
#   make test-deb   that package installed into a fresh Debian root, and run there
DEB_BUILD := build/deb
DEB_SRC   := $(DEB_BUILD)/matcap-kiosk-$(VERSION)
DEB_TREE  := Makefile README.md LICENSE src shaders matcaps config systemd tests

# systemd.pc and udev.pc (where units and rules go) are in systemd-dev from
# Debian 13 on, in systemd and udev before.
deps-deb:
	$(CROSS_SUDO) apt-get update -qq
	sd=$$(apt-cache show systemd-dev >/dev/null 2>&1 && echo systemd-dev || echo systemd udev); \
	$(CROSS_SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
		--no-install-recommends build-essential debhelper lintian dpkg-dev mmdebstrap file $$sd

# A package for another architecture (dpkg-buildpackage -a) would need
# that architecture's libraries installed with dpkg, for dpkg-shlibdeps to
# find ${shlibs:Depends}; the sysroot above does without them on purpose.
deb:
	@[ -z "$(ARCH)" ] || [ "$(ARCH)" = "$$(dpkg --print-architecture)" ] || \
		{ echo "make deb builds for this machine only: build the $(ARCH) package on the Pi"; \
		exit 2; }
	@v=$$(dpkg-parsechangelog -l config/debian/changelog -SVersion); [ "$$v" = "$(VERSION)" ] || \
		{ echo "config/debian/changelog: version $$v, the Makefile says $(VERSION)"; exit 1; }
	rm -rf $(DEB_BUILD)
	mkdir -p $(DEB_SRC)
	tar -c --exclude=tests/out --exclude=tests/vm/cache $(DEB_TREE) | tar -x -C $(DEB_SRC)
	cp -r config/debian $(DEB_SRC)/debian
	cp systemd/matcap-kiosk.sysusers $(DEB_SRC)/debian/matcap-kiosk.sysusers
	cd $(DEB_SRC) && dpkg-buildpackage --build=binary --no-sign
	lintian --fail-on error $(DEB_BUILD)/matcap-kiosk_$(VERSION)_*.deb

# The package installed with apt into a fresh Debian root (build/deb-root),
# rendering from the installed files (as root: the root is a chroot).
test-deb: deb
	sh tests/cross/deb-install.sh $(DEB_BUILD)/matcap-kiosk_$(VERSION)_$$(dpkg --print-architecture).deb \
		build/deb-root

.PHONY: deps-deb deb test-deb
