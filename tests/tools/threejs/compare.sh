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
# 0.187.0), MATCAP (default matcaps/pearl.png).
# Prints imgdiff's figures per model; exits 1 when a model has more of its
# pixels off by more than 8/255 than its row below allows (2%: a knot at
# 320x240 has 1%, its silhouette and the matcap's mipmap level at the rim).
set -eu

cd "$(dirname "$0")/../../.."
size=${1:-320x240}
w=${size%x*}
h=${size#*x}
chromium=${CHROMIUM:-chromium}
version=${THREE_VERSION:-0.187.0}
matcap=${MATCAP:-matcaps/pearl.png}
top=$PWD
work=$top/build/threejs
www=$work/www
out=$work/out

for tool in "$chromium" npm python3; do
	command -v "$tool" >/dev/null || {
		echo "compare.sh: needs $tool (apt-get install chromium npm python3)" >&2
		exit 2
	}
done
make -s -j2 matcap-kiosk build/tools/mkmodels build/tools/imgdiff

mkdir -p "$work/npm" "$out"
if [ ! -f "$work/npm/node_modules/three/package.json" ] ||
	! grep -q "\"version\": \"$version\"" "$work/npm/node_modules/three/package.json"; then
	npm install --prefix "$work/npm" --no-audit --no-fund --silent "three@$version"
fi

# The page, three.js, the models and the matcap under one folder served
# over HTTP: module scripts do not load from file:// URLs.
rm -rf "$www"
mkdir -p "$www/models"
build/tools/mkmodels "$www/models" >/dev/null
ln -s "$top/tests/tools/threejs/index.html" "$top/tests/tools/threejs/render.js" "$www/"
ln -s "$work/npm/node_modules" "$www/node_modules"
cp "$matcap" "$www/matcap.png"
cp tests/corpus/blender/*.glb "$www/models/"
# Several materials: assimp-testmodels' TextureTransformTest (nine, each its
# own map and transform) and 2CylinderEngine (34), when installed.
assimp=/usr/share/assimp/models/glTF2
[ -d $assimp/textureTransform ] && cp -r $assimp/textureTransform "$www/models/"
[ -f $assimp/2CylinderEngine-glTF-Binary/2CylinderEngine.glb ] &&
	cp $assimp/2CylinderEngine-glTF-Binary/2CylinderEngine.glb "$www/models/"

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server --bind 127.0.0.1 --directory "$www" "$port" >"$out/http.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT INT TERM
python3 - "$port" <<'EOF'
import sys, time, urllib.request
for _ in range(50):
    try:
        urllib.request.urlopen("http://127.0.0.1:%s/index.html" % sys.argv[1]); break
    except OSError:
        time.sleep(0.1)
EOF

# three NAME QUERY: the page's picture, read back from the text it leaves
# in its <pre> (the canvas's own bytes, not a screenshot through the
# compositor).
three() {
	"$chromium" --headless=new --no-sandbox --user-data-dir="$work/profile" \
		--use-angle=swiftshader --enable-unsafe-swiftshader --virtual-time-budget=20000 \
		--dump-dom "http://127.0.0.1:$port/index.html?matcap=matcap.png&w=$w&h=$h&$2" \
		2>"$out/$1.chromium.log" >"$out/$1.html"
	sed -n 's/.*<pre id="out">data:image\/png;base64,\([^<]*\)<.*/\1/p' "$out/$1.html" |
		base64 -d >"$out/$1-three.png"
	if [ ! -s "$out/$1-three.png" ]; then
		echo "compare.sh: $1: no picture from chromium: $(grep -o '<pre id="out">[^<]*' "$out/$1.html")" >&2
		return 1
	fi
}

# kiosk NAME ARGS: the kiosk's picture at the resting view, every triangle
# drawn (three.js draws the whole mesh); zoom: the scale [scene] fit chose
# for it (src/render/framing.c), which the page's camera takes as its zoom.
kiosk() {
	name=$1
	shift
	./matcap-kiosk -v -b osmesa --size "$size" -c "$matcap" --lod-pixels 0 \
		--output "$out/$name-kiosk.png" "$@" 2>"$out/$name-kiosk.log"
	zoom=$(sed -n 's/.*framing: zoom \([0-9.]*\).*/\1/p' "$out/$name-kiosk.log")
}

fail=0
# name | model | share of pixels allowed off | kiosk's extra option |
# page's extra query. The Blender cube's checker, magnified, has a
# blue-yellow edge in every texel it crosses: filtered as sRGB bytes by
# the kiosk, in linear light by three.js (tests/README.md); so have the
# parts' 64-texel checker and stripes.
while IFS='|' read -r name model share kopt query; do
	# shellcheck disable=SC2086 # kopt is zero or two words
	kiosk "$name" --model "$www/models/$model" $kopt
	three "$name" "model=models/$model$query&zoom=${zoom:-1}" || {
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
EOF
echo "pictures in $out"
exit $fail
