#!/bin/sh
# Builds the guest for tests/vm/systemd-test.sh: a small Debian 12 root
# with systemd as PID 1, udev and the kiosk's runtime libraries, made of
# this machine's own installed files (it is Debian 12, as tests/vm/build.sh
# makes the board's userspace of them): the files dpkg lists for PACKAGES,
# the packages of the libraries the kiosk links, everything they depend on
# and what debootstrap's minbase holds (Essential and Priority: required),
# then what those packages' scripts would have made (the system users and
# groups, ld.so.cache, the units systemd's postinst enables). No download,
# nothing run from the archive: minutes less CI than a debootstrap. The
# kiosk installed into it by `make install` (binary, matcaps, kiosk.ini,
# the systemd unit, sysusers.d file and udev rule), its user made by
# systemd-sysusers and the unit enabled exactly as on a board; the virtual
# board's kernel modules (vkms, from the cache of tests/vm/build.sh); and
# the guest test (tests/vm/systemd-guest.sh) as a oneshot unit ordered
# after the kiosk. Packed as an lz4 initramfs whose /init is systemd.
#
#   tests/vm/systemd-build.sh         prints VM_KERNEL=... and VM_INITRD=...
#
# Environment: VM_CACHE (the board's cache, default tests/vm/cache),
# SYSTEMD_VM_CACHE (default build/vm-systemd: the root, about 250 MB; the
# initramfs). Needs root (the root's files keep their owners).
set -eu

HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
CACHE=${SYSTEMD_VM_CACHE:-$REPO/build/vm-systemd}
say() { printf '[vm-systemd] %s\n' "$*" >&2; }
die() {
	printf '[vm-systemd] error: %s\n' "$*" >&2
	exit 125
}

# What the guest test uses, Mesa's drivers and the kiosk's libraries (the
# packages of those ldd names are added below). /init is systemd itself and
# the guest powers off through systemctl: no systemd-sysv.
PACKAGES="systemd udev kmod procps libegl-mesa0 libgl1-mesa-dri libgbm1 libegl1
libgles2 libdrm2 libpng16-16 libturbojpeg0 libwebp7 libtinygltf2d libsystemd0 libgpiod2 libevdev2
libcamera0.0.3 libosmesa6 libstdc++6 zlib1g libmeshoptimizer2d"

# shellcheck disable=SC2086
missing=$(dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' $PACKAGES 2>&1 |
	awk '/^ii/ {ok[$2] = 1} END {n = split(p, a, " "); for (i = 1; i <= n; i++)
		if (!(a[i] in ok)) print a[i]}' p="$PACKAGES" | tr '\n' ' ')
[ -z "$missing" ] || {
	say "installing on this machine: $missing"
	# shellcheck disable=SC2086
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing \
		>/dev/null || die "cannot install $missing"
}
mkdir -p "$CACHE"

# The board's kernel and vkms: its build.sh prints where they are.
board=$("$HERE/build.sh") || die "tests/vm/build.sh failed"
KERNEL=$(printf '%s\n' "$board" | sed -n 's/^VM_KERNEL=//p')
KDIR=$(dirname "$(dirname "$(dirname "$KERNEL")")")
KVER=$(ls "$KDIR/root/lib/modules")
[ -f "$KDIR/root/lib/modules/$KVER/extra/vkms.ko" ] || die "no vkms.ko under $KDIR"

make -s -j"$(nproc)" -C "$REPO" matcap-kiosk >/dev/null || die "the kiosk does not build"
# The packages of the kiosk's libraries, as ldd finds them here (by the
# file's name: dpkg may list it under /lib or /usr/lib).
libpkgs=$(ldd "$REPO/matcap-kiosk" | awk -v d="$(gcc -print-multiarch)" \
	'$2 == "=>" && $3 ~ /^\// {n = split($3, p, "/"); print "*lib/" d "/" p[n]}' |
	xargs -r dpkg-query -S 2>/dev/null | sed 's/:.*//' | sort -u)

