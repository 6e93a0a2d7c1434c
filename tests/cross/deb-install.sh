#!/bin/sh
# The package as a user gets it: installed with apt into a fresh Debian root
# (mmdebstrap, this machine's release), where the installed program renders
# offscreen with the installed matcaps, and the config, unit, sysusers file
# and udev rule are in place; removing the package keeps the edited config,
# purging it does not. Ends with one "N passed, N failed" line. Needs root
# (the root is a chroot).
# Usage: tests/cross/deb-install.sh DEB ROOT [SUITE]
set -u
deb=$1
root=$2
suite=${3:-$(. /etc/os-release && echo "$VERSION_CODENAME")}
CHECK_LOG=$root.log
# shellcheck source=../tools/checks.sh
. "$(dirname "$0")/../tools/checks.sh"
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin "$@"; }

rm -rf "$root"
check "a fresh $suite root" mmdebstrap --quiet --variant=apt "$suite" "$root" \
	"deb http://deb.debian.org/debian $suite main"
cp "$deb" "$root/tmp/"
# OSMesa is only recommended (offscreen rendering); this test renders offscreen.
check "apt-get install ./$(basename "$deb")" in_root sh -c "apt-get update -qq &&
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq ./tmp/$(basename "$deb") libosmesa6"
for f in /usr/bin/matcap-kiosk /etc/matcap-kiosk/kiosk.ini \
	/usr/share/matcap-kiosk/matcaps/gold.png /usr/lib/sysusers.d/matcap-kiosk.conf; do
	check "installed: $f" test -s "$root$f"
done
check "installed: the unit and the udev rule where this release looks" sh -c "
	ls $root/lib/systemd/system/matcap-kiosk.service $root/usr/lib/systemd/system/matcap-kiosk.service \
		2>/dev/null | grep -q . &&
	ls $root/lib/udev/rules.d/60-matcap-kiosk-gpio.rules \
		$root/usr/lib/udev/rules.d/60-matcap-kiosk-gpio.rules 2>/dev/null | grep -q ."
check "installed: the folder for drop-in settings" test -d "$root/etc/matcap-kiosk/kiosk.ini.d"
check "the installed settings check valid (--check-config: every file named loads)" in_root \
	/usr/bin/matcap-kiosk --check-config --config /etc/matcap-kiosk/kiosk.ini
check "the config is a conffile" sh -c \
	"chroot $root dpkg-query -W -f='\${Conffiles}' matcap-kiosk | grep -q /etc/matcap-kiosk/kiosk.ini"
check "the service's user and groups exist" sh -c "grep -q '^matcap-kiosk:' $root/etc/passwd &&
	grep -q '^gpio:' $root/etc/group"
check "the service is installed, not enabled" sh -c \
	"! ls $root/etc/systemd/system/*.wants/matcap-kiosk.service 2>/dev/null | grep -q ."
check "the installed program renders offscreen with the installed matcaps" in_root \
	/usr/bin/matcap-kiosk --backend osmesa --size 320x240 --output /tmp/installed.png
check "the render is a 320x240 PNG" sh -c "file $root/tmp/installed.png | grep -q '320 x 240'"

# Removal keeps an edited config; purge takes it.
echo "# edited" >>"$root/etc/matcap-kiosk/kiosk.ini"
check "apt-get remove" in_root apt-get remove -y -qq matcap-kiosk
check "removed: the program gone, the edited config kept" sh -c "
	[ ! -e $root/usr/bin/matcap-kiosk ] && grep -q '^# edited' $root/etc/matcap-kiosk/kiosk.ini"
check "apt-get purge" in_root apt-get purge -y -qq matcap-kiosk
check "purged: the config gone" test ! -e "$root/etc/matcap-kiosk/kiosk.ini"

summary
