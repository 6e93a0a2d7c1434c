#!/bin/sh
# Guest script (tests/e2e/host.sh boots it with tests/vm/run.sh --outputs 2):
# one matcap-kiosk drives both outputs of one card ([display] outputs),
# each showing its own view.  vkms in 6.1 has one CRTC, so the card is
# QEMU's virtio-gpu with two outputs beside it: its connectors are
# Virtual-2 and Virtual-3 (Linux 6.1 numbers the connectors of a type
# across all cards; vkms, loaded first, has Virtual-1), one CRTC each.
# On the atomic and the legacy path: both CRTCs scan out the kiosk's
# frames, each matching its OSMesa reference (--as-output, the same
# settings file, /share/ref/outputs.ini: Virtual-3 shows view = mirror)
# and unlike the other; Virtual-3 unplugged and plugged back in while
# Virtual-2 goes on, the same process.  Then outputs = all takes both and
# Virtual-2 keeps flipping while Virtual-3 is out (attract mode), and an
# output that does not exist is named with the real ones while the other
# runs.  The card held by another program: the kiosk waits, then takes
# both outputs.  Last, the screen's power: blank_after puts both CRTCs to sleep
# (ACTIVE 0), a key wakes both with new frames.  Ends with "vm: N passed,
# N failed".
#
# virtio-gpu sends no uevent when the sysfs status is forced either (as
# vkms, tests/e2e/kms-hotplug.sh), so a cable is the status plus a change
# event of the card.  Virtual-3 is connected only because run.sh forces it
# (video=Virtual-3:e): QEMU without a display enables output 0 alone, so
# "plugged in" is status "on", not "detect" (which reads QEMU's "off").
set -u
. /repo/tests/e2e/lib.sh

INI=$REF/outputs.ini
A=Virtual-2 B=Virtual-3
CARD=$(drm_card_of virtio_gpu)
vm_check "the board has a virtio-gpu card beside vkms (${CARD:-none})" test -n "$CARD"
[ -n "$CARD" ] || { vm_summary; exit 1; }
vm_check "vkms stays /dev/dri/card0" test "$(drm_card)" = /dev/dri/card0
CA=$(drm_crtc_of "$CARD" $A)
CB=$(drm_crtc_of "$CARD" $B)
vm_check "$A and $B are connected, each with a CRTC of its own (${CA:-none}, ${CB:-none})" \
	sh -c "[ \"\$(cat /sys/class/drm/${CARD##*/}-$A/status /sys/class/drm/${CARD##*/}-$B/status)\" = \
		\"\$(printf 'connected\nconnected')\" ] && [ -n '$CA' ] && [ -n '$CB' ] && [ '$CA' != '$CB' ]"

# fb_of CRTC: the framebuffer it scans out now ("" for none).
fb_of() { vm-grab -D "$CARD" -c "$1" 2>/dev/null | sed -n 's/.* fb \([0-9]*\) .*/\1/p'; }
# shows_new CRTC OLD_FB: another framebuffer than OLD_FB, drawn on.
shows_new() {
	_g=$(vm-grab -D "$CARD" -c "$1" 2>/dev/null)
	_fb=$(echo "$_g" | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
	[ -n "$_fb" ] && [ "$_fb" != "$2" ] && echo "$_g" | grep -q 'differ=[1-9][0-9][0-9][0-9]'
}
grab() { vm-grab -D "$CARD" -c "$1" -o "$2" >/dev/null; }
# cable in|out: Virtual-3's.
cable() {
	case $1 in in) echo on ;; out) echo off ;; esac >"/sys/class/drm/${CARD##*/}-$B/status"
	echo change >"/sys/class/drm/${CARD##*/}/uevent"
}
one_kiosk() { [ "$(pidof matcap-kiosk)" = "$KPID" ]; }
# flipping CRTC: its framebuffer changes twice within 30 s.
flipping() {
	_f0=$(fb_of "$1")
	wait_until 15 sh -c "[ \"\$(vm-grab -D $CARD -c $1 2>/dev/null | sed -n 's/.* fb \([0-9]*\) .*/\1/p')\" != '$_f0' ]" || return 1
	_f1=$(fb_of "$1")
	[ -n "$_f1" ] && wait_until 15 sh -c "[ \"\$(vm-grab -D $CARD -c $1 2>/dev/null | sed -n 's/.* fb \([0-9]*\) .*/\1/p')\" != '$_f1' ]"
}
modesets() { grep -c "kms: $1 640x480@60" "$2"; }

