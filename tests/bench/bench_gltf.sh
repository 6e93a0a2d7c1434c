#!/bin/sh
# glTF figures, printed and never asserted:
#  - start-up of the 100k triangle knot in the forms users bring: as
#    written (floats), skinned (posed on the CPU at load), quantized
#    (gltfpack), meshopt-compressed (gltfpack -c), Draco-compressed
#    (draco_transcoder), and textured (2048 px base colour, normal and
#    occlusion maps in its buffer) with every map sampled, with the base
#    colour only (detail off), and with none (detail and base colour off):
#    launch to first frame (the kiosk's own first_frame_ms, and the
#    process's wall time), peak RSS (/usr/bin/time -f %M), cold (an empty
#    prepared-mesh cache) and warm, the median of ROUNDS runs (5), every
#    form taking its turn in each round; beside them the images the
#    loader decoded (its debug line);
#  - the level of detail on models with seams: the knot flat-shaded
#    (every edge a seam in normals) and, where Debian's assimp-testmodels
#    is installed, a real CAD model with hard edges: triangles before and
#    after, the count wanted and the error measured, at lod_pixels 1, 2,
#    4 and 8.
# Environment: KIOSK, TOOLS; ROUNDS; BASELINE: another kiosk (an older
# commit's) measured cold on the textured model with its defaults.
set -eu
out=$(pwd)/tests/out/bench-gltf
rounds=${ROUNDS:-5}
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
. "$(dirname "$0")/startup_lib.sh"
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
knot=$out/knot-100k

# The forms, one a line: LABEL KIOSK FILE [OPTION]...
forms="plain $KIOSK $knot.glb
skinned $KIOSK $knot-skinned.glb"
if command -v gltfpack >/dev/null; then
	gltfpack -i "$knot.glb" -o "$knot-quantized.glb" >/dev/null
	gltfpack -i "$knot.glb" -o "$knot-meshopt.glb" -c >/dev/null
	forms="$forms
quantized $KIOSK $knot-quantized.glb
meshopt $KIOSK $knot-meshopt.glb"
fi
if command -v draco_transcoder >/dev/null; then
	draco_transcoder -i "$knot.glb" -o "$knot-draco.glb" >/dev/null 2>&1
	forms="$forms
draco $KIOSK $knot-draco.glb"
fi
forms="$forms
textured $KIOSK $knot-textured.glb
textured-base-only $KIOSK $knot-textured.glb --detail off
textured-unsampled $KIOSK $knot-textured.glb --detail off --base-color off"
if [ -n "${BASELINE:-}" ]; then
	forms="$forms
textured-baseline $BASELINE $knot-textured.glb"
fi

# decoded KIOSK FILE [OPTION]...: the images the loader decoded, from
# its debug line: none for a model without a material, "-" for a kiosk
# that has no such line.
decoded() {
	_kiosk=$1 _file=$2
	shift 2
	rm -rf "$out/cache-count"
	n=$(XDG_CACHE_HOME=$out/cache-count "$_kiosk" -b osmesa --size 1280x720 --frames 3 \
		--log-level debug --model "$_file" "$@" </dev/null 2>&1 | sed -n 's/.* \([0-9]*\) images decoded$/\1/p')
	if [ -z "$n" ]; then
		grep -q "images decoded" "$_kiosk" && n=0 || n=-
	fi
	echo "$n"
}

rm -f "$out"/runs-*
for i in $(seq "$rounds"); do
	for start in cold warm; do
		echo "$forms" | while read -r label kiosk file opts; do
			[ "$start" = cold ] || [ "$kiosk" = "$KIOSK" ] || continue
			cache=$out/cache-$label
			rm -rf "$cache"
			# shellcheck disable=SC2086 # the options are words
			if [ "$start" = warm ]; then
				run "$kiosk" "$file" "$cache" $opts </dev/null >/dev/null
			fi
			# shellcheck disable=SC2086
			run "$kiosk" "$file" "$cache" $opts </dev/null >>"$out/runs-$label-$start"
		done
	done
done

echo "## glTF forms of a 100k triangle knot ($(uname -m), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg), median of $rounds, osmesa 1280x720, LOD at its default)"
echo
echo "| form | options | file MB | images decoded | start | first_frame_ms | setup ms | process wall ms | peak RSS MiB |"
echo "|---|---|---|---|---|---|---|---|---|"
echo "$forms" | while read -r label kiosk file opts; do
	# shellcheck disable=SC2086
	n=$(decoded "$kiosk" "$file" $opts)
	mb=$(stat -c %s "$file" | awk '{ printf "%.2f", $1 / 1048576 }')
	for start in cold warm; do
		[ -f "$out/runs-$label-$start" ] || continue
		medians "$out/runs-$label-$start" | {
			read -r wall first rss setup
			awk -v l="$label" -v o="${opts:--}" -v mb="$mb" -v n="$n" -v s="$start" \
				-v w="$wall" -v f="$first" -v r="$rss" -v su="$setup" 'BEGIN {
				printf "| %s | %s | %s | %s | %s | %.0f | %.0f | %d | %.0f |\n",
					l, o, mb, n, s, f, su, w, r / 1024 }'
		}
	done
done

# lod FILE PIXELS: "before after wanted error" from the kiosk's lod line
# (the after equal to the before, no error, where nothing was simplified).
lod() {
	rm -rf "$out/cache-lod"
	XDG_CACHE_HOME=$out/cache-lod "$KIOSK" -b osmesa --size 1280x720 --frames 3 \
		--log-level debug --lod-pixels "$2" --model "$1" 2>&1 |
		sed -n -e 's/.*lod: \([0-9]*\) -> \([0-9]*\) triangles for .* (\([0-9]*\) of .* error \([0-9.]*\) px).*/\1 \2 \3 \4/p' \
			-e 's/.*lod: \([0-9]*\) triangles kept for .* (\([0-9]*\) of .*/\1 \1 \2 -/p'
}
echo
echo "## Level of detail on seamed models (1280x720)"
echo
echo "| model | lod_pixels | triangles before | after | wanted | error px |"
echo "|---|---|---|---|---|---|"
for model in "$knot-flat.glb" "$engine"; do
	[ -f "$model" ] || continue
	for px in 1 2 4 8; do
		lod "$model" "$px" | {
			read -r before after wanted err
			echo "| ${model##*/} | $px | $before | $after | $wanted | $err |"
		}
	done
done
rm -rf "$out"/cache-* "$out"/runs-*
