#!/bin/sh
# Guest script (tests/e2e/host.sh): SIGHUP opens the input devices again
# when their section of kiosk.ini changed, as --help says. [buttons] moves
# the left button from GPIO17 to GPIO5 on a gpio-sim chip: the old line is
# given back, the new one is read, the old one no more. [keyboard] goes
# from none to auto: the virtual keyboard is found and its keys act. A
# reload with the same sections opens nothing again. [camera] changes
# (mirror): the camera (vimc's Sensor B) is started again, with one helper
# process, and is back on the model. Ends with "vm: N passed, N failed".
set -u
. "$VM_LIB"

chip=$(gpiosim_make buttons 5 GPIO17 GPIO27 GPIO22 GPIO5 GPIO6)
sys=$(gpiosim_sysfs buttons)
for l in 0 1 2 3 4; do echo pull-up >"$sys/sim_gpio$l/pull"; done
GPIO17=0 GPIO5=3

printf '%s\n' '[display]' 'backend = kms' 'mode = 640x480' '[kiosk]' 'attract_after = 0' \
	'[buttons]' 'left = GPIO17' 'right = none' 'select = none' '[keyboard]' 'device = none' \
	'[camera]' 'enabled = off' >reload.ini
# click LINE: a clean press and release.
click() {
	echo pull-down >"$sys/sim_gpio$1/pull"
	sleep 0.5
	echo pull-up >"$sys/sim_gpio$1/pull"
	sleep 0.5
}
# libgpiod 2's gpioinfo takes the chip with -c (a bare word is a line's
# name) and prints the consumer as consumer="matcap-kiosk"; libgpiod 1's
# takes the chip alone and prints "matcap-kiosk".
c=
gpioinfo --version 2>/dev/null | grep -q ' v1\.' || c=-c
held_by_kiosk() { gpioinfo $c "$chip" | grep "\"$1\"" | grep -q 'matcap-kiosk'; }
reloads_done() { [ "$(grep -c 'reload: done' kiosk.log)" -ge "$1" ]; }

vkbd_start
matcap-kiosk --config reload.ini -v >kiosk.log 2>&1 &
kpid=$!
vm_check "kiosk shows its first frame on KMS" wait_until 120 grep -q "ready: the first frame" kiosk.log
vm_check "the left button on GPIO17" held_by_kiosk GPIO17
vm_check "no keyboard (device = none)" sh -c "! grep -q 'keyboard vm-key keyboard' kiosk.log"

sed -i -e 's/^left = GPIO17/left = GPIO5/' -e 's/^device = none/device = auto/' reload.ini
kill -HUP $kpid
vm_check "reload with new [buttons] and [keyboard] is done" wait_until 120 reloads_done 1
vm_check "... it says it opens the buttons again" \
	grep -q "reload: \[buttons\] changed: opening the buttons again" kiosk.log
vm_check "... and the keyboards" \
	grep -q "reload: \[keyboard\] or \[knob\] changed: opening the keyboards and knobs again" kiosk.log
vm_check "GPIO17 is given back" sh -c "gpioinfo $c $chip | grep -q '\"GPIO17\"' &&
	! gpioinfo $c $chip | grep '\"GPIO17\"' | grep -q matcap-kiosk"
vm_check "GPIO5 is the left button now" held_by_kiosk GPIO5
click $GPIO17
click $GPIO5
vm_check "a press on GPIO5 is read" wait_until 30 grep -q "(GPIO5 on $chip): pressed at" kiosk.log
vm_check "a press on GPIO17 is not" sh -c "! grep -q '(GPIO17 on $chip): pressed at' kiosk.log"
vm_check "the keyboard is found" grep -q "keyboard vm-key keyboard" kiosk.log
vkbd_press M
vm_check "... and its keys act (m: the next mode)" wait_until 30 grep -q "^matcap-kiosk: mode " kiosk.log

kill -HUP $kpid
vm_check "a reload with the same sections is done" wait_until 120 reloads_done 2
vm_check "... and opens nothing again" sh -c "
	[ \$(grep -c 'opening the buttons again' kiosk.log) = 1 ] &&
	[ \$(grep -c 'opening the keyboards and knobs again' kiosk.log) = 1 ]"
vm_check "GPIO5 is still the left button" held_by_kiosk GPIO5
vm_check "still running" kill -0 $kpid
kill -TERM $kpid
wait $kpid
vm_check "SIGTERM exits 0" test $? = 0
vkbd_stop

# What the CRTC shows now, into FILE; true when it has MIN..MAX bar hues.
shows_hues() { # FILE MIN MAX
	vm-grab -o "$1" >/dev/null && hues "$1" "$2" "$3" >/dev/null
}
helpers() { grep -ls "^matcap-kiosk-camera" /proc/[0-9]*/cmdline | wc -l; }
printf '%s\n' '[keyboard]' 'device = none' '[camera]' 'enabled = on' 'mirror = false' >camera.ini
matcap-kiosk --backend kms --size 1024x768 --matcap /repo/matcaps/gold.png --mode view \
	--attract-after 0 --config camera.ini -v >camera.log 2>&1 &
kpid=$!
# The first frames are slow under TCG (llvmpipe compiles the shaders).
wait_until 180 grep -q "frames reach the GPU" camera.log
wait_until 60 shows_hues camera1.png 5 6
vm_check "the camera's colour bars are on the model" hues camera1.png 5 6
sed -i 's/^mirror = false/mirror = true/' camera.ini
kill -HUP $kpid
vm_check "a reload with new [camera] is done" wait_until 120 grep -q "reload: done" camera.log
vm_check "... it says it starts the camera again" \
	grep -q "reload: \[camera\] changed: starting the camera again" camera.log
wait_until 120 sh -c "[ \$(grep -c 'frames reach the GPU' camera.log) -ge 2 ]"
wait_until 120 shows_hues camera2.png 5 6
vm_check "the camera is back on the model" hues camera2.png 5 6
vm_check "one camera helper runs ($(helpers))" test "$(helpers)" = 1
kill -TERM $kpid
wait $kpid
vm_check "SIGTERM exits 0" test $? = 0
vm_check "no camera helper is left behind" test "$(helpers)" = 0
dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
