#!/bin/sh
# Builds the guest for tests/vm/systemd-test.sh: a small Debian 12 root
# (debootstrap --variant=minbase) with systemd as PID 1, udev and the
# kiosk's runtime libraries; the kiosk installed into it by `make install`
# (binary, matcaps, kiosk.ini, the systemd unit, sysusers.d file and udev
# rule), its user made by systemd-sysusers and the unit enabled exactly as
# on a board; the virtual board's kernel modules (vkms, from the cache of
# tests/vm/build.sh); and the guest test (tests/vm/systemd-guest.sh) as a
# oneshot unit ordered after the kiosk. Packed as an lz4 initramfs whose
# /init is systemd.
#
#   tests/vm/systemd-build.sh         prints VM_KERNEL=... and VM_INITRD=...
#
# Environment: VM_CACHE (the board's cache, default tests/vm/cache),
# SYSTEMD_VM_CACHE (default build/vm-systemd: the debootstrap root, kept
# while the package list is unchanged, about 270 MB; the initramfs).
# Needs root (debootstrap, chown), and installs debootstrap when missing.
set -eu

HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
CACHE=${SYSTEMD_VM_CACHE:-$REPO/build/vm-systemd}
MIRROR=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
say() { printf '[vm-systemd] %s\n' "$*" >&2; }
die() {
	printf '[vm-systemd] error: %s\n' "$*" >&2
	exit 125
}

# The kiosk's libraries (ldd of the binary, by package), Mesa's drivers,
# and what the guest test uses.
PACKAGES="systemd systemd-sysv udev kmod procps libegl-mesa0 libgl1-mesa-dri libgbm1 libegl1
libgles2 libdrm2 libpng16-16 libturbojpeg0 libtinygltf2d libinih1 libsystemd0 libgpiod2 libevdev2
libcamera0.0.3 libosmesa6 libstdc++6 zlib1g libmeshoptimizer2d"

command -v debootstrap >/dev/null || {
	say "installing debootstrap"
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null ||
		die "cannot install debootstrap"
}
mkdir -p "$CACHE"

# The board's kernel and vkms: its build.sh prints where they are.
board=$("$HERE/build.sh") || die "tests/vm/build.sh failed"
KERNEL=$(printf '%s\n' "$board" | sed -n 's/^VM_KERNEL=//p')
KDIR=$(dirname "$(dirname "$(dirname "$KERNEL")")")
KVER=$(ls "$KDIR/root/lib/modules")
[ -f "$KDIR/root/lib/modules/$KVER/extra/vkms.ko" ] || die "no vkms.ko under $KDIR"

key=$(printf '%s %s' "$PACKAGES" "$MIRROR" | sha256sum | cut -c1-16)
base=$CACHE/root-$key
if [ ! -f "$base/.complete" ]; then
	say "debootstrap of bookworm into $base (a few minutes, once)"
	rm -rf "$CACHE"/root-*
	# shellcheck disable=SC2086
	debootstrap --variant=minbase --include="$(echo $PACKAGES | tr ' ' ',')" bookworm \
		"$base" "$MIRROR" >"$CACHE/debootstrap.log" 2>&1 ||
		die "debootstrap failed, see $CACHE/debootstrap.log"
	rm -rf "$base/var/cache/apt/archives"/*.deb "$base/var/lib/apt/lists"/*
	touch "$base/.complete"
fi

work=$CACHE/work
rm -rf "$work"
cp -a "$base" "$work"
rm -f "$work/.complete"

# The kiosk, installed as a user would (the unit's ExecStart names
# /usr/local/bin/matcap-kiosk), with its user and groups and the unit on.
make -s -C "$REPO" matcap-kiosk >/dev/null || die "the kiosk does not build"
make -s -C "$REPO" install DESTDIR="$work" PREFIX=/usr/local SYSCONFDIR=/etc >/dev/null ||
	die "make install failed"
# Libraries the kiosk gained since the package list was written: the host
# runs the same Debian release, so its copies fit.
for lib in $(ldd "$REPO/matcap-kiosk" | awk '$2 == "=>" && $3 ~ /^\// {print $3}'); do
	[ -e "$work$lib" ] || {
		say "copying $lib from this machine (not in the package list)"
		mkdir -p "$work$(dirname "$lib")"
		cp -L "$lib" "$work$lib"
	}
done
systemd-sysusers --root="$work" >/dev/null 2>&1 || die "systemd-sysusers failed"
systemctl --root="$work" enable matcap-kiosk.service >/dev/null 2>&1 ||
	die "cannot enable matcap-kiosk.service"
# vkms has one connector; the kiosk takes it through KMS.
sed -i 's/^backend = .*/backend = kms/' "$work/etc/matcap-kiosk/kiosk.ini"

# The board's display: vkms and what it needs, loaded by systemd.
mdir=$work/lib/modules/$KVER
mkdir -p "$mdir/extra"
cp "$KDIR/root/lib/modules/$KVER/extra/vkms.ko" "$mdir/extra/"
for dep in $(sed -n 's|^extra/vkms.ko: *||p' "$KDIR/root/lib/modules/$KVER/modules.dep"); do
	mkdir -p "$mdir/$(dirname "$dep")"
	cp "$KDIR/root/lib/modules/$KVER/$dep" "$mdir/$dep"
