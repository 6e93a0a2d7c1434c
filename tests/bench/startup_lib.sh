# Shared by the start-up benches (bench_startup.sh, bench_gltf.sh):
# sourced, never run. Each start is three frames with --stats (one would
# start the live loop) at 1280x720 offscreen.

now_ns() { date +%s%N; }

median() { tr ' ' '\n' | sed '/^$/d' | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# run KIOSK MODEL CACHE [OPTION]...: "wall_ms first_ms rss_kib setup_ms"
# of one start; setup is the first frame less a frame's drawing (the
# median of three): what the start costs beyond the picture the level of
# detail decides.
run() {
	_kiosk=$1 _model=$2 _cache=$3
	shift 3
	t0=$(now_ns)
	stats=$(XDG_CACHE_HOME=$_cache /usr/bin/time -f "rss %M" "$_kiosk" -q -b osmesa \
		--size 1280x720 --frames 3 --stats --model "$_model" "$@" 2>&1)
	t1=$(now_ns)
	first=$(echo "$stats" | sed -n 's/.*first_frame_ms \([0-9.]*\).*/\1/p')
	frame=$(echo "$stats" | sed -n 's/.*median_ms \([0-9.]*\).*/\1/p')
	rss=$(echo "$stats" | sed -n 's/^rss //p')
	echo "$(((t1 - t0) / 1000000)) $first $rss $(awk -v f="$first" -v d="$frame" 'BEGIN { print f - d }')"
}

# medians FILE: "wall first rss setup", each the median of FILE's runs.
medians() {
	echo "$(cut -d' ' -f1 "$1" | median)" "$(cut -d' ' -f2 "$1" | median)" \
		"$(cut -d' ' -f3 "$1" | median)" "$(cut -d' ' -f4 "$1" | median)"
}
