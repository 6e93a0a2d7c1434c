#!/bin/sh
# Input figures, printed and never asserted: what a live kiosk (OSMesa,
# the real poll loop) costs while nobody touches it. The issue's target:
# no frame drawn and under 10 ms of CPU in 10 s of idle, attract mode off.
# Environment: KIOSK; IDLE_S (default 10).
set -eu
out=tests/out/bench-input
mkdir -p "$out"
idle=${IDLE_S:-10}
tick_ms=$((1000 / $(getconf CLK_TCK)))

# Everything the process's threads spent on a CPU: utime + stime (whole
# clock ticks), and the scheduler's nanoseconds where the kernel keeps them.
cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$1/stat"; }
cpu_ns() {
	cat /proc/"$1"/task/*/schedstat 2>/dev/null | awk '{ s += $1 } END { printf "%.0f", s }'
}
wakeups() { awk '/^voluntary_ctxt_switches/ { v = $2 } /^nonvoluntary/ { n = $2 }
	END { print v + n }' "/proc/$1/status"; }
wait_for() { # FILE PATTERN: up to 30 s
	i=0
	while ! grep -q -- "$2" "$1" 2>/dev/null; do
		i=$((i + 1))
		[ $i -gt 600 ] && return 1
		sleep 0.05
	done
}

echo "## matcap-kiosk input bench ($(uname -m), $(nproc) cores, ${idle} s idle, OSMesa live loop)"
echo
echo "| run | frames after the start-up one | CPU ms (utime+stime) | CPU ms (schedstat) | main-thread wake-ups |"
echo "|---|---|---|---|---|"
# The last row is a control: attract mode from 0.5 s, so the model turns
# and the same counters must show frames and CPU.
for run in none:0 auto:0 none:0.5; do
	keyboard=${run%:*}
	attract=${run#*:}
	log=$out/stderr-$keyboard-$attract
	$KIOSK --backend osmesa --size 640x360 --attract-after "$attract" --keyboard $keyboard \
		2>"$log" &
	pid=$!
	wait_for "$log" "first frame"
	sleep 1 # let start-up settle (threads parked, pages touched)
	t0=$(cpu_ticks $pid)
	n0=$(cpu_ns $pid)
	w0=$(wakeups $pid)
	sleep "$idle"
	t1=$(cpu_ticks $pid)
	n1=$(cpu_ns $pid)
	w1=$(wakeups $pid)
	kill -TERM $pid
	wait $pid || true
	# The first frame is the start-up one; every other was drawn idle.
	frames=$(sed -n 's/.* \([0-9]*\) frames drawn.*/\1/p' "$log")
	ms_ns=$(awk -v a="$n0" -v b="$n1" 'BEGIN {
		if (a > 0) printf "%.2f", (b - a) / 1e6; else print "n/a" }')
	scene="built-in knot, keyboard $keyboard, attract after ${attract} s"
	[ "$attract" = 0 ] && scene="built-in knot, keyboard $keyboard, attract mode off"
	printf '| %s | %s | %s | %s | %s |\n' "$scene" $((frames - 1)) \
		$(((t1 - t0) * tick_ms)) "$ms_ns" $((w1 - w0))
done
echo
echo "utime+stime counts whole clock ticks of ${tick_ms} ms; schedstat is exact."
echo
# The edge-to-frame latency needs GPIO lines and a display: the virtual
# board's gpio-sim and vkms (qemu, a few minutes), so only on request.
if [ "${BENCH_VM:-0}" = 1 ]; then
	rm -rf "$out/vm"
	if tests/vm/run.sh --bin "$KIOSK" --share "$out/vm" --quiet --timeout 900 \
		-- tests/vm/gpio-test.sh >"$out/vm.log" 2>&1; then
		echo "Virtual board (qemu TCG, gpio-sim, vkms, llvmpipe), $(grep -c . "$out/vm/latency-read.txt") presses of a line:"
		sed 's/^/- /' "$out/vm/latency-summary.txt"
	else
		echo "Virtual board run failed: see $out/vm.log and $out/vm/console.log"
	fi
else
	echo "Edge-to-frame latency: BENCH_VM=1 make bench runs tests/vm/gpio-test.sh on the"
	echo "virtual board (qemu, a few minutes) and prints it here."
fi
