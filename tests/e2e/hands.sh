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
mkdir -p "$dir/run" "$dir/state" "$dir/bin"
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
# What an import cut short (stopped, the power gone) left: the kiosk's
# start removes it.
mkdir -p "$STATE_DIRECTORY/.content.new/model"
echo half >"$STATE_DIRECTORY/.content.new/model/half.bin"
# shellcheck disable=SC2086
"$kiosk" $scene --config "$dir/kiosk.ini" --matcap matcaps/gold.png >"$dir/kiosk.log" 2>&1 &
pid=$!
step "the poster is shown before the model" wait_for "$dir/kiosk.log" "poster: $dir/poster.png"
step "the kiosk listens for --status" wait_for "$dir/kiosk.log" "status: matcap-kiosk --status"
wait_for "$dir/kiosk.log" "ready: the first frame"
step "the kiosk's start removes a staging folder an import cut short left, and says so" sh -c "
	! test -e '$STATE_DIRECTORY/.content.new' &&
	grep -q '.content.new: removed what an import cut short left there' '$dir/kiosk.log'"
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
# A NAME.ini put beside an imported model by other means than the import
# is still a stick's: read with a stick's rules (issue 32's second line).
printf '[scene]\nmatcap = /usr/share/pixmaps\n' >"$STATE_DIRECTORY/content/model/sphere.ini"
"$kiosk" --config "$dir/kiosk.ini" --keyboard none --output "$dir/own.png" 2>"$dir/own.err"
step "an imported model's NAME.ini is read with a stick's rules" sh -c "
	grep -q \"sphere.ini:2: \[scene\] matcap = '/usr/share/pixmaps': a USB stick's paths\" \
		'$dir/own.err' && grep -q 'its own settings are ignored' '$dir/own.err'"
rm -f "$STATE_DIRECTORY/content/model/sphere.ini"
tree "$STATE_DIRECTORY" >"$dir/before"

# Broken sticks: a truncated model, a bad kiosk.ini, nothing of ours.
mkdir -p "$dir/broken/matcap-kiosk" "$dir/badini/matcap-kiosk" "$dir/empty/matcap-kiosk"
head -c 300 "$models/sphere.glb" >"$dir/broken/matcap-kiosk/sphere.glb"
cp "$models/sphere.glb" "$dir/badini/matcap-kiosk/"
cp "$dir/bad.ini" "$dir/badini/matcap-kiosk/kiosk.ini"
mkdir -p "$dir/state0"
STATE_DIRECTORY=$dir/state0 "$kiosk" --config "$dir/kiosk.ini" \
	--import "$dir/broken/matcap-kiosk" 2>/dev/null
step "a refused stick leaves an empty state folder empty (no lock file)" \
	[ -z "$(ls -A "$dir/state0")" ]
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

# Sticks that reach further: each refused, with a line that says why.
stick_with() { # NAME: a stick folder with the model in it
	mkdir -p "$dir/$1/matcap-kiosk"
	cp "$models/sphere.glb" "$dir/$1/matcap-kiosk/"
}
refused() { # NAME CODE PATTERN: its import exits CODE and says PATTERN
	timeout 60 "$kiosk" --config "$dir/kiosk.ini" --import "$dir/$1/matcap-kiosk" \
		2>"$dir/$1.err"
	_rc=$?
	[ $_rc = "$2" ] && grep -q -- "$3" "$dir/$1.err"
}
stick_with display
printf '[scene]\nmode = normal\n[display]\nbackend = osmesa\n' \
	>"$dir/display/matcap-kiosk/kiosk.ini"
step "a stick may not set [display] (78, naming the line)" refused display 78 \
	"kiosk.ini:4: \[display\] backend cannot be set from a USB stick"
stick_with loglevel
printf '[kiosk]\nturn_speed = 45\nlog_level = debug\n' >"$dir/loglevel/matcap-kiosk/kiosk.ini"
step "... nor [kiosk] log_level (turn_* it may)" refused loglevel 78 \
	"kiosk.ini:3: \[kiosk\] log_level cannot be set from a USB stick"
