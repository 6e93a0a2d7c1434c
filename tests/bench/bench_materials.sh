#!/bin/sh
# The material features' cost, printed and never asserted: median and p90
# ms per 1280x720 frame (glFinish after each) with each feature off and
# on, and the time to the first finished frame (which holds the load-time
# work: texture packing, tangents, subdivision and displacement).
# Environment: KIOSK, TOOLS; FRAMES (default 50).
set -eu
out=tests/out/bench-materials
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
frames=${FRAMES:-50}
size=1280x720
knot="$out/knot-100k.glb"
coarse="$out/sphere-coarse.glb"
detail="--detail-map $out/detail.png"
irid="--iridescence on"
ramp="--iridescence-ramp $out/ramp.png"
disp="--displacement-map $out/height.png --displacement-scale 0.15"

now_ms() { date +%s%N | cut -c1-13; }

# row BACKEND NAME MODEL [OPTION...]: one line of the table.
row() {
	backend=$1 name=$2 model=$3
	shift 3
	args="$*"
	log=$($KIOSK -b "$backend" --size $size --frames "$frames" --stats --model "$model" \
		$args 2>&1)
	tris=$(echo "$log" | sed -n 's/.* \([0-9]*\) triangles$/\1/p' | tail -1)
	t0=$(now_ms)
	$KIOSK -q -b "$backend" --size $size --model "$model" --output "$out/first.png" $args
	t1=$(now_ms)
	set -- $(echo "$log" | grep '^frames ')
	printf '| %s | %s | %s | %s | %s | %s |\n' "$backend" "$name" "$tris" "$4" "$6" $((t1 - t0))
}

echo "## material features ($(uname -m), $(nproc) cores, $frames frames at $size)"
echo
echo "| backend | scene | triangles | median ms/frame | p90 ms | process start to first frame ms |"
echo "|---|---|---|---|---|---|"
for backend in osmesa egl-headless; do
	row $backend "knot, matcap only (every feature off)" "$knot"
	for pair in "iridescence|$irid" "iridescence, ramp|$irid $ramp" "detail map|$detail" \
		"detail map + iridescence|$detail $irid" "lit|--lit on" \
		"lit, detail map|--lit on $detail" "lit beside the matcap|--lit beside" \
		"everything|$detail $irid $ramp --lit beside"; do
		row $backend "knot + ${pair%%|*}" "$knot" ${pair#*|}
	done
	row $backend "coarse sphere, matcap only" "$coarse"
	row $backend "coarse sphere + displacement" "$coarse" $disp
	row $backend "coarse sphere + displacement + detail map" "$coarse" $disp $detail
done
