#!/bin/sh
# The corpus: glTF files nobody on the project wrote, each with its expected
# result (tests/corpus/expected.txt), and files made here with gltfpack and
# Draco's transcoder from the models mkmodels writes. Every file goes
# through the ASan build: it shows (fitted and shaded, tests/corpus/
# silhouette.c; a made file also like its source, within a stated
# tolerance) or is refused with its one error line's words; never a
# sanitizer report. With FUZZ_GLTF, each file also runs once through that
# harness, leak checks on (the kiosk's own renders leave them to OSMesa's
# leaks). Prints "ok NAME" or "not ok NAME" per check, and the count.
#   sh tests/corpus/run.sh KIOSK TOOLS MODELS OUT
set -u
kiosk=$1
tools=$2
models=$3
out=$4
here=$(dirname "$0")
assimp=/usr/share/assimp/models
shown=0
refused=0
mkdir -p "$out/gen"

render() { # FILE PNG [OPTION]...: the status; stderr in $out/stderr
	_file=$1 _png=$2
	shift 2
	ASAN_OPTIONS=detect_leaks=0 "$kiosk" --backend osmesa --size 96x96 --lod-pixels 0 \
		--matcap matcaps/gold.png --model "$_file" --output "$_png" "$@" >"$out/stdout" \
		2>"$out/stderr"
}
clean() {
	! grep -qE 'Sanitizer|runtime error' "$out/stderr"
}
said() {
	tr '\n' ' ' <"$out/stderr" | cut -c1-400
}
# A model of several materials says so (src/scene/gltf_mesh.cc): each
# part drawn with its own. TextureTransformTest's nine materials all have
# a base map: every tile must show its own.
several() { # NAME
	line=$(grep -o '[0-9]* materials ([0-9]* with a base map shown), [0-9]* draw ranges' \
		"$out/stderr") || return 0
	echo "ok several materials: $1 shows each part with its own: $line"
	case $1 in
	*TextureTransformTest*)
		case $line in
		"9 materials (9 with a base map shown)"*) echo "ok every tile of $1 shows its texture" ;;
		*) echo "not ok every tile of $1 shows its texture: $line" ;;
		esac
		;;
	esac
}
fuzz_once() { # FILE
	[ -x "${FUZZ_GLTF:-}" ] || return 0
	FUZZ_GLTF_DIR=$(cd "$(dirname "$1")" && pwd) "$FUZZ_GLTF" "$1" >"$out/fuzz.log" 2>&1 &&
		echo "ok no sanitizer report in the loader alone: $2" ||
		echo "not ok the loader alone on $2: $(grep -m3 -E 'ERROR|SUMMARY' "$out/fuzz.log")"
}
shows() { # NAME FILE [OPTION]...
	png=$out/$(echo "$1" | tr '/: ' '___').png
	_name=$1 _file=$2
	shift 2
	render "$_file" "$png" "$@"
	status=$?
	if [ $status -eq 0 ] && clean && fig=$("$tools/silhouette" "$png"); then
		shown=$((shown + 1))
		echo "ok shows $_name ($fig)"
		several "$_name"
	else
		echo "not ok shows $_name (status $status: $(said) ${fig:-})"
	fi
	fuzz_once "$_file" "$_name"
}
refuses() { # NAME FILE WORDS
	render "$2" "$out/refused.png"
	status=$?
	lines=$(grep -c 'error' "$out/stderr")
	if [ $status -eq 1 ] && [ "$lines" -eq 1 ] && grep -qF -- "$3" "$out/stderr" && clean; then
		refused=$((refused + 1))
		echo "ok refuses $1: $3"
	else
		echo "not ok refuses $1 with \"$3\" (status $status, $lines error lines: $(said))"
	fi
	fuzz_once "$2" "$1"
}
# like NAME FILE REFERENCE.png: a made file renders like its source.
like() {
	shows "$1" "$2"
	if "$tools/imgdiff" --tol 24 --share 0.01 "$3" "$png" >"$out/diff" 2>&1; then
		echo "ok $1 renders like its source ($(cat "$out/diff"))"
	else
		echo "not ok $1 renders unlike its source ($(cat "$out/diff"))"
	fi
}

