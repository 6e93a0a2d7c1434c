#!/bin/sh
# The golden scenes, rendered through OSMesa into DIR: every mode on the
# built-in torus knot and on a sphere. Used by `make golden` (into
# tests/golden) and by tests/run.sh (into a scratch folder, then compared).
set -eu
# The offscreen backend: osmesa, or egl-headless where Mesa has no OSMesa
# (the Makefile sets OFFSCREEN_BACKEND from what the build has).
offscreen=${OFFSCREEN_BACKEND:-osmesa}
out=$1
models=${MODELS:-tests/out/models}
mkdir -p "$out" "$models"
"$TOOLS/mkmodels" "$models" >/dev/null
for mode in normal view sem-vertex sem-fragment; do
	$KIOSK -q --backend $offscreen --size 320x240 --matcap matcaps/gold.png --mode $mode \
		--output "$out/knot-$mode.png"
	$KIOSK -q --backend $offscreen --size 320x240 --matcap matcaps/gold.png --mode $mode \
		--model "$models/sphere.glb" --output "$out/sphere-$mode.png"
done
# The material features (issue 6), each on a model that exercises it:
# glTF textures (embedded; beside the model with TANGENT and
# KHR_materials_iridescence), the settings' maps, displacement, lit.
k="$KIOSK -q --backend $offscreen --size 320x240"
m=$models
$k -c matcaps/black-shiny.png --iridescence on --output "$out/knot-iridescence.png"
$k -c matcaps/black-shiny.png --iridescence on --iridescence-ramp "$m/ramp.png" \
	--output "$out/knot-iridescence-ramp.png"
$k -c matcaps/pearl.png --detail-map "$m/detail.png" --iridescence on \
	--output "$out/knot-detail-map.png"
$k -c matcaps/gold.png --model "$m/sphere-detail.glb" --output "$out/sphere-detail-gltf.png"
$k -c matcaps/black-shiny.png --model "$m/sphere-beetle.gltf" --output "$out/sphere-beetle-gltf.png"
$k -c matcaps/gold.png --model "$m/sphere-coarse.glb" --displacement-map "$m/height.png" \
	--displacement-scale 0.15 --output "$out/sphere-displaced.png"
$k --model "$m/sphere-detail.glb" --lit on --output "$out/sphere-lit.png"
$k -c matcaps/chrome-studio.png --model "$m/sphere-coarse.glb" --displacement-map "$m/height.png" \
	--displacement-scale 0.15 --detail-map "$m/detail.png" --lit beside \
	--output "$out/sphere-lit-beside.png"
