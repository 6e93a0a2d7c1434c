#!/bin/sh
# Hands-off operation on this machine, through the offscreen backend:
# --status against a running kiosk (and none), the poster, --check-config,
# and --import of a USB stick's folder (a good one, then broken ones that
# must change nothing), with the imported content shown after a reload.
# Last, the Plymouth hand-over of systemd/matcap-kiosk.service, played as
# systemd plays a Type=notify unit (ExecStartPre=, the program until it
# sends READY=1, ExecStartPost=) with a fake plymouth that records what it
# is asked.
#   hands.sh KIOSK IMGDIFF MODELS DIR NOTIFY_LISTEN
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end.
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa}
kiosk=$1
imgdiff=$2
models=$3
dir=$4
listen=$5
rm -rf "$dir"
mkdir -p "$dir/run" "$dir/state"
dir=$(cd "$dir" && pwd)
export RUNTIME_DIRECTORY="$dir/run" STATE_DIRECTORY="$dir/state"
# Leaks: see tests/e2e/live.sh (OSMesa's, at unload).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
scene="--backend $offscreen --size 96x96 --keyboard none --camera off --attract-after 0"

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@" >>"$dir/steps.log" 2>&1; then echo "ok $name"; else echo "not ok $name"; fi
}
wait_for() { # FILE PATTERN: until it is there (10 s at most)
	i=0
	until grep -q -- "$2" "$1" 2>/dev/null; do
		i=$((i + 1))
		[ $i -gt 200 ] && return 1
		sleep 0.05
	done
}
# tree DIR: every file's name and checksum, to tell a tree that changed.
tree() { (cd "$1" && find . -type f | sort | xargs -r md5sum); }

# --status with no kiosk: a clear line and a failure.
"$kiosk" --status >"$dir/none.out" 2>"$dir/none.err"
rc=$?
step "--status with no kiosk running fails" [ $rc -ne 0 ]
step "--status with no kiosk says so" grep -q "no kiosk answers at $dir/run/status.sock" \
	"$dir/none.err"

# A live kiosk, a poster first, then --status.
"$kiosk" --size 96x96 --matcap matcaps/gold.png --output "$dir/poster.png" -q
printf '[display]\nposter = %s\n[kiosk]\ninclude = %s/content/kiosk.ini\n' "$dir/poster.png" \
	"$STATE_DIRECTORY" >"$dir/kiosk.ini"
# shellcheck disable=SC2086
"$kiosk" $scene --config "$dir/kiosk.ini" --matcap matcaps/gold.png >"$dir/kiosk.log" 2>&1 &
pid=$!
step "the poster is shown before the model" wait_for "$dir/kiosk.log" "poster: $dir/poster.png"
step "the kiosk listens for --status" wait_for "$dir/kiosk.log" "status: matcap-kiosk --status"
wait_for "$dir/kiosk.log" "ready: the first frame"
"$kiosk" --status >"$dir/status.json" 2>"$dir/status.err"
step "--status exits 0 with a kiosk running" [ $? -eq 0 ]
step "--status prints the state" grep -q '"frames_drawn": [1-9]' "$dir/status.json"
step "--status names the matcap and the power state" sh -c \
	"grep -q '\"matcap\": \"matcaps/gold.png\"' '$dir/status.json' &&
	grep -q '\"power\": \"on\"' '$dir/status.json'"
step "state.json is the same JSON" cmp -s "$dir/status.json" "$dir/run/state.json"
# shellcheck disable=SC2086
"$kiosk" $scene --matcap matcaps/gold.png --output "$dir/ref.png" -q
step "frame.png is the frame on screen" "$imgdiff" --tol 8 --share 0.005 "$dir/ref.png" \
	"$dir/run/frame.png"

# --check-config.
printf '[scene]\nmode = sideways\n' >"$dir/bad.ini"
step "--check-config passes a good file" "$kiosk" --check-config --config "$dir/kiosk.ini"
"$kiosk" --check-config --config "$dir/bad.ini" 2>"$dir/bad.err"
step "--check-config fails a bad file with 78" [ $? -eq 78 ]

# A stick: a model, a matcap, a settings fragment, and files not to take.
stick=$dir/stick/matcap-kiosk
mkdir -p "$stick/matcaps"
cp "$models/sphere.glb" "$stick/"
cp matcaps/pearl.png "$stick/matcaps/"
printf '[scene]\nmode = normal\n' >"$stick/kiosk.ini"
printf '#!/bin/sh\necho ran >%s/ran\n' "$dir" >"$stick/run.sh"
ln -s /etc/passwd "$stick/passwd.png"
step "--import copies a good stick" "$kiosk" --config "$dir/kiosk.ini" --import "$stick"
step "the model, matcap and settings are in the content folder" sh -c "
	test -f '$STATE_DIRECTORY/content/model/sphere.glb' &&
	test -f '$STATE_DIRECTORY/content/matcaps/pearl.png' &&
	grep -q 'mode = normal' '$STATE_DIRECTORY/content/kiosk.ini'"
