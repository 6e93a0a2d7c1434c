#!/bin/sh
# Guest script: proves the virtual board works (display, writeback, GPIO,
# camera, Mesa on KMS).  Run it with
#   tests/vm/run.sh --share tests/vm/cache/smoke -- tests/vm/smoke.sh
# Writes writeback.png, kmscube.png, camera-frame.bin, kmscube.log and
# kernel.log into the share.  Ends with "vm: N passed, N failed".
set -u
# shellcheck source=guest-lib.sh
. "$VM_LIB"
export LIBCAMERA_LOG_LEVELS='*:ERROR'

# ---- display: vkms
vm_check "/dev/dri/card0 appears" wait_for /dev/dri/card0 10
card=$(drm_card || true)
vm_check "card0 is vkms ($card)" test "$card" = /dev/dri/card0
vm_check "Virtual-1 connected" test "$(drm_connector_status Virtual-1)" = connected
vm_check "a writeback connector exists" test -e /sys/class/drm/card0-Writeback-1
modetest -M vkms -c >/tmp/modetest.txt 2>&1
vm_check "modetest lists Virtual-1 connected" grep -Eq 'connected[[:space:]]+Virtual-1' /tmp/modetest.txt
vm_check "writeback capture equals the pattern shown (vm-grab -w)" vm-grab -w -o writeback.png

# ---- GPIO: gpio-sim through configfs, seen by libgpiod tools
chip=$(gpiosim_make smoke 4 btn-prev btn-next btn-mode btn-cam)
vm_check "gpio-sim chip /dev/$chip with 4 lines" sh -c "gpiodetect | grep -q '^$chip \[smoke\] (4 lines)'"
gpiosim_pull smoke 1 up
vm_check "gpioget reads a pull-up as 1" test "$(gpioget "$chip" 1)" = 1
gpiosim_pull smoke 1 down
vm_check "gpioget reads a pull-down as 0" test "$(gpioget "$chip" 1)" = 0
gpiosim_pull smoke 2 up
gpiomon --num-events=1 --falling-edge "$chip" 2 >/tmp/gpiomon.txt 2>&1 &
mon=$!
wait_until 10 sh -c "gpioinfo $chip | grep -q gpiomon"
gpiosim_pull smoke 2 down
( sleep 10; kill $mon 2>/dev/null ) &
watchdog=$!
wait $mon
kill $watchdog 2>/dev/null
vm_check "gpiomon sees the falling edge of a button press" grep -q 'FALLING EDGE offset: 2' /tmp/gpiomon.txt
# The older gpio-mockup: lines driven through debugfs.
gpiomockup_load -1,4
mock=$(gpiodetect | sed -n 's/^\(gpiochip[0-9]*\) \[gpio-mockup-A\].*/\1/p')
vm_check "gpio-mockup chip appears (${mock:-none})" test -n "$mock"
[ -z "$mock" ] || echo 1 >"/sys/kernel/debug/gpio-mockup/$mock/3"
vm_check "gpio-mockup line pulled up through debugfs reads 1" test "$(gpioget "${mock:-none}" 3 2>/dev/null)" = 1

# ---- keyboard: uinput device driven by vm-key
vkbd_start
ev=${VKBD_DEV:-}
vm_check "virtual keyboard appears (${ev:-none})" test -c "${ev:-/nonexistent}"
if [ -n "$ev" ]; then
	dd if="$ev" of=/tmp/keys.bin bs=24 count=4 2>/dev/null &
	reader=$!
	sleep 0.3
	vkbd_press ENTER
	( sleep 10; kill $reader 2>/dev/null ) &
	watchdog=$!
	wait $reader
	kill $watchdog 2>/dev/null
fi
vm_check "a key press reaches evdev (press, syn, release, syn)" test "$(wc -c </tmp/keys.bin 2>/dev/null)" = 96
vkbd_stop

# ---- camera: vimc through libcamera (needs udev's database)
vm_check "vimc media controller is registered" vimc_ready
vm_check "vimc media and video nodes exist" sh -c 'ls /dev/media0 /dev/video0 /dev/video1 /dev/video2 >/dev/null'
vm_check "udev initialised the video nodes" sh -c 'ls /run/udev/data/c81:* >/dev/null 2>&1'
cam --list >/tmp/cam-list.txt 2>&1
cat /tmp/cam-list.txt
vm_check "cam --list lists a vimc camera" grep -q "^1: .*vimc" /tmp/cam-list.txt
rm -f /tmp/frame-*
cam -c 1 --capture=3 -s width=640,height=480 --file=/tmp/frame-#.bin >/tmp/cam-capture.txt 2>&1
# vimc adjusts 640x480 to 636x480 (its scaler's step); accept what it chose.
vm_check "cam captures 3 frames of about 640x480 BGR888" sh -c '[ "$(ls /tmp/frame-*.bin 2>/dev/null | wc -l)" = 3 ] && [ "$(wc -c </tmp/frame-cam0-stream0-000002.bin)" -ge 900000 ]'
cp /tmp/frame-cam0-stream0-000002.bin camera-frame.bin 2>/dev/null || cat /tmp/cam-capture.txt

# ---- Mesa on KMS: kmscube (llvmpipe through kms_swrast/GBM on vkms)
# Debian's kmscube passes DRM_FORMAT_MOD_INVALID from gbm_bo_get_modifier()
# with DRM_MODE_FB_MODIFIERS, which vkms refuses ("failed to set mode:
# Invalid argument"); the shim reports LINEAR instead.  kmscube also quits
# on input from stdin, so it gets a FIFO nobody writes.
before=$(vm-grab | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
mkfifo /tmp/kmscube.in
LD_PRELOAD=/usr/lib/vm/libgbm-linear.so timeout 90 kmscube -D /dev/dri/card0 -c 60 \
	<>/tmp/kmscube.in >kmscube.log 2>&1 &
kc=$!
# vm-grab lets go of DRM master at once, but kmscube must be the one that
# opens the display first: no readback until the kernel lists it as master.
wait_until 60 awk '$1 == "kmscube" && $4 == "y" { found = 1 } END { exit !found }' \
	/sys/kernel/debug/dri/0/clients
# Wait until kmscube's framebuffer is on the CRTC with a cube drawn in it (its
# first frame is a blank buffer, and the first draw compiles the shaders),
# then save what the CRTC shows.
kms_drawn() {
	_g=$(vm-grab)
	_fb=$(echo "$_g" | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
	[ -n "$_fb" ] && [ "$_fb" != "$before" ] && echo "$_g" | grep -q 'differ=[1-9][0-9][0-9][0-9]'
}
wait_until 60 kms_drawn
grabbed=$(vm-grab -o kmscube.png)
echo "$grabbed"
wait $kc
kc_rc=$?
grep -E 'Rendered|failed|Using modifier' kmscube.log
vm_check "kmscube ran 60 frames on vkms (exit $kc_rc)" sh -c "[ $kc_rc = 0 ] && grep -q '^Rendered' kmscube.log"
vm_check "the CRTC showed kmscube's frame (not a flat screen)" \
	sh -c "echo '$grabbed' | grep -q 'differ=[1-9][0-9][0-9][0-9]'"
fps=$(sed -n 's/^Rendered .*(\([0-9.]*\) fps)$/\1/p' kmscube.log | tail -1)
echo "kmscube fps on vkms (llvmpipe under TCG): ${fps:-?}"

# ---- the kernel stayed healthy
dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'

vm_summary
