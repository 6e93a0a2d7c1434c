#!/bin/sh
# The kiosk's picture against three.js's MeshMatcapMaterial for the same
# model, matcap, camera and size, drawn by headless chromium (software GL).
# A manual check, not part of `make test`: it needs chromium and the npm
# registry (three.js is installed into build/threejs/ at run time; none of
# it is kept in the tree).
#
#   tests/tools/threejs/compare.sh [WxH]
#
# Environment: CHROMIUM (default chromium), THREE_VERSION (default
# 0.187.0), MATCAP (default matcaps/pearl.png), MAPFILTER (linear or
# stored: how the page filters sRGB maps, see lib.sh). lib.sh holds what
# it shares with anim-compare.sh (the poses of animated models).
# Prints imgdiff's figures per model; exits 1 when a model has more of its
# pixels off by more than 8/255 than its row below allows (2%: a knot at
# 320x240 has 1%, its silhouette and the matcap's mipmap level at the rim).
set -eu

size=${1:-320x240}
# shellcheck source-path=SCRIPTDIR source=lib.sh
. "$(dirname "$0")/lib.sh"

build/tools/mkmodels "$www/models" >/dev/null
cp tests/corpus/blender/*.glb "$www/models/"
# Several materials: assimp-testmodels' TextureTransformTest (nine, each its
# own map and transform) and 2CylinderEngine (34), when installed.
assimp=/usr/share/assimp/models/glTF2
[ -d $assimp/textureTransform ] && cp -r $assimp/textureTransform "$www/models/"
[ -f $assimp/2CylinderEngine-glTF-Binary/2CylinderEngine.glb ] &&
	cp $assimp/2CylinderEngine-glTF-Binary/2CylinderEngine.glb "$www/models/"

# Issue 37's models as three.js reads them (for_three.py): their
# extensions listed in extensionsUsed, spec-gloss as metallic-roughness.
for model in parts-unlit parts-emissive parts-emissive-uv1 parts-specgloss; do
	python3 tests/tools/threejs/for_three.py "$www/models/$model.glb" "$www/models/three-$model.glb"
done

fail=0
# name | model | share of pixels allowed off | kiosk's extra option |
# page's extra query | page's model (the kiosk's by default). The Blender
# cube's checker, magnified, has a blue-yellow edge in every texel it
# crosses: filtered as sRGB bytes by the kiosk, in linear light by
# three.js (tests/README.md); so have the
# parts' 64-texel checker and stripes, unlit's (bare, not darkened by a
# matcap) and spec-gloss's. MAPFILTER=stored filters the page's maps as
# the kiosk does: then each of these rows is off in under 0.1% of its
# pixels.
while IFS='|' read -r name model share kopt query tmodel; do
	# shellcheck disable=SC2086 # kopt is zero or two words
	kiosk "$name" --model "$www/models/$model" $kopt || {
		fail=1
		continue
	}
	three "$name" "model=models/${tmodel:-$model}$query&zoom=${zoom:-1}$shift" || {
		fail=1
		continue
	}
	printf '%-18s ' "$name"
	build/tools/imgdiff --tol 8 --share "$share" "$out/$name-kiosk.png" "$out/$name-three.png" ||
		fail=1
done <<'EOF'
vertex-color|sphere-vertex-color.glb|0.02||
base-map|sphere-base-map.glb|0.02||
base-map-off|sphere-base-map.glb|0.02|--base-color off|&basecolor=off
knot|knot.glb|0.02||
blender-sphere|sphere-material.glb|0.02||
blender-cube|cube-textured.glb|0.25||
blender-tube|tube-skinned.glb|0.02||
blender-modifiers|cube-modifiers.glb|0.02||
blender-suzanne|suzanne-colors.glb|0.02||
parts-textures|parts-textures.glb|0.12||
parts-mask|parts-mask.glb|0.02||
parts-blend|parts-blend.glb|0.02||
parts-leaf|parts-leaf.glb|0.02||
texture-transform|textureTransform/TextureTransformTest.gltf|0.02||
engine-34|2CylinderEngine.glb|0.05||
normals-flat|cube-nonormals.glb|0.02||
unlit|parts-unlit.glb|0.12|||three-parts-unlit.glb
emissive|parts-emissive.glb|0.02|||three-parts-emissive.glb
emissive-uv1|parts-emissive-uv1.glb|0.02|||three-parts-emissive-uv1.glb
variant-default|variants.gltf|0.02||
variant-blue|variants.gltf|0.02|--variant blue|&variant=blue
specgloss|parts-specgloss.glb|0.12|||three-parts-specgloss.glb
EOF
echo "pictures in $out"
exit $fail
