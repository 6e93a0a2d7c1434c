#!/bin/bash
# Build the virtual board: Debian 12's own kernel, the five test drivers it
# lacks (vkms, vimc, gpio-sim, gpio-mockup, irq_sim) built as external modules
# from linux-source-6.1, and an lz4 initramfs with busybox, udev, Mesa,
# libcamera, gpiod tools, kmscube and the board's own helpers (tools/).
# The userspace is this machine's: on Debian 13 (tests/trixie/chroot.sh)
# the board is Debian 12's kernel under Debian 13's libraries and tools
# (libgpiod 2, libcamera 0.4, Mesa 25), the kernel folder taken ready-made
# from VM_KERNEL_DIR or from the one kernel-* folder in the cache.
#
#   tests/vm/build.sh [--bin PATH]...
#
# Everything lands in tests/vm/cache (or $VM_CACHE), keyed by versions and
# content, so a second run only checks keys.  Binaries given with --bin go
# into a small second cpio appended to the cached base, so rebuilding the
# kiosk does not repack Mesa.  The last two lines on stdout are
#   VM_KERNEL=/path/vmlinuz
#   VM_INITRD=/path/initrd
# Progress goes to stderr.
set -eu
set -o pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
CACHE=${VM_CACHE:-$HERE/cache}
ARCHDIR=x86_64-linux-gnu
JOBS=${VM_JOBS:-$(nproc)}
CODENAME=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")

say() { printf '[vm-build] %s\n' "$*" >&2; }
die() { printf '[vm-build] error: %s\n' "$*" >&2; exit 1; }

BINS=()
while [ $# -gt 0 ]; do
	case $1 in
	--bin) [ $# -ge 2 ] || die "--bin needs a path"
		[ -f "$2" ] && [ -x "$2" ] || die "--bin $2: not an executable file"
		BINS+=("$(readlink -f "$2")"); shift 2 ;;
	-h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 0 ;;
	*) die "unknown argument '$1' (usage: build.sh [--bin PATH]...)" ;;
	esac
done

mkdir -p "$CACHE"
exec 9>"$CACHE/.lock"
flock -w 900 9 || die "another build holds $CACHE/.lock for 15 minutes"

APT_UPDATED=0
apt_update() {
	[ "$APT_UPDATED" = 0 ] && [ "$(id -u)" = 0 ] || return 1
	say "apt-get update"
	apt-get -o DPkg::Lock::Timeout=600 update >>"$CACHE/apt.log" 2>&1 || die "apt-get update failed, see $CACHE/apt.log"
	APT_UPDATED=1
}

# ---------------------------------------------------------------- packages
# Host packages the board is made of (userspace is copied from this host,
# which is Debian 12 like the guest) and the tools to build it.
PKGS="qemu-system-x86 kmod busybox-static lz4 cpio udev kmscube libdrm-tests
libcamera-tools libcamera-ipa gpiod libgl1-mesa-dri
libegl1 libegl-mesa0 libgbm1 libgles2 libdrm2
libdrm-dev libgbm-dev zlib1g-dev gcc-12 gcc make pkg-config xz-utils util-linux v4l-utils"
case $CODENAME in
bookworm) PKGS="$PKGS libcamera0.0.3 libgpiod2 libosmesa6 libglapi-mesa" ;;
trixie) PKGS="$PKGS libcamera0.4 libgpiod3 libosmesa6" ;;
*) die "the board is built on Debian 12 or 13, not '$CODENAME'" ;;
esac

missing=""
for p in $PKGS; do
	st=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
	[ "$st" = "install ok installed" ] || missing="$missing $p"
done
if [ -n "$missing" ]; then
	[ "$(id -u)" = 0 ] || die "missing packages:$missing (run as root, or: apt-get install$missing)"
	say "installing:$missing"
	if ! DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends $missing >"$CACHE/apt.log" 2>&1; then
		apt_update || die "apt-get install failed, see $CACHE/apt.log"
		DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends $missing >>"$CACHE/apt.log" 2>&1 ||
			die "apt-get install failed, see $CACHE/apt.log"
	fi
fi

