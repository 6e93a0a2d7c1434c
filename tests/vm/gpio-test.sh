#!/bin/sh
# Guest script: the real kiosk's buttons on the virtual board. gpio-sim
# lines stand in for three buttons wired to ground (pull-up, active low);
# the kiosk draws on vkms, and every check reads the screen back.
#   make vm-test VM_TESTS=tests/vm/gpio-test.sh VM_BINS=./matcap-kiosk
# Checks: a clean press and a bouncing one each cycle the matcap exactly
# once (the frames must match those of 1, 2, 3 clean presses); a long
# press does not cycle; a held line turns the model and it stops when let
# go; nothing is drawn and no CPU used while idle; the keyboard cycles and
# resets; a missing chip, a missing line and a line held by another
# program are one journal line each and the kiosk runs on; two buttons on
# one line exit 78. Prints the edge-to-frame latency. Outputs (logs,
# frames) are left in the share. Ends with "vm: N passed, N failed".
# (Not here: a chip that disappears while its line is requested. Linux 6.1
# does not wake poll() on unbind, and gpio-sim's teardown then warns.)
set -u
# shellcheck source=guest-lib.sh
. "$VM_LIB"

chip=$(gpiosim_make buttons 5 GPIO17 GPIO27 GPIO22 GPIO5 GPIO6)
sys=$(gpiosim_sysfs buttons)
for l in 0 1 2 3 4; do echo pull-up >"$sys/sim_gpio$l/pull"; done
LEFT=0 SELECT=2

mkdir -p /tmp/mc
cp /repo/matcaps/gold.png /repo/matcaps/chrome-studio.png /repo/matcaps/clay-red.png /tmp/mc/
# A small mode keeps llvmpipe under TCG quick. Debouncing is 30 ms, not
# 10: under TCG one write to the simulator's sysfs can take several ms,
# and the bursts below must stay inside the window.
cat >gpio.ini <<EOF
[display]
backend = kms
mode = 640x480
[scene]
matcap = /tmp/mc
[kiosk]
attract_after = 0
turn_speed = 20
[buttons]
debounce_ms = 30
long_press_ms = 800
left = GPIO17
right = GPIO27
select = GPIO22
[keyboard]
device = auto
[camera]
enabled = off
EOF

# ---- helpers
down() { echo pull-down >"$sys/sim_gpio$1/pull"; }
up() { echo pull-up >"$sys/sim_gpio$1/pull"; }
# A switch that bounces: five edges back to back, ending down (or up).
bounce_down() {
	_p=$sys/sim_gpio$1/pull
	echo pull-down >"$_p"; echo pull-up >"$_p"; echo pull-down >"$_p"
	echo pull-up >"$_p"; echo pull-down >"$_p"
}
bounce_up() {
	_p=$sys/sim_gpio$1/pull
	echo pull-up >"$_p"; echo pull-down >"$_p"; echo pull-up >"$_p"
	echo pull-down >"$_p"; echo pull-up >"$_p"
}
# The kiosk logs (at debug) one line per frame that shows a new input.
presented() { grep -c "presented .* ms after the input" kiosk.log; }
# wait_frame COUNT: until a frame newer than COUNT inputs ago is drawn.
wait_frame() { wait_until 30 sh -c "[ \$(grep -c 'presented .* ms after the input' kiosk.log) -gt $1 ]"; }
same() { cmp -s "$1" "$2"; }
differ() { ! cmp -s "$1" "$2"; }
new_fb() { [ "$(crtc_fb)" != "$1" ]; }
# click LINE: a clean press and release, 0.2 s apart.
click() { down "$1"; sleep 0.2; up "$1"; }
edges() { grep -c "button $1 .*: \(pressed\|released\) at" kiosk.log; }

# ---- the main run: buttons and a keyboard
vkbd_start
matcap-kiosk --config gpio.ini -v >kiosk.log 2>&1 &
KPID=$!
vm_check "kiosk shows its first frame on KMS" wait_until 120 grep -q "ready: the first frame" kiosk.log
vm_check "three buttons on the simulated chip" \
	sh -c "[ \$(grep -c 'button .* on $chip): ' kiosk.log) = 3 ]"
vm_check "the virtual keyboard is found" grep -q "keyboard vm-key keyboard" kiosk.log
still f0.ppm
ticks=$(cpu)
fb=$(crtc_fb)
sleep 3
vm_check "idle: no frame drawn in 3 s (fb $fb stays)" test "$(crtc_fb)" = "$fb"
vm_check "idle: no CPU used in 3 s ($ticks ticks, then $(cpu))" test "$(cpu)" = "$ticks"

n=$(presented); click $SELECT; wait_frame "$n"; still f1.ppm
n=$(presented); click $SELECT; wait_frame "$n"; still f2.ppm
n=$(presented); click $SELECT; wait_frame "$n"; still f3.ppm
vm_check "a clean press cycles to another matcap" differ f0.ppm f1.ppm
vm_check "... and to a third" sh -c "! cmp -s f1.ppm f2.ppm && ! cmp -s f0.ppm f2.ppm"
vm_check "three clean presses come back to the first (3 matcaps)" same f0.ppm f3.ppm

e0=$(edges select)
n=$(presented)
bounce_down $SELECT
sleep 0.3
bounce_up $SELECT
wait_frame "$n"
still fb1.ppm
e1=$(edges select)
echo "bounce bursts: $((e1 - e0)) edges reached the kiosk"
vm_check "the bursts reached the kiosk as bounces ($((e1 - e0)) edges, more than 2)" \
	test $((e1 - e0)) -gt 2
vm_check "a bouncing press and release cycle the matcap exactly once" same f1.ppm fb1.ppm

