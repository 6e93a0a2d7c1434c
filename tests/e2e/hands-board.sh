#!/bin/sh
# Guest script (tests/e2e/host.sh): hands-off operation on vkms, with the
# root file system read-only as on an overlay-root kiosk. The kiosk writes
# only to its cache, state and runtime folders (tmpfs here, as systemd's
# CacheDirectory=, StateDirectory= and RuntimeDirectory= would be on a
# read-only root). Checks: a poster is on the screen before the model;
# --status answers with the frame on screen; the udev rule matches a USB
# stick; a stick with a broken second model (and a device node and a pipe,
# passed over) changes nothing; a good stick's model
# is copied, and shown after the reload the import unit asks for. The two
# sticks (tests/e2e/sticks.sh) are plugged in at boot and unplugged here
# at once (their USB "authorized" switch), then plugged in one at a time.
# Prints the time from start to the poster and to the model, and from the
# stick appearing to its model on the screen. Ends with "vm: N passed,
# N failed".
set -u
. /repo/tests/e2e/lib.sh

ms() { awk '{ printf "%d", $1 * 1000 }' /proc/uptime; }
# usb_dev SERIAL: the stick's USB device folder in sysfs.
usb_dev() { grep -lx "$1" /sys/bus/usb/devices/*/serial 2>/dev/null | head -1 | xargs -r dirname; }
# stick_block SERIAL: its block device name (sda...), once the kernel has it.
stick_block() {
	for _b in /sys/class/block/sd?; do
		[ -e "$_b" ] || continue
		case $(readlink -f "$_b") in "$(readlink -f "$(usb_dev "$1")")"/*) basename "$_b" ;; esac
	done
}
plug() { echo "$2" >"$(usb_dev "$1")/authorized"; }
there() { for _s in "$@"; do [ -n "$(stick_block "$_s")" ] || return 1; done; }
gone() { for _s in "$@"; do [ -z "$(stick_block "$_s")" ] || return 1; done; }
# import SERIAL: what matcap-kiosk-import@.service does, with the block
# device the udev rule names: mount read-only, noexec; import; reload.
import() {
	_dev=$(stick_block "$1")
	_mnt=/run/matcap-kiosk-import/$_dev
	mkdir -p "$_mnt" || return 2
	mount -o ro,nosuid,nodev,noexec "/dev/$_dev" "$_mnt" || { dmesg | tail -5; return 2; }
	matcap-kiosk --config /share/kiosk.ini --import "$_mnt/matcap-kiosk" >>import.log 2>&1
	_rc=$?
	umount "$_mnt"
	[ $_rc = 0 ] && kill -HUP "$KPID"
	return $_rc
}
content_sum() { (cd /var/lib/matcap-kiosk && find . -type f | sort | xargs -r md5sum); }
# poster_shown OLD_FB: a framebuffer other than OLD_FB (the console's),
# one colour all over, the poster's (32, 96, 192): tests/e2e/poster.png is
# flat and of the screen's shape. The PPM's header is 16 bytes at 1024x768.
poster_shown() {
	_g=$(vm-grab -o poster.ppm 2>/dev/null)
	_fb=$(echo "$_g" | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
	[ -n "$_fb" ] && [ "$_fb" != "$1" ] && echo "$_g" | grep -q ' differ=0$' &&
		[ "$(od -A n -t u1 -j 16 -N 3 poster.ppm | tr -s ' ')" = " 32 96 192" ]
}

modprobe -a xhci_pci usb_storage sd_mod ext4 vfat nls_cp437 nls_ascii nls_utf8 nls_iso8859_1 2>&1
vm_check "the board has xhci, usb-storage, ext4 and vfat" sh -c \
	'lsmod | grep -q usb_storage && lsmod | grep -q ext4 && lsmod | grep -q vfat'
vm_check "both sticks are there" wait_until 30 there GOOD BROKEN
good=$(stick_block GOOD)

# The udev rule of the package, asked about the good stick.
mkdir -p /etc/udev/rules.d
cp /repo/systemd/61-matcap-kiosk-usb.rules /etc/udev/rules.d/
udevadm control --reload 2>/dev/null
udevadm test --action=add "/sys/class/block/$good" >udev-test.log 2>&1
vm_check "the udev rule starts the import unit for the stick" \
	grep -q "SYSTEMD_WANTS=matcap-kiosk-import@$good.service" udev-test.log
plug GOOD 0
plug BROKEN 0
vm_check "unplugged: the sticks are gone" wait_until 10 gone GOOD BROKEN

# The read-only root, with the service's folders writable as systemd
# gives them.
for d in /var/cache/matcap-kiosk /var/lib/matcap-kiosk /run/matcap-kiosk \
	/run/matcap-kiosk-import; do
	mkdir -p "$d"
done
export CACHE_DIRECTORY=/var/cache/matcap-kiosk STATE_DIRECTORY=/var/lib/matcap-kiosk \
	RUNTIME_DIRECTORY=/run/matcap-kiosk MESA_SHADER_CACHE_DIR=/var/cache/matcap-kiosk
cat >kiosk.ini <<EOF2
[display]
mode = 1024x768
poster = /repo/tests/e2e/poster.png
[kiosk]
include = /var/lib/matcap-kiosk/content/kiosk.ini
EOF2
mount -o remount,ro / || vm_log "cannot remount / read-only"
for d in $CACHE_DIRECTORY $STATE_DIRECTORY $RUNTIME_DIRECTORY /run/matcap-kiosk-import; do
	mount -t tmpfs -o mode=0755 tmpfs "$d"
done
vm_check "the root is read-only" sh -c '! touch /probe 2>/dev/null'

# The poster first, then the model.
console_fb=$(crtc_fb)
start=$(ms)
kiosk_start kiosk.log --config /share/kiosk.ini --keyboard none
poster_at=""
until has kiosk.log "ready: the first frame" || ! kiosk_alive ||
	[ $(($(ms) - start)) -gt 90000 ]; do
	[ -z "$poster_at" ] && poster_shown "${console_fb:-none}" && poster_at=$(ms)
	sleep 0.05
done
ready_at=$(ms)
vm_check "the poster is on the screen before the model" test -n "$poster_at"
echo "start to poster on screen: $((${poster_at:-$ready_at} - start)) ms; to the model: $((ready_at - start)) ms (polled every 0.05 s)"
vm_check "then the model (a new frame)" wait_until 30 shows_new_frame none
vm_check "--status answers on a read-only root" sh -c 'matcap-kiosk --status >status.json'
vm-grab -o screen.png >/dev/null 2>&1
vm_check "--status's frame is the screen's" matches screen.png /run/matcap-kiosk/frame.png
cp /run/matcap-kiosk/frame.png knot.png 2>/dev/null
before=$(content_sum)

# A stick with a broken model: refused, nothing changed, the knot stays.
plug BROKEN 1
wait_until 30 there BROKEN
import BROKEN
rc=$?
vm_check "the broken stick is refused (exit $rc)" test $rc = 1
vm_check "... for its second model, which does not load" \
	grep -q "matcap-kiosk/sphere.glb: the model does not load" import.log
vm_check "... its device node (nodev) and pipe passed over, not opened" sh -c "
	grep -q 'null.png: a device node, not a plain file: skipped' import.log &&
	grep -q 'p.bin: a pipe (FIFO), not a plain file: skipped' import.log"
vm_check "... and changes nothing" test "$(content_sum)" = "$before"
vm_check "... the kiosk shows the knot still" grep -q '"model": null' status.json
plug BROKEN 0

# The good stick: appears, is imported, its model shown.
fb=$(crtc_fb)
t0=$(ms)
plug GOOD 1
wait_until 30 there GOOD
import GOOD
rc=$?
vm_check "the good stick is imported (exit $rc)" test $rc = 0
vm_check "the kiosk reloads with it" wait_log 60 kiosk.log "reload: done"
vm_check "a new frame is on the screen" wait_until 30 shows_new_frame "$fb"
echo "USB stick appearing to its model on screen: $(($(ms) - t0)) ms"
matcap-kiosk --status >status2.json 2>&1
vm_check "--status names the stick's model" \
	grep -q '"model": "/var/lib/matcap-kiosk/content/model/sphere.gltf"' status2.json
vm_check "... and its buffer was copied from the stick's subfolder" \
	test -f /var/lib/matcap-kiosk/content/model/buffers/sphere.bin
vm_check "the frame shows another picture than the knot" \
	sh -c '! imgdiff --tol 8 --share 0.005 knot.png /run/matcap-kiosk/frame.png >/dev/null'
vm_check "the prepared mesh is cached in CacheDirectory" \
	sh -c 'ls /var/cache/matcap-kiosk | grep -q .'
kiosk_stop TERM
vm_check "the kiosk ends cleanly on a read-only root (exit $KRC)" test "$KRC" = 0
vm_check "it logged no error" sh -c '! grep -q "error:" kiosk.log'
for d in $CACHE_DIRECTORY $STATE_DIRECTORY $RUNTIME_DIRECTORY /run/matcap-kiosk-import; do
	umount "$d"
done
mount -o remount,rw /
show kiosk.log import.log | head -60
vm_summary
