#!/bin/sh
# Guest script (tests/e2e/host.sh): display hotplug with the real
# matcap-kiosk --backend kms on vkms.  Started with no display connected it
# waits; a display plugged in is used; unplugged, the kiosk stops scanning
# out and waits; plugged back in, the scene is there again, with no
# restart.  Ends with "vm: N passed, N failed".
#
# vkms in 6.1 has no hotplug detection: forcing Virtual-1 through debugfs
# (/sys/kernel/debug/dri/0/Virtual-1/force) or sysfs (…/status) changes
# what a probe reports, but the kernel sends no uevent for it (vkms never
# starts the output poll helper that would).  So a cable is played here as
# the sysfs status plus the change event of the card that a real cable
# would make the kernel send ("change" with HOTPLUG=1); the kiosk takes any
# change event of its card as "probe again", and acts only on a real change.
set -u
. /repo/tests/e2e/lib.sh

status=/sys/class/drm/card0-Virtual-1/status
cable() { # in | out
	case $1 in in) echo detect >"$status" ;; out) echo off >"$status" ;; esac
	echo change >/sys/class/drm/card0/uevent
}
modesets() { grep -c "kms: Virtual-1 1024x768@60" hotplug.log; }

# ---- started with no display: waits for one
echo off >"$status"
vm_check "Virtual-1 reads disconnected" test "$(drm_connector_status Virtual-1)" = disconnected
kiosk_start hotplug.log
wait_log 60 hotplug.log "ready: waiting for a display"
sleep 2
vm_check "no display at start: says it waits for one" \
	has hotplug.log "kms: no display is connected to /dev/dri/card0; waiting for one"
vm_check "no display at start: keeps running" kiosk_alive
vm_check "no display at start: sets no mode" test "$(modesets)" = 0

# ---- plugged in
old=$(crtc_fb)
cable in
wait_log 60 hotplug.log "kms: Virtual-1 1024x768@60"
wait_until 60 shows_new_frame "${old:-none}" && vm-grab -o plugged.png >/dev/null
vm_check "a display plugged in: the kiosk sets its mode" test "$(modesets)" = 1
vm_check "a display plugged in: shows the scene (matches the OSMesa reference)" \
	matches "$REF/knot-1024x768.png" plugged.png

# ---- a change event that changes nothing: no new modeset, no flicker
shown=$(crtc_fb)
echo change >/sys/class/drm/card0/uevent
sleep 2
vm_check "a change event with the same display: no new modeset" test "$(modesets)" = 1
vm_check "a change event with the same display: the same frame stays" test "$(crtc_fb)" = "$shown"

# ---- unplugged
cable out
wait_log 30 hotplug.log "Virtual-1 was disconnected; waiting for a display"
vm_check "unplugged: says so and waits" has hotplug.log "Virtual-1 was disconnected"
vm_check "unplugged: the CRTC scans out no frame of ours" \
	sh -c "fb=\$(vm-grab 2>/dev/null | sed -n 's/.* fb \([0-9]*\) .*/\1/p'); [ \"\$fb\" != '$shown' ]"
vm_check "unplugged: keeps running" kiosk_alive

# ---- plugged back in: the scene again, the same process
cable in
wait_until 60 sh -c "[ \$(grep -c 'kms: Virtual-1 1024x768@60' hotplug.log) -ge 2 ]"
wait_until 60 shows_new_frame none && vm-grab -o replugged.png >/dev/null
vm_check "plugged back in: the kiosk sets the mode again" test "$(modesets)" = 2
vm_check "plugged back in: shows the scene (matches the OSMesa reference)" \
	matches "$REF/knot-1024x768.png" replugged.png
vm_check "plugged back in: without a restart (the same process)" kiosk_alive
kiosk_stop TERM
vm_check "SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
