#!/bin/sh
# The live kiosk's crash memory (src/content/load_guard.h), as systemd's
# restart meets it: the state folder holds the marker a process killed
# while loading a model leaves (written here as the kiosk writes it: no
# test hook in the program), and the next start passes that model over,
# says so, and shows the folder's other model (or the built-in knot when
# it was the only one), until the file changes. Also a folder whose model
# nests its JSON 30,000 deep: refused, the other shown, no crash.
#   crash_memory.sh KIOSK MODEL_A MODEL_B DIR
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran".
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa}
kiosk=$1
dir=$4
rm -rf "$dir"
mkdir -p "$dir/m" "$dir/one" "$dir/deep" "$dir/state"
dir=$(cd "$dir" && pwd)
cp "$2" "$dir/m/a.glb"
cp "$3" "$dir/m/b.glb"
cp "$2" "$dir/one/only.glb"
cp "$3" "$dir/deep/b.glb"
sh tests/fuzz/deep_json.sh 30002 gltf >"$dir/deep/a-deep.gltf"
export STATE_DIRECTORY="$dir/state"
# Its prepared-mesh cache apart: a model from the cache is guarded too,
# but the test must not depend on it.
export XDG_CACHE_HOME="$dir/cache"

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@"; then echo "ok $name"; else echo "not ok $name"; fi
}
# seed MODEL: the marker a kiosk killed while loading MODEL leaves.
seed() {
	printf 'boot %s\n%s %s %s\n' "$(cat /proc/sys/kernel/random/boot_id)" \
		"$(stat -c %s "$1")" "$(stat -c %.9Y "$1")" "$1" >"$dir/state/loading"
}
# live LOG MODEL: the live kiosk until its first frame, then SIGTERM;
# true when it got there and exited 0 with no sanitizer report.
live() {
	: >"$1" # made before the kiosk starts, for the grep below
	ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 "$kiosk" --backend "$offscreen" \
		--size 64x64 --keyboard none --matcap matcaps/gold.png --model "$2" 2>"$1" &
	pid=$!
	i=0
	until grep -q 'ready: the first frame' "$1" || [ $i -gt 300 ]; do
		sleep 0.1
		i=$((i + 1))
	done
	kill -TERM $pid
	wait $pid && grep -q 'ready: the first frame' "$1" && ! grep -qE 'Sanitizer|runtime error' "$1"
}
has() { grep -qF -- "$2" "$1"; }
count() { [ "$(grep -cF -- "$2" "$1")" = "$3" ]; }

seed "$dir/m/a.glb"
step "a start after a kill runs to its first frame" live "$dir/1.log" "$dir/m"
step "... one error names the model it died loading" count "$dir/1.log" \
	"$dir/m/a.glb: the last start died while loading it (the process was killed); skipped until it changes" 1
step "... and that model is passed over" has "$dir/1.log" "$dir/m/a.glb: skipped: the kiosk died while loading it before"
step "... the folder's other model is shown" has "$dir/1.log" "models: 2, showing $dir/m/b.glb"
step "... the marker is gone, the skip list names it" sh -c \
	"[ ! -e '$dir/state/loading' ] && grep -q ' $dir/m/a.glb\$' '$dir/state/skip'"
step "the next start passes it over again, without the kill's line" live "$dir/2.log" "$dir/m"
step "... skipped" has "$dir/2.log" "$dir/m/a.glb: skipped"
step "... no second kill" count "$dir/2.log" "the last start died" 0
step "... the other model shown" has "$dir/2.log" "models: 2, showing $dir/m/b.glb"
touch -d '+1 second' "$dir/m/a.glb"
step "the file changed: it is tried again and shown" live "$dir/3.log" "$dir/m"
step "... shown first" has "$dir/3.log" "models: 2, showing $dir/m/a.glb"
step "... no marker left after a load" test ! -e "$dir/state/loading"

seed "$dir/one/only.glb"
step "the only model killed the last start: the kiosk runs" live "$dir/4.log" "$dir/one/only.glb"
step "... with the built-in knot, saying why" sh -c \
	"grep -qF 'showing the built-in torus knot instead of $dir/one/only.glb' '$dir/4.log' &&
	grep -qF 'models: 1, showing the built-in knot' '$dir/4.log'"

# A one-shot render is no kiosk: it neither reads nor writes the marker.
seed "$dir/one/only.glb"
cp "$dir/state/loading" "$dir/seeded"
# (Leak checks off as in live(): OSMesa's own 592 bytes, tests/e2e/live.sh.)
step "a render (--output) loads the model and leaves the marker alone" sh -c \
	"ASAN_OPTIONS=detect_leaks=0 '$kiosk' --backend $offscreen --size 64x64 --model '$dir/one/only.glb' \
		--output '$dir/x.png' 2>'$dir/5.log' && cmp -s '$dir/seeded' '$dir/state/loading'"
rm -f "$dir/state/loading"

step "a folder with a model nested 30,000 deep: the kiosk runs" live "$dir/6.log" "$dir/deep"
step "... one error names it and the depth" count "$dir/6.log" \
	"$dir/deep/a-deep.gltf: JSON nested deeper than 64 levels at byte 97 (line 1)" 1
step "... the other model shown" has "$dir/6.log" "models: 2, showing $dir/deep/b.glb"
step "... nothing remembered: the depth refused it, no kill" sh -c \
	"[ ! -e '$dir/state/loading' ] && ! grep -q a-deep '$dir/state/skip'"
echo "ok every step ran"
