#!/bin/sh
# make test-deb: the package built in fresh roots with only its
# Build-Depends (tests/cross/deb-build.sh), for each SUITE and ARCH, then
# installed into a fresh root of its own architecture and run there
# (tests/cross/deb-install.sh), each render compared with the amd64
# package's of the same suite. Says each part's time, each package's size
# and Depends line, and ends with one "N passed, N failed" line (the
# install checks and one per build). Needs root.
# Usage: tests/cross/deb-test.sh SRC IMGDIFF "SUITES" "ARCHS" "INSTALL"
#   SUITES  e.g. "trixie bookworm"; Debian 13's packages go to build/deb/,
#           the others' to build/deb/SUITE/
#   ARCHS   e.g. "arm64 armhf", built for the first suite (and for the
#           others where DEB_OTHER_ARCHS names them); this machine's
#           architecture (amd64) is always built and installed first: its
#           render is the reference
#   INSTALL the SUITE:ARCH pairs of other architectures installed, or "all"
set -u
src=$1
imgdiff=$2
suites=$3
archs=$4
install=$5
native=$(dpkg --print-architecture)
dir=$(dirname "$0")
first=${suites%% *}
passed=0
failed=0
failures=
times=
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# part LABEL COMMAND...: run it, its output shown as it comes (its own
# "N passed, N failed" indented, so that only the total below is counted
# by .ci/run), add its checks to the total (a command without such a line
# counts as one check), say its time.
part() {
	label=$1
	shift
	t0=$(date +%s)
	{
		"$@"
		echo $? >"$tmp/rc"
	} 2>&1 | tee "$tmp/log" | sed 's/^[0-9]* passed, [0-9]* failed/  (&)/'
	rc=$(cat "$tmp/rc")
	line=$(sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed.*/\1 \2/p' "$tmp/log" | tail -1)
	if [ -n "$line" ]; then
		passed=$((passed + ${line% *}))
		failed=$((failed + ${line#* }))
	elif [ "$rc" = 0 ]; then
		passed=$((passed + 1))
	else
		failed=$((failed + 1))
	fi
	[ "$rc" = 0 ] || failures="$failures $label"
	t="$label: $(($(date +%s) - t0)) s (exit $rc)"
	echo "== $t"
	times="$times  $t
"
	return "$rc"
}

wanted() {
	[ "$install" = all ] && return 0
	for p in $install; do [ "$p" = "$1:$2" ] && return 0; done
	return 1
}

version=$(dpkg-parsechangelog -l "$src/debian/changelog" -SVersion)
for suite in $suites; do
	out=build/deb
	[ "$suite" = trixie ] || out=build/deb/$suite
	# This machine's package first: the reference render, and the one
	# built with nothing but its Build-Depends in the root. The other
	# architectures on the first suite (Debian 13, what Pi OS is); on the
	# others only where DEB_OTHER_ARCHS names them (the recipe is the same,
	# and each build costs minutes of CI).
	order=$native
	suite_archs=$archs
	[ "$suite" = "$first" ] || suite_archs=${DEB_OTHER_ARCHS-}
	for a in $suite_archs; do [ "$a" = "$native" ] || order="$order $a"; done
	part "build $suite ($order)" sh "$dir/deb-build.sh" "$suite" "$order" "$src" "$out"
	for arch in $order; do
		deb=$out/matcap-kiosk_${version}_$arch.deb
		[ -e "$deb" ] || continue
		echo "$deb: $(stat -c %s "$deb") bytes"
		echo "  Depends: $(dpkg-deb -f "$deb" Depends)"
	done
	# This machine's install first: its render is the others' reference.
	deb=$out/matcap-kiosk_${version}_$native.deb
	[ -e "$deb" ] && part "install $suite $native" sh "$dir/deb-install.sh" "$deb" \
		"build/deb-root-$suite-$native" "$suite"
	ref=build/deb-root-$suite-$native.png
	[ -e "$ref" ] || ref=
	# The other architectures' installs run side by side: each is dpkg and
	# the program under qemu-user, one emulated thread, minutes long. Each
	# keeps its output and time, shown and counted afterwards in order.
	foreign=
	for arch in $order; do
		deb=$out/matcap-kiosk_${version}_$arch.deb
		[ "$arch" != "$native" ] && [ -e "$deb" ] && wanted "$suite" "$arch" || continue
		part "binfmt $arch" sh "$dir/binfmt.sh" "$arch" || continue
		foreign="$foreign $arch"
		(
			t1=$(date +%s)
			sh "$dir/deb-install.sh" "$deb" "build/deb-root-$suite-$arch" "$suite" $ref \
				${ref:+"$imgdiff"} >"$tmp/install-$arch.log" 2>&1
			echo $? >"$tmp/install-$arch.rc"
			echo $(($(date +%s) - t1)) >"$tmp/install-$arch.s"
		) &
	done
	wait
	for arch in $foreign; do
		part "install $suite $arch (beside the others: $(cat "$tmp/install-$arch.s") s)" \
			sh -c 'cat "$1.log"; exit "$(cat "$1.rc")"' sh "$tmp/install-$arch"
	done
done

echo "== test-deb: the time of each part"
printf '%s' "$times"
[ -z "$failures" ] || echo "failed:$failures"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ -z "$failures" ]
