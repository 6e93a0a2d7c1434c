#!/bin/sh
# The README's quick start on one Pi, rehearsed in a fresh Debian 13 arm64
# root under qemu-user (mmdebstrap's apt variant with sudo: less than a Pi
# OS Lite has, and no package lists yet, as on a fresh image). The
# commands are read from the README's first ```sh block after "## Quick
# start" and run verbatim, in one shell, each one timed; the last step,
# `systemctl enable --now`, cannot start a service in a chroot: the
# installed program renders offscreen instead, and the render must not be
# blank. Then: the package built is arm64, the root has no foreign
# architecture and neither mmdebstrap nor qemu-user-static (a native
# build needs neither). Ends with one "N passed, N failed" line.
#
# The commands run as root: qemu-user's binfmt handler has no C flag, so
# sudo cannot gain root from a user in the chroot; as root, sudo is a
# no-op and make-deps.sh runs apt itself. Under emulation on two shared
# cores this takes long (see docs/building.md): it is not part of .ci/run.
# Needs root (mmdebstrap's root mode, chroot).
# Usage: tests/cross/pi-quickstart.sh TARBALL OUT
#   TARBALL  the source tarball (make dist); OUT gets the log and the render
# DEB_CACHE and DEB_MIRROR as in deb-build.sh; PI_SUITE (default trixie).
set -eu
if [ "$1" = --in-root ]; then
	# The customize hook: $2 is the root, the rest from the environment.
	root=$2
	cp "$PI_TARBALL" "$root/root/"
	# One shell: `cd` carries over from one command to the next.
	awk '{ q = $0; gsub(/\047/, "\047\\\047\047", q)
		print "echo \047== " q "\047; t0=$(date +%s)"; print
		print "echo \"== $(($(date +%s) - t0)) s\"" }' "$PI_COMMANDS" >"$root/root/quickstart.sh"
	rc=0
	chroot "$root" env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb \
		sh -ec 'cd /root && . ./quickstart.sh' || rc=$?
	echo "$rc" >"$PI_OUT/commands.rc"
	cp -aln "$root"/var/cache/apt/archives/*.deb "$DEB_CACHE_DIR/" 2>/dev/null || :
	[ "$rc" = 0 ] || exit 0
	echo "== matcap-kiosk --output /tmp/quickstart.png (instead of systemctl enable --now)"
	chroot "$root" env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
		matcap-kiosk --output /tmp/quickstart.png || :
	cp "$root/tmp/quickstart.png" "$PI_OUT/" 2>/dev/null || :
	chroot "$root" dpkg --print-foreign-architectures >"$PI_OUT/foreign.txt"
	# shellcheck disable=SC2016 # dpkg-query's fields, not the shell's.
	chroot "$root" dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' mmdebstrap \
		qemu-user-static 2>/dev/null | sed -n 's/^ii *//p' >"$PI_OUT/cross-tools.txt"
	# shellcheck disable=SC2016 # dpkg-query's field, not the shell's.
	chroot "$root" dpkg-query -W -f='${Architecture}' matcap-kiosk >"$PI_OUT/arch.txt" || :
	exit 0
fi

tarball=$(realpath "$1")
out=$2
suite=${PI_SUITE:-trixie}
mkdir -p "$out"
out=$(realpath "$out")
rm -f "$out"/commands.rc "$out"/quickstart.png "$out"/*.txt
cache=$(realpath -m "${DEB_CACHE:-build/deb-cache}/$suite")
mkdir -p "$cache"
commands=$out/commands.sh
awk '/^## Quick start/ { q = 1 } q && /^ *```sh/ { b = 1; next } b && /^ *```/ { exit }
	b { sub(/^ +/, ""); print }' README.md >"$commands"
[ -s "$commands" ] || { echo "pi-quickstart: README.md: no \`\`\`sh block after ## Quick start"; exit 1; }
echo "The README's commands:"
sed 's/^/  /' "$commands"
sh "$(dirname "$0")/binfmt.sh" arm64

self=$(realpath "$0")
export PI_TARBALL="$tarball" PI_OUT="$out" PI_COMMANDS="$commands" DEB_CACHE_DIR="$cache" \
	PI_SELF="$self"
t0=$(date +%s)
# shellcheck disable=SC2016 # $1 and $DEB_CACHE_DIR are the hooks', expanded there.
mmdebstrap --quiet --variant=apt --architectures=arm64 --include=sudo --skip=essential/unlink \
	--setup-hook='mkdir -p "$1/var/cache/apt/archives/partial" &&
		cp -al "$DEB_CACHE_DIR/." "$1/var/cache/apt/archives/"' \
	--customize-hook='sh "$PI_SELF" --in-root "$1"' \
	"$suite" /dev/null "deb ${DEB_MIRROR:-http://deb.debian.org/debian} $suite main" 2>&1 |
	tee "$out/log.txt"
echo "== all: $(($(date +%s) - t0)) s"

passed=0
failed=0
check() {
	if [ "$2" = 0 ]; then
		passed=$((passed + 1))
	else
		failed=$((failed + 1))
		echo "FAIL: $1"
	fi
}
rc=$(cat "$out/commands.rc" 2>/dev/null || echo missing)
check "the README's commands ran (exit $rc)" "$([ "$rc" = 0 ] && echo 0 || echo 1)"
# A blank frame has one colour; the knot in a matcap has thousands.
colours=$(convert "$out/quickstart.png" -format %k info: 2>/dev/null || echo 0)
check "the installed program's render is not blank ($colours colours)" \
	"$([ "$colours" -gt 100 ] && echo 0 || echo 1)"
check "the package is arm64 ($(cat "$out/arch.txt" 2>/dev/null))" \
	"$([ "$(cat "$out/arch.txt" 2>/dev/null)" = arm64 ] && echo 0 || echo 1)"
check "no foreign architecture in the root ($(tr '\n' ' ' 2>/dev/null <"$out/foreign.txt"))" \
	"$([ -f "$out/foreign.txt" ] && [ ! -s "$out/foreign.txt" ] && echo 0 || echo 1)"
check "neither mmdebstrap nor qemu-user-static in the root ($(tr '\n' ' ' 2>/dev/null <"$out/cross-tools.txt"))" \
	"$([ -f "$out/cross-tools.txt" ] && [ ! -s "$out/cross-tools.txt" ] && echo 0 || echo 1)"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
