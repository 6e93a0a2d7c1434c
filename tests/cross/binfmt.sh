#!/bin/sh
# Lets this machine run ARCH's programs in a chroot (mmdebstrap's roots of
# another architecture): qemu-user-static's binfmt handler for ARCH,
# registered with the kernel unless it already is. The handlers come with
# the F flag (the interpreter is opened now, so it need not exist inside
# the chroot). A machine without systemd-binfmt running (a container, CI)
# has them installed but not registered, sometimes without binfmt_misc
# mounted: both are done here. Needs root.
# Usage: tests/cross/binfmt.sh ARCH
set -eu
arch=$1
case $arch in
arm64) name=qemu-aarch64 ;;
armhf) name=qemu-arm ;;
*) [ "$arch" = "$(dpkg --print-architecture)" ] && exit 0
	echo "binfmt.sh: no qemu handler named for $arch" >&2; exit 2 ;;
esac
dir=/proc/sys/fs/binfmt_misc
[ -e "$dir/register" ] || mount -t binfmt_misc binfmt_misc "$dir"
if [ ! -e "$dir/$name" ]; then
	conf=/usr/lib/binfmt.d/$name.conf
	[ -e "$conf" ] || { echo "binfmt.sh: $conf missing: run make deps-deb" >&2; exit 1; }
	cat "$conf" >"$dir/register"
fi
grep -qx enabled "$dir/$name" || echo 1 >"$dir/$name"
# The proof: a program of that architecture runs.
arch-test "$arch" >/dev/null || { echo "binfmt.sh: $arch programs still do not run" >&2; exit 1; }
