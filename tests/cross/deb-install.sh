#!/bin/sh
# The package as a user gets it: installed with apt into a fresh Debian root
# of the package's own architecture (mmdebstrap; arm64 and armhf run
# through qemu-user's binfmt handlers, tests/cross/binfmt.sh), where the
# installed program says its version and renders offscreen with the
# installed matcaps, and the config, units, sysusers file and udev rules
# are in place; removing the package keeps the edited config, purging it
# does not. With REF (the amd64 package's render) and IMGDIFF, the render
# through softpipe with the level of detail off must agree with amd64's
# (the PSNR is printed). The renders are kept as ROOT.png (default) and
# ROOT.compare.png. Ends with one "N passed, N failed" line. Needs root (the root
# is a chroot).
# Usage: tests/cross/deb-install.sh DEB ROOT SUITE [REF IMGDIFF]
# DEB_CACHE as in deb-build.sh: packages already downloaded are reused.
set -u
deb=$1
root=$2
suite=$3
ref=${4:-}
imgdiff=${5:-}
arch=$(dpkg-deb -f "$deb" Architecture)
CHECK_LOG=$root.log
# shellcheck source=../tools/checks.sh
. "$(dirname "$0")/../tools/checks.sh"
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin "$@"; }
cache=$(realpath -m "${DEB_CACHE:-build/deb-cache}/$suite")
mkdir -p "$cache"
export DEB_CACHE_DIR="$cache"

rm -rf "$root" "$root.png" "$root.compare.png"
# shellcheck disable=SC2016 # the hooks' $1 and $DEB_CACHE_DIR are theirs.
check "a fresh $suite $arch root" mmdebstrap --quiet --variant=apt --architectures="$arch" \
	--skip=essential/unlink --skip=cleanup/apt/cache \
	--setup-hook='mkdir -p "$1/var/cache/apt/archives/partial" &&
		cp -al "$DEB_CACHE_DIR/." "$1/var/cache/apt/archives/"' \
	"$suite" "$root" "deb ${DEB_MIRROR:-http://deb.debian.org/debian} $suite main"
cp "$deb" "$root/tmp/"
# OSMesa is only recommended (offscreen rendering); this test renders offscreen.
check "apt-get install ./$(basename "$deb")" in_root sh -c "apt-get update -qq &&
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq ./tmp/$(basename "$deb") libosmesa6"
cp -aln "$root"/var/cache/apt/archives/*.deb "$cache/" 2>/dev/null
for f in /usr/bin/matcap-kiosk /etc/matcap-kiosk/kiosk.ini /usr/share/matcap-kiosk/kiosk.ini.example \
	/usr/lib/sysusers.d/matcap-kiosk.conf; do
	check "installed: $f" test -s "$root$f"
done
check "installed: the six matcaps" sh -c "[ \$(ls $root/usr/share/matcap-kiosk/matcaps/*.png | wc -l) = 6 ]"
check "installed: the units and the udev rules where this release looks" sh -c "
	for f in systemd/system/matcap-kiosk.service systemd/system/matcap-kiosk-import@.service \
		udev/rules.d/60-matcap-kiosk-gpio.rules udev/rules.d/61-matcap-kiosk-usb.rules; do
		ls $root/lib/\$f $root/usr/lib/\$f 2>/dev/null | grep -q . || { echo missing: \$f; exit 1; }
	done"
check "installed: the folder for drop-in settings" test -d "$root/etc/matcap-kiosk/kiosk.ini.d"
check "the installed settings check valid (--check-config: every file named loads)" in_root \
	/usr/bin/matcap-kiosk --check-config --config /etc/matcap-kiosk/kiosk.ini
check "the config is a conffile" sh -c \
	"chroot $root dpkg-query -W -f='\${Conffiles}' matcap-kiosk | grep -q /etc/matcap-kiosk/kiosk.ini"
check "the service's user and groups exist" sh -c "grep -q '^matcap-kiosk:' $root/etc/passwd &&
	grep -q '^gpio:' $root/etc/group"
check "the service is installed, not enabled" sh -c \
	"! ls $root/etc/systemd/system/*.wants/matcap-kiosk.service 2>/dev/null | grep -q ."
check "the installed program is built for $arch" sh -c \
	"[ \"\$(chroot $root dpkg-query -W -f='\${Architecture}' matcap-kiosk)\" = $arch ]"
# The test hooks (-DMK_TEST_HOOKS: MK_TEST_PREPARE_DELAY_MS) are for the
# sanitizer builds and tests/vm/systemd-test.sh's own build, never shipped.
check "the packaged program has no test hook" sh -c \
	"! grep -q MK_TEST_PREPARE_DELAY_MS $root/usr/bin/matcap-kiosk"
check "matcap-kiosk --version" sh -c "chroot $root /usr/bin/matcap-kiosk --version |
	grep -qx 'matcap-kiosk $(dpkg-deb -f "$deb" Version)'"
check "the installed program renders offscreen with the installed matcaps" in_root \
	/usr/bin/matcap-kiosk --backend osmesa --size 320x240 --output /tmp/installed.png
check "the render is a 320x240 PNG" sh -c "file $root/tmp/installed.png | grep -q '320 x 240'"
cp "$root/tmp/installed.png" "$root.png" 2>/dev/null
# Compared with amd64's drawn the way the cross tests draw theirs
# (tests/cross/run.sh): softpipe, the level of detail off. Debian's arm64
# build of meshoptimizer simplifies the model differently, and llvmpipe's
# code differs per CPU (under qemu-user on armhf it draws no matcap): the
# default render's difference is printed, not judged.
check "the installed program renders through softpipe, the level of detail off" in_root \
	env GALLIUM_DRIVER=softpipe /usr/bin/matcap-kiosk --backend osmesa --size 320x240 \
	--lod-pixels 0 --output /tmp/compare.png
cp "$root/tmp/compare.png" "$root.compare.png" 2>/dev/null
if [ -n "$ref" ]; then
	# The tolerance of the cross tests: a few pixels may round the other
	# way on another architecture's floats.
	check "the $arch render agrees with amd64's (softpipe, no LOD)" "$imgdiff" --tol 8 \
		--share 0.005 "${ref%.png}.compare.png" "$root/tmp/compare.png"
	echo "  $arch vs amd64, softpipe, no LOD: $(cat "$CHECK_LOG")"
	echo "  $arch vs amd64, default (llvmpipe, LOD; not judged): $("$imgdiff" --tol 8 \
		--share 0.005 "$ref" "$root/tmp/installed.png" 2>&1)"
fi

# Removal keeps an edited config; purge takes it.
echo "# edited" >>"$root/etc/matcap-kiosk/kiosk.ini"
check "apt-get remove" in_root apt-get remove -y -qq matcap-kiosk
check "removed: the program gone, the edited config kept" sh -c "
	[ ! -e $root/usr/bin/matcap-kiosk ] && grep -q '^# edited' $root/etc/matcap-kiosk/kiosk.ini"
check "apt-get purge" in_root apt-get purge -y -qq matcap-kiosk
check "purged: the config gone" test ! -e "$root/etc/matcap-kiosk/kiosk.ini"

# The root is a few hundred MB: kept only when something failed.
[ "$failed" -gt 0 ] || rm -rf "$root"
summary
