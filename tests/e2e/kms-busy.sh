#!/bin/sh
# Guest script (tests/e2e/host.sh): the display held by another program
# (vm-hold -k keeps DRM master, as a desktop would), and no permission on
# /dev/dri.  on_busy = exit stops at once naming the holder; on_busy =
# wait leaves the holder's picture alone and takes the display once the
# holder is gone: as root (SET_MASTER) and as the service's kind of user,
# in the video group (a fresh open of the node).  Ends with
# "vm: N passed, N failed".
set -u
. /repo/tests/e2e/lib.sh

# Users like the service's: not root; "kiosk" in the video group, "guest"
# in no group but its own.
echo 'kiosk:x:1000:1000::/tmp/kiosk:/bin/sh' >>/etc/passwd
echo 'guest:x:1001:1001::/tmp/guest:/bin/sh' >>/etc/passwd
printf 'kiosk:x:1000:\nguest:x:1001:\n' >>/etc/group
sed -i 's/^video:x:\([0-9]*\):$/video:x:\1:kiosk/' /etc/group
mkdir -p /tmp/kiosk /tmp/guest && chown 1000:1000 /tmp/kiosk && chown 1001:1001 /tmp/guest
as_user() { # USER COMMAND: with the user's groups, as su gives them; the
	# command's pid goes to /tmp/kiosk/pid (su stays between it and us)
	su -s /bin/sh "$1" -c "unset XDG_RUNTIME_DIR; echo \$\$ >/tmp/kiosk/pid; exec $2"
}
video=$(sed -n 's/^video:x:\([0-9]*\):.*/\1/p' /etc/group)

vm_check "/dev/dri/card0 is root:video, 0660 (udev's rules)" \
	sh -c "ls -ln /dev/dri/card0 | grep -q '^crw-rw----  *1  *0  *$video '"

# ---- no permission
as_user guest "/usr/local/bin/matcap-kiosk --backend kms $KIOSK_SCENE" >perm.log 2>&1
KRC=$?
show perm.log
# 77 (EX_NOPERM): the unit's RestartPreventExitStatus= does not restart it.
vm_check "not in the video group: exit 77, forbidden (got $KRC)" test "$KRC" = 77
vm_check "not in the video group: says the display is forbidden" sh -c \
	"grep -q 'the display cannot be opened: forbidden' perm.log"
vm_check "not in the video group: the error names the group, once" sh -c \
	"[ \$(grep -c \"/dev/dri/card0: permission denied: add the user to the 'video' group\" perm.log) = 1 ]"

# ---- on_busy = exit
hold_start -k
vm_check "vm-hold holds DRM master, showing its picture" restored
matcap-kiosk --backend kms $KIOSK_SCENE --on-busy exit >exit.log 2>&1
KRC=$?
show exit.log
vm_check "on_busy = exit: exit 75, busy (got $KRC)" test "$KRC" = 75
vm_check "on_busy = exit: names the holder and the setting" has exit.log \
	"/dev/dri/card0 is held by vm-hold (pid $HOLD_PID) (it is DRM master): exiting, as \[display\] on_busy = exit says"
vm_check "on_busy = exit: the holder's picture is untouched" restored

# ---- on_busy = wait, as root
kiosk_start wait.log --on-busy wait
wait_log 60 wait.log "waiting for it"
sleep 3
vm_check "on_busy = wait: says it waits, naming the holder" has wait.log \
	"/dev/dri/card0 is held by vm-hold (pid $HOLD_PID) (it is DRM master): waiting for it"
vm_check "on_busy = wait: keeps running" kiosk_alive
vm_check "on_busy = wait: leaves the holder's picture alone" restored
hold_stop
# (The holder's framebuffer id is free again and the kiosk's may get it.)
wait_log 30 wait.log "is free now: taking the display"
wait_log 60 wait.log "ready: the first frame is on the screen" && vm-grab -o wait.png >/dev/null
vm_check "the holder gone: takes the display" has wait.log "/dev/dri/card0 is free now"
vm_check "the holder gone: shows the scene (matches the OSMesa reference)" \
	matches "$REF/knot-1024x768.png" wait.png
kiosk_stop TERM
vm_check "SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

# ---- on_busy = wait, as a user in the video group (no SET_MASTER for it)
hold_start -k
as_user kiosk "/usr/local/bin/matcap-kiosk --backend kms $KIOSK_SCENE" >user.log 2>&1 &
su_pid=$!
wait_log 60 user.log "waiting for it"
KPID=$(cat /tmp/kiosk/pid)
sleep 3
vm_check "user in the video group: waits for the display" has user.log \
	"/dev/dri/card0 is held by another program (it is DRM master): waiting for it"
vm_check "user in the video group: leaves the holder's picture alone" restored
hold_stop
wait_log 30 user.log "is free now: taking the display"
wait_log 60 user.log "ready: the first frame is on the screen" && vm-grab -o user.png >/dev/null
vm_check "user in the video group: takes the display once it is free" \
	has user.log "/dev/dri/card0 is free now"
vm_check "user in the video group: shows the scene (matches the OSMesa reference)" \
	matches "$REF/knot-1024x768.png" user.png
kill -TERM "$KPID"
wait "$su_pid"
KRC=$?
vm_check "user in the video group: SIGTERM, exit status 0 (got $KRC)" test "$KRC" = 0
show user.log

dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
