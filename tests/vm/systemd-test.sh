#!/bin/sh
# The kiosk as a systemd service on the virtual board: boots the Debian root
# of tests/vm/systemd-build.sh (systemd as PID 1, the kiosk installed by
# `make install` and enabled) on the board's kernel with vkms, under qemu,
# and reports what tests/vm/systemd-guest.sh saw: READY=1 after the first
# frame, the scene on vkms, a SIGSTOPped kiosk restarted by the watchdog,
# reload, a reload that outlasts WatchdogSec=3s not killed (the kiosk
# built with -DMK_TEST_HOOKS, frames flipped meanwhile counted, the loop's
# longest step during it printed), a config error not restarted (78), and
# the console's mode back after `systemctl stop`. SYSTEMD_VM_MODEL=knot-1m
# reloads the 1M-triangle knot instead of the 100k one (minutes more).
#
#   tests/vm/systemd-test.sh [OUTDIR]    (default build/vm-systemd/out)
#
# Prints one "ok NAME" or "not ok NAME" line per guest check, then
# "ok every check ran" when the guest got to its end. The serial console is
# OUTDIR/console.log. VM_TIMEOUT (seconds, default 900) bounds the boot.
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
out=${1:-$REPO/build/vm-systemd/out}
limit=${VM_TIMEOUT:-900}
# As tests/vm/run.sh: no AVX, which QEMU 7.2's TCG gets wrong for llvmpipe.
cpu=${VM_CPU:-max,-avx,-avx2,-fma,-f16c,-vaes,-vpclmulqdq}
mkdir -p "$out"

built=$("$HERE/systemd-build.sh") || {
	echo "not ok the systemd guest did not build"
	exit 1
}
kernel=$(printf '%s\n' "$built" | sed -n 's/^VM_KERNEL=//p')
initrd=$(printf '%s\n' "$built" | sed -n 's/^VM_INITRD=//p')

start=$(date +%s)
timeout -k 5 "$limit" qemu-system-x86_64 -accel tcg,thread=multi -cpu "$cpu" -smp 2 -m 3072 \
	-nodefaults -no-user-config -display none -no-reboot \
	-kernel "$kernel" -initrd "$initrd" \
	-append "console=ttyS0 loglevel=3 panic=-1 mitigations=off systemd.show_status=0" \
	-serial "file:$out/console.log" 2>"$out/qemu.err"
status=$?
echo "# qemu ran $(($(date +%s) - start)) s (status $status)"

# systemd puts the unit's output on the console behind a time and a name.
tr -d '\r' <"$out/console.log" | sed -n 's/.*vm-systemd: \(ok .*\)/\1/p; s/.*vm-systemd: \(not ok .*\)/\1/p'
if grep -q 'vm-systemd: [0-9]* passed, [0-9]* failed' "$out/console.log"; then
	echo "ok every check ran"
else
	echo "not ok the guest test did not finish (see $out/console.log)"
fi