done
cp "$KDIR/root/lib/modules/$KVER"/modules.builtin* "$KDIR/root/lib/modules/$KVER"/modules.order \
	"$mdir/"
depmod -b "$work" "$KVER" || die "depmod failed"
echo vkms >"$work/etc/modules-load.d/vkms.conf"

# vm-grab (the board's tool) reads back what the CRTC scans out.
gcc -std=c11 -O2 -o "$work/usr/local/bin/vm-grab" "$HERE/tools/vm-grab.c" \
	$(pkg-config --cflags --libs libdrm zlib) || die "vm-grab did not build"

# The guest test, and a unit that notes the console's mode before the kiosk.
mkdir -p "$work/usr/local/lib/vm-systemd"
# For its reload under WatchdogSec=3s: the kiosk built with the test hooks
# (-DMK_TEST_HOOKS: MK_TEST_PREPARE_DELAY_MS holds a reload's preparation),
# beside the test, not in BINDIR; the drop-in of that check alone runs it.
# The shipped build (make, the .deb) has no -DMK_TEST_HOOKS; the guest and
# tests/cross/deb-install.sh check that it has no hook.
hooks=build/vm-systemd/hooks
make -s -C "$REPO" BUILD=$hooks KIOSK=$hooks/matcap-kiosk OPT="-O2 -g -DMK_TEST_HOOKS" \
	$hooks/matcap-kiosk >/dev/null || die "the kiosk with the test hooks does not build"
cp "$REPO/$hooks/matcap-kiosk" "$work/usr/local/lib/vm-systemd/matcap-kiosk-hooks"
# The model it reloads, where the service user may read it: the bench's
# 100k-triangle knot, or SYSTEMD_VM_MODEL=knot-1m (the loop's longest step
# during its reload is the figure of issue 22; minutes under TCG).
make -s -C "$REPO" build/tools/mkmodels >/dev/null || die "mkmodels does not build"
mkdir -p "$CACHE/models"
[ -s "$CACHE/models/knot-1m.glb" ] || "$REPO/build/tools/mkmodels" "$CACHE/models" --bench \
	>/dev/null || die "mkmodels failed"
model=${SYSTEMD_VM_MODEL:-knot-100k}
[ -s "$CACHE/models/$model.glb" ] || die "no model $model (mkmodels --bench writes knot-10k, -100k, -1m)"
mkdir -p "$work/srv/matcap-kiosk"
cp "$CACHE/models/$model.glb" "$work/srv/matcap-kiosk/"
echo "/srv/matcap-kiosk/$model.glb" >"$work/usr/local/lib/vm-systemd/reload-model"
cp "$HERE/systemd-guest.sh" "$work/usr/local/lib/vm-systemd/guest.sh"
cat >"$work/etc/systemd/system/vm-systemd-before.service" <<'EOF'
[Unit]
Description=What the display shows before the kiosk (for the systemd test)
Before=matcap-kiosk.service
After=systemd-modules-load.service systemd-udev-settle.service
Wants=systemd-udev-settle.service

[Service]
Type=oneshot
ExecStart=/bin/sh -c 'udevadm settle; for i in 1 2 3 4 5 6 7 8 9 10; do test -e /dev/dri/card0 && break; sleep 0.5; done; vm-grab -o /run/before.ppm >/run/before.txt 2>&1'
RemainAfterExit=yes

[Install]
WantedBy=multi-user.target
EOF
cat >"$work/etc/systemd/system/vm-systemd-test.service" <<'EOF'
[Unit]
Description=The systemd test of matcap-kiosk.service
After=matcap-kiosk.service vm-systemd-before.service

[Service]
Type=oneshot
ExecStart=/bin/sh /usr/local/lib/vm-systemd/guest.sh
StandardOutput=journal+console
StandardError=journal+console
TimeoutStartSec=900

[Install]
WantedBy=multi-user.target
EOF
systemctl --root="$work" enable vm-systemd-before.service vm-systemd-test.service \
	>/dev/null 2>&1 || die "cannot enable the test units"
# A quiet, non-interactive boot: no login prompts, no first-boot questions.
ln -sf /dev/null "$work/etc/systemd/system/serial-getty@ttyS0.service"
ln -sf /dev/null "$work/etc/systemd/system/systemd-firstboot.service"
echo 8f1c2ea4c6b54a9a9b7c6c1e3d0a7f21 >"$work/etc/machine-id"
echo kiosk-vm >"$work/etc/hostname"
ln -sf /lib/systemd/systemd "$work/init"

INITRD=$CACHE/initrd.cpio.lz4
say "packing $INITRD"
(cd "$work" && find . | cpio -o -H newc --quiet) | lz4 -l -q -1 >"$INITRD.tmp" ||
	die "cannot pack the initramfs"
mv "$INITRD.tmp" "$INITRD"
echo "VM_KERNEL=$KERNEL"
echo "VM_INITRD=$INITRD"
