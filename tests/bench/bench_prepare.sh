#!/bin/sh
# Preparation figures (issue 34), printed and never asserted: for the
# 10k, 100k and 1M bench knots, the first frame cold (an empty
# prepared-mesh cache) and warm (the entry the cold start wrote), still
# (--output: the process's wall time to the one frame written) and live
# (the kiosk's own first_frame_ms, --frames 3 --stats: the live loop), on
# one thread and on all ([kiosk] prepare_threads = auto: a thread a core),
# with the peak RSS of each start; the median of ROUNDS (3), every
# variant taking its turn in each round so that the machine's load falls
# on all alike. Then the ratios the issue asks about, and what the speed-up
# measured here projects for four cores (Amdahl's law: the share of a cold
# start that the threads shorten, from this machine's speed-up on its
# cores). Environment: KIOSK, TOOLS.
set -eu
out=$(pwd)/tests/out/bench-prepare
rounds=${ROUNDS:-3}
models="knot-10k knot-100k knot-1m"
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
. "$(dirname "$0")/startup_lib.sh"

# still MODEL CACHE THREADS: "wall_ms rss_kib" of one start that writes
# one frame and exits.
still() {
	t0=$(now_ns)
	rss=$(XDG_CACHE_HOME=$2 /usr/bin/time -f "%M" "$KIOSK" -q -b osmesa --size 1280x720 \
		--frames 1 --model "$1" --prepare-threads "$3" --output "$out/still.png" 2>&1 |
		tail -1)
	t1=$(now_ns)
	echo "$(((t1 - t0) / 1000000)) $rss"
}

# live MODEL CACHE THREADS: "first_frame_ms rss_kib" of one live start.
live() {
	set -- $(run "$KIOSK" "$1" "$2" --prepare-threads "$3")
	echo "$2 $3"
}

# start KIND MODEL THREADS: "cold_ms warm_ms cold_rss warm_rss", the warm
# start finding the entry the cold one wrote.
start() {
	cache=$out/cache
	rm -rf "$cache"
	set -- $($1 "$out/$2.glb" "$cache" "$3") $($1 "$out/$2.glb" "$cache" "$3")
	echo "$1 $3 $2 $4"
}

rm -f "$out"/runs-*
for i in $(seq "$rounds"); do
	for model in $models; do
		for threads in 1 auto; do
			for kind in still live; do
				start $kind $model $threads >>"$out/runs-$model-$threads-$kind"
			done
		done
	done
done
rm -rf "$out/cache"

col() { cut -d' ' -f"$1" "$2" | median; }
echo "## Preparation: threads and memory ($(uname -m), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg), median of $rounds, osmesa 1280x720)"
echo
echo "| model | prepare_threads | first frame | cold ms | warm ms | peak RSS cold MiB | warm MiB | cold / warm RSS |"
echo "|---|---|---|---|---|---|---|---|"
for model in $models; do
	for threads in 1 auto; do
		for kind in still live; do
			f=$out/runs-$model-$threads-$kind
			awk -v m=$model -v t=$threads -v k=$kind -v c="$(col 1 "$f")" \
				-v w="$(col 2 "$f")" -v rc="$(col 3 "$f")" -v rw="$(col 4 "$f")" \
				'BEGIN { printf "| %s | %s | %s | %.0f | %.0f | %.0f | %.0f | %.2f |\n",
					m, t, k, c, w, rc / 1024, rw / 1024, rc / rw }'
		done
	done
done

# The issue's goals and the projection, from the medians above.
echo
awk -v n="$(nproc)" -v s1="$(col 1 "$out/runs-knot-1m-1-still")" \
	-v sa="$(col 1 "$out/runs-knot-1m-auto-still")" \
	-v l1="$(col 1 "$out/runs-knot-1m-1-live")" -v la="$(col 1 "$out/runs-knot-1m-auto-live")" \
	-v small="$(col 1 "$out/runs-knot-10k-auto-still")" 'BEGIN {
	printf "- 1M knot cold, still: %.0f ms on 1 thread, %.0f on %d: %.2fx; live: %.0f, %.0f: %.2fx\n",
		s1, sa, n, s1 / sa, l1, la, l1 / la
	printf "- 1M knot cold still against the 10k one (goal within 3x): %.1fx\n", sa / small
	if (n > 1 && s1 > sa) {
		p = (1 - sa / s1) / (1 - 1 / n)
		if (p > 1) p = 1
		printf "- the threads shorten %.0f%% of the 1M cold still here; on 4 such cores: %.0f ms, %.2fx\n",
			100 * p, s1 * ((1 - p) + p / 4), 1 / ((1 - p) + p / 4)
	} else
		print "- no speed-up measured here (one core, or none free): no projection"
}'
rm -f "$out"/runs-*