down $SELECT
sleep 1.5
up $SELECT
sleep 0.5
still flong.ppm
vm_check "a long press does not cycle the matcap" same f1.ppm flong.ppm

n=$(presented); vkbd_press SPACE; wait_frame "$n"; still fk.ppm
vm_check "space on the keyboard cycles the matcap" same f2.ppm fk.ppm
n=$(presented); vkbd_press BACKSPACE; wait_frame "$n"; still fk2.ppm
vm_check "backspace goes back" same f1.ppm fk2.ppm

# Held: a new frame after the press, and another after that one.
fb=$(crtc_fb)
down $LEFT
wait_until 60 new_fb "$fb"
sleep 0.2
fb=$(crtc_fb)
vm-grab -o h1.ppm >/dev/null
wait_until 60 new_fb "$fb"
sleep 0.2
vm-grab -o h2.ppm >/dev/null
up $LEFT
still h3.ppm
fb=$(crtc_fb)
sleep 2
vm-grab -o h4.ppm >/dev/null
vm_check "holding a line turns the model" differ f1.ppm h1.ppm
vm_check "... on and on while held" differ h1.ppm h2.ppm
vm_check "... and it stops when let go" sh -c "cmp -s h3.ppm h4.ppm && [ $fb = $(crtc_fb) ]"
n=$(presented); vkbd_press R; wait_frame "$n"; still fr.ppm
vm_check "r on the keyboard resets the orientation" same f1.ppm fr.ppm

# The latency: clean taps of left (a turn starts at the edge itself).
n0=$(presented)
r0=$(grep -c "button left .*: pressed at" kiosk.log)
for i in 1 2 3 4; do
	n=$(presented); down $LEFT; wait_frame "$n"; up $LEFT; quiet
done
grep "presented .* ms after the input" kiosk.log | tail -n +$((n0 + 1)) |
	sed -n 's/.*presented \([0-9.]*\) ms after.*/\1/p' >latency-frame.txt
grep "button left .*: pressed at" kiosk.log | tail -n +$((r0 + 1)) |
	sed -n 's/.* read \([0-9.]*\) ms later.*/\1/p' >latency-read.txt
summary() { # WHAT FILE
	sort -n "$2" | awk -v w="$1" '{ v[NR] = $1 } END {
		if (NR) printf "%s: median %.2f ms, max %.2f ms over %d edges\n", w,
			v[int((NR + 1) / 2)], v[NR], NR }'
}

kill -TERM $KPID
wait $KPID
rc=$?
{
	summary "edge to the kiosk reading it" latency-read.txt
	summary "edge to the frame that shows it, presented" latency-frame.txt
	sed -n 's/.*kms: \(.* page flips in .*\)/\1/p' kiosk.log | tail -1
} | tee latency-summary.txt
vm_check "SIGTERM: exit 0 ($rc)" test $rc = 0
vm_check "no error in the log" sh -c "! grep -q ': error: ' kiosk.log"
grep "frames drawn" kiosk.log
vkbd_stop

# ---- faults: a missing line, a busy line, a line that goes away
gpiosim_make spare 1 GPIO23 >/dev/null
spare=$(gpiosim_sysfs spare)
# libgpiod 2's tools (Debian 13) take the chip with -c.
c=
gpiomon --version 2>/dev/null | grep -q ' v1\.' || c=-c
gpiomon $c "$chip" 3 >/dev/null 2>&1 &
mon=$!
wait_until 10 sh -c "gpioinfo $c $chip | grep -q gpiomon"
matcap-kiosk --config gpio.ini -v --button-left GPIO99 --button-right GPIO5 \
	--button-select GPIO23 >faults.log 2>&1 &
KPID=$!
wait_until 120 grep -q "ready: the first frame" faults.log
vm_check "a missing line is one error naming it" \
	sh -c "[ \$(grep -c 'error: button left: no GPIO line named GPIO99' faults.log) = 1 ]"
vm_check "a line used by another program is one error naming it and the user" \
	sh -c "[ \$(grep -c 'error: button right (GPIO5 on $chip): the line is used by another program (gpiomon)' faults.log) = 1 ]"
n=$(grep -c "presented .* ms after the input" faults.log)
echo pull-down >"$spare/sim_gpio0/pull"
sleep 0.2
echo pull-up >"$spare/sim_gpio0/pull"
wait_until 30 sh -c "[ \$(grep -c 'presented .* ms after the input' faults.log) -gt $n ]"
vm_check "the button that is there works" grep -q "matcap /tmp/mc/clay-red.png" faults.log
vm_check "the kiosk runs on" kill -0 $KPID
kill -TERM $KPID
wait $KPID
kill $mon 2>/dev/null
wait $mon 2>/dev/null
cat faults.log

matcap-kiosk --config gpio.ini --gpio-chip nosuchchip >nochip.log 2>&1 &
KPID=$!
wait_until 120 grep -q "ready: the first frame" nochip.log
vm_check "a missing chip is one error per button, naming chip and line" \
	sh -c "[ \$(grep -c 'GPIO chip nosuchchip not found.*line GPIO' nochip.log) = 3 ]"
vm_check "... and the kiosk runs on" kill -0 $KPID
kill -TERM $KPID
wait $KPID

# GPIO17 by name and by offset 0 on the same chip (named by its label):
# one line, two buttons.
matcap-kiosk --config gpio.ini --gpio-chip buttons --button-right 0 >dup.log 2>&1
rc=$?
cat dup.log
vm_check "two buttons on one line: exit 78 ($rc)" test $rc = 78
vm_check "... naming both" grep -q "left = GPIO17 and right = 0 are the same line" dup.log

dmesg >kernel.log
vm_check "no kernel warning, BUG or oops" sh -c '! grep -Eq "WARNING:|BUG:|Oops|Call Trace" kernel.log'
vm_summary
