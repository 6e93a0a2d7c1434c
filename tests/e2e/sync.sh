#!/bin/sh
# Content by sync: a live kiosk (offscreen) watches a model folder while
# real rsync, slowed down (--bwlimit), copies models into it, and while
# files come in under Syncthing's temporary names. The kiosk must never try
# a file that is still being written (no error, no texture "not used"), and
# must show each model once it is whole: a large .glb, then a .gltf laid
# out as Blender and Sketchfab write it (scene.gltf first, its buffer in
# data/ and its textures in textures/ after it, in rsync's order).
#   sync.sh KIOSK MODELS DIR
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end.
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa}
kiosk=$1
models=$2
dir=$3
rm -rf "$dir"
mkdir -p "$dir/shown" "$dir/big" "$dir/layout/data" "$dir/layout/textures"
dir=$(cd "$dir" && pwd)
# Leaks: see tests/e2e/live.sh (OSMesa's, at unload).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@"; then echo "ok $name"; else echo "not ok $name"; fi
}
# wait_for FILE PATTERN [SECONDS]: until PATTERN is in FILE (20 s at most).
wait_for() {
	i=0
	until grep -q -- "$2" "$1" 2>/dev/null; do
		i=$((i + 1))
		[ $i -gt $((${3:-20} * 20)) ] && return 1
		sleep 0.05
	done
}
# rsync_slowly SRC: rsync SRC/ into the watched folder at 300 KB/s, in the
# background; partial.seen gets the temporary names seen meanwhile.
rsync_slowly() {
	rsync -r --bwlimit=300 "$1/" "$dir/shown/" &
	sync_pid=$!
	while kill -0 $sync_pid 2>/dev/null; do
		find "$dir/shown" -name '.*.*' -type f >>"$dir/partial.seen"
		sleep 0.05
	done
	wait $sync_pid
}
# errors: the kiosk's error lines and unused textures, counted.
errors() { grep -c -e 'error:' -e 'not used' "$dir/kiosk.log"; }

cp "$models/sphere.glb" "$dir/shown/sphere.glb"
"$kiosk" --backend "$offscreen" --size 64x64 --keyboard none --camera off --attract-after 0 \
	--model "$dir/shown" >"$dir/kiosk.log" 2>&1 &
pid=$!
step "the kiosk shows the folder's one model" wait_for "$dir/kiosk.log" "models: 1, showing"

# 1. One large .glb (860 KiB: 3 s at 300 KB/s), written as rsync writes:
#    .knot.glb.XXXXXX, renamed knot.glb when whole.
cp "$models/knot-flat.glb" "$dir/big/knot.glb"
: >"$dir/partial.seen"
rsync_slowly "$dir/big"
step "rsync exits 0" [ $? = 0 ]
step "rsync wrote under a temporary name, seen mid-copy" grep -q '/\.knot\.glb\.' "$dir/partial.seen"
step "the large model is shown once it has landed" \
	wait_for "$dir/kiosk.log" "model 1 of 2: $dir/shown/knot.glb"
step "... and no partial file was tried (no error)" [ "$(errors)" = 0 ]

# 2. scene.gltf lands first, its buffer (data/) and textures (textures/)
#    after it: the kiosk waits for them.
sed -e 's#"uri":"sphere-beetle.bin"#"uri":"data/scene.bin"#' \
	-e 's#"uri":"\([a-z]*\)\.png"#"uri":"textures/\1.png"#g' \
	"$models/sphere-beetle.gltf" >"$dir/layout/scene.gltf"
cp "$models/sphere-beetle.bin" "$dir/layout/data/scene.bin"
# 1 MB that rsync sends before scene.bin (3 s at 300 KB/s): the buffer is
# certainly not there yet when the kiosk first looks after scene.gltf.
head -c 1000000 /dev/urandom >"$dir/layout/data/aa-first.bin"
cp "$models/normal.png" "$models/occlusion.png" "$models/thickness.png" "$dir/layout/textures/"
: >"$dir/partial.seen"
rsync_slowly "$dir/layout"
step "rsync of a model folder with subfolders exits 0" [ $? = 0 ]
step "its buffer was written under a temporary name in data/, after scene.gltf" \
	grep -q '/data/\.scene\.bin\.' "$dir/partial.seen"
step "the kiosk said it waits for the sync" \
	grep -q "models: a sync is writing into $dir/shown: waiting until it is done" "$dir/kiosk.log"
step "scene.gltf is shown once its buffer and textures are there" \
	wait_for "$dir/kiosk.log" "model 2 of 3: $dir/shown/scene.gltf"
step "... with no error and every texture used" [ "$(errors)" = 0 ]

# 3. Syncthing: .syncthing.NAME.tmp (Linux) and ~syncthing~NAME.tmp
#    (where dot files are not hidden), cut short, then whole and renamed.
head -c 4000 "$models/sphere-coarse.glb" >"$dir/shown/.syncthing.c.glb.tmp"
head -c 4000 "$models/sphere-coarse.glb" >"$dir/shown/~syncthing~d.glb.tmp"
sleep 1.5
step "Syncthing's temporary files are not tried" [ "$(errors)" = 0 ]
cat "$models/sphere-coarse.glb" >"$dir/shown/.syncthing.c.glb.tmp"
cat "$models/sphere-coarse.glb" >"$dir/shown/~syncthing~d.glb.tmp"
mv "$dir/shown/.syncthing.c.glb.tmp" "$dir/shown/c.glb"
mv "$dir/shown/~syncthing~d.glb.tmp" "$dir/shown/d.glb"
step "renamed into place, they are taken" wait_for "$dir/kiosk.log" "model [0-9] of 5: $dir/shown/d.glb"
step "... with no error" [ "$(errors)" = 0 ]

kill -TERM $pid
wait $pid
step "the kiosk ends cleanly" [ $? = 0 ]
echo "ok every step ran"