stick_with abspath
printf '[scene]\nmatcap = /etc/passwd\n' >"$dir/abspath/matcap-kiosk/kiosk.ini"
step "... nor an absolute path" refused abspath 78 "kiosk.ini:2: \[scene\] matcap = '/etc/passwd'"
stick_with listpath
printf '[scene]\nmodel = sphere.glb, /etc/passwd\n' >"$dir/listpath/matcap-kiosk/kiosk.ini"
step "... also as the second of a list" refused listpath 78 "kiosk.ini:2: \[scene\] model = "
stick_with dotdot
printf '[material]\ndetail_map = a/../../x.png\n' >"$dir/dotdot/matcap-kiosk/kiosk.ini"
step "... nor a path with .." refused dotdot 78 "kiosk.ini:2: \[material\] detail_map"
# The attacker's stick (issue 32): in [scene], matcap = a,a,a.png ; padded
# with x to 380 bytes, [display] over bytes 181-189, ';' at byte 199, then
# size = 77x55; the folders a,model/a,model/ hold a.png, where the old
# rewrite pointed. libinih split the rewritten line anew and a [display]
# size was installed; now the line is one value, read whole.
stick_with padded
mkdir -p "$dir/padded/matcap-kiosk/a,model/a,model"
cp matcaps/pearl.png "$dir/padded/matcap-kiosk/a,model/a,model/a.png"
line=$(printf 'matcap = a,a,a.png ;%0360d' 0 | tr 0 x)
line="$(echo "$line" | cut -c1-181)[display]$(echo "$line" | cut -c191-199);$(echo "$line" | cut -c201-)"
printf '[scene]\n%ssize = 77x55\n' "$line" >"$dir/padded/matcap-kiosk/kiosk.ini"
step "the padded-line stick is 380 bytes a line, [display] at 181, ';' at 199" sh -c "
	[ \$(sed -n 2p '$dir/padded/matcap-kiosk/kiosk.ini' | cut -c1-380 | wc -c) = 381 ] &&
	[ \$(sed -n 2p '$dir/padded/matcap-kiosk/kiosk.ini' | cut -c182-190) = '[display]' ]"
step "... is not imported, and sets no [display] size" sh -c "
	! timeout 60 '$kiosk' --config '$dir/kiosk.ini' --import '$dir/padded/matcap-kiosk' \
		2>'$dir/padded.err' && ! grep -q 'size = 77x55' '$STATE_DIRECTORY/content/kiosk.ini'"
# A stick's NAME.ini escaped the stick's path rules: the kiosk's own
# pictures and fonts were imported and shown on the public screen.
for kv in 'scene:matcap = /usr/share/pixmaps' \
	'caption:logo = ../../../../usr/share/pixmaps/debian-logo.png' \
	'caption:font = /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf' \
	'display:background = /usr/share/images/desktop-base/x.png' \
	'material:detail_map = /etc/passwd'; do
	name=nameini-${kv%%:*}-$(echo "${kv#*:}" | cut -d' ' -f1)
	stick_with "$name"
	printf '[%s]\n%s\n' "${kv%%:*}" "${kv#*:}" >"$dir/$name/matcap-kiosk/sphere.ini"
	step "a stick's NAME.ini may not name [${kv%%:*}] ${kv#*:} (78)" refused "$name" 78 \
		"sphere.ini:2: .*a USB stick's paths must be relative"
done
stick_with inilink
ln -s "$dir/kiosk.ini" "$dir/inilink/matcap-kiosk/kiosk.ini"
step "a kiosk.ini that is a link is refused" refused inilink 78 "kiosk.ini: not a plain file"
stick_with inififo
mkfifo "$dir/inififo/matcap-kiosk/kiosk.ini"
step "a kiosk.ini that is a pipe is refused, without waiting on it" refused inififo 78 \
	"kiosk.ini: not a plain file"
