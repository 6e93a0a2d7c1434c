#!/bin/sh
# /init of the virtual board's initramfs (baked in by build.sh).  It only
# mounts the basics and the 9p job share, then hands over to the job's
# guest-boot.sh, which run.sh copies in fresh for every run, so changes to
# the boot sequence do not need a new initramfs.
export PATH=/usr/local/bin:/usr/sbin:/usr/bin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs -o mode=0755 devtmpfs /dev
mkdir -p /dev/pts /dev/shm
mount -t devpts -o gid=5,mode=620 devpts /dev/pts
mount -t tmpfs -o mode=1777 tmpfs /dev/shm
mount -t tmpfs -o mode=0755 tmpfs /run
mount -t tmpfs -o mode=1777 tmpfs /tmp
hostname -F /etc/hostname

fail() {
	echo "[vm-init] error: $*"
	echo "VM-GUEST-EXIT=125"
	poweroff -f
}

modprobe -a virtio_pci 9pnet_virtio 9p || fail "cannot load the 9p modules"
i=0
until mount -t 9p -o trans=virtio,version=9p2000.L,msize=1048576,cache=none vmjob /vm 2>/dev/null; do
	i=$((i + 1))
	[ $i -lt 50 ] || fail "cannot mount the 9p share 'vmjob' (run the board with tests/vm/run.sh)"
	sleep 0.1
done
[ -r /vm/guest-boot.sh ] || fail "/vm/guest-boot.sh missing from the job share"
exec /bin/sh /vm/guest-boot.sh
