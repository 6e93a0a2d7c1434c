#!/bin/sh
# The guest half of tests/vm/systemd-test.sh, run by vm-systemd-test.service
# once systemd has started matcap-kiosk.service from its installed unit
# (the unit is ordered after it, so it runs once READY=1 came, or the start
# failed). Prints "vm-systemd: ok NAME" or "vm-systemd: not ok NAME" per
# check on the console, then "vm-systemd: N passed, N failed", and powers
# the machine off.
set -u
unit=matcap-kiosk.service
passed=0
failed=0

check() { # NAME COMMAND...
	name=$1
	shift
	if "$@" >/tmp/check.log 2>&1; then
		passed=$((passed + 1))
		echo "vm-systemd: ok $name"
	else
		failed=$((failed + 1))
		echo "vm-systemd: not ok $name"
		sed 's/^/vm-systemd:   /' /tmp/check.log | head -20
	fi
}
prop() { systemctl show -p "$1" --value "$unit"; }
# until SECONDS COMMAND...: true once COMMAND is.
until_ok() {
	end=$(($(date +%s) + $1))
	shift
	while ! "$@" >/dev/null 2>&1; do
		[ "$(date +%s)" -lt "$end" ] || return 1
		sleep 1
	done
}
shows_scene() { # the CRTC scans out a picture, not a flat console
	vm-grab -o /run/now.ppm >/run/now.txt 2>&1 &&
		[ "$(sed -n 's/.*differ=\([0-9]*\).*/\1/p' /run/now.txt)" -gt 10000 ]
}
journal_has() { journalctl -b -u "$unit" --no-pager -o cat | grep -q -- "$1"; }

echo "vm-systemd: guest test starts ($(uptime))"
check "the unit is active after boot (READY=1 came)" [ "$(prop ActiveState)" = active ]
check "READY=1 was sent after the first frame: $(prop StatusText)" \
	[ "$(prop StatusText)" = "showing the scene" ]
check "it runs as the user matcap-kiosk" sh -c \
	"ps -o user= -p $(prop MainPID) | grep -qx matcap-kiosk"
check "the scene is on vkms ($(vm-grab 2>&1 | sed -n 's/.*\(differ=[0-9]*\).*/\1/p'))" shows_scene
check "the journal says the first frame is on the screen" journal_has "first frame is on the screen"

# The watchdog: a stopped process pings no more; systemd kills it after
# WatchdogSec= and Restart=on-failure starts it again.
pid=$(prop MainPID)
restarts=$(prop NRestarts)
kill -STOP "$pid"
echo "vm-systemd: SIGSTOP to $pid at $(date +%T); waiting for the watchdog"
check "the watchdog restarts a stopped kiosk" until_ok 120 sh -c \
	"[ \$(systemctl show -p NRestarts --value $unit) -gt $restarts ] &&
	 [ \$(systemctl show -p ActiveState --value $unit) = active ]"
check "... for a watchdog timeout ($(date +%T))" sh -c \
	"journalctl -b --no-pager -o cat | grep -q 'matcap-kiosk.service: Watchdog timeout'"
check "... and it shows the scene again" until_ok 60 shows_scene

# A reload keeps the process and the picture.
pid=$(prop MainPID)
sed -i 's/^mode = .*/mode = normal/' /etc/matcap-kiosk/kiosk.ini
systemctl reload "$unit"
check "systemctl reload: the new config is read" until_ok 30 journal_has "reload: done"
check "... by the same process" [ "$(prop MainPID)" = "$pid" ]
check "... still showing the scene" shows_scene

# A reload that takes longer than WatchdogSec=3s (issue 22): the kiosk
# built with the test hooks (systemd-build.sh) holds the preparation of a
# bench knot 5 s on its worker, so the reload outlasts the watchdog
# whatever the guest's speed. systemd must not kill it: the loop draws,
# flips and pings meanwhile (attract mode turns the model, so every pass
# draws), and the knot shows after. The shipped binary has no such hook.
check "the installed kiosk has no test hook (built without -DMK_TEST_HOOKS)" sh -c \
	"! grep -q MK_TEST_PREPARE_DELAY_MS /usr/local/bin/matcap-kiosk"
cp /etc/matcap-kiosk/kiosk.ini /run/kiosk.ini.before-slow
echo "vm-systemd: the drop-in ($(date +%T))" >/dev/console
mkdir -p "/etc/systemd/system/$unit.d"
printf '%s\n' "[Service]" "ExecStart=" \
	"ExecStart=/usr/local/lib/vm-systemd/matcap-kiosk-hooks --config /etc/matcap-kiosk/kiosk.ini" \
	"WatchdogSec=3s" "Environment=MK_TEST_PREPARE_DELAY_MS=5000" \
	>"/etc/systemd/system/$unit.d/slow-reload.conf"
# 640x480: llvmpipe under TCG draws a 1024x768 frame in up to 2.5 s, and
# a flip pending for half of WatchdogSec= stops the pings by design.
sed -i 's/^attract_after = .*/attract_after = 1/; s/^;mode = .*/mode = 640x480/' \
	/etc/matcap-kiosk/kiosk.ini
echo "vm-systemd: the hooked kiosk with WatchdogSec=3s starts ($(date +%T))" >/dev/console
systemctl daemon-reload
systemctl restart --no-block "$unit"
check "slow reload: the hooked kiosk runs with WatchdogSec=3s" until_ok 120 sh -c \
	"[ \$(systemctl show -p ActiveState --value $unit) = active ] &&
	 [ \$(systemctl show -p WatchdogUSec --value $unit) = 3s ]"
