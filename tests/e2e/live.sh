#!/bin/sh
# The live loop of a real kiosk process (the ASan build, through OSMesa),
# driven the way systemd and a technician drive it, with no systemd: a
# socket of tests/notify_listen stands in for NOTIFY_SOCKET.
#   live.sh KIOSK NOTIFY_LISTEN MODEL DIR
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end.
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa} # egl-headless where Mesa has no OSMesa
kiosk=$1
listen=$2
model=$(cd "$(dirname "$3")" && pwd)/$(basename "$3") # a path in kiosk.ini is the file's folder's
dir=$4
rm -rf "$dir"
mkdir -p "$dir/mc" "$dir/run"
dir=$(cd "$dir" && pwd) # NOTIFY_SOCKET must be an absolute path
export RUNTIME_DIRECTORY="$dir/run" # --status's socket
cp matcaps/gold.png matcaps/pearl.png "$dir/mc/"
printf '[scene]\nmode = view\n' >"$dir/kiosk.ini"

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@"; then echo "ok $name"; else echo "not ok $name"; fi
}
# wait_for FILE PATTERN [COUNT]: until PATTERN is on COUNT lines (10 s at most).
wait_for() {
	i=0
	# grep -c prints nothing for a file not there yet: that counts 0.
	while n=$(grep -c -- "$2" "$1" 2>/dev/null); [ "${n:-0}" -lt "${3:-1}" ]; do
		i=$((i + 1))
		[ $i -gt 200 ] && return 1
		sleep 0.05
	done
}

"$listen" "$dir/notify" 60 >"$dir/notify.log" &
listener=$!
i=0
while [ ! -S "$dir/notify" ] && [ $i -lt 100 ]; do
	i=$((i + 1))
	sleep 0.05
done
# WATCHDOG_PID must be the kiosk's own pid: the shell's, which exec keeps.
# Leak detection is off here: Mesa's OSMesa leaks a fixed 592 bytes per
# process inside OSMesaCreateContextAttribs and its first shader compile,
# and as the library is unloaded at exit LeakSanitizer can neither name nor
# suppress them. The project's own code on these paths is leak-checked by
# valgrind in the soak test (tests/soak/soak.sh), which keeps the library loaded.
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
NOTIFY_SOCKET=$dir/notify WATCHDOG_USEC=400000 sh -c 'export WATCHDOG_PID=$$; exec "$0" "$@"' \
	"$kiosk" --backend $offscreen --size 64x64 --config "$dir/kiosk.ini" --matcap "$dir/mc" -v \
	2>"$dir/stderr" &
kiosk_pid=$!

step "READY=1 once the first frame is drawn" wait_for "$dir/notify.log" "READY=1 STATUS=showing"
step "ready logged after the first frame" wait_for "$dir/stderr" "ready: the first frame"

printf '[scene]\nmode = normal\nmodel = %s\n' "$model" >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "SIGHUP reloads a new config and model" wait_for "$dir/stderr" "reload: done"
step "RELOADING=1 then READY=1 around the reload" sh -c "grep -q RELOADING=1 '$dir/notify.log' &&
	grep -A9 RELOADING=1 '$dir/notify.log' | grep -q 'READY=1 STATUS=reloaded'"
step "the reloaded mode is used" wait_for "$dir/stderr" "mode normal"

# SIGHUP does what --help says of each section: [buttons] and [camera]
# are opened again when they changed (there is no GPIO chip here: one
# error line, and the kiosk runs on), [display] waits for a restart.
printf '[scene]\nmode = normal\nmodel = %s\n[buttons]\nchip = gpiochip9\nleft = 5\n[camera]\nstall_timeout = 5\n[display]\non_busy = exit\n' \
	"$model" >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a reload with new [buttons] opens the buttons again" wait_for "$dir/stderr" \
	"reload: .buttons. changed: opening the buttons again"
step "... a missing GPIO chip is one error line" wait_for "$dir/stderr" \
	"button left: GPIO chip gpiochip9 not found"
step "a reload with new [camera] starts the camera again" wait_for "$dir/stderr" \
	"reload: .camera. changed: starting the camera again"
step "a reload with new [display] says it waits for a restart" wait_for "$dir/stderr" \
	"reload: .display. settings apply at the next start"
step "... and the reload is done" wait_for "$dir/stderr" "reload: done" 2
kill -HUP $kiosk_pid
step "a reload with the same [buttons] and [camera] leaves them" sh -c "
	i=0; while [ \$(grep -c 'reload: done' '$dir/stderr') -lt 3 ] && [ \$i -lt 200 ]; do
		i=\$((i + 1)); sleep 0.05; done
	[ \$(grep -c 'reload: done' '$dir/stderr') -eq 3 ] &&
	[ \$(grep -c 'opening the buttons again' '$dir/stderr') -eq 1 ] &&
	[ \$(grep -c 'starting the camera again' '$dir/stderr') -eq 1 ] &&
	[ \$(grep -c 'gpiochip9 not found' '$dir/stderr') -eq 1 ]"

