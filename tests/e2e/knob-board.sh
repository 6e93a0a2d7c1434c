#!/bin/sh
# Guest script (tests/e2e/host.sh): a rotary knob on vkms. knob_inject
# (tests/tools/knob_inject.c) is a uinput knob as the kernel's
# rotary-encoder driver makes one (REL_X, a count a detent) with KEY_ENTER
# beside it, made before the kiosk starts (udev lists it). Checks: the
# kiosk takes it as a knob (and not as a keyboard or a touchscreen);
# [knob] turns = model: three detents turn the model 45 degrees (the yaw
# --status reports, from -30 to 15; the picture changed) and three back
# give the start view (the OSMesa reference); turns = stops: detents step
# to the stops both ways (the yaw of each, the reference at the first);
# then a scripted visit (four detents, a press of the knob, a wait at the
# stop, idle until attract mode, a detent) and the counters of the
# metrics file equal what the script did; and the issue's visit with two
# languages (en de) and a GPIO button (gpio-sim) bound to next-language:
# a press of the knob, a wait, the button, idle until attract mode; the
# counters in the metrics file and in --status's state.json equal what
# the script did: the presses per action and source, one visit, seconds
# in both languages and in attract mode. Ends with "vm: N passed, N failed".
set -u
. /repo/tests/e2e/lib.sh

FIFO=/run/knob.fifo
STOPS='-30 20 1; 60 20 1'
PROM=/tmp/knob.prom

knob_start() {
	rm -f "$FIFO" inject.out
	knob_inject "$FIFO" >inject.out 2>&1 &
	IPID=$!
	wait_until 10 grep -q '^ready' inject.out || { cat inject.out; return 1; }
}
# knob_do CMD: one command to the knob, waited for.
knob_do() {
	_d=$(grep -c '^done' inject.out)
	echo "$*" >"$FIFO"
	wait_until 30 sh -c "[ \$(grep -c '^done' inject.out) -gt $_d ]"
}
# yaw_is DEGREES: the view --status reports is the start pitch (20) and
# that yaw: orientation = pitch x yaw for the knot, so its y and w are
# cos(10) sin(yaw/2) and cos(10) cos(yaw/2), here worked out for the yaws
# the script reaches (busybox awk has no trigonometry), within 2e-4 (0.02
# degree).
yaw_is() {
	case $1 in
	15) _q="0.128543 0.976383" ;;
	60) _q="0.492404 0.852869" ;;
	-30) _q="-0.254887 0.951251" ;;
	esac
	matcap-kiosk --status >status.json 2>&1 || return 1
	sed -n 's/.*"view": \[\(.*\)\].*/\1/p' status.json | tr -d ',' |
		awk -v q="$_q" '{ split(q, e, " "); dy = $2 - e[1]; dw = $4 - e[2]; seen = 1
			if (dy < 0) dy = -dy; if (dw < 0) dw = -dw
			if (dy > 2e-4 || dw > 2e-4) { print "view " $0 ", expected y w " q; bad = 1 } }
			END { exit !seen || bad }'
}
differ() { ! cmp -s "$1" "$2"; }
# prom_has LINE: the metrics file has that whole line.
prom_has() { grep -qxF -- "$1" "$PROM"; }
# prom_positive PREFIX: the value of the line starting with PREFIX is > 0.
prom_positive() {
	awk -v p="$1" 'index($0, p) == 1 { v = $NF } END { exit !(v > 0) }' "$PROM"
}

# --status answers in the runtime folder systemd would make.
mkdir -p /run/matcap-kiosk
vm_check "knob_inject makes a uinput knob" knob_start

# ---- turns = model
kiosk_start m.log --display-mode 800x600 --log-level debug --stops "$STOPS"
vm_check "the kiosk shows its first frame" \
	wait_log 90 m.log "ready: the first frame is on the screen"
vm_check "udev lists it: the kiosk takes it as a knob on REL_X" \
	wait_log 10 m.log "knob knob-inject knob (/dev/input/event[0-9]*, REL_X): a detent model"
vm_check "it is not taken for a touchscreen" sh -c '! grep -q "touchscreen knob-inject" m.log'
still s0.png
vm_check "the start view matches the OSMesa reference" matches "$REF/knot-800x600.png" s0.png
knob_do turn 3 80
still s1.png
vm_check "three detents turned the model: the picture changed" differ s0.png s1.png
vm_check "three detents of 15 degrees: the yaw is 15 (from -30)" yaw_is 15
knob_do turn -3 80
still s2.png
vm_check "three back: the start view again (the reference)" matches "$REF/knot-800x600.png" s2.png
vm_check "and the yaw -30" yaw_is -30
kiosk_stop TERM

# ---- turns = stops
kiosk_start s.log --display-mode 800x600 --stops "$STOPS" --knob-turns stops
vm_check "turns = stops: the first frame" \
	wait_log 90 s.log "ready: the first frame is on the screen"
knob_do turn 2 80
still t1.png
vm_check "two detents: the second stop (yaw 60)" yaw_is 60
knob_do turn -1 80
still t2.png
vm_check "one back: the first stop (yaw -30)" yaw_is -30
vm_check "the first stop is the start view (the reference)" \
	matches "$REF/knot-800x600.png" t2.png
