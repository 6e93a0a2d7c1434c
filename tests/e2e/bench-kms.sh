#!/bin/sh
# Guest script for tests/bench/bench_kms.sh: kmscube, then matcap-kiosk, each
# flipping frames on vkms at 1024x768 in this one boot (llvmpipe through
# kms_swrast + GBM).  Prints "bench kmscube FRAMES SECONDS FPS" and
# "bench kiosk FLIPS SECONDS FPS"; their logs go into the share.
#   ARGS: [KMSCUBE_FRAMES] [KIOSK_SECONDS]
set -u
. "$VM_LIB"
frames=${1:-300}
seconds=${2:-20}

# Debian's kmscube needs the board's shim on vkms (tests/vm/README.md), and
# quits on input from stdin: it gets a FIFO nobody writes.
mkfifo /tmp/kmscube.in
LD_PRELOAD=/usr/lib/vm/libgbm-linear.so timeout 300 kmscube -D /dev/dri/card0 -c "$frames" \
	<>/tmp/kmscube.in >kmscube.log 2>&1
sed -n 's/^Rendered \([0-9]*\) frames in \([0-9.]*\) sec (\([0-9.]*\) fps)$/bench kmscube \1 \2 \3/p' \
	kmscube.log | tail -1

# The kiosk turning the built-in knot by itself (attract mode), uncapped
# (attract_fps 0: a frame per vblank, as kmscube), with the shipped
# defaults otherwise; its page flips are counted at exit.
matcap-kiosk --backend kms --matcap /repo/matcaps/gold.png --keyboard none --camera off \
	--attract-after 0.1 --attract-fps 0 >kiosk.log 2>&1 &
kiosk=$!
wait_until 120 grep -q "ready: the first frame is on the screen" kiosk.log
sleep "$seconds"
kill -TERM "$kiosk"
wait "$kiosk"
sed -n 's/.*kms: \([0-9]*\) page flips in \([0-9.]*\) s (\([0-9.]*\) per second).*/bench kiosk \1 \2 \3/p' \
	kiosk.log
grep -E "kms: Virtual|lod:" kiosk.log
