#!/bin/sh
# The golden scenes, rendered through OSMesa into DIR: every mode on the
# built-in torus knot and on a sphere. Used by `make golden` (into
# tests/golden) and by tests/run.sh (into a scratch folder, then compared).
set -eu
out=$1
models=${MODELS:-tests/out/models}
mkdir -p "$out" "$models"
"$TOOLS/mkmodels" "$models" >/dev/null
for mode in normal view sem-vertex sem-fragment; do
	$KIOSK -q --backend osmesa --size 320x240 --matcap matcaps/gold.png --mode $mode \
		--output "$out/knot-$mode.png"
	$KIOSK -q --backend osmesa --size 320x240 --matcap matcaps/gold.png --mode $mode \
		--model "$models/sphere.glb" --output "$out/sphere-$mode.png"
done