# ---------------------------------------------------------------- kernel
# The kernel is the one linux-image-amd64 points at; image, headers and
# source are downloaded (never installed) so the host kernel is untouched.
resolve_kernel() {
	KPKG=${VM_KERNEL_PKG:-$(apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/{print $2; exit}')}
	KDEB=""
	[ -n "$KPKG" ] && KDEB=$(apt-cache show --no-all-versions "$KPKG" 2>/dev/null | awk '/^Version:/{print $2; exit}')
	[ -n "$KDEB" ]
}
# Elsewhere than Debian 12, a kernel folder built there (and its modules).
given_kernel() {
	KDIR=${VM_KERNEL_DIR:-}
	[ -n "$KDIR" ] || [ "$CODENAME" = bookworm ] || KDIR=$(ls -d "$CACHE"/kernel-* 2>/dev/null | head -1)
	[ -n "$KDIR" ] || return 1
	[ -e "$KDIR/.extracted" ] && ls -d "$KDIR"/mods-*/.built >/dev/null 2>&1 ||
		die "$KDIR: not a kernel folder that a Debian 12 build.sh completed"
	KVER=$(basename "$KDIR" | sed -n 's/^kernel-\(.*-amd64\)-.*/\1/p')
	KDEB=$(basename "$KDIR" | sed -n 's/^kernel-.*-amd64-//p')
	KPKG=linux-image-$KVER
}
if ! given_kernel; then
	[ "$CODENAME" = bookworm ] ||
		die "on $CODENAME the board takes Debian 12's kernel folder: run tests/vm/build.sh on Debian 12 and give its cache's kernel-* as VM_KERNEL_DIR"
	resolve_kernel || { apt_update && resolve_kernel; } ||
		die "cannot tell which kernel linux-image-amd64 depends on (run apt-get update as root)"
	KVER=${KPKG#linux-image-}
	KDIR=$CACHE/kernel-$KVER-$KDEB
fi
KROOT=$KDIR/root
KSRC=$KDIR/src

if [ ! -e "$KDIR/.extracted" ]; then
	say "downloading $KPKG $KDEB, its headers and linux-source-6.1"
	rm -rf "$KDIR"; mkdir -p "$KDIR/debs" "$KROOT" "$KSRC"
	# The build tools and the source are separate source packages: a
	# security update can publish them under another Debian revision of the
	# same upstream release (6.1.192-3 beside the image's 6.1.192-2, the
	# -2 gone). Same version where the mirror has it, else the newest of
	# the same upstream release.
	same_upstream() { # PACKAGE
		apt-cache madison "$1" 2>/dev/null | awk -v want="$KDEB" -v up="${KDEB%-*}-" '
			{ v = $3 } v == want { print v; found = 1; exit }
			index(v, up) == 1 && !best { best = v }
			END { if (!found && best) print best }'
	}
	kdownload() {
		kbuild=$(same_upstream linux-kbuild-6.1)
		ksource=$(same_upstream linux-source-6.1)
		(cd "$KDIR/debs" && apt-get download -o APT::Sandbox::User=root \
			"$KPKG=$KDEB" "linux-headers-$KVER=$KDEB" \
			"linux-headers-${KVER%-*}-common=$KDEB" "linux-kbuild-6.1=${kbuild:-$KDEB}" \
			"linux-source-6.1=${ksource:-$KDEB}" >"$KDIR/download.log" 2>&1)
	}
	# Stale package lists name files the mirror no longer has: update once.
	kdownload || { apt_update && kdownload; } ||
		die "apt-get download failed (kernel, headers and linux-source-6.1 of version $KDEB must all be on the mirror), see $KDIR/download.log"
	for d in "$KDIR"/debs/*.deb; do
		case $d in *linux-source*) dpkg-deb -x "$d" "$KDIR/srcdeb" ;; *) dpkg-deb -x "$d" "$KROOT" ;; esac
	done
	# Only the drivers we build are taken out of the 140 MB tarball.
	tar -xJf "$KDIR"/srcdeb/usr/src/linux-source-6.1.tar.xz -C "$KSRC" --strip-components=1 \
		--wildcards 'linux-source-6.1/drivers/gpu/drm/vkms/*' \
		'linux-source-6.1/drivers/media/test-drivers/vimc/*' \
		linux-source-6.1/drivers/gpio/gpio-sim.c linux-source-6.1/drivers/gpio/gpio-mockup.c \
		linux-source-6.1/drivers/gpio/gpiolib.h linux-source-6.1/kernel/irq/irq_sim.c
	rm -rf "$KDIR/srcdeb" "$KDIR/debs"
	# The headers' Makefile includes the common tree by absolute path.
	sed -i "s#^include /usr/src/#include $KROOT/usr/src/#" "$KROOT/usr/src/linux-headers-$KVER/Makefile"
	touch "$KDIR/.extracted"
	for old in "$CACHE"/kernel-*; do [ "$old" = "$KDIR" ] || rm -rf "$old"; done
fi
VMLINUZ=$KROOT/boot/vmlinuz-$KVER
[ -f "$VMLINUZ" ] || die "$VMLINUZ missing; remove $KDIR and retry"

# ---------------------------------------------------------------- modules
MODS_KEY=$( { echo "$KVER $KDEB"; gcc-12 --version | head -1; sed -n '/^# >>> modules recipe/,/^# <<< modules recipe/p' "$0"; } | sha256sum | cut -c1-16)
MODDIR=$KDIR/mods-$MODS_KEY
# A given folder's modules are taken as built (another compiler, same code).
[ "$CODENAME" = bookworm ] || MODDIR=$(dirname "$(ls -d "$KDIR"/mods-*/.built | head -1)")
if [ ! -e "$MODDIR/.built" ]; then
	say "building vkms vimc gpio-sim gpio-mockup irq_sim against $KVER"
	t0=$(date +%s)
	rm -rf "$KDIR"/mods-*; mkdir -p "$MODDIR"
# >>> modules recipe
	M=$MODDIR/src
	mkdir -p "$M/vkms" "$M/vimc" "$M/gpio" "$M/irq"
	cp "$KSRC"/drivers/gpu/drm/vkms/* "$M/vkms/"
	cp "$KSRC"/drivers/media/test-drivers/vimc/*.[ch] "$KSRC/drivers/media/test-drivers/vimc/Makefile" "$M/vimc/"
	cp "$KSRC"/drivers/gpio/gpio-sim.c "$KSRC"/drivers/gpio/gpio-mockup.c "$KSRC"/drivers/gpio/gpiolib.h "$M/gpio/"
	cp "$KSRC"/kernel/irq/irq_sim.c "$M/irq/"
	# Debian leaves CONFIG_IRQ_SIM out, so irq_sim becomes a module; its one
	# use of the unexported irq_to_desc() becomes the exported equivalent.
	sed -i -e '/^\tint irqnum;$/d' -e '/irqnum = irq_find_mapping(work_ctx->domain, offset);/d' \
		-e 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_domain_irq(work_ctx->domain, offset);/' "$M/irq/irq_sim.c"
	grep -q 'generic_handle_domain_irq(work_ctx->domain, offset)' "$M/irq/irq_sim.c" ||
		die "irq_sim.c changed upstream: the irq_to_desc patch did not apply"
	printf '\nMODULE_LICENSE("GPL");\nMODULE_DESCRIPTION("Interrupt simulator, out-of-tree build");\n' >>"$M/irq/irq_sim.c"
	echo 'obj-m += gpio-sim.o gpio-mockup.o' >"$M/gpio/Kbuild"
	echo 'obj-m += irq_sim.o' >"$M/irq/Kbuild"
	echo 'obj-m += vkms/ vimc/ gpio/ irq/' >"$M/Kbuild"
	make -C "$KROOT/usr/src/linux-headers-$KVER" M="$M" CONFIG_DRM_VKMS=m CONFIG_VIDEO_VIMC=m \
		-j"$JOBS" modules >"$MODDIR/build.log" 2>&1 || { tail -30 "$MODDIR/build.log" >&2; die "module build failed, see $MODDIR/build.log"; }
# <<< modules recipe
	for m in vkms/vkms vimc/vimc gpio/gpio-sim gpio/gpio-mockup irq/irq_sim; do
		cp "$M/$m.ko" "$MODDIR/"
		vm=$(modinfo -F vermagic "$MODDIR/${m#*/}.ko")
		case $vm in "$KVER "*) ;; *) die "${m#*/}.ko has vermagic '$vm', kernel is $KVER" ;; esac
	done
	touch "$MODDIR/.built"
	say "modules built in $(( $(date +%s) - t0 )) s"
