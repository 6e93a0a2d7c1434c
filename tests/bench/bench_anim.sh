#!/bin/sh
# Animated models (issue 26), printed and never asserted: a posed still
# (--time) against the same model in its rest pose, cold (an empty
# prepared-mesh cache: the pose is baked, after the clip's key times are
# loaded once each for its fit) and warm (the posed mesh from the cache),
# start-up and peak RSS, median of three. Then live playback a frame
# (bench_anim_live): the 100k knot skinned and turned by an animation
# and the 100k knot morphing (two targets with normals, mkmodels),
# RiggedSimple's skin and AnimatedMorphCube's morph, skinned and morphed
# on the GPU (the bones and weights a frame), morphed on the CPU and
# skinned on the GPU (the arrays a frame), and posed on the CPU, drawn,
# against the same model's still. What each path costs in error:
# bench_anim_paths.sh, in the speed-against-error report. Last, the live
# kiosk's start-up and memory with the model playing against the same
# file still.
# Models from Debian's assimp-testmodels: a skin and a morph.
# Environment: KIOSK, TOOLS.
set -eu
out=$(pwd)/tests/out/bench-anim
mkdir -p "$out"
# shellcheck source-path=SCRIPTDIR source=startup_lib.sh
. "$(dirname "$0")/startup_lib.sh"
a=/usr/share/assimp/models/glTF2
echo "## posed stills against the rest pose ($(uname -m), $(nproc) cores, 1280x720 offscreen)"
echo
echo "| model | pose | cache | wall ms | first frame ms | peak RSS KiB |"
echo "|---|---|---|---|---|---|"
for m in simple_skin/simple_skin.gltf \
	glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf; do
	[ -f "$a/$m" ] || {
		echo "| $(basename "$m") | - | - | - | - | not installed (assimp-testmodels) |"
		continue
	}
	for pose in rest 1.5; do
		opt=
		[ $pose = rest ] || opt="--time $pose"
		for cache in cold warm; do
			: >"$out/runs"
			for _ in 1 2 3; do
				[ $cache = cold ] && rm -rf "$out/cache"
				# shellcheck disable=SC2086 # opt is zero or two words
				run "$KIOSK" "$a/$m" "$out/cache" $opt >>"$out/runs"
			done
			# shellcheck disable=SC2046 # four numbers, one word each
			set -- $(medians "$out/runs")
			echo "| $(basename "$m") | $pose | $cache | $1 | $2 | $3 |"
		done
	done
done

echo
echo "## live playback a frame ($(uname -m), $(nproc) cores, median of 100)"
echo
echo "The still keeps its level of detail ([scene] lod_pixels); a model that plays has none."
echo
echo "| model | path | backend | vertices | triangles | pose ms | draw ms | still triangles | still draw ms |"
echo "|---|---|---|---|---|---|---|---|---|"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
cube="$a/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"
for m in "$out/knot-100k-turning.glb" "$out/knot-100k-morphing.glb" \
	tests/corpus/khronos/RiggedSimple.gltf "$cube"; do
	[ -f "$m" ] || continue
	paths="gpu cpu"
	case $m in *morph* | *Morph*) paths="gpu cpu-morphs cpu" ;; esac
	for backend in osmesa egl-headless; do
		for path in $paths; do
			"$TOOLS/bench_anim_live" $backend 1280x720 "$m" 100 "$path" ||
				echo "| $(basename "$m") | $path | $backend | - | - | - | - | - | did not run |"
		done
	done
done

# The live kiosk started on a model that plays against the same file shown
# still (--animation off: its rest pose, with the prepared-mesh cache and
# the level of detail a still has): launch to "ready: the first frame" in
# the journal, then after 3 s of playing (30 fps) the process's peak and
# current RSS (/proc/PID/status). Cold: an empty cache; warm: the entry
# the cold start wrote (a model that plays: its mesh and playback data).
echo
echo "## start-up and memory, playing against still ($(uname -m), $(nproc) cores, osmesa 1280x720, median of 3)"
echo
echo "| model | animation | cache | launch to first frame ms | peak RSS KiB | RSS after 3 s KiB |"
echo "|---|---|---|---|---|---|"
# live_run MODEL ANIMATION CACHE: "ready_ms hwm_kib rss_kib" of one start.
live_run() {
	: >"$out/live.err"
	t0=$(now_ns)
	XDG_CACHE_HOME=$3 "$KIOSK" -b osmesa --size 1280x720 --model "$1" --animation "$2" \
		--animation-fps 30 --attract-after 0 -v 2>"$out/live.err" &
	pid=$!
	i=0
	while ! grep -q "ready: the first frame" "$out/live.err" && [ $i -lt 3000 ]; do
		i=$((i + 1))
		sleep 0.01
	done
	t1=$(now_ns)
	sleep 3
	hwm=$(sed -n 's/^VmHWM:[[:space:]]*\([0-9]*\).*/\1/p' /proc/$pid/status)
	rss=$(sed -n 's/^VmRSS:[[:space:]]*\([0-9]*\).*/\1/p' /proc/$pid/status)
	kill -TERM $pid
	wait $pid || true
	echo "$(((t1 - t0) / 1000000)) $hwm $rss"
}
for m in "$out/knot-100k-turning.glb" tests/corpus/khronos/RiggedSimple.gltf \
	"$a/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"; do
	[ -f "$m" ] || continue
	for anim in off auto; do
		for cache in cold warm; do
			: >"$out/runs"
			for _ in 1 2 3; do
				[ $cache = cold ] && rm -rf "$out/cache"
				[ $cache = warm ] && [ ! -d "$out/cache" ] &&
					live_run "$m" $anim "$out/cache" >/dev/null
				live_run "$m" $anim "$out/cache" >>"$out/runs"
			done
			echo "| $(basename "$m") | $anim | $cache |" \
				"$(cut -d' ' -f1 "$out/runs" | median) |" \
				"$(cut -d' ' -f2 "$out/runs" | median) |" \
				"$(cut -d' ' -f3 "$out/runs" | median) |"
		done
	done
done