stick_with inibig
head -c 70000 /dev/zero | tr '\0' '#' >"$dir/inibig/matcap-kiosk/kiosk.ini"
step "a kiosk.ini over 64 KiB is refused" refused inibig 78 "of 64 KiB at most"
mkdir -p "$dir/toplink"
ln -s "$stick" "$dir/toplink/matcap-kiosk"
step "a matcap-kiosk folder that is a link is refused" refused toplink 1 "not a folder"
stick_with big
truncate -s 3G "$dir/big/matcap-kiosk/big.glb"
step "more than 2 GiB (or the free space) is refused before a byte is copied" refused big 1 \
	"the most an import may take"
# Sized before a byte is copied: with 1 MiB the most the import may write
# (ulimit -f), a copy begun is killed (SIGXFSZ) and leaves its staging.
stick_with big2
truncate -s 1500M "$dir/big2/matcap-kiosk/a.bin" "$dir/big2/matcap-kiosk/b.bin"
step "two files of 1.5 GB are refused before a byte is copied, naming the largest" sh -c "
	ulimit -f 2048; timeout 60 '$kiosk' --config '$dir/kiosk.ini' \
		--import '$dir/big2/matcap-kiosk' 2>'$dir/big2.err'
	[ \$? = 1 ] && grep -q 'nothing copied; the largest: a.bin (1500.0 MiB), b.bin (1500.0 MiB)' \
		'$dir/big2.err'"
step "... leaving no staging folder" test ! -e "$STATE_DIRECTORY/.content.new"
mkdir -p "$STATE_DIRECTORY/.content.new/model"
echo half >"$STATE_DIRECTORY/.content.new/model/half.bin"
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/big2/matcap-kiosk" 2>"$dir/stale.err"
step "the next import removes a staging folder one cut short left, and says so" sh -c "
	! test -e '$STATE_DIRECTORY/.content.new' &&
	grep -q '.content.new: removed what an import cut short left there' '$dir/stale.err'"
# Every model the settings name loads, not only the first: the kiosk
# takes turns through a list or a folder.
stick_with models
cp "$models/sphere.glb" "$dir/models/matcap-kiosk/a.glb"
head -c 300 "$models/sphere.glb" >"$dir/models/matcap-kiosk/z.glb"
printf '[scene]\nmodel = a.glb, z.glb\n' >"$dir/models/matcap-kiosk/kiosk.ini"
step "a list whose second model does not load is refused, naming it" refused models 1 \
	"models/matcap-kiosk/z.glb: the model does not load"
printf '[scene]\nmodel = .\n' >"$dir/models/matcap-kiosk/kiosk.ini"
step "... and so is a folder with such a model" refused models 1 \
	"models/matcap-kiosk/z.glb: the model does not load"
tree "$STATE_DIRECTORY" >"$dir/after2"
step "... and these change nothing either" cmp -s "$dir/before" "$dir/after2"
step "no stale staging folder is left" test ! -e "$STATE_DIRECTORY/.content.new"

# No matcap-kiosk/ folder on the stick: nothing to do, and no failure.
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/plain/matcap-kiosk" 2>"$dir/plain.err"
step "a stick without matcap-kiosk/ exits 0" [ $? -eq 0 ]
step "... and says there is nothing to import" grep -q "nothing to import" "$dir/plain.err"

# Names the generated kiosk.ini could not hold are passed over; a stick
# that names its matcap while bringing matcaps/ gets its own.
stick_with names
for n in 'a=b.glb' 'c;d.glb' '[e].glb' ' f.glb' "$(printf 'g\001h.glb')"; do
	cp "$models/sphere.glb" "$dir/names/matcap-kiosk/$n"
