#!/bin/sh
# Guest script (tests/vm/run.sh, driven by tests/e2e/host.sh): the real
# matcap-kiosk --backend kms on vkms.  Discovery and the preferred mode,
# atomic and legacy, what the display scans out against the OSMesa
# reference (a readback of the CRTC's framebuffer: vkms 6.1 cannot drive
# Virtual-1 and Writeback-1 from one CRTC, see tests/vm/README.md), at
# least 30 page flips, antialias = 4, render_scale 0.5 (the GL pass: vkms
# refuses the scaling plane), rotation, a chosen mode, the screen given back as
# it was after SIGTERM and SIGINT, and the errors for a connector or mode
# that does not exist.  Ends with "vm: N passed, N failed".
set -u
. /repo/tests/e2e/lib.sh

vm_check "vkms is /dev/dri/card0" test "$(drm_card)" = /dev/dri/card0
# A known picture first: what the kiosk must give back when it exits.
hold_start -m 800x600
vm_check "vm-hold shows colour bars at 800x600 (fb ${HOLD_FB:-none})" restored
vm-grab -o before.png >/dev/null

# ---- auto: discovery, the preferred mode, atomic; SIGTERM
kiosk_start atomic.log --log-level debug
grab_when_shown atomic.log atomic.png "$HOLD_FB"
vm_check "finds vkms, sets Virtual-1 1024x768@60 with atomic modesetting" \
	has atomic.log "kms: Virtual-1 1024x768@60, atomic modesetting"
vm_check "the EGL surface has a depth buffer" has atomic.log "bit depth buffer"
vm_check "antialias = auto: off on llvmpipe, a plain config" \
	sh -c "grep -q 'antialias = auto: off (a software rasteriser)' atomic.log &&
		grep -q 'bit depth buffer, 0 samples' atomic.log"
vm_check "what the display scans out matches the OSMesa reference" \
	matches "$REF/knot-1024x768.png" atomic.png
kiosk_stop TERM
vm_check "SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0
vm_check "SIGTERM: the CRTC shows vm-hold's framebuffer at 800x600 again" restored
vm-grab -o after-term.png >/dev/null
vm_check "SIGTERM: and the same picture" cmp before.png after-term.png

# ---- antialias = 4: a multisampled EGL config for the GBM surface. auto
# is off here (llvmpipe is a software rasteriser: the cost is in
# tests/bench/report/speed-error.md), so 4 is asked for by name. Where
# vkms and llvmpipe offer a 4-sample config the frame matches EGL
# headless's multisampled reference and not the aliased one; where they
# offer none, the log says what they offer and the frame is the aliased one.
kiosk_start aa4.log --antialias 4 --log-level debug
grab_when_shown aa4.log aa4.png "$HOLD_FB"
show aa4.log
if has aa4.log "kms: antialias 4 samples"; then
	echo "antialias 4: vkms + llvmpipe offer a 4-sample config"
	vm_check "antialias 4: the EGL config has 4 samples" has aa4.log "bit depth buffer, 4 samples"
	vm_check "antialias 4: matches EGL headless's 4-sample reference" \
		matches "$REF/knot-1024x768-aa4.png" aa4.png
	vm_check "antialias 4: its edges differ from the aliased reference" \
		sh -c "! imgdiff --tol 8 --share 0.002 $REF/knot-1024x768.png aa4.png >/dev/null"
else
	echo "antialias 4: no 4-sample config on vkms + llvmpipe"
	vm_check "antialias 4: the log says what the driver offers" \
		has aa4.log "no EGL config with 4 samples scans out (the driver offers"
	vm_check "antialias 4: drawn without, as the aliased reference" \
		matches "$REF/knot-1024x768.png" aa4.png
fi
kiosk_stop TERM
vm_check "antialias 4: exit 0 (got $KRC)" test "$KRC" = 0

# ---- render_scale 0.5: vkms scales no plane, so the atomic test commit
# with the plane's source smaller than its CRTC rectangle is refused,
# said once, and the GL pass draws 512x384 and scales it up: the CRTC
# scans out a full 1024x768 frame, as OSMesa draws it through the pass.
kiosk_start half.log --render-scale 0.5
grab_when_shown half.log half.png "$HOLD_FB"
show half.log
vm_check "render_scale 0.5: vkms refuses the scaling plane in a test commit, said once" \
	test "$(grep -c 'primary plane cannot scale 512x384 up to 1024x768 (the test commit says' half.log)" = 1
vm_check "render_scale 0.5: the GL pass draws 512x384 and scales it up" \
	has half.log "render_scale 0.50: the scene drawn at 512x384, scaled up to 1024x768 by a GL pass"
vm_check "render_scale 0.5: the CRTC scans out a 1024x768 frame" \
	sh -c "[ \"\$(vm-grab | sed -n 's/.* mode \([^ ]*\) differ.*/\1/p')\" = 1024x768 ]"
