#!/bin/sh
# One cross build's tests under qemu-user: the unit tests (built with
# UBSan), then the golden scenes (tests/golden/golden.sh).
#
# The scenes must agree with the host's, renderer for renderer, at the
# golden tolerance: both sides draw through OSMesa's softpipe with the level
# of detail off, so that every difference is this project's code. The two
# things left out are Debian's builds for each architecture, not this code:
# meshoptimizer's simplifier picks other (equally good) collapses on arm64,
# and llvmpipe's code differs per CPU (on armhf under qemu-arm it draws
# wrong textures). Against tests/golden/*.png, drawn by llvmpipe on amd64,
# ten scenes of every kind are drawn as the host draws them, and each
# difference is printed (NOTE), with the largest, not counted.
# Ends with one "N passed, N failed" line.
# Usage: tests/cross/run.sh ARCH BUILD SYSROOT QEMU HOST_KIOSK HOST_TOOLS
#   (set by `make test-cross`)
set -u
arch=$1
build=$2
sysroot=$3
qemu=$4
host_kiosk=$5
host_tools=$6
out=$build/out
rm -rf "$out"
mkdir -p "$out/bin" "$out/models" "$out/host-models" "$out/render" "$out/host" "$out/golden"
CHECK_LOG=$out/last.log
# shellcheck source=../tools/checks.sh
. "$(dirname "$0")/../tools/checks.sh"

# qemu-user finds the other architecture's loader and libraries in the
# sysroot (binfmt_misc is not needed, nor mounted in a container). llvmpipe
# rasterises in the calling thread: emulated threads only cost time.
# lttng-ust (through libcamera) does not wait for a session daemon.
QEMU_LD_PREFIX=$sysroot
guest_env=LP_NUM_THREADS=0,LTTNG_UST_REGISTER_TIMEOUT=0
case $arch in armhf) guest_env=$guest_env,GALLIUM_DRIVER=softpipe ;; esac
QEMU_SET_ENV=$guest_env
# The prepared-mesh cache of every program here: this run's own, never the
# user's ~/.cache (where one stage's entries were another's warm start).
XDG_CACHE_HOME=$PWD/$out/cache
export QEMU_LD_PREFIX QEMU_SET_ENV XDG_CACHE_HOME
# fontconfig's system cache: the sysroot's own, made afresh each run.
# Where the sysroot has no /var/cache/fontconfig, qemu-user opens the
# host's, and the 32-bit entries (le32d8) an earlier armhf run wrote there
# for other fonts still pass fontconfig's check, as the sysroot's folders
# keep the dates their packages gave them: the Noto CJK fallback went unseen.
rm -rf "$sysroot/var/cache/fontconfig"
mkdir -p "$sysroot/var/cache/fontconfig"
# Each program through qemu, under the name golden.sh calls it by.
wrap() { # NAME BINARY
	printf '#!/bin/sh\nexec %s %s "$@"\n' "$qemu" "$PWD/$2" >"$out/bin/$1"
	chmod +x "$out/bin/$1"
}
wrap matcap-kiosk "$build/matcap-kiosk"
wrap matcap-kiosk-ubsan "$build/ubsan/matcap-kiosk"
wrap mkmodels "$build/ubsan/tools/mkmodels"
# stitch (the wall's slices side by side) is image work alone, not what
# is tested: the host's.
ln -sf "$(cd "$host_tools" && pwd)/stitch" "$out/bin/stitch"

echo "cross $arch: $(file -b "$build/matcap-kiosk" | cut -d, -f1-2), through $qemu"

# Every program here runs single-threaded under qemu (LP_NUM_THREADS=0
# above), so the independent parts run side by side, as many at once as
# there are cores: the unit tests as a pool, each golden set as one job.
# Their results are counted afterwards, in this order.
jobs=${CROSS_JOBS:-$(nproc)}
mkdir -p "$out/unit"
check "$arch models written" "$out/bin/mkmodels" "$out/models"
check "$arch models are the host's, byte for byte" sh -c "$host_tools/mkmodels $out/host-models \
	>/dev/null && diff -r $out/models $out/host-models"