done
mkdir -p "$dir/names/matcap-kiosk/matcaps"
cp matcaps/pearl.png "$dir/names/matcap-kiosk/matcaps/"
printf '[scene]\nmatcap = matcaps/pearl.png\n[kiosk]\nturn_speed = 45\n' \
	>"$dir/names/matcap-kiosk/kiosk.ini"
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/names/matcap-kiosk" 2>"$dir/names.err"
step "a stick that sets [scene] matcap and brings matcaps/ is imported" [ $? -eq 0 ]
step "... its matcap line is the only one" sh -c \
	"[ \$(grep -c '^matcap' '$STATE_DIRECTORY/content/kiosk.ini') = 1 ] &&
	grep -qx 'matcap = matcaps/pearl.png' '$STATE_DIRECTORY/content/kiosk.ini'"
step "names with ;#=[], control characters or blanks at an end are skipped" sh -c "
	[ \$(ls '$STATE_DIRECTORY/content/model') = sphere.glb ] &&
	grep -qx 'model = model/sphere.glb' \
		'$STATE_DIRECTORY/content/kiosk.ini' && grep -q 'skipped' '$dir/names.err'"
# Names of control characters, at every level: passed over, and named
# escaped, so that none writes a journal line of its own (<0>: emergency).
stick_with ctrl
mkdir -p "$dir/ctrl/matcap-kiosk/matcaps" "$dir/ctrl/matcap-kiosk/$(printf 'tex\001')" \
	"$dir/ctrl/matcap-kiosk/textures"
cp matcaps/pearl.png "$dir/ctrl/matcap-kiosk/matcaps/$(printf 'x\n<0>forged.png')"
cp matcaps/pearl.png "$dir/ctrl/matcap-kiosk/matcaps/ok.png"
cp matcaps/pearl.png "$dir/ctrl/matcap-kiosk/$(printf 'tex\001')/a.png"
cp matcaps/pearl.png "$dir/ctrl/matcap-kiosk/textures/$(printf 'b\177.png')"
cp matcaps/pearl.png "$dir/ctrl/matcap-kiosk/textures/$(printf '\303\251t\303\251.png')"
JOURNAL_STREAM=8:8 "$kiosk" --config "$dir/kiosk.ini" --import "$dir/ctrl/matcap-kiosk" \
	2>"$dir/ctrl.err"