[ "$(prop ActiveState)" = active ] ||
	systemctl status --no-pager -n 30 "$unit" | sed 's/^/vm-systemd:   /' >/dev/console
pid=$(prop MainPID)
restarts=$(prop NRestarts)
timeouts=$(journalctl -b --no-pager -o cat | grep -c "$unit: Watchdog timeout")
model=$(cat /usr/local/lib/vm-systemd/reload-model)
sed -i "s|^;model = .*|model = $model|" /etc/matcap-kiosk/kiosk.ini
sleep 2 # attract mode on: frames drawn without input
since=$(date '+%F %T')
t0=$(date +%s)
echo "vm-systemd: reloading $model ($(date +%T))" >/dev/console
systemctl reload --no-block "$unit"
reload_log() { journalctl -b -u "$unit" --since "$since" --no-pager -o cat; }
# Done, or failed (then the checks below say so at once).
until_ok 900 sh -c "journalctl -b -u $unit --since '$since' --no-pager -o cat |
	grep -qE 'reload: done|keeping the scene on screen' ||
	[ \$(systemctl show -p MainPID --value $unit) != $pid ]"
check "slow reload: done" sh -c "journalctl -b -u $unit --since '$since' --no-pager -o cat |
	grep -q 'reload: done'"
took=$(($(date +%s) - t0))
frames=$(reload_log | sed -n 's/.*reload: done (\([0-9]*\) frames drawn meanwhile).*/\1/p')
check "... it took longer than WatchdogSec=3s (${took} s)" [ "$took" -gt 3 ]
check "... not killed: the same process, no restart, no watchdog timeout" sh -c \
	"[ \$(systemctl show -p MainPID --value $unit) = $pid ] &&
	 [ \$(systemctl show -p NRestarts --value $unit) = $restarts ] &&
	 [ \$(journalctl -b --no-pager -o cat | grep -c '$unit: Watchdog timeout') = $timeouts ]"
check "... frames drawn and flipped during it (${frames:-none})" [ "${frames:-0}" -ge 5 ]
check "... the new model shows after" sh -c \
	"RUNTIME_DIRECTORY=/run/matcap-kiosk /usr/local/bin/matcap-kiosk --status |
	 grep -q '\"model\": \"$model\"'"
check "... on vkms" shows_scene
until_ok 30 sh -c "journalctl -b -u $unit --since '$since' --no-pager -o cat |
	grep -q 'longest step during it'"
longest=$(reload_log | sed -n 's/.*longest step during it took \([0-9.]*\) ms.*/\1/p')
echo "vm-systemd: the loop's longest step during the reload of $model: ${longest:-?} ms"
check "... the loop's longest step during it is logged (${longest:-none} ms)" [ -n "$longest" ]
# What the kiosk and systemd said meanwhile (a kill would show here).
journalctl -b --since "$since" --no-pager -o short-monotonic |
	grep -E "matcap-kiosk|$unit" | grep -vE 'GPIO|plymouth' | head -40 | sed 's/^/vm-systemd:   /'
rm -r "/etc/systemd/system/$unit.d"
cp /run/kiosk.ini.before-slow /etc/matcap-kiosk/kiosk.ini
systemctl daemon-reload
systemctl restart --no-block "$unit"
until_ok 60 sh -c "[ \$(systemctl show -p ActiveState --value $unit) = active ]"

# A config error stops the kiosk with 78 and is not restarted.
cp /etc/matcap-kiosk/kiosk.ini /run/kiosk.ini.good
printf '[kiosk]\nno_such_key = 1\n' >>/etc/matcap-kiosk/kiosk.ini
systemctl restart "$unit"
check "a config error: exit status 78, not restarted" until_ok 30 sh -c \
	"[ \$(systemctl show -p ExecMainStatus --value $unit) = 78 ] &&
	 [ \$(systemctl show -p ActiveState --value $unit) = failed ]"
cp /run/kiosk.ini.good /etc/matcap-kiosk/kiosk.ini
systemctl reset-failed "$unit"
systemctl start "$unit"
check "fixed, it starts again" [ "$(prop ActiveState)" = active ]

# Stop: the console's mode and framebuffer come back.
systemctl stop "$unit"
vm-grab -o /run/after.ppm >/run/after.txt 2>&1
# "crtc N fb N WxH FORMAT pitch N modifier M mode NAME differ=N": all but
# the picture itself, which the console's cursor may have changed.
before=$(sed 's/ differ=.*//' /run/before.txt)
after=$(sed 's/ differ=.*//' /run/after.txt)
echo "vm-systemd: before the kiosk: $before"
echo "vm-systemd: after the stop:   $after"
check "systemctl stop: it exits cleanly ($(prop Result), status $(prop ExecMainStatus))" \
	[ "$(prop Result)" = success ]
check "... and the display is back to its framebuffer and mode from before the kiosk" \
	sh -c '[ -n "$1" ] && [ "$1" = "$2" ]' - "$before" "$after"

echo "vm-systemd: --- the kiosk's journal ---"
journalctl -b -u "$unit" --no-pager -o short-monotonic | tail -40 | sed 's/^/vm-systemd:   /'
echo "vm-systemd: $passed passed, $failed failed"
systemctl poweroff --no-block