kiosk_stop TERM

# ---- a scripted visit, then the counters
rm -f "$PROM"
kiosk_start v.log --display-mode 800x600 --stops "$STOPS" --attract-after 3 --metrics "$PROM"
vm_check "the visit's kiosk: the first frame" \
	wait_log 90 v.log "ready: the first frame is on the screen"
knob_do turn 4 50
knob_do press
sleep 1
# Idle: attract mode after 3 s without input, then a second visitor.
sleep 5
knob_do turn 1 50
sleep 1
kiosk_stop TERM
vm_check "the kiosk wrote its metrics at the stop" prom_has "matcap_kiosk_up 0"
vm_check "four detents counted: presses_total{knob, turn-right} 5 (4 + the second visitor's)" \
	prom_has 'matcap_kiosk_presses_total{source="knob",action="turn-right"} 5'
vm_check "the press counted: presses_total{knob, select} 1" \
	prom_has 'matcap_kiosk_presses_total{source="knob",action="select"} 1'
vm_check "nothing else was pressed" \
	test "$(grep -c '^matcap_kiosk_presses_total{' "$PROM")" = 2
vm_check "two visits (the second after attract mode)" prom_has "matcap_kiosk_visits_total 2"
vm_check "seconds at the first stop (the press went there)" \
	prom_positive 'matcap_kiosk_shown_seconds_total{kind="stop",name="1"}'
vm_check "seconds in attract mode" \
	prom_positive 'matcap_kiosk_shown_seconds_total{kind="attract",name=""}'

# ---- the issue's visit: press, wait, switch language by a button, idle
# state_has TEXT: --status's state.json (the running kiosk's) holds it.
state_has() { grep -qF -- "$1" state.json; }
# state_positive KIND NAME: its seconds in state.json are > 0.
state_positive() {
	tr '{' '\n' <state.json | grep -F "\"kind\": \"$1\", \"name\": \"$2\"" |
		sed -n 's/.*"seconds": \([0-9.]*\).*/\1/p' | awk '{ v = $1 } END { exit !(v > 0) }'
}
chip=$(gpiosim_make langbutton 1 GPIO22)
sys=$(gpiosim_sysfs langbutton)
echo pull-up >"$sys/sim_gpio0/pull"
click() { echo pull-down >"$sys/sim_gpio0/pull"; sleep 0.2; echo pull-up >"$sys/sim_gpio0/pull"; }
rm -f "$PROM"
kiosk_start l.log --display-mode 800x600 --stops "$STOPS" --attract-after 5 --metrics "$PROM" \
	--caption Knot --caption-languages "en de" --gpio-chip "$chip" --button-left none \
	--button-right none --button-select GPIO22 --select-press next-language \
	--select-long-press none
vm_check "the languages' kiosk: the first frame" \
	wait_log 90 l.log "ready: the first frame is on the screen"
knob_do press
sleep 1
click
# Idle: attract mode 5 s after the button, some seconds of it.
sleep 9
vm_check "--status answers during attract mode" sh -c 'matcap-kiosk --status >state.json 2>&1'
vm_check "state.json: the button's next-language press" \
	state_has '{"source": "button", "action": "next-language", "count": 1}'
vm_check "state.json: the knob's press" \
	state_has '{"source": "knob", "action": "select", "count": 1}'
vm_check "state.json: one visit" state_has '"visits": {"count": 1,'
vm_check "state.json: seconds in en" state_positive language en
vm_check "state.json: seconds in de" state_positive language de
vm_check "state.json: seconds in attract mode" state_positive attract ""
kiosk_stop TERM
vm_check "the languages' kiosk wrote its metrics at the stop" prom_has "matcap_kiosk_up 0"
vm_check "the button counted: presses_total{button, next-language} 1" \
	prom_has 'matcap_kiosk_presses_total{source="button",action="next-language"} 1'
vm_check "the knob's press counted: presses_total{knob, select} 1" \
	prom_has 'matcap_kiosk_presses_total{source="knob",action="select"} 1'
vm_check "nothing else was pressed" \
	test "$(grep -c '^matcap_kiosk_presses_total{' "$PROM")" = 2
vm_check "one visit (the button was the same visitor)" prom_has "matcap_kiosk_visits_total 1"
vm_check "seconds in en (from the press to the button)" \
	prom_positive 'matcap_kiosk_shown_seconds_total{kind="language",name="en"}'
vm_check "seconds in de (from the button to attract mode)" \
	prom_positive 'matcap_kiosk_shown_seconds_total{kind="language",name="de"}'
vm_check "seconds at the first stop (the knob's press went there)" \
	prom_positive 'matcap_kiosk_shown_seconds_total{kind="stop",name="1"}'
vm_check "seconds in attract mode after the idle" \
	prom_positive 'matcap_kiosk_shown_seconds_total{kind="attract",name=""}'
vm_check "no language has seconds beyond the two" \
	test "$(grep -c '^matcap_kiosk_shown_seconds_total{kind="language"' "$PROM")" = 2
echo quit >"$FIFO"
wait "$IPID"
vm_summary