vm_check "render_scale 0.5: matches the OSMesa reference at 0.5" \
	matches "$REF/knot-1024x768-half.png" half.png
vm_check "render_scale 0.5: and not the full-size one" \
	sh -c "! imgdiff --tol 8 --share 0.002 $REF/knot-1024x768.png half.png >/dev/null"
kiosk_stop TERM
vm_check "render_scale 0.5: exit 0 (got $KRC)" test "$KRC" = 0

# ---- attract mode: a frame per vblank at most, counted at exit; SIGINT
# A background job of a script ignores SIGINT, so the kiosk runs in the
# foreground and a background job interrupts it after 25 s: llvmpipe under
# TCG draws 640x480 at 3 to 5 frames a second here, so twice the time 30
# flips take on a loaded machine.
(
	wait_log 90 attract.log "ready: the first frame is on the screen"
	sleep "${ATTRACT_SECONDS:-25}"
	kill -INT "$(cat /tmp/kiosk.pid)"
) &
helper=$!
sh -c 'echo $$ >/tmp/kiosk.pid; exec matcap-kiosk --backend kms "$@"' sh $KIOSK_SCENE \
	--display-mode 640x480 --attract-after 0.1 --attract-speed 45 >attract.log 2>&1
KRC=$?
wait "$helper"
flips=$(number attract.log 's/.*kms: \([0-9]*\) page flips.*/\1/p')
drawn=$(number attract.log 's/.* \([0-9]*\) frames drawn.*/\1/p')
rate=$(sed -n 's/.*page flips in .* (\([0-9.]*\) per second).*/\1/p' attract.log)
echo "attract mode: $flips page flips, $drawn frames drawn, ${rate:-?} per second"
vm_check "SIGINT: exit status 0 (got $KRC)" test "$KRC" = 0
vm_check "SIGINT: logged as an interrupt" has attract.log "Interrupt: shutting down"
vm_check "at least 30 page flips completed ($flips)" test "$flips" -ge 30
vm_check "every frame drawn reached the screen by a flip ($drawn drawn)" test "$drawn" = "$flips"
vm_check "no faster than the 60 Hz vblank (${rate:-?}/s)" \
	awk -v r="${rate:-0}" 'BEGIN { exit !(r > 0 && r <= 61) }'
vm_check "SIGINT: the CRTC shows vm-hold's framebuffer at 800x600 again" restored

# ---- rotation 90, atomic asked for by name
kiosk_start rot90.log --rotate 90 --kms-api atomic
grab_when_shown rot90.log rot90.png "$HOLD_FB"
vm_check "kms_api = atomic: atomic modesetting" has rot90.log "atomic modesetting"
vm_check "rotation 90: matches the OSMesa reference turned for the panel" \
	matches "$REF/knot-1024x768-rot90.png" rot90.png
kiosk_stop TERM

