#!/bin/sh
# Guest script (tests/e2e/host.sh): HDMI-CEC on the virtual board. vivid
# emulates an HDMI input, whose CEC adapter plays the TV (cec-ctl --tv,
# logical address 0), and an HDMI output behind it, which the kiosk's CEC
# code (through tests/tools/cec_power.c) claims as a playback device. The
# TV's side records what it receives. Checks: standby and wake arrive as
# <Standby>, <Image View On> and <Active Source> with the output's
# physical address; a TV that is gone (its adapter unconfigured) gives a
# non-zero status and one journal line for several changes, no retry loop.
# Then the kiosk itself on vkms with [power] cec = on: its screen sleeps
# after blank_after and the TV gets <Standby>; a key wakes both.
# Ends with "vm: N passed, N failed".
set -u
# shellcheck source=lib.sh
. /repo/tests/e2e/lib.sh

modprobe vivid n_devs=1 num_inputs=1 input_types=0x3 num_outputs=1 output_types=0x1 ||
	echo "FAIL - vivid loads"
wait_for /dev/cec1 20
vm_check "vivid gives a CEC adapter for its HDMI input and one for its output" \
	test -c /dev/cec0 -a -c /dev/cec1
# Which adapter is the input (the TV side) is told by cec-ctl.
tv=/dev/cec0 out=/dev/cec1
cec-ctl -d "$tv" --tv >tv-config.log 2>&1
vm_check "the input's adapter is configured as a TV" grep -q 'Logical Address.*: 0' tv-config.log
cec-ctl -d "$tv" --monitor-all >tv-monitor.log 2>&1 &
monitor=$!
sleep 1

cec_power "$out" off >off.log 2>&1
vm_check "standby is acknowledged by the TV (exit $?)" test $? = 0
cec_power "$out" on >on.log 2>&1
vm_check "wake is acknowledged by the TV" test $? = 0
sleep 1
kill "$monitor" 2>/dev/null
cat tv-monitor.log
vm_check "the TV received <Standby>" grep -qi 'STANDBY' tv-monitor.log
vm_check "the TV received <Image View On>" grep -qi 'IMAGE_VIEW_ON' tv-monitor.log
vm_check "the TV saw <Active Source>" grep -qi 'ACTIVE_SOURCE' tv-monitor.log
vm_check "the kiosk claimed a playback device address" grep -q 'logical address 4' off.log

# The kiosk drives the TV itself: blank_after (minutes) puts the screen to
# sleep and the TV to standby; a key wakes the screen and the TV.
cat >cec.ini <<EOF2
[display]
mode = 640x480
[power]
blank_after = 0.1
cec = on
cec_device = $out
EOF2
cec-ctl -d "$tv" --monitor-all >kiosk-tv.log 2>&1 &
monitor=$!
vkbd_start
kiosk_start cec-kiosk.log --config cec.ini --keyboard auto
wait_log 90 cec-kiosk.log "ready: the first frame is on the screen"
vm_check "the kiosk: the screen sleeps after blank_after" wait_until 60 has cec-kiosk.log "screen off"
vm_check "the kiosk: the TV received <Standby>" wait_until 10 grep -qi STANDBY kiosk-tv.log
vkbd_press SPACE
vm_check "the kiosk: a key wakes the screen" wait_until 20 has cec-kiosk.log "screen on"
vm_check "the kiosk: the TV received <Image View On>" \
	wait_until 10 grep -qi IMAGE_VIEW_ON kiosk-tv.log
kiosk_stop TERM
vm_check "the kiosk: SIGTERM exits 0" test "$KRC" = 0
vkbd_stop
kill "$monitor" 2>/dev/null
grep -i "cec" cec-kiosk.log

# The TV goes away: its adapter stops answering.
cec-ctl -d "$tv" --clear >/dev/null 2>&1
cec_power "$out" off on off >gone.log 2>&1
rc=$?
cat gone.log
vm_check "a silent TV: non-zero status ($rc)" test "$rc" = 1
vm_check "a silent TV: said once for three changes" \
	test "$(grep -c 'did not take' gone.log)" = 1
vm_summary