step "names with control characters under matcaps/ and subfolders are not copied" sh -c "
	[ $? -eq 0 ] && [ -z \"\$(cd '$STATE_DIRECTORY/content' && LC_ALL=C find . -name '*[[:cntrl:]]*')\" ] &&
	test -f '$STATE_DIRECTORY/content/matcaps/ok.png' &&
	test -f '$STATE_DIRECTORY/content/model/textures/$(printf '\303\251t\303\251.png')'"
step "... each named escaped in one line, none a line of its own" sh -c "
	grep -qF 'matcaps/x\\n<0>forged.png: a name with a control character' '$dir/ctrl.err' &&
	grep -qF 'matcap-kiosk/tex\\x01: a name' '$dir/ctrl.err' &&
	grep -qF 'textures/b\\x7f.png: a name' '$dir/ctrl.err' &&
	! grep -v '^<[346]>' '$dir/ctrl.err'"
# Pipes, sockets and device nodes: passed over with their reason, never
# opened (one that is waits for a writer; a device's open may act).
stick_with odd
mkdir -p "$dir/odd/matcap-kiosk/matcaps" "$dir/odd/matcap-kiosk/textures"
mkfifo "$dir/odd/matcap-kiosk/f.bin" "$dir/odd/matcap-kiosk/matcaps/p.png"
python3 -c "import socket; socket.socket(socket.AF_UNIX).bind('$dir/odd/matcap-kiosk/textures/s.bin')" \
	2>/dev/null || mkfifo "$dir/odd/matcap-kiosk/textures/s.bin"
timeout 60 "$kiosk" --config "$dir/kiosk.ini" --import "$dir/odd/matcap-kiosk" 2>"$dir/odd.err"
step "pipes and sockets are passed over, the rest imported" sh -c "[ $? -eq 0 ] &&
	grep -q 'matcap-kiosk/f.bin: a pipe (FIFO), not a plain file: skipped' '$dir/odd.err' &&
	grep -q 'matcaps/p.png: a pipe (FIFO), not a plain file: skipped' '$dir/odd.err' &&
	grep -q 'textures/s.bin: a .*, not a plain file: skipped' '$dir/odd.err' &&
	test -f '$STATE_DIRECTORY/content/model/sphere.glb'"
# A device node on a stick mounted nodev, as the import unit mounts it:
# opening it fails, and that refused the whole stick. mknod and a mount
# need root here; the virtual board (hands-board.sh) does it always.
mkdir -p "$dir/nodev"
if [ "$(id -u)" = 0 ] && unshare -m true 2>/dev/null; then
	unshare -m sh -c "mount -t tmpfs -o nodev tmpfs '$dir/nodev' &&
		mkdir '$dir/nodev/matcap-kiosk' && cp '$models/sphere.glb' '$dir/nodev/matcap-kiosk/' &&
		mknod '$dir/nodev/matcap-kiosk/null.png' c 1 3 &&
		exec timeout 60 '$kiosk' --config '$dir/kiosk.ini' --import '$dir/nodev/matcap-kiosk'" \
		2>"$dir/nodev.err"
	step "a device node on a nodev stick is passed over, the rest imported" sh -c "[ $? -eq 0 ] &&
		grep -q 'null.png: a device node, not a plain file: skipped' '$dir/nodev.err'"
else
	echo "ok a device node on a nodev stick is passed over # skip: not root (hands-board.sh)"
fi
stick_with mlink
ln -s "$PWD/matcaps" "$dir/mlink/matcap-kiosk/matcaps"
"$kiosk" --config "$dir/kiosk.ini" --import "$dir/mlink/matcap-kiosk" 2>"$dir/mlink.err"
step "a matcaps/ that is a link is passed over" sh -c "[ $? -eq 0 ] &&
	! test -e '$STATE_DIRECTORY/content/matcaps' &&
	grep -q 'matcaps: not a folder (a link?): skipped' '$dir/mlink.err'"

# A model folder as Sketchfab and Blender write it: scene.gltf, scene.bin,
# textures/ (a subfolder under it too); a link to a folder and a hidden
# folder are not taken, and a subfolder's .gltf is no model.
sk=$dir/sketchfab/matcap-kiosk
mkdir -p "$sk/textures/more" "$sk/.hidden" "$sk/parts"
sed -e 's#"uri":"sphere-beetle.bin"#"uri":"scene.bin"#' \
	-e 's#"uri":"\([a-z]*\)\.png"#"uri":"textures/\1.png"#g' \
	"$models/sphere-beetle.gltf" >"$sk/scene.gltf"
cp "$models/sphere-beetle.bin" "$sk/scene.bin"
cp "$models/normal.png" "$models/occlusion.png" "$models/thickness.png" "$sk/textures/"
cp "$models/normal.png" "$sk/textures/more/"
cp "$models/normal.png" "$sk/.hidden/"
cp "$models/sphere.glb" "$sk/parts/other.glb"
ln -s /etc "$sk/etc"
"$kiosk" --config "$dir/kiosk.ini" --import "$sk" 2>"$dir/sketchfab.err"
step "a stick with textures/ in a subfolder is imported" [ $? -eq 0 ]
step "... the subfolders are copied, the model loads them without a warning" sh -c "
	test -f '$STATE_DIRECTORY/content/model/textures/normal.png' &&
	test -f '$STATE_DIRECTORY/content/model/textures/thickness.png' &&
	test -f '$STATE_DIRECTORY/content/model/textures/more/normal.png' &&
	grep -qx 'model = model/scene.gltf' \
		'$STATE_DIRECTORY/content/kiosk.ini' && ! grep -q 'not used' '$dir/sketchfab.err'"
step "... a link to a folder, a hidden folder and a subfolder's model are not taken" sh -c "
	! test -e '$STATE_DIRECTORY/content/model/etc' &&
	! test -e '$STATE_DIRECTORY/content/model/.hidden' &&
	! test -e '$STATE_DIRECTORY/content/model/parts/other.glb' &&
	grep -q 'etc: a link, not a folder: skipped' '$dir/sketchfab.err'"
rm "$sk/textures/normal.png"
"$kiosk" --config "$dir/kiosk.ini" --import "$sk" 2>"$dir/sketchfab2.err"
step "a texture missing from the stick: imported, with a warning that says so" sh -c "
	[ $? -eq 0 ] && grep -q 'textures/normal.png. is not in the model.s folder (no such file)' \
		'$dir/sketchfab2.err'"

stick_with bom
printf '\357\273\277[scene]\npitch = 10\n' >"$dir/bom/matcap-kiosk/kiosk.ini"
step "a kiosk.ini with a byte order mark (Notepad's) is imported" \
	"$kiosk" --config "$dir/kiosk.ini" --import "$dir/bom/matcap-kiosk"

# Two partitions at once: one import after the other, each whole.
for i in 1 2 3; do
	stick_with "par$i"
	printf '[scene]\nyaw = %d\n' "$((i * 10))" >"$dir/par$i/matcap-kiosk/kiosk.ini"
done
for i in 1 2 3; do
	"$kiosk" --config "$dir/kiosk.ini" --import "$dir/par$i/matcap-kiosk" \
		2>"$dir/par$i.err" &
	eval "par$i=\$!"
done
ok=0
# shellcheck disable=SC2154
for p in "$par1" "$par2" "$par3"; do wait "$p" && ok=$((ok + 1)); done
step "three imports at once all succeed" [ $ok = 3 ]
step "... and the content is one of them, whole" sh -c "
	[ \$(grep -c '^yaw' '$STATE_DIRECTORY/content/kiosk.ini') = 1 ] &&
	test -f '$STATE_DIRECTORY/content/model/sphere.glb' &&
	test ! -e '$STATE_DIRECTORY/.content.new'"

# The rule takes only the file systems the unit mounts, and the unit
# mounts with the type udev found (udevadm and mount stand-ins here).
rule=systemd/61-matcap-kiosk-usb.rules
iunit=systemd/matcap-kiosk-import@.service
step "the USB rule matches vfat, exfat and ext2/3/4 only" grep -q \
	'ENV{ID_FS_TYPE}=="vfat|exfat|ext2|ext3|ext4"' "$rule"
pre=$(sed -n "s|^ExecStartPre=+/bin/sh -ec '\(.*\)'\$|\1|p" "$iunit" |
	sed -e 's|%I|sdz1|g' -e "s|%t|$dir/run|g" -e 's|\$\$|$|g')
printf '#!/bin/sh\necho "$FS"\n' >"$dir/bin/udevadm"
printf '#!/bin/sh\necho "$*" >>%s/mount.log\n' "$dir" >"$dir/bin/mount"
chmod +x "$dir/bin/udevadm" "$dir/bin/mount"
FS=vfat PATH=$dir/bin:$PATH sh -ec "$pre" 2>"$dir/mount.err"
step "the unit mounts a FAT stick with -t vfat, read-only" grep -qxF -e \
	"-t vfat -o ro,nosuid,nodev,noexec /dev/sdz1 $dir/run/matcap-kiosk-import/sdz1" \
	"$dir/mount.log"
FS=ntfs PATH=$dir/bin:$PATH sh -ec "$pre" 2>"$dir/mount.err"
step "... and refuses another type without mounting" sh -c "[ $? -ne 0 ] &&
	[ \$(wc -l <'$dir/mount.log') = 1 ] && grep -q ntfs '$dir/mount.err'"

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
