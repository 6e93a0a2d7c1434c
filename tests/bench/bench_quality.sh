#!/bin/sh
# Speed against error: bench_quality draws each scene with every
# quality setting and writes the tables and the data, gnuplot draws time
# against error with the front marked. Printed, never asserted.
#   sh tests/bench/bench_quality.sh OUTDIR [--frames N] [--size WxH] [--backend B]
# `make report` writes tests/bench/report (checked in); `make bench`, a scratch
# copy. Environment: TOOLS; KIOSK adds the render_scale rows.
set -eu
out=$1
shift
# The maps it draws with, outside tests/out, which `make test` empties.
scratch=$(mktemp -d /tmp/matcap-bench-XXXXXX)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$out"
"$TOOLS/bench_quality" "$out" "$scratch" "$@"
# [display] render_scale's rows (bench_scale.sh), where the kiosk is built.
if [ -n "${KIOSK:-}" ]; then
	echo >>"$out/speed-error.md"
	sh tests/bench/bench_scale.sh 1920x1080 3840x2160 >>"$out/speed-error.md"
fi
# [scene] normals: the flat split's vertices and cost (bench_normals.sh).
if [ -n "${KIOSK:-}" ]; then
	echo >>"$out/speed-error.md"
	sh tests/bench/bench_normals.sh >>"$out/speed-error.md"
fi
# Live playback's paths (bench_anim_paths.sh).
echo >>"$out/speed-error.md"
sh tests/bench/bench_anim_paths.sh >>"$out/speed-error.md"
gnuplot -e "dir='$out'" tests/bench/report/speed-error.gp
cat "$out/speed-error.md"
echo "plot: $out/speed-error.png"
