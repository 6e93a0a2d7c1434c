#!/bin/bash
# The tests on Debian 13 (trixie), from any Debian host: a chroot built
# from Debian's archive with debootstrap, kept in tests/trixie/cache/root
# (or $TRIXIE_ROOT) and reused, a fresh copy of this tree in it, then the
# README's commands there: apt-get install make, make deps, make deps-test,
# make test.
#
#   tests/trixie/chroot.sh [-- COMMAND...]      (as root; make test-trixie)
#
# COMMAND runs in the copy instead of the tests (e.g. -- bash for a shell).
# Knobs: TRIXIE_ROOT, DEBIAN_MIRROR, MAKE_TEST (the make arguments for the
# tests, default "test"), JOBS (make -j, default 2), TSAN=1 (the ThreadSanitizer
# group too: off here by default, it runs on the host), VM_E2E=0 (no virtual
# board), VM_E2E_SCRIPTS (the board scripts booted here: by default the
# display, the GPIO buttons and the camera, the ones whose libraries Debian 13
# changes; the rest test the kernel and our code, which the host's run
# already covers; empty: all), FUZZ_SECONDS (5 here: the host fuzzes 20 s,
# the same code), VM_SYSTEMD (0 here: the systemd board's root is made of
# Debian 12's packages, tests/vm/systemd-build.sh names them; the host's
# run boots it). The board boots Debian 12's kernel (tests/vm/build.sh makes it on
# this host, which must then be Debian 12) with Debian 13's libgpiod 2,
# libcamera 0.4 and Mesa 25 inside: the GPIO and camera tests on those.
# /proc, /sys and /dev are mounted inside only while this runs; every exit
# path unmounts them. Each step's time is printed as "trixie: STEP N s".
set -eu
set -o pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
TOP=$(cd "$HERE/../.." && pwd)
ROOT=${TRIXIE_ROOT:-$HERE/cache/root}
MIRROR=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
MAKE_TEST=${MAKE_TEST:-test}
JOBS=${JOBS:-2}
SRC=/src/matcap-kiosk

say() { printf '[trixie] %s\n' "$*" >&2; }
die() {
	printf '[trixie] error: %s\n' "$*" >&2
	exit 1
}
[ "${1:-}" != -- ] || shift
[ "$(id -u)" = 0 ] || die "debootstrap, mount and chroot need root (sudo make test-trixie)"

MOUNTS=()
unmount_all() {
	for ((i = ${#MOUNTS[@]} - 1; i >= 0; i--)); do
		umount -R "${MOUNTS[i]}" 2>/dev/null || umount -lR "${MOUNTS[i]}" || true
	done
}
trap unmount_all EXIT
trap 'exit 130' INT TERM

t0=$(date +%s)
step() {
	t1=$(date +%s)
	printf 'trixie: %s %d s\n' "$1" $((t1 - t0))
	t0=$t1
}

# ---- the root: debootstrap once, then reused
if [ ! -e "$ROOT/.complete" ]; then
	command -v debootstrap >/dev/null || {
		say "installing debootstrap on the host"
		apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
			--no-install-recommends debootstrap >/dev/null
	} || die "cannot install debootstrap"
	say "debootstrap trixie into $ROOT from $MIRROR"
	rm -rf "$ROOT"
	mkdir -p "$ROOT"
	debootstrap --variant=minbase trixie "$ROOT" "$MIRROR" >"$ROOT.log" 2>&1 ||
		die "debootstrap failed, see $ROOT.log"
	# Packages must not start services inside the chroot.
	printf '#!/bin/sh\nexit 101\n' >"$ROOT/usr/sbin/policy-rc.d"
	chmod 755 "$ROOT/usr/sbin/policy-rc.d"
	touch "$ROOT/.complete"
fi
step debootstrap
cp -L /etc/resolv.conf "$ROOT/etc/resolv.conf" 2>/dev/null || true

for m in proc sys dev; do
	mkdir -p "$ROOT/$m"
	mountpoint -q "$ROOT/$m" && die "$ROOT/$m is mounted already (another run?)"
done
mount -t proc proc "$ROOT/proc" && MOUNTS+=("$ROOT/proc")
mount --rbind /sys "$ROOT/sys" && mount --make-rslave "$ROOT/sys" && MOUNTS+=("$ROOT/sys")
mount --rbind /dev "$ROOT/dev" && mount --make-rslave "$ROOT/dev" && MOUNTS+=("$ROOT/dev")

# ---- the virtual board: Debian 12's kernel folder (built on this host by
# tests/vm/build.sh) under Debian 13's userspace; hard links, no copy.
VM_IN=/var/cache/matcap-kiosk-vm
if [ "${VM_E2E:-1}" != 0 ]; then
	host_k=$(ls -d "$TOP"/tests/vm/cache/kernel-* 2>/dev/null | head -1)
	if [ -z "$host_k" ]; then
		say "building the board's kernel folder on the host (tests/vm/build.sh)"
		"$TOP/tests/vm/build.sh" >/dev/null || die "tests/vm/build.sh failed on the host"
		host_k=$(ls -d "$TOP"/tests/vm/cache/kernel-* | head -1)
	fi
	mkdir -p "$ROOT$VM_IN"
	if [ ! -d "$ROOT$VM_IN/$(basename "$host_k")" ]; then
		rm -rf "$ROOT$VM_IN"/kernel-*
		cp -al "$host_k" "$ROOT$VM_IN/" 2>/dev/null || cp -a "$host_k" "$ROOT$VM_IN/"
	fi
fi
step board-kernel

# ---- a fresh copy of this tree (builds and caches stay on the host)
rm -rf "$ROOT$SRC"
mkdir -p "$ROOT$SRC"
tar -C "$TOP" --exclude=./.git --exclude=./build --exclude=./tests/out \
	--exclude=./tests/vm/cache --exclude=./tests/trixie/cache --exclude=./matcap-kiosk \
	-cf - . | tar -C "$ROOT$SRC" -xf -
step copy

in_root() {
	chroot "$ROOT" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
		LANG=C.UTF-8 TERM="${TERM:-dumb}" VM_CACHE=$VM_IN VM_E2E="${VM_E2E:-1}" TSAN="${TSAN:-0}" \
		VM_E2E_SCRIPTS="${VM_E2E_SCRIPTS-kms gpio-test camera}" FUZZ_SECONDS="${FUZZ_SECONDS:-5}" \
		VM_SYSTEMD="${VM_SYSTEMD:-0}" "$@"
}

if [ $# -gt 0 ]; then
	in_root sh -c "cd $SRC && exec \"\$@\"" sh "$@"
	exit
fi
# The README's first command, verbatim as a root user would type it, then
# its test command's first half.
# A CI page shows only this script's output: a failure prints its log's end.
in_root sh -c "cd $SRC && sh tests/tools/make-deps.sh && make deps-test" >"$ROOT.deps.log" 2>&1 ||
	{ tail -n 30 "$ROOT.deps.log" >&2; die "make deps failed in the chroot, see $ROOT.deps.log"; }
# The downloaded packages are installed and not read again (1.5 GB of disk).
in_root apt-get clean
step deps
in_root sh -c "cd $SRC && make -j$JOBS all test-tools" >"$ROOT.build.log" 2>&1 ||
	{ tail -n 30 "$ROOT.build.log" >&2; die "the build failed in the chroot, see $ROOT.build.log"; }
step build
rc=0
in_root sh -c "cd $SRC && make -j$JOBS $MAKE_TEST" || rc=$?
step tests
exit $rc
