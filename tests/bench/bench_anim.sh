#!/bin/sh
# Animated models (issue 26), printed and never asserted: a posed still
# (--time) against the same model in its rest pose, cold (an empty
# prepared-mesh cache: the pose is baked, after the clip's key times are
# loaded once each for its fit) and warm (the posed mesh from the cache),
# start-up and peak RSS, median of three. Live playback (ms per frame of
# a skinned model on the GPU and CPU paths, of a morph) is not there yet.
# Models from Debian's assimp-testmodels: a skin and a morph.
# Environment: KIOSK.
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
