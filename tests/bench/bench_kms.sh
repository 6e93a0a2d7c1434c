#!/bin/sh
# Frames per second on the virtual board's display (vkms, llvmpipe under
# qemu TCG): matcap-kiosk beside kmscube, measured one after the other in
# one boot of tests/vm, and their ratio. A figure, never asserted.
# Environment: KIOSK; KMSCUBE_FRAMES (300), KIOSK_SECONDS (20), BENCH_KMS_OUT.
set -u
out=${BENCH_KMS_OUT:-tests/out/bench-kms}
rm -rf "$out"
mkdir -p "$out"
# The other figures of `make bench` still come when this one cannot.
if ! command -v qemu-system-x86_64 >/dev/null && [ "$(id -u)" != 0 ]; then
	echo "bench_kms: no figure: no qemu-system-x86_64 for the virtual board (make deps)"
	exit 0
fi
if ! tests/vm/run.sh --quiet --timeout 400 --bin "${KIOSK:-./matcap-kiosk}" --share "$out" \
	-- tests/e2e/bench-kms.sh "${KMSCUBE_FRAMES:-300}" "${KIOSK_SECONDS:-20}" >"$out/run.log" 2>&1; then
	echo "bench_kms: no figure: the board run failed, see $out/run.log and $out/console.log"
	tail -5 "$out/run.log"
	exit 0
fi
cube=$(sed -n 's/^bench kmscube //p' "$out/console.log")
kiosk=$(sed -n 's/^bench kiosk //p' "$out/console.log")
lod=$(sed -n 's/.*lod: \([0-9]* -> [0-9]*\) triangles.*/\1/p' "$out/console.log")
echo
echo "## KMS on the virtual board ($(nproc)-core host, qemu TCG without AVX, 2 vCPUs, llvmpipe, vkms 1024x768)"
echo
echo "| program | frames flipped | seconds | frames per second |"
echo "|---|---|---|---|"
set -- $cube
echo "| kmscube (one textured cube) | ${1:-?} | ${2:-?} | ${3:-?} |"
cube_fps=${3:-0}
set -- $kiosk
echo "| matcap-kiosk (built-in knot, ${lod:-16384} triangles, attract mode) | ${1:-?} | ${2:-?} | ${3:-?} |"
awk -v k="${3:-0}" -v c="$cube_fps" 'BEGIN {
	if (k > 0 && c > 0)
		printf "\nmatcap-kiosk / kmscube: %.2f (%.0f ms against %.0f ms a frame)\n", k / c, 1000 / k, 1000 / c
	else
		print "\nmatcap-kiosk / kmscube: no figure (a run reported nothing)"
}'
