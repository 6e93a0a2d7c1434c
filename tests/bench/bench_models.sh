#!/bin/sh
# Figures for several models and attract mode, printed and never asserted:
#  - attract mode's CPU per second of wall time, on the offscreen backend
#    (the live loop drawing into an unseen buffer), at the default
#    attract_fps (30), uncapped (0: every frame it can), and with attract
#    mode off (idle: nothing drawn);
#  - a folder of a 10k and a 1M triangle knot taking turns in attract
#    mode: the time from the step to the new model swapped in (loaded and
#    prepared on the worker thread, uploaded), cold (an empty
#    prepared-mesh cache) and warm, one frame's drawing to add for its
#    first frame, and the process's peak RSS beside that of the 1M knot
#    shown alone.
# Environment: KIOSK, TOOLS; SECONDS_RUN (8) per attract figure.
set -eu
out=$(pwd)/tests/out/bench-models
run_s=${SECONDS_RUN:-8}
mkdir -p "$out/folder"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
cp "$out/knot-10k.glb" "$out/folder/a-knot-10k.glb"
cp "$out/knot-1m.glb" "$out/folder/b-knot-1m.glb"
hz=$(getconf CLK_TCK)

# cpu_per_s ARGS...: the live kiosk for run_s seconds; "CPU | frames",
# its CPU seconds (user + system, /proc/PID/stat) and frames drawn per
# second, from 2 s in (the start and the first frame left out).
cpu_per_s() {
	"$KIOSK" -b osmesa --size 1280x720 --keyboard none --camera off "$@" 2>"$out/cpu.log" &
	pid=$!
	sleep 2
	t0=$(awk '{ print $14 + $15 }' "/proc/$pid/stat")
	sleep "$run_s"
	t1=$(awk '{ print $14 + $15 }' "/proc/$pid/stat")
	kill -TERM "$pid"
	wait "$pid" || true
	n=$(sed -n 's/.* \([0-9]*\) frames drawn.*/\1/p' "$out/cpu.log")
	awk -v a="$t0" -v b="$t1" -v hz="$hz" -v s="$run_s" -v n="${n:-0}" \
		'BEGIN { printf "%.3f | %.1f", (b - a) / hz / s, n / (s + 2) }'
}

echo "## attract mode and several models ($(uname -m), $(nproc) cores, 1280x720 offscreen)"
echo
echo "| attract mode | CPU s per s | frames per s (whole run) |"
echo "|---|---|---|"
echo "| off (attract_after 0): idle | $(cpu_per_s --attract-after 0) |"
echo "| on, attract_fps 30 (default) | $(cpu_per_s --attract-after 0.1 --attract-fps 30) |"
echo "| on, attract_fps 0 (uncapped) | $(cpu_per_s --attract-after 0.1 --attract-fps 0) |"

# switches CACHE: the folder in turns every 4 s for 30 s; the swap times
# logged, and the peak RSS (VmHWM, read before it stops).
switches() {
	rm -f "$out/switch.log"
	XDG_CACHE_HOME=$1 "$KIOSK" -b osmesa --size 1280x720 --keyboard none --camera off \
		--log-level debug --model "$out/folder" --attract-after 0.1 \
		--attract-model-seconds 4 >"$out/switch.log" 2>&1 &
	pid=$!
	sleep 30
	sed -n 's/^VmHWM:[[:space:]]*\([0-9]*\) kB/\1/p' "/proc/$pid/status" >"$out/rss"
	kill -TERM "$pid" 2>/dev/null || true
	wait "$pid" || true
}
frame_ms() {
	"$KIOSK" -q -b osmesa --size 1280x720 --frames 20 --stats --model "$1" |
		sed -n 's/.*median_ms \([0-9.]*\).*/\1/p'
}
rm -rf "$out/cache"
switches "$out/cache"
# Which model each swap brought: the "model N of 2" line before it.
awk '/model [0-9] of 2/ { m = $0 ~ /knot-1m/ ? "1m" : "10k" }
	/swapped in/ { sub(/.*swapped in /, ""); sub(/ ms.*/, ""); print m, $0 }' \
	"$out/switch.log" >"$out/swaps"
rss=$(cat "$out/rss")
alone=$(XDG_CACHE_HOME=$out/cache-alone /usr/bin/time -f "%M" "$KIOSK" -q -b osmesa \
	--size 1280x720 --frames 3 --model "$out/knot-1m.glb" 2>&1 >/dev/null | tail -1)
rm -rf "$out/cache-alone"
cold=$(awk '$1 == "1m" { print $2; exit }' "$out/swaps")
warm=$(awk '$1 == "1m" { n++; if (n > 1) { s += $2; c++ } } END { if (c) printf "%.1f", s / c }' \
	"$out/swaps")
small=$(awk '$1 == "10k" { s += $2; c++ } END { if (c) printf "%.1f", s / c }' "$out/swaps")
echo
echo "| a folder of a 10k and a 1M triangle knot | ms |"
echo "|---|---|"
echo "| step to the 1M knot swapped in, cold cache | ${cold:-?} |"
echo "| step to the 1M knot swapped in, warm (mean) | ${warm:-?} |"
echo "| step to the 10k knot swapped in (mean) | ${small:-?} |"
echo "| then its first frame: one frame of the 1M knot's (median) | $(frame_ms "$out/knot-1m.glb") |"
echo
echo "peak RSS: the folder in turns $((rss / 1024)) MiB; the 1M knot alone $((${alone:-0} / 1024)) MiB"
