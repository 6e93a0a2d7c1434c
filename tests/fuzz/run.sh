#!/bin/sh
# Runs each libFuzzer harness from its seeds for FUZZ_SECONDS (as many side
# by side as there are CPUs for their FUZZ_JOBS workers), then replays
# every file of tests/fuzz/regressions once (a crash found once stays
# fixed).
#   run.sh [HARNESS]...   gltf, image, config, mesh_cache, remote (all when none is named) Prints one line per step, "ok NAME" or "not ok NAME", with the
# figures (runs, seconds, runs per second, corpus size) in NAME.
# Environment: FUZZ_DIR (the harnesses), FUZZ_SECONDS, FUZZ_JOBS (workers
# per harness; more than 1 for long runs), FUZZ_OUT (scratch).
set -u
seconds=${FUZZ_SECONDS:-20}
jobs=${FUZZ_JOBS:-1}
out=${FUZZ_OUT:-tests/out/fuzz}
mkdir -p "$out"
# Absolute paths: each harness runs in its scratch folder, where libFuzzer
# writes its per-job logs (fuzz-N.log) when FUZZ_JOBS > 1.
top=$(pwd)
dir=$(cd "${FUZZ_DIR:-build/fuzz}" && pwd)
out=$(cd "$out" && pwd)
export FUZZ_GLTF_DIR="$top/tests/fuzz/corpus/gltf"
harnesses=${*:-gltf image config mesh_cache remote}

# fuzz_one NAME: one harness for FUZZ_SECONDS; its "ok"/"not ok" line goes
# to its scratch folder's result, printed in order below.
fuzz_one() {
	t=$1
	work=$out/$t
	rm -rf "$work"
	mkdir -p "$work/corpus"
	# New inputs go to the scratch corpus; the seeds are only read. A crash
	# leaves its input as $work/crash-*, to be copied into regressions/.
	set -- -max_total_time="$seconds" -print_final_stats=1 -max_len=16384 -timeout=10 \
		-rss_limit_mb=2048 -artifact_prefix="$work/" "$work/corpus" "$top/tests/fuzz/corpus/$t"
	if [ "$jobs" -gt 1 ]; then
		set -- -jobs="$jobs" -workers="$jobs" "$@"
	fi
	(cd "$work" && "$dir/fuzz_$t" "$@") >"$work/log" 2>&1
	status=$?
	cat "$work"/fuzz-*.log >>"$work/log" 2>/dev/null
	runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log" | awk '{s += $1} END {print s + 0}')
	secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$work/log" | sort -n | tail -1)
	secs=${secs:-$seconds}
	units=$(ls "$work/corpus" | wc -l)
	rate=$(awk -v r="$runs" -v s="$secs" 'BEGIN { printf "%d", (s > 0 ? r / s : r) }')
	if [ $status -eq 0 ] && ! ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* \
		"$work"/oom-* >/dev/null 2>&1; then
		echo "ok $t: $runs runs in ${secs} s ($rate/s), $units new inputs, no crash"
	else
		grep -A30 -E "ERROR|runtime error|deadly signal" "$work/log" | head -60 >&2
		echo "not ok $t: crashed after $runs runs (input in $work/, log $work/log)"
	fi
}

# The harnesses side by side, as many at a time as there are CPUs for
# their workers: each still fuzzes FUZZ_SECONDS on a core of its own (one
# after the other, a 2-core machine idled a core for 80 s of CI).
cpus=$(nproc 2>/dev/null || echo 1)
at_once=$((cpus / jobs))
[ "$at_once" -ge 1 ] || at_once=1
n=0
for t in $harnesses; do
	fuzz_one "$t" >"$out/$t.result" &
	n=$((n + 1))
	[ $((n % at_once)) -ne 0 ] || wait
done
wait
for t in $harnesses; do
	cat "$out/$t.result"
done

# Regressions too large to keep as files, written by their scripts: JSON
# nested 30,000 deep (60 KB of brackets) killed the loader by recursion.
gen=$out/generated
mkdir -p "$gen"
for c in gltf glb; do
	sh "$top/tests/fuzz/deep_json.sh" 30002 $c >"$gen/gltf-json-30000-deep.$c"
done
for t in $harnesses; do
	set --
	for f in tests/fuzz/regressions/"$t"-* "$gen"/"$t"-*; do
		[ -e "$f" ] && set -- "$@" "$f"
	done
	[ $# -gt 0 ] || continue
	if "$dir/fuzz_$t" "$@" >"$out/replay-$t.log" 2>&1; then
		echo "ok $t: $# regression inputs replayed"
	else
		tail -40 "$out/replay-$t.log" >&2
		echo "not ok $t: a regression input fails again (see $out/replay-$t.log)"
	fi
done
