# Guest-side helpers for the display end-to-end scripts (busybox sh), on
# top of the board's own ($VM_LIB).  The host (tests/e2e/host.sh) puts the
# OSMesa references in /share/ref and matcap-kiosk and imgdiff on PATH.
. "$VM_LIB"

# The scene the references show: the built-in knot with the gold matcap,
# still (no attract mode), with no live camera (vimc), and the model as it
# is (the mesh is simplified for the display size, which a kiosk waiting
# for a display does not know yet).
KIOSK_SCENE="--matcap /repo/matcaps/gold.png --keyboard none --camera off --attract-after 0
	--lod-pixels 0"
REF=/share/ref

# kiosk_start LOG [ARGS]...: matcap-kiosk --backend kms in the background
# (KPID).  SIGINT is ignored by background jobs of a script; stop it with
# TERM, or run it in the foreground (kiosk_fg) to test SIGINT.
kiosk_start() {
	_log=$1; shift
	matcap-kiosk --backend kms $KIOSK_SCENE "$@" >"$_log" 2>&1 &
	KPID=$!
}
# kiosk_stop SIGNAL: send it and wait for the exit status (KRC).
kiosk_stop() {
	kill -"$1" "$KPID" 2>/dev/null
	wait "$KPID"
	KRC=$?
}
# kiosk_alive: the background kiosk still runs.
kiosk_alive() { kill -0 "$KPID" 2>/dev/null; }

# has LOG PATTERN / wait_log SECONDS LOG PATTERN
has() { grep -q -- "$2" "$1"; }
wait_log() { wait_until "$1" grep -q -- "$3" "$2"; }
# count LOG SED_EXPR: the number a line of the log gives, or 0.
number() { _n=$(sed -n "$2" "$1" | tail -1); echo "${_n:-0}"; }

# The mode the CRTC scans out now (vm-grab reads it back, no master needed).
crtc_mode() { vm-grab 2>/dev/null | sed -n 's/.* mode \([^ ]*\) differ=.*/\1/p'; }
# shows_new_frame OLD_FB: the CRTC shows another framebuffer, drawn on.
shows_new_frame() {
	_g=$(vm-grab 2>/dev/null)
	_fb=$(echo "$_g" | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
	[ -n "$_fb" ] && [ "$_fb" != "$1" ] && echo "$_g" | grep -q 'differ=[1-9][0-9][0-9][0-9]'
}
# grab_when_shown LOG OUT.png [OLD_FB]: once the kiosk says its first frame
# is on the screen, read the screen back into OUT.png.
grab_when_shown() {
	wait_log 90 "$1" "ready: the first frame is on the screen" &&
		wait_until 30 shows_new_frame "${3:-none}" && vm-grab -o "$2"
}
# matches REF OUT: within the golden images' tolerance (tests/run.sh).
matches() { imgdiff --tol 8 --share 0.005 "$1" "$2"; }

# hold_start [vm-hold ARGS]: a known picture on the display (HOLD_FB,
# HOLD_MODE, HOLD_PID); -k keeps DRM master.
hold_start() {
	rm -f /tmp/hold.out
	vm-hold "$@" >/tmp/hold.out 2>&1 &
	HOLD_PID=$!
	wait_until 20 grep -q '^hold ' /tmp/hold.out || { cat /tmp/hold.out; return 1; }
	HOLD_FB=$(sed -n 's/^hold crtc [0-9]* fb \([0-9]*\) .*/\1/p' /tmp/hold.out)
	HOLD_MODE=$(sed -n 's/.* mode \([^ ]*\) master.*/\1/p' /tmp/hold.out)
}
hold_stop() { kill "$HOLD_PID" 2>/dev/null; wait "$HOLD_PID" 2>/dev/null; }
# restored: the CRTC shows vm-hold's framebuffer in its mode again.
restored() { [ "$(crtc_fb)" = "$HOLD_FB" ] && [ "$(crtc_mode)" = "$HOLD_MODE" ]; }

# show LOG...: the kiosk's log in the console, for whoever reads a failure.
show() { for _f in "$@"; do echo "--- $_f"; cat "$_f"; done; }
