#!/bin/sh
# Guest script (tests/e2e/host.sh): a folder of three models on vkms, the
# middle one broken. Page Down and a GPIO button bound to next-model step
# through the two good ones, each with its own picture on the screen; the
# broken one is passed over with one journal line however often the cycle
# comes round. The folder is watched: a model copied in is shown once it
# is closed (not while half written), a broken one copied in is one line
# and the picture stays. Then attract mode: no frame while idle, frames
# once the idle time is up, and none again at once after a key; an
# animated model flips at animation_fps until animation_pause_after. Ends with
# "vm: N passed, N failed".
set -u
. /repo/tests/e2e/lib.sh

# The models on the guest's own tmpfs: inotify sees no change on the 9p
# share (cache=none), as it would on a network filesystem.
m=/tmp/m
mkdir -p all $m
mkmodels all >/dev/null
cp all/knot.glb $m/a-knot.glb
cp all/bad-truncated.glb $m/b-broken.glb
cp all/sphere.glb $m/c-sphere.glb
chip=$(gpiosim_make buttons 1 GPIO22)
sys=$(gpiosim_sysfs buttons)
echo pull-up >"$sys/sim_gpio0/pull"
click() { echo pull-down >"$sys/sim_gpio0/pull"; sleep 0.2; echo pull-up >"$sys/sim_gpio0/pull"; }

# Under TCG a frame may take a second: "drawn" is read from the kiosk, which
# uses no CPU at all once it has nothing left to draw.
differ() { ! cmp -s "$1" "$2"; }
shown() { [ "$(grep -c "model $1 of 3" models.log)" -ge "$2" ]; }
broken_lines() { grep -c 'b-broken.glb' models.log; }
same_fb() {
	_a=$(crtc_fb)
	for _i in $(seq $(($1 * 4))); do
		sleep 0.25
		[ "$(crtc_fb)" = "$_a" ] || return 1
	done
}
new_fbs() { ! same_fb "$1"; }

vkbd_start
kiosk_start models.log --display-mode 640x480 --model $m --keyboard auto -v \
	--gpio-chip "$chip" --button-left none --button-right none --button-select GPIO22 \
	--select-press next-model --select-long-press none
vm_check "the kiosk starts on the folder's first model" \
	wait_log 90 models.log "ready: the first frame is on the screen"
vm_check "three models in the folder" has models.log "models: 3, showing $m/a-knot.glb"
still a.png
vkbd_press PAGEDOWN
vm_check "Page Down: the third model shown (the second passed over)" wait_until 60 shown 3 1
still c.png
vm_check "the third model's frame differs from the first's" differ a.png c.png
vm_check "the broken model is one journal line" test "$(broken_lines)" = 1
click
vm_check "the button (next-model): back to the first model" wait_until 60 shown 1 1
still a2.png
vm_check "the first model's frame again" matches a.png a2.png
vkbd_press PAGEUP
vm_check "Page Up: the third model again" wait_until 60 shown 3 2
click
vm_check "the button again: the first" wait_until 60 shown 1 2
vm_check "round twice: the broken model is still one journal line ($(broken_lines))" \
	test "$(broken_lines)" = 1

# ---- the folder is watched: a model copied in is shown once it is whole;
# one half written is not loaded meanwhile; a broken one changes nothing.
cp all/sphere-coarse.glb whole.glb
size=$(wc -c <whole.glb)
{
	head -c $((size / 2)) whole.glb
	sleep 4
	tail -c +$((size / 2 + 1)) whole.glb
} >$m/d-new.glb &
writer=$!
sleep 3
vm_check "a model half written is not loaded" sh -c "! grep -q 'd-new' models.log"
wait "$writer"
vm_check "once closed, it is loaded and shown" wait_until 60 has models.log "model 4 of 4: $m/d-new.glb"
still d.png
vm_check "the new model's frame differs from the first's" differ a.png d.png
cp all/bad-index.glb $m/e-bad.glb
# One error line (beside the info line that it arrived): wait for it,
# then give a second one time to show.
vm_check "a broken model copied in: an error line" \
	wait_until 60 grep -q 'error: .*e-bad.glb' models.log
sleep 2
vm_check "... one only ($(grep -c 'error: .*e-bad.glb' models.log))" \
	test "$(grep -c 'error: .*e-bad.glb' models.log)" = 1
still d2.png
vm_check "and the model on screen stays" matches d.png d2.png
vm_check "the kiosk runs on" kiosk_alive
kiosk_stop TERM
vm_check "SIGTERM: exit status 0 (got $KRC)" test "$KRC" = 0

# ---- attract mode: after the idle time, and stopped at once by a key.
kiosk_start attract.log --display-mode 640x480 --keyboard auto --attract-after 12 \
	--attract-fps 30
wait_log 90 attract.log "ready: the first frame is on the screen"
vm_check "idle before attract_after: no page flip for 3 s" same_fb 3
vm_check "after attract_after: it turns by itself (new frames)" wait_until 30 new_fbs 1
vkbd_press UP
sleep 2
vm_check "a key stops it at once: no page flip for 4 s" same_fb 4
kiosk_stop TERM

# ---- a model that moves (issue 26): it flips by itself at [scene]
# animation_fps (4), never faster, until animation_pause_after (6 s) of no
# input pauses it; the still knot above drew none while idle.
kiosk_start anim.log --display-mode 640x480 --animation-fps 4 --animation-pause-after 6 \
	--model /repo/tests/corpus/khronos/AnimatedTriangle.gltf
wait_log 90 anim.log "ready: the first frame is on the screen"
vm_check "an animated model plays live" has anim.log "plays animation 0 of 1"
# 15 s: the first steps of an emulated board under a loaded CI (its
# first upload and programs) have taken 3.9 s.
vm_check "it flips frames by itself" wait_until 15 new_fbs 1
sleep 6
vm_check "paused after animation_pause_after: no page flip for 3 s" same_fb 3
kiosk_stop TERM
frames=$(number anim.log 's/.* \([0-9]*\) frames drawn.*/\1/p')
vm_check "at most 4 frames a second over its 6 s ($frames frames), at least 1" \
	test "$frames" -le 27 -a "$frames" -ge 6
vkbd_stop
show models.log | grep -E 'model|error|warning' | head -30
vm_summary
