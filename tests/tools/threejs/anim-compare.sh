#!/bin/sh
# Poses of animated models: the kiosk's still at a clip time against
# three.js's AnimationMixer at the same time (render.js: mixer.setTime),
# same matcap, camera and size. A manual check, not part of `make test`
# (chromium, npm; see compare.sh).
#
#   tests/tools/threejs/anim-compare.sh [WxH] [SECONDS...]
#
# Default 320x240 at 0 0.5 1.0 1.7 s. Prints one row per model and time:
# the silhouettes' intersection over union and the PSNR of the pictures
# (imgdiff --iou). The kiosk draws a time with `--time T --frames 1
# --output X.png`; a kiosk without --time (before issue 26's playback) is
# compared at t=0 in its rest pose (the model as loaded, the page without
# a mixer: pose "rest") and its other times are reported as not drawn.
# FIT=pose fits the page's view to the pose drawn instead of the whole
# clip's bounds (FIT=clip, the default: the kiosk keeps an animated model
# in frame over its clip). Exits 1 when a picture could not be made. BoxAnimated has two clips
# (the inner box's turn from 1.25 s, its rise and fall): `clip=all` in the
# page plays both, for a row with the kiosk's own way to ask for all.
set -eu

size=320x240
case ${1:-} in *x*) size=$1 && shift ;; esac
times=${*:-0 0.5 1.0 1.7}
fit=${FIT:-clip}
# shellcheck source-path=SCRIPTDIR source=lib.sh
. "$(dirname "$0")/lib.sh"

khronos=tests/corpus/khronos
assimp=/usr/share/assimp/models/glTF2
cp $khronos/AnimatedTriangle.gltf $khronos/BoxAnimated.gltf $khronos/RiggedSimple.gltf "$www/models/"
[ -d $assimp/glTF-Sample-Models/AnimatedMorphCube-glTF ] &&
	cp $assimp/glTF-Sample-Models/AnimatedMorphCube-glTF/* "$www/models/"
[ -f $assimp/simple_skin/simple_skin.gltf ] && cp $assimp/simple_skin/simple_skin.gltf "$www/models/"

# Does this kiosk draw a time? Asked once, of its --help, so a kiosk that
# lacks the option is said to lack it rather than failing every row.
has_time=0
./matcap-kiosk --help 2>&1 | grep -q -- '--time' && has_time=1
[ $has_time = 1 ] ||
	echo "anim-compare.sh: this matcap-kiosk has no --time: t=0 is its rest pose against three.js's model as loaded; other times are not drawn" >&2

fail=0
printf '%-18s %6s %-5s %7s %8s  %s\n' model time pose iou psnr_db note
# name | model (under models/) | the page's clip (name, index or all;
# empty: the first, as [scene] animation = auto) | the kiosk's extra
# options (the same choice of clip, once the kiosk has one).
while IFS="|" read -r label model clip kopt; do
	if [ ! -f "$www/models/$model" ]; then
		printf '%-18s %6s %-5s %7s %8s  %s\n' "$label" - - - - "no $model (assimp-testmodels?)"
		continue
	fi
	for t in $times; do
		row=$label-t$t
		if [ $has_time = 1 ]; then
			pose=clip
			# shellcheck disable=SC2086 # kopt is zero or more words
			kiosk "$row" --model "$www/models/$model" --time "$t" --frames 1 $kopt || {
				fail=1
				continue
			}
			query="model=models/$model&t=$t&clip=$clip&fit=$fit&zoom=${zoom:-1}$shift"
		elif awk -v t="$t" 'BEGIN { exit !(t + 0 == 0) }'; then
			pose=rest
			# shellcheck disable=SC2086
			kiosk "$row" --model "$www/models/$model" $kopt || {
				fail=1
				continue
			}
			query="model=models/$model&zoom=${zoom:-1}$shift"
		else
			printf '%-18s %6s %-5s %7s %8s  %s\n' "$label" "$t" - - - "not drawn: the kiosk has no --time"
			continue
		fi
		three "$row" "$query" || {
			fail=1
			continue
		}
		figures=$(build/tools/imgdiff --iou --tol 8 --share 1 "$out/$row-kiosk.png" "$out/$row-three.png" || true)
		iou=$(echo "$figures" | sed -n 's/.* iou \([0-9.]*\).*/\1/p')
		psnr=$(echo "$figures" | sed -n 's/.*psnr_db \([0-9.inf]*\).*/\1/p')
		share=$(echo "$figures" | sed -n 's/.*share_over_tol \([0-9.]*\).*/\1/p')
		printf '%-18s %6s %-5s %7s %8s  %s\n' "$label" "$t" "$pose" "${iou:-?}" "${psnr:-?}" \
			"${share:+$share of pixels off by >8/255}"
	done
done <<'LIST'
animated-triangle|AnimatedTriangle.gltf||
box-animated|BoxAnimated.gltf||
box-animated-all|BoxAnimated.gltf|all|--animation all
rigged-simple|RiggedSimple.gltf||
morph-cube|AnimatedMorphCube.gltf||
simple-skin|simple_skin.gltf||
LIST
echo "pictures in $out"
exit $fail