# closure PACKAGE...: those packages, minbase's (Essential, Priority:
# required) and what they depend on, as installed here (an alternative or a
# virtual package: the first one installed).
closure() {
	dpkg-query -W -f='${db:Status-Abbrev}\t${Package}\t${Architecture}\t${Essential}\t${Priority}\t${Provides}\t${Pre-Depends}, ${Depends}\n' |
		awk -F '\t' -v want="$*" -v arch="$(dpkg --print-architecture)" '
		function name(s) { sub(/\(.*/, "", s); sub(/:.*/, "", s); gsub(/ /, "", s); return s }
		$1 ~ /^ii/ && ($3 == arch || $3 == "all") {
			have[$2] = 1; deps[$2] = $7
			if ($4 == "yes" || $5 == "required") queue[++n] = $2
			m = split($6, p, ","); for (i = 1; i <= m; i++) { v = name(p[i]); if (!(v in prov)) prov[v] = $2 }
		}
		END {
			k = split(want, w, " "); for (i = 1; i <= k; i++) queue[++n] = w[i]
			for (q = 1; q <= n; q++) {
				pk = queue[q]; if (pk in seen || !(pk in have)) continue
				seen[pk] = 1; print pk
				m = split(deps[pk], d, ",")
				for (i = 1; i <= m; i++) {
					a = split(d[i], alt, "|")
					for (j = 1; j <= a; j++) {
						v = name(alt[j]); if (v == "") continue
						if (v in have) { queue[++n] = v; break }
						if (v in prov) { queue[++n] = prov[v]; break }
					}
				}
			}
		}'
}

# The root: every file those packages installed here (merged /usr as on
# this machine; no documentation, manual pages or translations), then what
# their maintainer scripts make.
work=$CACHE/work
rm -rf "$work" "$CACHE"/root-* "$CACHE/debootstrap.log"
mkdir -p "$work"
# shellcheck disable=SC2086
pkgs=$(closure $PACKAGES $libpkgs)
echo "$pkgs" >"$CACHE/packages"
merged=
for d in bin sbin lib lib32 lib64 libx32; do
	[ -L "/$d" ] || continue
	ln -s "$(readlink "/$d")" "$work/$d"
	merged="$merged s|^/$d/|/usr/$d/|; \\|^/$d\$|d;"
done
# shellcheck disable=SC2086
dpkg-query -L $pkgs | grep '^/.' | grep -vx '/\.' | sed "$merged" |
	grep -Ev '^/usr/share/(doc|man|info|locale|lintian)(/|$)' | sed 's|^/||' | LC_ALL=C sort -u >"$CACHE/files"
tar -C / --no-recursion --ignore-failed-read -cf - -T "$CACHE/files" 2>/dev/null |
	tar -C "$work" --keep-directory-symlink -xf - || die "cannot copy this machine's files"
say "root: $(echo "$pkgs" | wc -l) packages of this machine, $(du -sh "$work" | cut -f1)"
# base-passwd's, base-files' and libc-bin's scripts.
cp /usr/share/base-passwd/passwd.master "$work/etc/passwd"
cp /usr/share/base-passwd/group.master "$work/etc/group"
awk -F: '{print $1 ":*:19000:0:99999:7:::"}' "$work/etc/passwd" >"$work/etc/shadow"
awk -F: '{print $1 ":*::"}' "$work/etc/group" >"$work/etc/gshadow"
chmod 640 "$work/etc/shadow" "$work/etc/gshadow"
chgrp shadow "$work/etc/shadow" "$work/etc/gshadow" 2>/dev/null || :
[ ! -f /usr/share/base-files/nsswitch.conf ] || cp /usr/share/base-files/nsswitch.conf "$work/etc/"
ldconfig -r "$work" || die "ldconfig failed"
# What Debian's systemd postinst enables (getty@tty1, which the kiosk's
# unit conflicts with, among them).
systemctl --root="$work" enable getty@.service remote-fs.target systemd-pstore.service \
	>/dev/null 2>&1 || die "cannot enable systemd's own units"

# The kiosk, installed as a user would (the unit's ExecStart names
# /usr/local/bin/matcap-kiosk), with its user and groups and the unit on.
make -s -C "$REPO" install DESTDIR="$work" PREFIX=/usr/local SYSCONFDIR=/etc >/dev/null ||
	die "make install failed"
# A library dpkg does not know (installed by hand here): copied.
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
make -s -j"$(nproc)" -C "$REPO" BUILD=$hooks KIOSK=$hooks/matcap-kiosk OPT="-O2 -g -DMK_TEST_HOOKS" \
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
