#!/bin/sh
# Live playback's paths, speed against error (issue 26), printed and never
# asserted, for the speed-against-error report: the 100k knot morphing
# (two targets that move positions and normals) and the 100k knot skinned
# and turned (mkmodels --bench), each frame posed and drawn at 1280x720
# through OSMesa (bench_anim_live: ms to pose and set the bones, weights or
# arrays; ms to draw) on each path, and the error of each path's maths
# against the --time still the loader bakes in double (bench_anim_error:
# the GPU's through the C mirror of its vertex shader, tests/oracle/
# anim_mirror.c). Environment: TOOLS.
set -eu
scratch=$(mktemp -d /tmp/matcap-anim-XXXXXX)
trap 'rm -rf "$scratch"' EXIT
"$TOOLS/mkmodels" "$scratch" --bench >/dev/null
echo "## Live playback's paths"
echo
echo "A model that plays its animation is posed each frame on one of three paths (docs/curator.md,"
echo "Animations): its bones and morph targets in the vertex shader (\"GPU, morphs too\"),"
echo "the bones there and the targets on the CPU where the GPU's vertex attributes do not"
echo "hold them (\"GPU, morphs on the CPU\": the arrays replaced a frame), or all on the CPU."
echo "Time: the median of 100 frames at 1280x720 through OSMesa, ms to pose and set what the"
echo "path sets, ms to draw (glFinish); llvmpipe runs the vertex shader on the CPU too, so"
echo "the GPU path's draws cost what its pose saves. Error: at 8 times of the clip against"
echo "the --time still (the bake, in double): the largest position error in the fitted"
echo "radius and in pixels of a 1080-line screen the model fills, the largest normal error in"
echo "degrees; the GPU's through the C mirror of its vertex shader in binary32 (the vertex"
echo "stage is highp), and with the morph deltas held as half floats (binary16, what"
echo "GL_OES_vertex_half_float arrays would cost: not shipped)."
echo
echo "| model | path | backend | vertices | triangles | pose ms | draw ms | still triangles | still draw ms |"
echo "|---|---|---|---|---|---|---|---|---|"
for m in knot-100k-morphing knot-100k-turning; do
	paths="gpu cpu"
	[ $m = knot-100k-morphing ] && paths="gpu cpu-morphs cpu"
	for path in $paths; do
		"$TOOLS/bench_anim_live" osmesa 1280x720 "$scratch/$m.glb" 100 "$path" ||
			echo "| $m.glb | $path | osmesa | - | - | - | - | - | did not run |"
	done
done
echo
echo "| model | path | position (radius) | position (px at 1080) | normal (degrees) |"
echo "|---|---|---|---|---|"
for m in knot-100k-morphing knot-100k-turning; do
	"$TOOLS/bench_anim_error" "$scratch/$m.glb" ||
		echo "| $m.glb | - | - | - | did not run |"
done