# ---- both outputs, each its own view, unplugged and back: atomic, legacy
for api in atomic legacy; do
	oa=$(fb_of "$CA") ob=$(fb_of "$CB")
	kiosk_start "$api.log" --config "$INI" --device "$CARD" --kms-api $api
	wait_log 90 "$api.log" "ready: the first frame is on the screen"
	wait_until 30 shows_new "$CA" "${oa:-none}" && grab "$CA" "$api-$A.png"
	wait_until 30 shows_new "$CB" "${ob:-none}" && grab "$CB" "$api-$B.png"
	show "$api.log"
	vm_check "$api: $A 640x480@60 set, $api modesetting" has "$api.log" "kms: $A 640x480@60, $api modesetting"
	vm_check "$api: $B 640x480@60 set, $api modesetting" has "$api.log" "kms: $B 640x480@60, $api modesetting"
	vm_check "$api: one kiosk process drives both" one_kiosk
	vm_check "$api: $A shows its view (matches --as-output $A)" matches "$REF/outputs-$A.png" "$api-$A.png"
	vm_check "$api: $B shows its view, mirror (matches --as-output $B)" \
		matches "$REF/outputs-$B.png" "$api-$B.png"
	vm_check "$api: the two outputs show different pictures" \
		sh -c "! imgdiff --tol 8 --share 0.005 $api-$A.png $api-$B.png >/dev/null"

	# Virtual-3 unplugged: said, its CRTC no longer shows our frame,
	# Virtual-2 still shows its view.
	shown=$(fb_of "$CB")
	cable out
	wait_log 30 "$api.log" "kms: $B was disconnected"
	vm_check "$api: $B unplugged: the log says so, the other goes on" \
		has "$api.log" "kms: $B was disconnected; the other outputs go on"
	vm_check "$api: $B unplugged: its CRTC scans out no frame of ours" \
		sh -c "[ \"\$(vm-grab -D $CARD -c $CB 2>/dev/null | sed -n 's/.* fb \([0-9]*\) .*/\1/p')\" != '$shown' ]"
	grab "$CA" "$api-$A-alone.png"
	vm_check "$api: $B unplugged: $A still shows its view" matches "$REF/outputs-$A.png" "$api-$A-alone.png"
	vm_check "$api: $B unplugged: the kiosk runs on" kiosk_alive

	# Plugged back in: its mode and its view again, the same process.
	cable in
	wait_until 60 sh -c "[ \$(grep -c 'kms: $B 640x480@60' $api.log) -ge 2 ]"
	wait_until 30 shows_new "$CB" none && grab "$CB" "$api-$B-again.png"
	vm_check "$api: $B plugged back in: its mode set again" test "$(modesets $B "$api.log")" = 2
	vm_check "$api: $B plugged back in: shows its view again" \
		matches "$REF/outputs-$B.png" "$api-$B-again.png"
	vm_check "$api: $B plugged back in: the same process" one_kiosk
	vm_check "$api: $A was set once" test "$(modesets $A "$api.log")" = 1
	kiosk_stop TERM
	vm_check "$api: SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0
done

# ---- outputs = all: both connectors; Virtual-2 keeps flipping while
# Virtual-3 is out (attract mode turns the model: a new frame per flip).
kiosk_start all.log --config "$INI" --device "$CARD" --outputs all --attract-after 0.1 \
	--attract-speed 45
