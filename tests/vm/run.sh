#!/bin/bash
# Boot the virtual board and run one guest script in it, as root.
#
#   tests/vm/run.sh [options] -- GUEST_SCRIPT [ARGS]...
#
#   --bin PATH      put PATH (and the libraries ldd names) on the guest's PATH
#                   as /usr/local/bin/NAME; repeatable
#   --share DIR     host directory mounted read-write at /share in the guest
#                   (the script's working directory); created if missing
#   --timeout S     kill the guest script after S seconds (default 300)
#   --log FILE      serial console log (default: DIR/console.log with
#                   --share, else tests/vm/cache/last-console.log)
#   --quiet         do not copy the console to stdout while it runs
#   --mem MB, --smp N   guest memory (2048) and CPUs (2)
#   --usb IMG:SERIAL  a raw disk image as a read-only USB stick (usb-storage
#                   on an xHCI controller) whose USB serial is SERIAL;
#                   repeatable
#   --outputs N     a second GPU beside vkms (which stays card0 with its
#                   Virtual-1): QEMU's virtio-gpu-pci with N outputs (2-16),
#                   one CRTC each, card1, connectors Virtual-2..Virtual-N+1
#                   (Linux 6.1 numbers connectors of a type across all
#                   cards); QEMU without a display enables only the first,
#                   the others are forced connected (video=Virtual-K:e)
#   VM_CPU=MODEL    qemu's -cpu (default: max without AVX, which QEMU 7.2's
#                   TCG emulates wrongly and slowly: an AVX2 gather whose
#                   index is xmm4/ymm4 loads every lane from the base address,
#                   which turned llvmpipe's texturing into noise, and 8-wide
#                   llvmpipe runs ~15x slower than its SSE4.1 path)
#
# In the guest: /repo is this repository (read-only), /share the --share dir,
# /vm/guest-lib.sh the helper functions ($VM_LIB).  Drivers are loaded (vkms
# with writeback, gpio-sim with configfs, vimc, uinput) and udev has settled
# before the script starts.  The exit status is the script's; 143 = the
# guest killed it at --timeout, 124 = the host-side timeout stopped qemu,
# 125 = the board failed before or around the script.
set -eu
set -o pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
CACHE=${VM_CACHE:-$HERE/cache}

say() { printf '[vm-run] %s\n' "$*" >&2; }
die() { printf '[vm-run] error: %s\n' "$*" >&2; exit 125; }

BUILD_ARGS=() SHARE="" LOG="" QUIET=0 USB_ARGS=() GPU_ARGS=() APPEND_EXTRA=""
TIMEOUT=${VM_TIMEOUT:-300} MEM=${VM_MEM:-2048} SMP=${VM_SMP:-2} CPU=${VM_CPU:-max,-avx,-avx2,-fma,-f16c,-vaes,-vpclmulqdq}
while [ $# -gt 0 ]; do
	case $1 in
	--bin) [ $# -ge 2 ] || die "--bin needs a path"; BUILD_ARGS+=(--bin "$2"); shift 2 ;;
	--share) [ $# -ge 2 ] || die "--share needs a directory"; SHARE=$2; shift 2 ;;
	--timeout) [ $# -ge 2 ] || die "--timeout needs seconds"; TIMEOUT=$2; shift 2 ;;
	--log) [ $# -ge 2 ] || die "--log needs a file"; LOG=$2; shift 2 ;;
	--mem) [ $# -ge 2 ] || die "--mem needs MB"; MEM=$2; shift 2 ;;
	--smp) [ $# -ge 2 ] || die "--smp needs a count"; SMP=$2; shift 2 ;;
	--quiet) QUIET=1; shift ;;
	--usb) [ $# -ge 2 ] || die "--usb needs IMG:SERIAL"
		[ ${#USB_ARGS[@]} -gt 0 ] || USB_ARGS=(-device qemu-xhci,id=xhci)
		n=${#USB_ARGS[@]}
		USB_ARGS+=(-drive "if=none,id=stick$n,format=raw,readonly=on,file=${2%:*}"
			-device "usb-storage,bus=xhci.0,drive=stick$n,serial=${2##*:}")
		shift 2 ;;
	--outputs) [ $# -ge 2 ] || die "--outputs needs a count"
		case $2 in [2-9]|1[0-6]) ;; *) die "--outputs wants 2 to 16 (virtio-gpu's max_outputs), not '$2'" ;; esac
		GPU_ARGS=(-device "virtio-gpu-pci,max_outputs=$2")
		# -display none: QEMU reports only output 0 as enabled; the
		# kernel's video=NAME:e forces the others connected (sysfs
		# status off/on still plays a cable on each; detect reads
		# QEMU's "disabled" again). vkms, loaded first, has Virtual-1.
		APPEND_EXTRA=$(seq 3 $(($2 + 1)) | sed 's/^/ video=Virtual-/; s/$/:e/' | tr -d '\n')
		shift 2 ;;
	--) shift; break ;;
	-h|--help) sed -n '2,31p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
	*) die "unknown option '$1' (see --help)" ;;
	esac