cp matcaps/skin.png "$dir/mc/skin.png.part"
mv "$dir/mc/skin.png.part" "$dir/mc/skin.png"
cp matcaps/clay-red.png "$dir/mc/"
step "matcaps copied into the folder are picked up" wait_for "$dir/stderr" "$dir/mc: 4 matcaps"
rm "$dir/mc/pearl.png"
step "a matcap removed from the folder is dropped" wait_for "$dir/stderr" "$dir/mc: 3 matcaps"

printf '[scene]\nmode = phong\n' >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a bad config is reported with its line" wait_for "$dir/stderr" "kiosk.ini:2: .scene. mode"
step "... and says the scene stays" wait_for "$dir/stderr" "settings have errors"
printf '[scene]\nmodel = %s/no-such-model.glb\n' "$dir" >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a missing model keeps the scene" wait_for "$dir/stderr" "keeping the scene on screen ($dir/no-such-model.glb: cannot open"
# --status's last error names the failed reload's cause; a good reload clears it.
step "--status names the cause of the failed reload" sh -c "
	ASAN_OPTIONS=detect_leaks=0 '$kiosk' --status 2>&1 | tee '$dir/status-bad.json' |
	grep -qF '\"last_error\": \"reload: the scene does not load; keeping the scene on screen ($dir/no-such-model.glb: cannot open: No such file or directory)\"'"
printf '[scene]\nmode = view\n' >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a good reload after it" wait_for "$dir/stderr" "reload: done" 4
step "... clears --status's last error" sh -c "
	ASAN_OPTIONS=detect_leaks=0 '$kiosk' --status 2>&1 | tee '$dir/status-good.json' |
	grep -qF '\"last_error\": \"\"'"
# A drop-in (kiosk.ini.d/*.ini) is read again by a reload, over kiosk.ini.
mkdir -p "$dir/kiosk.ini.d"
printf '[scene]\nmode = sem-vertex\n' >"$dir/kiosk.ini.d/10-fleet.ini"
kill -HUP $kiosk_pid
step "a reload reads a drop-in put in kiosk.ini.d/" wait_for "$dir/stderr" "mode sem-vertex"
rm -r "$dir/kiosk.ini.d"
printf '[scene]\nmode = phong\n' >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a reload with a bad setting" wait_for "$dir/stderr" "settings have errors" 2
step "... --status names its file and line" sh -c "
	ASAN_OPTIONS=detect_leaks=0 '$kiosk' --status 2>&1 | tee '$dir/status-setting.json' |
	grep -F 'the settings have errors; keeping the scene on screen ($dir/kiosk.ini:2: [scene] mode = ' |
	grep -qF 'is not valid'"

# 400 ms watchdog: a ping every 200 ms from the loop, even when idle.
sleep 1.2
pings=$(grep -c "WATCHDOG=1" "$dir/notify.log")
step "watchdog pinged from the idle loop ($pings pings)" [ "$pings" -ge 5 ]

step "still running after all of it" kill -0 $kiosk_pid
kill -TERM $kiosk_pid
wait $kiosk_pid
status=$?
step "SIGTERM exits 0 (status $status)" [ $status -eq 0 ]
step "STOPPING=1 sent" wait_for "$dir/notify.log" "STOPPING=1"
step "no sanitizer report (memory errors, undefined behaviour)" sh -c "! grep -qE 'Sanitizer|runtime error' '$dir/stderr'"
kill $listener 2>/dev/null
wait $listener 2>/dev/null

# A reload that takes longer than the watchdog (WATCHDOG_USEC=3 s, as
# systemd's WatchdogSec=3s; the test hook MK_TEST_PREPARE_DELAY_MS of the
# sanitizer builds holds its preparation 4 s on the worker): the loop
# draws, flips and pings meanwhile, answers --status with the old model,
# and shows the new one after. The model turns by itself (attract mode),
# so every pass draws a frame.
mkdir -p "$dir/slow/run"
printf '[kiosk]\nattract_after = 1\nattract_fps = 30\n' >"$dir/slow/kiosk.ini"
"$listen" "$dir/slow/notify" 60 >"$dir/slow/notify.log" &
listener=$!
i=0
while [ ! -S "$dir/slow/notify" ] && [ $i -lt 100 ]; do
	i=$((i + 1))
	sleep 0.05
done
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
RUNTIME_DIRECTORY=$dir/slow/run MK_TEST_PREPARE_DELAY_MS=4000 \
NOTIFY_SOCKET=$dir/slow/notify WATCHDOG_USEC=3000000 sh -c 'export WATCHDOG_PID=$$; exec "$0" "$@"' \
	"$kiosk" --backend $offscreen --size 64x64 --config "$dir/slow/kiosk.ini" --keyboard none \
	--camera off -v 2>"$dir/slow/stderr" &
kiosk_pid=$!
step "slow reload: READY=1 first" wait_for "$dir/slow/notify.log" "READY=1 STATUS=showing"
printf '[kiosk]\nattract_after = 1\nattract_fps = 30\n[scene]\nmodel = %s\n' "$model" \
	>"$dir/slow/kiosk.ini"
sleep 1.5 # attract mode on: frames drawn without input
kill -HUP $kiosk_pid
step "slow reload: started" wait_for "$dir/slow/stderr" "reload: reading the settings"
sleep 1
RUNTIME_DIRECTORY=$dir/slow/run "$kiosk" --status >"$dir/slow/during.json" 2>&1
step "slow reload: --status answered during it, with the old model" \
	grep -q '"model": null' "$dir/slow/during.json"
i=0
while ! grep -q "reload: done" "$dir/slow/stderr" && [ $i -lt 300 ]; do
	i=$((i + 1))
	sleep 0.05
done
step "slow reload: done after the 4 s preparation" grep -q "reload: done" "$dir/slow/stderr"
frames=$(sed -n 's/.*reload: done (\([0-9]*\) frames drawn meanwhile).*/\1/p' "$dir/slow/stderr")
step "slow reload: frames drawn and flipped during it (${frames:-none})" [ "${frames:-0}" -ge 20 ]
# The pings between RELOADING=1 and READY=1: none more than 3 s apart.
gap=$(awk '/RELOADING=1/ { on = 1; last = $1 } on && /WATCHDOG=1/ { if ($1 - last > max) max = $1 - last; last = $1; n++ }
	on && /STATUS=reloaded/ { if ($1 - last > max) max = $1 - last; print n + 0, max + 0; exit }' \
	"$dir/slow/notify.log")
step "slow reload: the watchdog pinged during it (pings, longest gap ms: ${gap:-none})" \
	sh -c "[ -n '$gap' ] && [ \$(echo '$gap' | cut -d' ' -f1) -ge 2 ] && [ \$(echo '$gap' | cut -d' ' -f2) -lt 3000 ]"
RUNTIME_DIRECTORY=$dir/slow/run "$kiosk" --status >"$dir/slow/after.json" 2>&1
step "slow reload: the new model shows after" grep -q "\"model\": \"$model\"" "$dir/slow/after.json"
step "slow reload: not killed" kill -0 $kiosk_pid
kill -TERM $kiosk_pid
wait $kiosk_pid
status=$?
step "slow reload: SIGTERM exits 0 (status $status)" [ $status -eq 0 ]
step "slow reload: no sanitizer report" sh -c "! grep -qE 'Sanitizer|runtime error' '$dir/slow/stderr'"
kill $listener 2>/dev/null
wait $listener 2>/dev/null
# A model's own matcap and background (its NAME.ini): swapped in with it
# (attract mode steps the folder each second), and kiosk.ini's again with
# the next model; then a single model file's NAME.ini, watched: written,
# the model is loaded again with it.
look=$dir/look
rm -rf "$look" # a NAME.ini left by an earlier run would not change when written
mkdir -p "$look/m" "$look/one" "$look/run"
cp "$model" "$look/m/a.glb"
cp "$model" "$look/m/b.glb"
cp "$model" "$look/one/s.glb"
cp matcaps/gold.png matcaps/pearl.png "$look/"
printf '[scene]\nmatcap = ../pearl.png\n[display]\nbackground = #304050\n' >"$look/m/a.ini"
printf '[kiosk]\nattract_after = 1\nattract_model_seconds = 1\n[scene]\nmodel = %s\nmatcap = %s\n' \
	"$look/m" "$look/gold.png" >"$look/m.ini"
printf '[scene]\nmodel = %s\n' "$look/one/s.glb" >"$look/one.ini"
look_kiosk() { # CONFIG LOG
	ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 RUNTIME_DIRECTORY=$look/run \
		"$kiosk" --backend "$offscreen" --size 64x64 --config "$1" --keyboard none --camera off \
		-v 2>"$2" &
	look_pid=$!
}
look_kiosk "$look/m.ini" "$look/stderr"
step "own look: the next model goes back to kiosk.ini's matcap" \
	wait_for "$look/stderr" "b.glb: shown with the matcaps $look/gold.png"
step "own look: a model's own matcap is swapped in with it" \
	wait_for "$look/stderr" "a.glb: shown with the matcaps $look/m/../pearl.png"
step "own look: ... with its own background" \
	wait_for "$look/stderr" "a.glb: shown on the background #304050"
kill -TERM $look_pid
wait $look_pid
look_kiosk "$look/one.ini" "$look/one.log"
wait_for "$look/one.log" "ready: the first frame"
printf '[display]\nbackground = #203040\n' >"$look/one/s.ini"
step "own look: a single model's NAME.ini written loads it again" \
	wait_for "$look/one.log" "s.glb: its settings changed: loading it again"
step "own look: ... with its background" \
	wait_for "$look/one.log" "s.glb: shown on the background #203040"
kill -TERM $look_pid
wait $look_pid
step "own look: no sanitizer report" \
	sh -c "! grep -qE 'Sanitizer|runtime error' '$look/stderr' '$look/one.log'"
echo "ok every step ran"
