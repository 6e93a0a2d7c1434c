#!/bin/sh
# The Debian package built as Debian's builders build it: in a fresh root
# of SUITE (mmdebstrap's buildd variant: essential packages and
# build-essential, nothing else) where `apt-get build-dep` installed only
# what config/debian/control declares, for this machine's architecture or,
# cross-built (dpkg-buildpackage -a, profiles cross and nocheck), for
# another: the root then holds both architectures through multiarch, the
# target's libraries included, so dpkg-shlibdeps computes ${shlibs:Depends}
# from the real ones. The host itself gets no foreign architecture.
#
# Several ARCHS share one root, built in the order given, each after its
# own `apt-get build-dep -a ARCH`: the first is built with nothing but its
# Build-Depends; a later one sees the earlier ones' packages too, but only
# those of other architectures (other triplets' libraries and .pc files,
# which its compiler and pkg-config never read) and the same
# architecture-independent ones its own build-dep would install anyway.
# One root per suite instead of one per package saves CI several minutes.
# lintian then runs in the same root (installed after the builds, so it
# cannot hide a missing Build-Depends); an error fails the build.
# Needs root (mmdebstrap's root mode, chroot).
# Usage: tests/cross/deb-build.sh SUITE "ARCHS" SRC OUT
#   SRC  the unpacked source tree (with debian/), made by `make deb-src`
#   OUT  where the .debs, the build log and lintian's output go
# DEB_CACHE (a folder, default build/deb-cache) keeps the downloaded
# packages between roots: each root is fresh, the downloads are not.
# DEB_MIRROR names the archive.
set -eu
if [ "$1" = --in-root ]; then
	# The customize hook: $2 is the root, the rest comes from the
	# environment. Each architecture builds in a copy of its own.
	root=$2
	log=$DEB_OUT/build.log
	: >"$log"
	in_root() { chroot "$root" env DEBIAN_FRONTEND=noninteractive "$@"; }
	fail() { tail -40 "$log"; echo "deb-build: $1 failed (the whole log: $log)"; exit 1; }
	cache() { cp -aln "$root"/var/cache/apt/archives/*.deb "$DEB_CACHE_DIR/" 2>/dev/null || :; }
	native=$(dpkg --print-architecture)
	for arch in $DEB_ARCHS; do
		profiles=nocheck
		[ "$arch" = "$native" ] || profiles=cross,nocheck
		dir=/build/$arch/$DEB_NAME
		mkdir -p "$root/build/$arch"
		cp -a "$DEB_SRC" "$root$dir"
		echo "== $arch: apt-get build-dep -a $arch -P $profiles" >>"$log"
		in_root apt-get build-dep -y -o APT::Install-Recommends=false -a "$arch" -P "$profiles" \
			"$dir" >>"$log" 2>&1 || fail "apt-get build-dep -a $arch"
		cache
		echo "== $arch: dpkg-buildpackage -a $arch -P $profiles" >>"$log"
		in_root sh -c "cd $dir && DEB_BUILD_OPTIONS='nocheck parallel=$(nproc)' \
			dpkg-buildpackage -a$arch -P$profiles --build=binary --no-sign" >>"$log" 2>&1 ||
			fail "dpkg-buildpackage -a $arch"
		cp "$root/build/$arch/"*.deb "$DEB_OUT/"
	done
	echo "== lintian" >>"$log"
	in_root apt-get install -y --no-install-recommends lintian >>"$log" 2>&1 ||
		fail "apt-get install lintian"
	cache
	# As nobody: lintian warns about running as root.
	for arch in $DEB_ARCHS; do
		rc=0
		chroot --userspec=65534:65534 "$root" env HOME=/tmp sh -c \
			"lintian --fail-on error /build/$arch/*_$arch.deb" >"$DEB_OUT/lintian-$arch.txt" 2>&1 ||
			rc=$?
		echo "$rc" >"$DEB_OUT/lintian-$arch.rc"
	done
	exit 0
fi

suite=$1
archs=$2
src=$(realpath "$3")
out=$4
mkdir -p "$out"
out=$(realpath "$out")
cache=$(realpath -m "${DEB_CACHE:-build/deb-cache}/$suite")
mkdir -p "$cache"
native=$(dpkg --print-architecture)
all=$native
include=
for arch in $archs; do
	[ "$arch" = "$native" ] && continue
	all=$all,$arch
	include=$include${include:+,}crossbuild-essential-$arch
done
for arch in $archs; do rm -f "$out/lintian-$arch.rc" "$out/lintian-$arch.txt"; done

# The hooks read these from the environment (mmdebstrap runs them with sh).
export DEB_SRC="$src" DEB_OUT="$out" DEB_CACHE_DIR="$cache" DEB_NAME="$(basename "$src")" \
	DEB_ARCHS="$archs" DEB_SELF="$(realpath "$0")"
# The packages downloaded into an earlier root are hard-linked in (the same
# file system), and the new ones linked back out before mmdebstrap's
# clean-up empties the root's cache.
# shellcheck disable=SC2016 # $1 and $DEB_* are the hooks', expanded there.
mmdebstrap --quiet --variant=buildd --architectures="$all" ${include:+--include="$include"} \
	--skip=essential/unlink \
	--setup-hook='mkdir -p "$1/var/cache/apt/archives/partial" &&
		cp -al "$DEB_CACHE_DIR/." "$1/var/cache/apt/archives/"' \
	--customize-hook='sh "$DEB_SELF" --in-root "$1"' \
	"$suite" /dev/null "deb ${DEB_MIRROR:-http://deb.debian.org/debian} $suite main"
status=0
for arch in $archs; do
	rc=$(cat "$out/lintian-$arch.rc")
	rm -f "$out/lintian-$arch.rc"
	echo "lintian ($suite, $arch):"
	sed 's/^/  /' "$out/lintian-$arch.txt"
	[ "$rc" = 0 ] || { echo "lintian reports an error for $arch (exit $rc)"; status=1; }
done
exit $status