# golden_set DIR LOG TOOLS [ENV=VALUE]...: golden.sh into DIR in the
# background, its exit status in DIR.rc. golden.sh writes its models
# first: each set into a folder of its own (DIR.models), so that no set
# reads a model while another rewrites it.
# $scenes: only those scenes (empty: every one).
scenes=
golden_set() {
	dir=$1 log=$2 tools=$3
	shift 3
	(
		# shellcheck disable=SC2086 # scene names, one word each
		env "$@" TOOLS="$tools" MODELS="$dir.models" sh tests/golden/golden.sh "$dir" $scenes \
			>"$log" 2>&1
		echo $? >"$dir.rc"
	) &
}
# 2. The golden scenes, here and on the host, through softpipe with the
#    level of detail off: the same models, and at most 0.5% of the pixels
#    off by more than 8/255.
golden_set "$out/render" "$out/render.log" "$out/bin" QEMU_SET_ENV=$guest_env,GALLIUM_DRIVER=softpipe \
	KIOSK="$out/bin/matcap-kiosk --lod-pixels 0"
golden_set "$out/host" "$out/host.log" "$host_tools" GALLIUM_DRIVER=softpipe KIOSK="$host_kiosk --lod-pixels 0"
# 3. Against tests/golden, drawn as the host's tests draw them (the level
#    of detail on; on armhf through softpipe, set in guest_env): printed,
#    not judged (Debian's simplifier and llvmpipe differ per CPU), so a
#    scene of each kind rather than all (llvmpipe compiles every program
#    under emulation: minutes of CI).
driver=llvmpipe
[ "$arch" = armhf ] && driver=softpipe
golden=$out/golden
scenes="knot-normal knot-sem-fragment sphere-lit-beside parts-textures parts-emissive-uv1"
scenes="$scenes caption-latin normals-flat variant-blue morph-t1 skin-t1"
golden_set "$golden" "$out/golden.log" "$out/bin" KIOSK="$out/bin/matcap-kiosk"
shown=$scenes
scenes=
# 1. Unit tests (cmocka), with UBSan: the pool, each test's output and exit
#    status kept under out/unit.
ls "$build"/ubsan/tests/test_* | xargs -P "$jobs" -I{} sh -c \
	'n=$(basename "$1"); "$2" "$1" >"$3/$n.log" 2>&1; echo $? >"$3/$n.rc"' sh {} "$qemu" "$out/unit"
wait
for t in "$build"/ubsan/tests/test_*; do
	n=$(basename "$t")
	check "$arch unit $n" sh -c "cat '$out/unit/$n.log'; exit \$(cat '$out/unit/$n.rc' 2>/dev/null || echo 1)"
done
check "$arch golden scenes rendered (softpipe, no LOD)" sh -c "cat $out/render.log; exit \$(cat $out/render.rc)"
check "host golden scenes rendered (softpipe, no LOD)" sh -c "cat $out/host.log; exit \$(cat $out/host.rc)"
for g in tests/golden/*.png; do
	name=$(basename "$g")
	check "$arch $name agrees with the host" "$host_tools/imgdiff" --tol 8 --share 0.005 \
		"$out/host/$name" "$out/render/$name"
done
check "$arch golden scenes rendered ($driver)" sh -c "cat $golden.log; exit \$(cat $golden.rc)"
worst=-1
for n in $shown; do
	name=$n.png
	g=tests/golden/$name
	d=$("$host_tools/imgdiff" --tol 8 --share 0.005 "$g" "$golden/$name")
	echo "NOTE $arch $name against tests/golden: $d"
	m=$(echo "$d" | sed -n 's/^max_diff \([0-9]*\) .*/\1/p')
	if [ -n "$m" ] && [ "$m" -gt "$worst" ]; then
		worst=$m
		worst_name="$name: $d"
	fi
done

# 4. The UBSan program on every material feature at once.
check "$arch UBSan program renders the material features" "$out/bin/matcap-kiosk-ubsan" -q \
	--backend osmesa --size 320x240 -c matcaps/chrome-studio.png \
	--model "$out/models/sphere-coarse.glb" --displacement-map "$out/models/height.png" \
	--displacement-scale 0.15 --detail-map "$out/models/detail.png" --lit beside \
	--output "$out/render/ubsan-lit-beside.png"

echo "NOTE largest difference on $arch against tests/golden ($driver): $worst_name"
summary
