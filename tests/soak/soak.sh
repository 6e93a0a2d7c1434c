#!/bin/sh
# The soak test (tests/soak/soak.c: the live loop through OSMesa at 64x64, a
# matcap change every 100 frames, a reload every SOAK_RELOAD_EVERY frames
# (and at least a second after the one before),
# resident memory flat within 4 MiB after two warm-up reloads), then
# valgrind on a short run of the same driver: no leak and no memory error
# in the project's own code. Mesa's and LLVM's own leaks are suppressed by
# tests/soak/soak.supp, which names them by library.
# Prints one "ok NAME" or "not ok NAME" line per check, figures included.
# Environment: SOAK (the driver), SOAK_FRAMES, SOAK_RELOAD_EVERY, SOAK_OUT,
# SOAK_VALGRIND_FRAMES (0: no valgrind run).
set -u
soak=${SOAK:-build/tools/soak}
frames=${SOAK_FRAMES:-100000}
every=${SOAK_RELOAD_EVERY:-10000}
vg_frames=${SOAK_VALGRIND_FRAMES:-400}
out=${SOAK_OUT:-tests/out/soak}
mkdir -p "$out"

if "$soak" "$out/run" --frames "$frames" --reload-every "$every" --matcap-every 100 \
	--warmup 2 --rss-bound 4096 --size 64 >"$out/run.log" 2>"$out/run.err"; then
	word=ok
else
	word="not ok"
	cat "$out/run.log" "$out/run.err" >&2
fi
echo "$word $(sed -n 's/^soak: //p' "$out/run.log" | paste -sd ';' -)"

[ "$vg_frames" -gt 0 ] || exit 0
if ! command -v valgrind >/dev/null; then
	echo "not ok valgrind is not installed (make deps)"
	exit 0
fi
# llvmpipe renders in the calling thread (LP_NUM_THREADS=0) and valgrind
# schedules threads fairly: both make the run ten times faster under it.
# A reload every 50 frames, more than a second apart under valgrind, lets
# the matcap folder's changes settle between reloads. --keep-debuginfo
# names the frames of a driver that EGL unloaded before the leak report
# (a build without OSMesa draws through EGL), so the suppressions match.
LP_NUM_THREADS=0 valgrind --fair-sched=yes --keep-debuginfo=yes --leak-check=full --show-leak-kinds=definite,indirect \
	--errors-for-leak-kinds=definite,indirect --suppressions=tests/soak/soak.supp \
	--error-exitcode=99 --log-file="$out/valgrind.log" \
	"$soak" "$out/vg" --frames "$vg_frames" --matcap-every 10 --reload-every 50 --warmup 1 \
	--rss-bound 1000000 --size 64 >"$out/vg.out" 2>"$out/vg.err"
status=$?
lost=$(sed -n 's/.*definitely lost: \([0-9,]*\) bytes.*/\1/p' "$out/valgrind.log")
suppressed=$(sed -n 's/.*suppressed: \([0-9,]*\) bytes.*/\1/p' "$out/valgrind.log")
if [ $status -eq 0 ]; then
	echo "ok valgrind, $vg_frames frames and $(grep -c '^reload' "$out/vg.out") reloads: ${lost:-?} bytes lost in the project's code, no memory error (${suppressed:-?} bytes leaked inside Mesa/LLVM, suppressed)"
else
	grep -A25 -E "Invalid|uninitialised|definitely lost in|indirectly lost in" \
		"$out/valgrind.log" | head -80 >&2
	cat "$out/vg.out" >&2
	echo "not ok valgrind (status $status): see $out/valgrind.log"
fi