fi

# ---------------------------------------------------------------- base initramfs
GUEST_MODULES="vkms vimc gpio-sim gpio-mockup irq_sim configfs 9p 9pnet_virtio virtio_pci uinput evdev
vivid"
# USB sticks (tests/e2e/hands-board.sh): the xHCI controller, usb-storage
# and the filesystems a stick has: FAT (with the code page and the I/O
# charsets: Debian mounts FAT with iocharset ascii by default) and ext2-4.
GUEST_MODULES="$GUEST_MODULES xhci_pci usb_storage sd_mod vfat nls_cp437 nls_ascii nls_utf8 nls_iso8859_1 ext4"
# A second GPU with two outputs (run.sh --outputs 2, tests/e2e/kms-outputs.sh):
# vkms in 6.1 has one CRTC, QEMU's virtio-gpu-pci one per output. Debian
# builds virtio-gpu as a module; its dependencies (drm_shmem_helper,
# virtio_dma_buf, ...) come with it. udev loads it when the device is there.
GUEST_MODULES="$GUEST_MODULES virtio-gpu"
BASE_BINS="/usr/bin/busybox /usr/bin/kmod /usr/bin/udevadm /usr/bin/kmscube /usr/bin/modetest
/usr/bin/modeprint /usr/bin/proptest /usr/bin/cam /usr/bin/gpiodetect /usr/bin/gpioinfo
/usr/bin/gpioget /usr/bin/gpioset /usr/bin/gpiomon /usr/bin/gpiofind /usr/bin/v4l2-ctl
/usr/bin/media-ctl /usr/bin/cec-ctl"
# Not on both releases: libglapi (gone in Mesa 25), gbm/dri_gbm.so (GBM's
# backend since Mesa 24.3), the versioned libcamera and libgpiod.
BASE_LIBS="/usr/lib/$ARCHDIR/dri/kms_swrast_dri.so /usr/lib/$ARCHDIR/dri/swrast_dri.so
/usr/lib/$ARCHDIR/libEGL.so.1 /usr/lib/$ARCHDIR/libEGL_mesa.so.0 /usr/lib/$ARCHDIR/libgbm.so.1
/usr/lib/$ARCHDIR/libGLESv2.so.2 /usr/lib/$ARCHDIR/libGLESv1_CM.so.1 /usr/lib/$ARCHDIR/libudev.so.1
$( { ls /usr/lib/$ARCHDIR/libOSMesa.so.8 /usr/lib/$ARCHDIR/libglapi.so.0 /usr/lib/$ARCHDIR/gbm/dri_gbm.so /usr/lib/$ARCHDIR/libcamera.so.0.* \
	/usr/lib/$ARCHDIR/libcamera-base.so.0.* /usr/lib/$ARCHDIR/libgpiod.so.[0-9] 2>/dev/null || true; } | sort -u)"
