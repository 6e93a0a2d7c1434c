#!/bin/sh
# Guest script (tests/e2e/host.sh): the screen's power on vkms, with a
# clock the test sets (tests/tools/clock_set). In attract mode the kiosk
# flips a new frame every vblank while awake, so a framebuffer that stays
# the same means no page flip. Checks, with atomic modesetting: at the end
# of the schedule the CRTC goes inactive and nothing is flipped; a key
# wakes it (CRTC active, new frames) and it sleeps again after
# blank_after; with legacy modesetting the connector's DPMS goes off; a
# clock that is not synchronised keeps the screen on and is said once.
# Prints the CPU the kiosk uses per second while asleep and the time from
# a key to the first frame. Ends with "vm: N passed, N failed".
set -u
. /repo/tests/e2e/lib.sh

# crtc_active / dpms: the CRTC's ACTIVE and the connector's DPMS property
# values as the kernel has them (modetest reads them without master).
# ACTIVE is an atomic property: only a client that asks for atomic (-a)
# sees it; connectors are listed with -c.
prop() { # SECTION NAME MODETEST_FLAGS
	modetest -M vkms $3 2>/dev/null | awk -v sec="$1" -v name="$2" '
		/^[A-Za-z]+:$/ { in_sec = ($0 == sec) }
		in_sec && $2 == name ":" { want = 1; next }
		want && $1 == "value:" { print $2; exit }'
}
crtc_active() { prop "CRTCs:" ACTIVE "-a -p"; }
dpms() { prop "Connectors:" DPMS -c; }
# same_fb SECONDS: the CRTC shows one framebuffer all that time (looked at
# four times a second: a flip swaps between two buffers).
same_fb() {
	_a=$(crtc_fb)
	for _i in $(seq $(($1 * 4))); do
		sleep 0.25
		[ "$(crtc_fb)" = "$_a" ] || return 1
	done
}
new_fbs() { ! same_fb "$1"; }
# offs N LOG: the kiosk has said "screen off" N times or more.
offs() { [ "$(grep -c 'screen off' "$2")" -ge "$1" ]; }
ms() { awk '{ printf "%d", $1 * 1000 }' /proc/uptime; }
# cpu_ticks PID: user + system time so far, in clock ticks.
cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$1/stat"; }

cat >power.ini <<EOF2
[display]
mode = 640x480
[power]
schedule = Mon 08:00-09:00
blank_after = 0.25
EOF2
# After KIOSK_SCENE's --attract-after 0, which it overrides.
ATTRACT="--attract-after 0.1 --attract-speed 30"
vkbd_start
# Monday 08:59:50 UTC: inside the schedule, 10 s before its end, and
# blank_after (15 s) later than that.
clock_set "2026-11-23 08:59:50" synced
kiosk_start atomic.log --config power.ini --keyboard auto --log-level debug $ATTRACT
wait_log 90 atomic.log "ready: the first frame is on the screen"
vm_check "on inside the schedule: the CRTC is active" test "$(crtc_active)" = 1
vm_check "awake, attract mode flips new frames" wait_until 15 new_fbs 1
wait_log 40 atomic.log "screen off: outside the schedule"
sleep 1
vm_check "09:00: the CRTC is inactive (atomic ACTIVE 0)" test "$(crtc_active)" = 0
t0=$(cpu_ticks "$KPID")
vm_check "asleep: no page flip for 5 s" same_fb 5
t1=$(cpu_ticks "$KPID")
hz=100 # USER_HZ: /proc counts in hundredths on every Linux
echo "asleep: $((t1 - t0)) CPU ticks in 5 s at $hz per second"
vm_check "asleep: under 2 % of a CPU ($((t1 - t0)) ticks in 5 s)" test $((t1 - t0)) -le $((hz / 10))
fb=$(crtc_fb)
start=$(ms)
vkbd_press SPACE
wait_until 10 shows_new_frame "$fb"
echo "key to the first frame after waking: $(($(ms) - start)) ms (polled every 0.1 s)"
vm_check "a key wakes it: the CRTC is active again" test "$(crtc_active)" = 1
vm_check "a key wakes it: a new frame is on the screen" has atomic.log "screen on: woken by an input"
woke=$(ms)
vm_check "woken outside the schedule, it sleeps again after blank_after" \
	wait_until 60 offs 2 atomic.log
echo "asleep again $(($(ms) - woke)) ms after waking (blank_after 15 s)"
kiosk_stop TERM
vm_check "asleep, SIGTERM still exits 0 (got $KRC)" test "$KRC" = 0

# Legacy modesetting: blank_after alone, the connector's DPMS.
clock_set "2026-11-23 12:00:00" synced
kiosk_start legacy.log --config power.ini --keyboard auto --kms-api legacy --schedule "" \
	--blank-after 0.1 $ATTRACT
wait_log 90 legacy.log "ready: the first frame is on the screen"
vm_check "legacy: on, DPMS on" test "$(dpms)" = 0
wait_log 30 legacy.log "screen off: blanked"
sleep 1
vm_check "legacy: after blank_after the connector's DPMS is off" test "$(dpms)" = 3
vm_check "legacy asleep: no page flip for 3 s" same_fb 3
fb=$(crtc_fb)
vkbd_press SPACE
vm_check "legacy: a key wakes it with a new frame" wait_until 10 shows_new_frame "$fb"
vm_check "legacy: DPMS on again" test "$(dpms)" = 0
kiosk_stop TERM

# A clock nobody has set: the schedule waits for it, the screen stays on.
clock_set "2026-11-22 03:00:00" unsynced
kiosk_start unsynced.log --config power.ini --keyboard none --blank-after 0 $ATTRACT
wait_log 90 unsynced.log "ready: the first frame is on the screen"
sleep 3
vm_check "unsynchronised clock: on, and said once" \
	test "$(grep -c 'not synchronised' unsynced.log)" = 1
vm_check "unsynchronised clock: the CRTC is active" test "$(crtc_active)" = 1
kiosk_stop TERM
vkbd_stop
show atomic.log legacy.log unsynced.log | grep -E 'screen|kms:|error|warning' | head -40
vm_summary