wait_log 90 all.log "ready: the first frame is on the screen"
wait_until 30 grep -q "kms: $B 640x480@60" all.log
show all.log
vm_check "outputs = all: $A set" has all.log "kms: $A 640x480@60"
vm_check "outputs = all: $B set" has all.log "kms: $B 640x480@60"
vm_check "outputs = all: both CRTCs scan out the kiosk's frames" \
	sh -c "[ -n \"\$(vm-grab -D $CARD -c $CA 2>/dev/null | grep 'differ=[1-9][0-9][0-9][0-9]')\" ] &&
		[ -n \"\$(vm-grab -D $CARD -c $CB 2>/dev/null | grep 'differ=[1-9][0-9][0-9][0-9]')\" ]"
cable out
wait_log 30 all.log "kms: $B was disconnected"
vm_check "outputs = all: $B unplugged, said" has all.log "kms: $B was disconnected; the other outputs go on"
vm_check "outputs = all: $B unplugged: $A keeps flipping (its framebuffer changes)" flipping "$CA"
vm_check "outputs = all: $B unplugged: the kiosk runs on" kiosk_alive
cable in
wait_until 60 sh -c "[ \$(grep -c 'kms: $B 640x480@60' all.log) -ge 2 ]"
vm_check "outputs = all: $B plugged back in: flipping again" flipping "$CB"
vm_check "outputs = all: the same process" one_kiosk
kiosk_stop TERM
vm_check "outputs = all: SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

# ---- an output that does not exist: named with the real ones, left
# out; the other runs.
ob=$(fb_of "$CA")
kiosk_start wrong.log --config "$INI" --device "$CARD" --outputs "$A, Virtual-9"
wait_log 90 wrong.log "ready: the first frame is on the screen"
wait_until 30 shows_new "$CA" "${ob:-none}" && grab "$CA" "wrong-$A.png"
show wrong.log
vm_check "a wrong output: the error names it, the card and the real connectors" \
	sh -c "grep 'connector Virtual-9 does not exist on $CARD; the connectors are: ' wrong.log |
		grep $A | grep -q $B"
vm_check "a wrong output: left out, the other goes on" \
	has wrong.log "kms: \[display\] outputs: Virtual-9 is left out; the other outputs go on"
vm_check "a wrong output: $A set and shows its view" \
	sh -c "grep -q 'kms: $A 640x480@60' wrong.log && imgdiff --tol 8 --share 0.005 $REF/outputs-$A.png wrong-$A.png"
vm_check "a wrong output: the kiosk runs on" kiosk_alive
kiosk_stop TERM
vm_check "a wrong output: SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

# ---- the card held by another program (a desktop keeping DRM master):
# the kiosk waits with both outputs, and takes both once it lets go.
hold_start -D "$CARD" -m 640x480 -k
kiosk_start busy.log --config "$INI" --device "$CARD"
wait_log 60 busy.log "is held by"
vm_check "busy: says who holds $CARD and waits" has busy.log "kms: $CARD is held by"
vm_check "busy: keeps running" kiosk_alive
hold_stop
wait_log 60 busy.log "is free now: taking the display"
vm_check "busy: once free, a frame of the kiosk on $A" wait_until 30 shows_new "$CA" "${HOLD_FB:-none}"
vm_check "busy: once free, a frame of the kiosk on $B" wait_until 30 shows_new "$CB" "${HOLD_FB:-none}"
kiosk_stop TERM
vm_check "busy: SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

# ---- the screen's power on every output: blank_after puts both CRTCs
# to sleep (atomic ACTIVE 0, no flips), a key wakes both with new frames.
# actives: "CRTC ACTIVE" of each CRTC, one modetest call (-a: atomic
# properties, read without master; seconds on virtio-gpu's long mode
# lists). A CRTC's own line starts at the margin; its properties and
# their blobs' hex lines are indented.
actives() {
	modetest -D "$CARD" -a -p 2>/dev/null | awk '
		/^CRTCs:$/ { in_sec = 1; next } /^Planes:$/ { exit }
		in_sec && /^[0-9]+\t/ { cur = $1 }
		in_sec && $2 == "ACTIVE:" { want = cur; next }
		want != "" && $1 == "value:" { printf "%s%s %s", sep, want, $2; sep = " "; want = "" }'
}
both() { # 0|1: what both CRTCs' ACTIVE should read
	_act=$(actives)
	echo "ACTIVE: $_act"
	[ "$_act" = "$CA $1 $CB $1" ] || [ "$_act" = "$CB $1 $CA $1" ]
}
vkbd_start
kiosk_start power.log --config "$INI" --device "$CARD" --keyboard auto --blank-after 0.4 \
	--attract-after 0.1 --attract-speed 30
wait_log 90 power.log "ready: the first frame is on the screen"
wait_log 90 power.log "screen off: blanked"
wait_until 10 sh -c "grep -q 'kms: $A asleep' power.log && grep -q 'kms: $B asleep' power.log"
show power.log
vm_check "blank_after: both outputs said asleep" \
	sh -c "grep -q 'kms: $A asleep' power.log && grep -q 'kms: $B asleep' power.log"
vm_check "blank_after: both CRTCs inactive (atomic ACTIVE 0)" both 0
fa=$(fb_of "$CA") fb=$(fb_of "$CB")
vkbd_press SPACE
wait_log 20 power.log "screen on:"
vm_check "a key wakes both: a new frame on $A" wait_until 20 shows_new "$CA" "${fa:-none}"
vm_check "a key wakes both: a new frame on $B" wait_until 20 shows_new "$CB" "${fb:-none}"
vm_check "a key wakes both: both CRTCs active again" both 1
vkbd_stop
kiosk_stop TERM
vm_check "power: SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
