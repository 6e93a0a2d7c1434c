#!/bin/sh
# Guest script for the virtual board (tests/vm): the live camera as the
# matcap, end to end. Run it with
#   make vm-test VM_TESTS=tests/e2e/camera.sh \
#       VM_BINS="./matcap-kiosk build/tools/hues build/tools/imgdiff"
# vimc's Sensor B through libcamera, drawn by the kiosk (kms backend) on
# vkms and read back from the CRTC: the test pattern's colour bars must be
# on the model. Then vimc is unbound under the running kiosk: it must go
# on showing the image matcap (the same picture as a software render of
# the scene), and wear the camera again once vimc is bound back.
# Writes camera.png, image.png, reference.png, again.png, kiosk.log,
# stats.txt and kernel.log into the share. Ends with "vm: N passed, N failed".
set -u
# shellcheck source=../vm/guest-lib.sh
. "$VM_LIB"

scene="--size 1024x768 --matcap /repo/matcaps/gold.png --mode view --attract-after 0"
vimc=/sys/bus/platform/drivers/vimc

# What the CRTC shows now, into FILE; true when it has MIN..MAX bar hues.
shows_hues() { # FILE MIN MAX
	vm-grab -o "$1" >/dev/null && hues "$1" "$2" "$3" >/dev/null
}

vm_check "libcamera lists vimc's Sensor B (cam --list)" \
	sh -c 'cam --list 2>/dev/null | grep -q "vimc.0 Sensor B"'

# --status answers in the runtime folder systemd would make.
mkdir -p /run/matcap-kiosk
# shellcheck disable=SC2086
matcap-kiosk --backend kms $scene --stats -v >stats.txt 2>kiosk.log &
kiosk=$!
# The first frames are slow under TCG (llvmpipe compiles the shaders).
wait_until 180 grep -q "frames reach the GPU" kiosk.log
streams=$(sed -n 's/.*camera: \(.* streams .*\)/\1/p' kiosk.log | head -1)
vm_check "the kiosk streams the camera (${streams:-nothing})" test -n "$streams"
path=$(sed -n 's/.*frames reach the GPU by \(.*\)/\1/p' kiosk.log | head -1)
vm_check "the log names how frames reach the GPU (${path:-nothing})" test -n "$path"
wait_until 60 shows_hues camera.png 5 6
vm_check "the camera's colour bars are on the model" hues camera.png 5 6
# No camera frame is ever written to a file: --status writes no frame.png.
matcap-kiosk --status >status.json 2>&1
vm_check "--status answers while the camera is the matcap" grep -q '"camera": true' status.json
vm_check "and says \"frame\": null" grep -q '"frame": null' status.json
vm_check "and no frame.png in the runtime folder" test ! -e /run/matcap-kiosk/frame.png

echo vimc.0 >"$vimc/unbind"
wait_until 30 grep -Eq "sent no frame|was removed" kiosk.log
vm_check "the kiosk notices the camera went" grep -Eq "sent no frame|was removed" kiosk.log
wait_until 60 shows_hues image.png 0 1
vm_check "the model wears the image matcap again" hues image.png 0 1
vm_check "the kiosk is still running" kill -0 $kiosk
# The same scene drawn in software, as the kiosk would with no camera.
# shellcheck disable=SC2086
matcap-kiosk --backend osmesa $scene --camera off -q --output reference.png
vm_check "what it shows is the scene with the image matcap (vs. OSMesa)" \
	imgdiff --tol 8 --share 0.01 reference.png image.png

echo vimc.0 >"$vimc/bind"
wait_until 120 shows_hues again.png 5 6
vm_check "the camera is picked up again once it is back" hues again.png 5 6

kill -TERM $kiosk
wait $kiosk
status=$?
vm_check "SIGTERM ends the kiosk with status 0 (got $status)" test "$status" = 0
vm_check "--stats reports the camera frames" grep -q "^camera frames_shown [1-9]" stats.txt
cat stats.txt
vm_check "no camera helper is left behind" \
	sh -c '! grep -sq "^matcap-kiosk-camera" /proc/[0-9]*/cmdline'
dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