# ---- [caption] on vkms's overlay plane (loaded with enable_overlay=1):
# an atomic test commit puts it there and GL draws none (the primary
# plane's frame is the reference without it); the atomic state shows the
# plane with its ARGB picture; the wall clock set 45 minutes on drifts it
# (x 0 to 6, y 6 to 5 pixels): the plane moves, the model's frame is the
# same framebuffer, not drawn again.  The font comes from the share (the
# guest has no /usr/share/fonts).
CAPTION="--caption Amphora,\\nכד --caption-font $REF/DejaVuSans.ttf"
plane_pos() { # the caption plane's crtc-pos in the atomic state, or nothing
	awk '/^plane\[/ { p = 0 } /format=AR24/ { p = 1 } p && /crtc-pos=/ { print $1 }' \
		/sys/kernel/debug/dri/0/state
}
plane_on() { [ -n "$(plane_pos)" ]; }
plane_moved() { plane_on && [ "$(plane_pos)" != "$pos1" ]; }
clock_set "2026-01-01 00:00:00" unsynced
kiosk_start plane.log $CAPTION --log-level debug
wait_log 90 plane.log "is on overlay plane"
wait_until 20 plane_on
show plane.log
pos1=$(plane_pos)
fb1=$(vm-grab -o plane.png | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
echo "caption plane: $pos1 over fb $fb1"
vm_check "caption: an atomic test commit put it on an overlay plane" \
	has plane.log "kms: the caption (.*) is on overlay plane"
vm_check "caption: the atomic state shows it on an ARGB overlay plane of the CRTC ($pos1)" \
	test -n "$pos1"
vm_check "caption on the plane: the model's frame has no caption drawn by GL" \
	matches "$REF/knot-1024x768-caption-room.png" plane.png
clock_set "2026-01-01 00:45:00" unsynced
wait_until 30 plane_moved
pos2=$(plane_pos)
fb2=$(vm-grab -o plane-drift.png | sed -n 's/.* fb \([0-9]*\) .*/\1/p')
echo "caption plane after 45 minutes: $pos2 over fb $fb2"
vm_check "caption drift: the plane moved ($pos1 to $pos2)" \
	sh -c "[ -n '$pos2' ] && [ '$pos1' != '$pos2' ]"
vm_check "caption drift: the model's frame was not drawn again (fb $fb1, $fb2)" \
	sh -c "[ -n '$fb1' ] && [ '$fb1' = '$fb2' ] && cmp plane.png plane-drift.png"
vm_check "caption drift: moved by the plane alone (log)" has plane.log "caption: its plane moved"
kiosk_stop TERM

# ---- [caption] where no plane takes it (legacy KMS has none): GL draws
# it over the model, as the OSMesa reference.
kiosk_start caption.log $CAPTION --caption-drift off --kms-api legacy
grab_when_shown caption.log caption.png "$HOLD_FB"
vm_check "caption: no plane with legacy KMS: drawn by GL, as the OSMesa reference" \
	matches "$REF/knot-1024x768-caption.png" caption.png
kiosk_stop TERM

# ---- legacy, on a named device; a chosen mode on a named connector
kiosk_start legacy.log --kms-api legacy --device /dev/dri/card0
grab_when_shown legacy.log legacy.png "$HOLD_FB"
vm_check "kms_api = legacy: legacy modesetting (SetCrtc + PageFlip)" \
	has legacy.log "kms: Virtual-1 1024x768@60, legacy modesetting"
vm_check "legacy: the frame matches the OSMesa reference" \
	matches "$REF/knot-1024x768.png" legacy.png
kiosk_stop TERM
vm_check "legacy: exit 0 and the previous mode and framebuffer are back" \
	sh -c "[ $KRC = 0 ] && [ \"\$(vm-grab | sed -n 's/.* fb \([0-9]*\) .*mode \([^ ]*\) .*/\1 \2/p')\" = '$HOLD_FB $HOLD_MODE' ]"

# ---- [kiosk] clock = shared on a screen: each moment of the clock's
# grid is logged when its flip reached the screen (the vblank's time); the
# state runs ahead by the average time a frame takes to the screen, so
# that it lands on the vblank closest to it. How far from its moment each
# frame reached the screen is printed (a measure: qemu's emulated CPU
# draws a 1024x768 frame in 250 to 700 ms, a Pi or a desktop in a few).
kiosk_start shared.log --clock shared --attract-after 1 --attract-fps 20 --log-level debug
sleep 8
kiosk_stop TERM
sed -n 's/.*clock: frame [0-9]* shows \([0-9.]*\) s, .* presented at \([0-9.]*\) s$/\1 \2/p' \
	shared.log >shared.frames
vm_check "clock = shared: 5 frames and more logged at their flip ($(wc -l <shared.frames))" \
	test "$(wc -l <shared.frames)" -ge 5
vm_check "clock = shared: every moment on the grid of 1/20 s" \
	awk '{ ms = $1 * 1000; if ((ms + 0.5) % 50 >= 1) bad++ } END { exit bad > 0 }' shared.frames
awk '{ print ($2 - $1) * 1000 }' shared.frames | sort -n | awk '{ v[NR] = $1 }
	END { printf "clock = shared on vkms at 60 Hz: on the screen %.1f ms after its moment (median), %.1f to %.1f ms\n",
		v[int((NR + 1) / 2)], v[1], v[NR] }'

kiosk_start mode.log --connector Virtual-1 --display-mode 800x600@60
grab_when_shown mode.log mode.png "$HOLD_FB"
vm_check "--display-mode 800x600@60 on Virtual-1" has mode.log "kms: Virtual-1 800x600@60"
vm_check "the CRTC runs 800x600 with the kiosk's frame" \
	sh -c "[ \"\$(vm-grab | sed -n 's/.* mode \([^ ]*\) differ.*/\1/p')\" = 800x600 ]"
vm_check "800x600: matches the OSMesa reference" matches "$REF/knot-800x600.png" mode.png
kiosk_stop TERM

# ---- settings that name what does not exist: one clear error, exit 1
matcap-kiosk --backend kms $KIOSK_SCENE --connector HDMI-A-1 >connector.log 2>&1
KRC=$?
show connector.log
vm_check "a wrong connector: exit 1 (got $KRC)" test "$KRC" = 1
vm_check "a wrong connector: the error lists the real ones" has connector.log \
	"connector HDMI-A-1 does not exist on /dev/dri/card0; the connectors are: Virtual-1 (connected)"
matcap-kiosk --backend kms $KIOSK_SCENE --display-mode 1234x567 >mode-bad.log 2>&1
KRC=$?
show mode-bad.log
vm_check "a wrong mode: exit 1 (got $KRC)" test "$KRC" = 1
vm_check "a wrong mode: the error lists the real ones" has mode-bad.log \
	"Virtual-1: there is no mode 1234x567; the modes are: .*1024x768@60"
vm_check "after the failed starts the screen is untouched" restored
hold_stop

dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
