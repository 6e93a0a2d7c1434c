#!/bin/sh
# The cost of a second output (issue 36): frames per second of one kiosk
# driving one, then both outputs of the virtual board's virtio-gpu
# (llvmpipe through kms_swrast under qemu TCG, 640x480), and the time a
# frame of both takes against one. A figure, never asserted.
# Environment: KIOSK; OUTPUTS_SECONDS (20), BENCH_OUTPUTS_OUT.
set -u
out=${BENCH_OUTPUTS_OUT:-tests/out/bench-outputs}
rm -rf "$out"
mkdir -p "$out"
if ! command -v qemu-system-x86_64 >/dev/null && [ "$(id -u)" != 0 ]; then
	echo "bench_outputs: no figure: no qemu-system-x86_64 for the virtual board (make deps)"
	exit 0
fi
if ! tests/vm/run.sh --quiet --outputs 2 --timeout 400 --bin "${KIOSK:-./matcap-kiosk}" \
	--share "$out" -- tests/e2e/bench-outputs.sh "${OUTPUTS_SECONDS:-20}" >"$out/run.log" 2>&1; then
	echo "bench_outputs: no figure: the board run failed, see $out/run.log and $out/console.log"
	tail -5 "$out/run.log"
	exit 0
fi
echo
echo "## A second output on the virtual board (virtio-gpu, llvmpipe under qemu TCG, 640x480)"
echo
echo "| outputs | frames flipped (each) | seconds | frames per second | ms a frame | peak memory MiB |"
echo "|---|---|---|---|---|---|"
sed -n 's/^bench outputs //p' "$out/console.log" | awk '
	{ ms = $4 > 0 ? 1000 / $4 : 0; printf "| %s | %s | %s | %s | %.1f | %.1f |\n", $1, $2, $3, $4, ms, $5 / 1024
	  if ($1 == 1) one = ms; if ($1 == 2) two = ms }
	END { if (one > 0 && two > 0)
		printf "\ntwo outputs / one: %.2f (%.1f ms against %.1f ms a frame)\n", two / one, two, one
	      else print "\ntwo outputs / one: no figure (a run reported nothing)" }'
