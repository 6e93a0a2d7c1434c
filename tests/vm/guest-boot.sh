#!/bin/sh
# Second stage of the virtual board's boot, run as root by /init from the
# 9p job share (/vm).  Loads the drivers, starts udev, mounts the repo and the
# share, runs the guest script with a timeout, reports its exit status and
# powers off.  /vm/env (written by run.sh) sets VM_TIMEOUT, VM_HAVE_SHARE and
# VM_ARGS (the script's arguments, shell-quoted).
set -u
export PATH=/usr/local/bin:/usr/sbin:/usr/bin
export HOME=/root XDG_RUNTIME_DIR=/run/user/0 TERM=dumb LANG=C.UTF-8 LIBCAMERA_LOG_NO_COLOR=1
mkdir -p /run/user/0 && chmod 700 /run/user/0
VM_TIMEOUT=300 VM_HAVE_SHARE=0 VM_ARGS=
. /vm/env

say() { echo "[vm] $*"; }
finish() {
	echo "$1" >/vm/rc
	sync
	echo "VM-GUEST-EXIT=$1"
	poweroff -f
}

t_start=$(cut -d' ' -f1 /proc/uptime)
modprobe configfs && mount -t configfs configfs /sys/kernel/config
mount -t debugfs debugfs /sys/kernel/debug 2>/dev/null || true
failed=""
modprobe vkms enable_writeback=1 enable_cursor=1 enable_overlay=1 || failed="$failed vkms"
modprobe gpio-sim || failed="$failed gpio-sim"
modprobe vimc || failed="$failed vimc"
modprobe -a uinput evdev || failed="$failed uinput/evdev"
[ -z "$failed" ] || say "warning: could not load:$failed"

mount -t 9p -o trans=virtio,version=9p2000.L,msize=1048576,cache=loose,ro repo /repo ||
	say "warning: repo share not mounted"
if [ "$VM_HAVE_SHARE" = 1 ]; then
	mount -t 9p -o trans=virtio,version=9p2000.L,msize=1048576,cache=none share /share ||
		{ say "error: cannot mount the share"; finish 125; }
fi

# libcamera 0.0.3 only lists devices that udev has initialised.
# Names resolved early, so the rules' GROUP="video" etc. apply (the
# initramfs has Debian's system groups): /dev/dri/card0 is root:video 0660
# as on a real Debian system, and permission tests mean something.
/usr/lib/systemd/systemd-udevd --daemon --resolve-names=early 2>/dev/null ||
	say "warning: systemd-udevd did not start"
udevadm trigger --type=subsystems --action=add
udevadm trigger --type=devices --action=add
udevadm settle --timeout=30 || say "warning: udevadm settle timed out"
ip link set lo up 2>/dev/null || true
say "board up in ${t_start}+$(awk -v s="$t_start" '{printf "%.1f", $1 - s}' /proc/uptime) s (kernel $(uname -r))"

export VM_SHARE=/share VM_REPO=/repo VM_LIB=/vm/guest-lib.sh
cd /share 2>/dev/null || cd /
eval "timeout -s TERM -k 5 $VM_TIMEOUT /bin/sh /vm/guest-script $VM_ARGS" </dev/null
rc=$?
[ $rc = 143 ] && say "guest script killed after ${VM_TIMEOUT} s"
finish $rc