done
[ $# -ge 1 ] || die "no guest script (usage: run.sh [options] -- GUEST_SCRIPT [ARGS]...)"
SCRIPT=$1; shift
[ -f "$SCRIPT" ] || die "guest script $SCRIPT not found"
case $TIMEOUT in ''|*[!0-9]*) die "--timeout wants whole seconds, not '$TIMEOUT'" ;; esac

out=$("$HERE/build.sh" ${BUILD_ARGS[@]+"${BUILD_ARGS[@]}"}) || die "board build failed"
KERNEL=$(printf '%s\n' "$out" | sed -n 's/^VM_KERNEL=//p')
INITRD=$(printf '%s\n' "$out" | sed -n 's/^VM_INITRD=//p')
[ -f "$KERNEL" ] && [ -f "$INITRD" ] || die "build.sh gave no kernel/initrd"

JOB=$(mktemp -d "${TMPDIR:-/tmp}/vmjob.XXXXXX")
QPID=""
cleanup() {
	[ -n "$QPID" ] && kill "$QPID" 2>/dev/null
	rm -rf "$JOB"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

cp "$HERE/guest-boot.sh" "$HERE/guest-lib.sh" "$JOB/"
cp "$SCRIPT" "$JOB/guest-script"
quoted=""
for a in "$@"; do quoted="$quoted '${a//\'/\'\\\'\'}'"; done
{
	echo "VM_TIMEOUT=$TIMEOUT"
	echo "VM_HAVE_SHARE=$([ -n "$SHARE" ] && echo 1 || echo 0)"
	echo "VM_ARGS='${quoted//\'/\'\\\'\'}'"
} >"$JOB/env"

SHARE_ARGS=()
if [ -n "$SHARE" ]; then
	mkdir -p "$SHARE" || die "cannot create $SHARE"
	SHARE=$(cd "$SHARE" && pwd)
	SHARE_ARGS=(-virtfs "local,path=$SHARE,mount_tag=share,security_model=none,multidevs=remap,id=share")
	rm -f "$SHARE/console.log"
fi
[ -n "$LOG" ] || LOG=${SHARE:+$SHARE/console.log}
[ -n "$LOG" ] || LOG=$CACHE/last-console.log
mkdir -p "$(dirname "$LOG")"; : >"$LOG"

# Enough for the slowest boot we measured several times over.
HOST_LIMIT=$((TIMEOUT + ${VM_BOOT_LIMIT:-120}))
say "booting ($(basename "$KERNEL"), TCG, ${SMP} cpu, ${MEM} MB); console: $LOG"
t0=$(date +%s%N)
timeout -k 5 "$HOST_LIMIT" qemu-system-x86_64 \
	-accel tcg,thread=multi -cpu "$CPU" -smp "$SMP" -m "$MEM" \
	-nodefaults -no-user-config -display none -no-reboot \
	-kernel "$KERNEL" -initrd "$INITRD" \
	-append "console=ttyS0 loglevel=3 panic=-1 mitigations=off$APPEND_EXTRA" \
	-serial "file:$LOG" \
	-virtfs "local,path=$JOB,mount_tag=vmjob,security_model=none,id=vmjob" \
	-virtfs "local,path=$REPO,mount_tag=repo,security_model=none,readonly=on,multidevs=remap,id=repo" \
	${SHARE_ARGS[@]+"${SHARE_ARGS[@]}"} ${USB_ARGS[@]+"${USB_ARGS[@]}"} ${GPU_ARGS[@]+"${GPU_ARGS[@]}"} \
	2>"$JOB/qemu.err" &
QPID=$!
TPID=""
if [ "$QUIET" = 0 ]; then
	tail -n +1 -s 0.2 -F --pid="$QPID" "$LOG" 2>/dev/null &
	TPID=$!
fi
qrc=0
wait "$QPID" || qrc=$?
QPID=""
[ -z "$TPID" ] || wait "$TPID" 2>/dev/null || true
secs=$(awk -v a="$t0" -v b="$(date +%s%N)" 'BEGIN{printf "%.1f", (b - a) / 1e9}')

if [ -s "$JOB/rc" ]; then
	rc=$(cat "$JOB/rc")
elif grep -q '^VM-GUEST-EXIT=' "$LOG"; then
	rc=$(sed -n 's/^VM-GUEST-EXIT=\([0-9]*\).*/\1/p' "$LOG" | tail -1)
elif [ "$qrc" = 124 ] || [ "$qrc" = 137 ]; then
	say "error: the board did not finish within ${HOST_LIMIT} s (host timeout); console: $LOG"
	tail -20 "$LOG" >&2
	exit 124
else
	say "error: the board stopped without reporting a status (qemu exit $qrc); console: $LOG"
	cat "$JOB/qemu.err" >&2
	tail -20 "$LOG" >&2
	exit 125
fi
[ -s "$JOB/qemu.err" ] && grep -v 'TCG doesn.t support requested feature' "$JOB/qemu.err" >&2 || true
say "guest script exited $rc after ${secs} s"
exit "$rc"
