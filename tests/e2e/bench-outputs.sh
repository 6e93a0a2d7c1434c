#!/bin/sh
# Guest script for tests/bench/bench_outputs.sh (booted with run.sh
# --outputs 2): the cost of a second output. matcap-kiosk turning the
# built-in knot by itself, uncapped (a frame per vblank at most), on the
# virtio-gpu card at 640x480: first on one output, then on both (one GL
# context, the frame drawn once per output, the next waiting for both
# flips). Prints "bench outputs N FLIPS SECONDS FPS PEAK_KB" for N = 1 and
# 2 (PEAK_KB: the kiosk's VmHWM).
#   ARGS: [SECONDS]
set -u
. "$VM_LIB"
seconds=${1:-20}
card=$(drm_card_of virtio_gpu)
[ -n "$card" ] || { echo "bench-outputs: no virtio-gpu card"; exit 1; }

run() { # N OUTPUTS
	matcap-kiosk --backend kms --device "$card" --outputs "$2" --display-mode 640x480 \
		--matcap /repo/matcaps/gold.png --keyboard none --camera off \
		--attract-after 0.1 --attract-fps 0 >"kiosk-$1.log" 2>&1 &
	kiosk=$!
	wait_until 120 grep -q "ready: the first frame is on the screen" "kiosk-$1.log"
	sleep "$seconds"
	hwm=$(sed -n 's/^VmHWM:[[:space:]]*\([0-9]*\).*/\1/p' "/proc/$kiosk/status")
	kill -TERM "$kiosk"
	wait "$kiosk"
	# One output logs "kms: N page flips", several "kms: NAME: N page
	# flips" each: the first output's (the frame waits for both).
	sed -n "s/.*kms: \(Virtual-2: \)\{0,1\}\([0-9]*\) page flips in \([0-9.]*\) s (\([0-9.]*\) per second).*/bench outputs $1 \2 \3 \4/p" \
		"kiosk-$1.log" | head -1 | sed "s/\$/ ${hwm:-0}/"
}
run 1 Virtual-2
run 2 "Virtual-2,Virtual-3"
grep -E "kms: Virtual|lod:" kiosk-2.log