# 1. The files as they come, each with its expected result.
grep -v '^#' "$here/expected.txt" | while read -r result name words; do
	case $name in
	assimp:*) file=$assimp/${name#assimp:} ;;
	khronos:*) file=$here/khronos/${name#khronos:} ;;
	gltfast:*) file=$here/gltfast/${name#gltfast:} ;;
	blender:*) file=$here/blender/${name#blender:} ;;
	esac
	if [ ! -f "$file" ]; then
		echo "not ok $name is missing (make deps installs assimp-testmodels)"
		continue
	fi
	case $result in
	shows) shows "$name" "$file" ;;
	# Near black in its own colours: shaded with base_color = off, and
	# drawn in its colours without a fault.
	dark)
		shows "$name" "$file" --base-color off
		render "$file" "$out/dark.png"
		status=$?
		if [ $status -eq 0 ] && clean; then
			echo "ok draws $name in its own dark colours"
		else
			echo "not ok draws $name in its own colours (status $status: $(said))"
		fi
		;;
	*) refuses "$name" "$file" "$words" ;;
	esac
done >"$out/list.log"
cat "$out/list.log"
shown=$(grep -c '^ok shows' "$out/list.log")
refused=$(grep -c '^ok refuses' "$out/list.log")

# 2. What gltfpack (quantized, meshopt, both compression levels, a .gltf
#    with its .bin) and draco_transcoder make of a smooth and a flat knot,
#    a skin and a morph target; and Blender exports through
#    draco_transcoder (Debian's Blender has no Draco library of its own).
gen=$out/gen
pack() { # SOURCE OUTPUT [OPTIONS]
	src=$1 dst=$2
	shift 2
	gltfpack -i "$src" -o "$gen/$dst" "$@" >"$out/pack.log" 2>&1 ||
		echo "not ok gltfpack $dst: $(cat "$out/pack.log")"
}
draco() { # SOURCE OUTPUT
	draco_transcoder -i "$1" -o "$gen/$2" >"$out/pack.log" 2>&1 ||
		echo "not ok draco_transcoder $2: $(cat "$out/pack.log")"
}
source_png() { # NAME FILE: the reference render of a source
	render "$2" "$gen/$1.png" || echo "not ok source $1 renders: $(said)"
}
skin=$assimp/glTF2/simple_skin/simple_skin.gltf
morph=$assimp/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf
source_png knot "$models/knot.glb"
source_png knot-flat "$models/knot-flat.glb"
source_png skin "$skin"
source_png morph "$morph"
source_png blender-cube "$here/blender/cube-textured.glb"
source_png blender-tube "$here/blender/tube-skinned.glb"
pack "$models/knot.glb" knot-quantized.glb
pack "$models/knot.glb" knot-noq.glb -noq
pack "$models/knot.glb" knot-meshopt.glb -c
pack "$models/knot.glb" knot-meshopt-cc.gltf -cc
pack "$models/knot-flat.glb" knot-flat-meshopt.glb -c
pack "$skin" skin-meshopt.glb -c
pack "$morph" morph-quantized.glb
draco "$models/knot.glb" knot-draco.glb
draco "$models/knot-flat.glb" knot-flat-draco.glb
draco "$here/blender/cube-textured.glb" blender-cube-draco.glb
draco "$here/blender/tube-skinned.glb" blender-tube-draco.glb
made=0
for f in knot-quantized.glb knot-noq.glb knot-meshopt.glb knot-meshopt-cc.gltf knot-draco.glb \
	knot-flat-meshopt.glb knot-flat-draco.glb skin-meshopt.glb morph-quantized.glb \
	blender-cube-draco.glb blender-tube-draco.glb; do
	src=${f%%-[a-z]*.gl*}
	case $f in
	knot-flat-*) src=knot-flat ;;
	blender-*) src=${f%-draco.glb} ;;
	esac
	like "made:$f" "$gen/$f" "$gen/$src.png"
done >"$out/made.log"
cat "$out/made.log"
made=$(grep -c '^ok shows' "$out/made.log")
several=$(grep -c '^ok several materials' "$out/list.log" "$out/made.log" |
	awk -F: '{ n += $2 } END { print n }')
echo "ok the corpus: $((shown + made)) files shown ($made made here, $several of several" \
	"materials, each part in its own), $refused refused as expected"