step "nothing else from the stick is taken" sh -c "
	! test -e '$STATE_DIRECTORY/content/model/run.sh' &&
	! test -e '$STATE_DIRECTORY/content/model/passwd.png' && ! test -e '$dir/ran'"
kill -HUP $pid
wait_for "$dir/kiosk.log" "reload: done"
"$kiosk" --status >"$dir/status2.json" 2>&1
step "after a reload the kiosk shows the stick's model" grep -q \
	"\"model\": \"$STATE_DIRECTORY/content/model/sphere.glb\"" "$dir/status2.json"
step "... and its settings" grep -q '"mode": "normal"' "$dir/status2.json"
tree "$STATE_DIRECTORY" >"$dir/before"

# Broken sticks: a truncated model, a bad kiosk.ini, nothing of ours.
mkdir -p "$dir/broken/matcap-kiosk" "$dir/badini/matcap-kiosk" "$dir/empty/matcap-kiosk"
head -c 300 "$models/sphere.glb" >"$dir/broken/matcap-kiosk/sphere.glb"
cp "$models/sphere.glb" "$dir/badini/matcap-kiosk/"
cp "$dir/bad.ini" "$dir/badini/matcap-kiosk/kiosk.ini"
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/broken/matcap-kiosk" 2>"$dir/broken.err"
step "a stick with a broken model is refused" [ $? -ne 0 ]
step "... with a line that names the file" grep -q "sphere.glb" "$dir/broken.err"
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/badini/matcap-kiosk" 2>"$dir/badini.err"
step "a stick with a bad kiosk.ini is refused (78)" [ $? -eq 78 ]
mkdir -p "$dir/incl/matcap-kiosk"
cp "$models/sphere.glb" "$dir/incl/matcap-kiosk/"
printf '[kiosk]\ninclude = /etc/passwd\n' >"$dir/incl/matcap-kiosk/kiosk.ini"
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/incl/matcap-kiosk" 2>"$dir/incl.err"
step "a stick whose kiosk.ini names a file to include is refused (78)" [ $? -eq 78 ]
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/empty/matcap-kiosk" 2>"$dir/empty.err"
step "a stick with nothing to import is refused" [ $? -ne 0 ]
tree "$STATE_DIRECTORY" >"$dir/after"
step "refused sticks change nothing" cmp -s "$dir/before" "$dir/after"

kill -TERM $pid
wait $pid
step "the kiosk ends cleanly" [ $? -eq 0 ]
step "its socket is gone" test ! -e "$dir/run/status.sock"

# Plymouth: the unit's own command lines, with plymouth a fake that logs.
unit=systemd/matcap-kiosk.service
mkdir -p "$dir/bin"
printf '#!/bin/sh\necho "$*" >>%s/plymouth.log\n' "$dir" >"$dir/bin/plymouth"
chmod +x "$dir/bin/plymouth"
pre=$(sed -n 's|^ExecStartPre=-+/usr/bin/plymouth ||p' "$unit")
post=$(sed -n 's|^ExecStartPost=-+/usr/bin/plymouth ||p' "$unit")
step "the unit orders itself before Plymouth's own quit" grep -qx \
	'Before=plymouth-quit.service' "$unit"
"$listen" "$dir/notify" 30 >"$dir/notify.log" &
listener=$!
wait_for_socket() { [ -S "$dir/notify" ]; }
i=0
until wait_for_socket || [ $i -gt 100 ]; do
	i=$((i + 1))
	sleep 0.05
done
# shellcheck disable=SC2086
"$dir/bin/plymouth" $pre
# shellcheck disable=SC2086
NOTIFY_SOCKET=$dir/notify "$kiosk" $scene --config "$dir/kiosk.ini" >"$dir/splash.log" 2>&1 &
pid=$!
wait_for "$dir/notify.log" "READY=1"
shown=$(grep -c "ready: the first frame is on the screen" "$dir/splash.log")
# shellcheck disable=SC2086
"$dir/bin/plymouth" $post
step "ExecStartPost= comes after the first frame" [ "$shown" = 1 ]
step "plymouth is told to let go first, and to quit keeping its splash last" sh -c \
	"[ \"\$(cat '$dir/plymouth.log')\" = \"\$(printf 'deactivate\nquit --retain-splash')\" ]"
kill -TERM $pid
wait $pid
wait $listener
echo "ok every step ran"
