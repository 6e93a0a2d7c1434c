#!/bin/sh
# Several materials, printed and never asserted: median and p90 ms per
# 1280x720 frame (glFinish after each), time to the first finished frame
# and peak RSS for a knot of about 100k triangles of one material, the same
# knot in 64 bands of a material each (every eighth with a base map:
# tests/tools/parts_models.c), and assimp-testmodels' 2CylinderEngine (34
# materials, when installed). KIOSK2: a second binary (e.g. the one before
# a change) measured on the same models, row by row.
# Environment: KIOSK, TOOLS; FRAMES (default 100).
set -eu
out=tests/out/bench-parts
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
frames=${FRAMES:-100}
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb

now_ms() { date +%s%N | cut -c1-13; }

row() { # KIOSK BACKEND NAME MODEL
	r_kiosk=$1 r_backend=$2 r_name=$3 r_model=$4
	stats=$($r_kiosk -q -b "$r_backend" --size 1280x720 --frames "$frames" --stats \
		--model "$r_model")
	t0=$(now_ms)
	$r_kiosk -q -b "$r_backend" --size 1280x720 --frames 1 --model "$r_model" \
		--output "$out/first.png"
	t1=$(now_ms)
	set -- $stats
	printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$r_backend" "$r_name" "$r_kiosk" "$4" \
		"$6" $((t1 - t0)) $((${10} / 1024))
}

echo "## several materials ($(uname -m), $(nproc) cores, $frames frames at 1280x720)"
echo
echo "| backend | model | binary | median ms/frame | p90 ms | first frame ms | peak RSS MiB |"
echo "|---|---|---|---|---|---|---|"
for backend in osmesa egl-headless; do
	for model in knot-100k knot-64-materials engine; do
		file=$out/$model.glb
		[ $model = engine ] && file=$engine
		[ -f "$file" ] || continue
		for k in $KIOSK ${KIOSK2:-}; do
			row "$k" $backend $model "$file"
		done
	done
done