BASE_DATA="/usr/share/glvnd/egl_vendor.d /usr/share/drirc.d /usr/share/libcamera
/usr/lib/$ARCHDIR/libcamera /usr/lib/udev/rules.d"

pkgvers=$(dpkg-query -W -f='${Package}=${Version}\n' $PKGS 2>/dev/null | sort)
BASE_KEY=$( { echo "$KVER $KDEB $MODS_KEY"; echo "$pkgvers"; echo "$GUEST_MODULES $BASE_BINS $BASE_LIBS $BASE_DATA";
	cat "$0" "$HERE/guest-init.sh" "$HERE"/tools/*.c; } | sha256sum | cut -c1-16)
BASE=$CACHE/base-$BASE_KEY.cpio.lz4

# copy_elf ROOT FILE: FILE, dereferenced, at its own path under ROOT, and
# every library ldd names for it (skipped if already there).
copy_elf() {
	copy_file "$1" "$2"
	copy_deps "$1" "$2"
}
copy_deps() { # copy_deps ROOT FILE: only the libraries of FILE
	local root=$1 f=$2 lib
	{ ldd "$f" 2>/dev/null || true; } | awk '/=> \//{print $3} /^\t\/[^ ]+ \(0x/{print $1}' | while read -r lib; do
		copy_file "$root" "$lib"
	done
}
copy_file() {
	local root=$1 f=$2
	[ -e "$root$f" ] && return 0
	mkdir -p "$root$(dirname "$f")"
	cp -L --preserve=mode "$f" "$root$f"
}
pack() { # pack DIR OUT: newc cpio, lz4 legacy frame (what the kernel unpacks)
	(cd "$1" && find . -mindepth 1 | LC_ALL=C sort | cpio -o -H newc -R 0:0 --quiet) | lz4 -l -q -c >"$2.tmp"
	mv "$2.tmp" "$2"
}

if [ ! -e "$BASE" ]; then
	say "building base initramfs ($BASE_KEY)"
	t0=$(date +%s)
	present=""
	for b in $BASE_BINS; do [ -x "$b" ] && present="$present $b"; done
	R=$CACHE/base-stage
	rm -rf "$R"; mkdir -p "$R"
	for d in usr/bin usr/sbin usr/lib usr/lib64 usr/local/bin etc proc sys dev run tmp root var/tmp mnt vm repo share; do mkdir -p "$R/$d"; done
	ln -s usr/bin "$R/bin"; ln -s usr/sbin "$R/sbin"; ln -s usr/lib "$R/lib"; ln -s usr/lib64 "$R/lib64"
	for b in $present; do copy_elf "$R" "$b"; done
	for l in $BASE_LIBS; do
		[ -e "$l" ] || die "$l missing on the host"
		case $l in */dri/*) ;; *) copy_elf "$R" "$l" ;; esac
	done
	# Mesa's DRI drivers are one megadriver under many names: copy it once
	# (with its deps) and hard-link the names Mesa looks up for vkms.
	copy_elf "$R" "/usr/lib/$ARCHDIR/dri/kms_swrast_dri.so"
	ln -f "$R/usr/lib/$ARCHDIR/dri/kms_swrast_dri.so" "$R/usr/lib/$ARCHDIR/dri/swrast_dri.so"
	for d in $BASE_DATA; do
		[ -e "$d" ] || die "$d missing on the host"
		mkdir -p "$R$(dirname "$d")"; cp -a "$d" "$R$(dirname "$d")/"
	done
	for f in "$R/usr/lib/$ARCHDIR"/libcamera/*; do
		case $f in *.sign) ;; *) copy_elf "$R" "${f#"$R"}" ;; esac
	done
	mkdir -p "$R/usr/lib/systemd"; ln -s ../../bin/udevadm "$R/usr/lib/systemd/systemd-udevd"
	# kmod answers to modprobe & co; busybox fills every other name.
	for n in modprobe insmod rmmod lsmod depmod modinfo; do ln -s ../bin/kmod "$R/usr/sbin/$n"; done
	busybox --list-full | while read -r a; do
		t=$R/usr/${a#usr/}
		[ -e "$t" ] || [ -L "$t" ] || ln -s /usr/bin/busybox "$t"
	done
	# vm-grab: reads back the CRTC's framebuffer / captures vkms writeback.
	gcc-12 -std=c11 -O2 -Wall -Wextra -Werror -o "$R/usr/bin/vm-grab" "$HERE/tools/vm-grab.c" \
		$(pkg-config --cflags --libs libdrm zlib) || die "vm-grab did not build"
	copy_deps "$R" "$R/usr/bin/vm-grab"
	gcc-12 -std=c11 -O2 -Wall -Wextra -Werror -o "$R/usr/bin/vm-key" "$HERE/tools/vm-key.c" || die "vm-key did not build"
	# vm-hold: a known picture on the display, with or without DRM master.
	gcc-12 -std=c11 -O2 -Wall -Wextra -Werror -o "$R/usr/bin/vm-hold" "$HERE/tools/vm-hold.c" \
		$(pkg-config --cflags --libs libdrm) || die "vm-hold did not build"
	mkdir -p "$R/usr/lib/vm"
	gcc-12 -std=c11 -O2 -Wall -Wextra -Werror -shared -fPIC -o "$R/usr/lib/vm/libgbm-linear.so" \
		"$HERE/tools/gbm-linear.c" $(pkg-config --cflags libdrm gbm) -ldl || die "gbm-linear did not build"
	# Modules: the closure of what the board loads, then depmod.
	mkdir -p "$KROOT/lib/modules/$KVER/extra"
	cp "$MODDIR"/*.ko "$KROOT/lib/modules/$KVER/extra/"
	depmod -b "$KROOT" "$KVER"
	for m in $GUEST_MODULES; do
		modprobe -d "$KROOT" -S "$KVER" --show-depends "$m" | awk '$1=="insmod"{print $2}'
	done | sort -u | while read -r ko; do
		rel=${ko#"$KROOT"/lib/modules/"$KVER"/}
		mkdir -p "$R/lib/modules/$KVER/$(dirname "$rel")"; cp "$ko" "$R/lib/modules/$KVER/$rel"
	done
	cp "$KROOT/lib/modules/$KVER"/modules.builtin* "$KROOT/lib/modules/$KVER/modules.order" "$R/lib/modules/$KVER/"
	depmod -b "$R" "$KVER"
	# Just enough /etc for udev (group names in rules) and the loader.
	printf 'root:x:0:0:root:/root:/bin/sh\n' >"$R/etc/passwd"
	awk -F: '$3 < 1000' /etc/group >"$R/etc/group"
	cp -a /etc/ld.so.conf /etc/ld.so.conf.d "$R/etc/"
	ldconfig -r "$R" 2>/dev/null || true
	echo board >"$R/etc/hostname"
	install -m 0755 "$HERE/guest-init.sh" "$R/init"
	find "$R" -type f | sed "s#^$R##" | LC_ALL=C sort >"$CACHE/base-$BASE_KEY.list"
	pack "$R" "$BASE"
	du -sh "$R" | awk '{print $1}' >"$CACHE/base-$BASE_KEY.size"
	rm -rf "$R"
	for old in "$CACHE"/base-*.cpio.lz4; do
		[ "$old" = "$BASE" ] || rm -f "$old" "${old%.cpio.lz4}.list" "${old%.cpio.lz4}.size"
	done
	say "base initramfs: $(cat "$CACHE/base-$BASE_KEY.size") unpacked, $(du -h "$BASE" | cut -f1) lz4, $(( $(date +%s) - t0 )) s"
fi

# ---------------------------------------------------------------- extra binaries
INITRD=$BASE
if [ ${#BINS[@]} -gt 0 ]; then
	EXTRA_KEY=$( { echo "$BASE_KEY"; for b in "${BINS[@]}"; do
		echo "$b"; sha256sum "$b"
		{ ldd "$b" 2>/dev/null || true; } | awk '/=> \//{print $3}' | sort | xargs -r sha256sum
	done; } | sha256sum | cut -c1-16)
	INITRD=$CACHE/initrd-$BASE_KEY-$EXTRA_KEY.lz4
	if [ ! -e "$INITRD" ]; then
		say "packing ${#BINS[@]} extra binar$([ ${#BINS[@]} = 1 ] && echo y || echo ies) ($EXTRA_KEY)"
		X=$CACHE/extra-stage
		rm -rf "$X"; mkdir -p "$X/usr/local/bin"
		for b in "${BINS[@]}"; do
			cp -L --preserve=mode "$b" "$X/usr/local/bin/$(basename "$b")"
			! { ldd "$b" 2>/dev/null || true; } | grep -q 'not found' || die "--bin $b: $(ldd "$b" | grep 'not found' | head -1)"
			{ ldd "$b" 2>/dev/null || true; } | awk '/=> \//{print $3} /^\t\/[^ ]+ \(0x/{print $1}' | while read -r lib; do
				grep -qxF "$lib" "$CACHE/base-$BASE_KEY.list" && continue
				# /lib is /usr/lib in the guest: store under the usr path.
				case $lib in /lib/*|/lib64/*) dest=/usr$lib ;; *) dest=$lib ;; esac
				grep -qxF "$dest" "$CACHE/base-$BASE_KEY.list" && continue
				mkdir -p "$X$(dirname "$dest")"; cp -L --preserve=mode "$lib" "$X$dest"
			done
		done
		pack "$X" "$CACHE/extra-$EXTRA_KEY.cpio.lz4"
		rm -rf "$X"
		# The kernel unpacks concatenated archives in order.
		cat "$BASE" "$CACHE/extra-$EXTRA_KEY.cpio.lz4" >"$INITRD.tmp"; mv "$INITRD.tmp" "$INITRD"
		rm -f "$CACHE/extra-$EXTRA_KEY.cpio.lz4"
	fi
	touch "$INITRD"
	# Keep the three most recently used combined images.
	ls -1t "$CACHE"/initrd-*.lz4 2>/dev/null | tail -n +4 | xargs -r rm -f
fi

echo "VM_KERNEL=$VMLINUZ"
echo "VM_INITRD=$INITRD"
