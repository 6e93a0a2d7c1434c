#!/bin/sh
# Start-up figures, printed and never asserted: for torus knots of about
# 10k, 100k and 1M triangles, launch to first frame (the kiosk's own
# first_frame_ms, from main to the first finished 1280x720 frame, and the
# process's wall time for two frames with --stats: one would start the
# live loop), cold (an empty prepared-mesh cache) and warm
# (the entry the cold start wrote), and peak RSS (/usr/bin/time -f %M);
# each also as a ratio to the 10k model's. The median of ROUNDS runs
# (3); all in one run, so a loaded machine weighs on every row alike.
# Environment: KIOSK, TOOLS; BASELINE: another kiosk to measure the same
# way (cold only: e.g. one built without the cache).
set -eu
out=$(pwd)/tests/out/bench-startup
rounds=${ROUNDS:-3}
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null

now_ns() { date +%s%N; }

median() { tr ' ' '\n' | sed '/^$/d' | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# run KIOSK MODEL CACHE: "wall_ms first_ms rss_kib" of one start.
run() {
	t0=$(now_ns)
	stats=$(XDG_CACHE_HOME=$3 /usr/bin/time -f "rss %M" "$1" -q -b osmesa --size 1280x720 \
		--frames 2 --stats --model "$2" 2>&1)
	t1=$(now_ns)
	first=$(echo "$stats" | sed -n 's/.*first_frame_ms \([0-9.]*\).*/\1/p')
	rss=$(echo "$stats" | sed -n 's/^rss //p')
	echo "$(((t1 - t0) / 1000000)) $first $rss"
}

# measure KIOSK MODEL cold|warm: the medians, "wall first rss". A warm
# start finds the entry an earlier start of the same model wrote.
measure() {
	walls="" firsts="" rsss=""
	for i in $(seq "$rounds"); do
		cache=$out/cache-$i
		rm -rf "$cache"
		if [ "$3" = warm ]; then
			run "$1" "$2" "$cache" >/dev/null
		fi
		r=$(run "$1" "$2" "$cache")
		walls="$walls ${r%% *}"
		r=${r#* }
		firsts="$firsts ${r%% *}"
		rsss="$rsss ${r#* }"
	done
	echo "$(echo "$walls" | median) $(echo "$firsts" | median) $(echo "$rsss" | median)"
}

echo "## Start-up ($(uname -m), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg), median of $rounds, osmesa 1280x720, LOD at its default)"
echo
echo "| kiosk | model | start | first_frame_ms | process wall ms | peak RSS MiB | x 10k: first frame | x 10k: RSS |"
echo "|---|---|---|---|---|---|---|---|"
report() {
	label=$1 warm=$2 kiosk=$3
	base=""
	for model in knot-10k knot-100k knot-1m; do
		set -- $(measure "$kiosk" "$out/$model.glb" "$warm")
		[ -n "$base" ] || base="$2 $3"
		awk -v l="$label" -v m="$model" -v w="$warm" -v wall="$1" -v f="$2" -v rss="$3" \
			-v b="$base" 'BEGIN { split(b, z, " ");
			printf "| %s | %s | %s | %.0f | %d | %.0f | %.2f | %.2f |\n", l, m, w, f, wall,
				rss / 1024, f / z[1], rss / z[2] }'
	done
}
report this cold "$KIOSK"
report this warm "$KIOSK"
if [ -n "${BASELINE:-}" ]; then
	report baseline cold "$BASELINE"
fi
rm -rf "$out"/cache-*
