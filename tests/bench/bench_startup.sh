#!/bin/sh
# Start-up figures, printed and never asserted: for torus knots of about
# 10k, 100k and 1M triangles, launch to first frame (the kiosk's own
# first_frame_ms, from main to the first finished 1280x720 frame, and the
# process's wall time for three frames with --stats: one would start the
# live loop), cold (an empty prepared-mesh cache) and warm
# (the entry the cold start wrote), and peak RSS (/usr/bin/time -f %M);
# each also as a ratio to the 10k model's. The median of ROUNDS runs
# (5); all in one run, so a loaded machine weighs on every row alike.
# Environment: KIOSK, TOOLS; BASELINE: another kiosk to measure the same
# way (cold only: e.g. one built without the cache).
set -eu
out=$(pwd)/tests/out/bench-startup
rounds=${ROUNDS:-5}
models="knot-10k knot-100k knot-1m"
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null

. "$(dirname "$0")/startup_lib.sh"
# The 100k and 1M knots keep the same 35k triangles at 1280x720, the 10k
# knot its 10k: setup (startup_lib.sh) is what their starts cost beyond that.

# measure: every variant (in $variants: label:cold|warm:kiosk) and model
# takes its turn in each round, so that a change in the machine's load
# falls on all of them alike; then, per variant and model, the medians
# "wall first rss setup" in $out/med-LABEL-START-MODEL. A warm start
# finds the entry an earlier start of the same model wrote.
measure() {
	rm -f "$out"/runs-* "$out"/med-*
	for i in $(seq "$rounds"); do
		for v in $variants; do
			label=${v%%:*} rest=${v#*:}
			start=${rest%%:*} kiosk=${rest#*:}
			for model in $models; do
				cache=$out/cache-$model
				rm -rf "$cache"
				if [ "$start" = warm ]; then
					run "$kiosk" "$out/$model.glb" "$cache" >/dev/null
				fi
				run "$kiosk" "$out/$model.glb" "$cache" >>"$out/runs-$label-$start-$model"
			done
		done
	done
	for f in "$out"/runs-*; do
		medians "$f" >"$out/med-${f##*/runs-}"
	done
}

echo "## Start-up ($(uname -m), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg), median of $rounds, osmesa 1280x720, LOD at its default)"
echo
echo "| kiosk | model | start | first_frame_ms | setup ms | process wall ms | peak RSS MiB | x 10k: first frame | x 10k: setup | x 10k: RSS |"
echo "|---|---|---|---|---|---|---|---|---|---|"
report() {
	for v in $variants; do
		label=${v%%:*} rest=${v#*:}
		start=${rest%%:*}
		base=""
		for model in $models; do
			read -r wall first rss setup <"$out/med-$label-$start-$model"
			[ -n "$base" ] || base="$first $rss $setup"
			awk -v l="$label" -v m="$model" -v w="$start" -v wall="$wall" -v f="$first" \
				-v rss="$rss" -v s="$setup" -v b="$base" 'BEGIN { split(b, z, " ");
				printf "| %s | %s | %s | %.0f | %.0f | %d | %.0f | %.2f | %.2f | %.2f |\n",
					l, m, w, f, s, wall, rss / 1024, f / z[1], s / z[3], rss / z[2] }'
		done
	done
}
variants="this:cold:$KIOSK this:warm:$KIOSK"
if [ -n "${BASELINE:-}" ]; then
	variants="$variants baseline:cold:$BASELINE"
fi
measure
report
rm -rf "$out"/cache-* "$out"/runs-* "$out"/med-*
