#!/bin/sh
# End-to-end tests on the virtual board (tests/vm): renders the OSMesa
# references on this machine, boots the board once per guest script with
# the kiosk and imgdiff on its PATH, and prints one "ok NAME" or
# "not ok NAME" line per check the guest made (tests/run.sh counts them),
# then "ok every script ran" when every script reported its totals; what
# explains a script that stopped goes to stderr.
#
#   KIOSK=./matcap-kiosk IMGDIFF=build/tools/imgdiff tests/e2e/host.sh OUTDIR [SCRIPT]...
#
# Default scripts: tests/e2e/kms.sh, kms-hotplug.sh and kms-busy.sh.  Each
# script's files (frames read back from the display, the kiosk's logs,
# console.log) are in OUTDIR/<script name>/, its references in ref/ there
# (/share/ref in the guest).  E2E_BINS (more host binaries for the guest's
# PATH), VM_TIMEOUT (seconds per script, default 240) and VM_RUN_FLAGS
# (extra tests/vm/run.sh options) are passed on.
set -u
# The offscreen backend: osmesa, or egl-headless where Mesa has no OSMesa
# (the Makefile sets OFFSCREEN_BACKEND from what the build has).
offscreen=${OFFSCREEN_BACKEND:-osmesa}
out=$1
shift
# The display first, then the buttons and the camera on it.
[ $# -gt 0 ] || set -- tests/e2e/kms.sh tests/e2e/kms-hotplug.sh tests/e2e/kms-busy.sh tests/e2e/kms-outputs.sh \
	tests/vm/gpio-test.sh tests/e2e/reload-devices.sh tests/e2e/camera.sh tests/e2e/cec.sh tests/e2e/power.sh \
	tests/e2e/touch.sh tests/e2e/knob-board.sh tests/e2e/models.sh tests/e2e/hands-board.sh
kiosk=${KIOSK:-./matcap-kiosk}
imgdiff=${IMGDIFF:-build/tools/imgdiff}
mkdir -p "$out/ref"

# The references: the scene of tests/e2e/lib.sh at the sizes vkms runs.
ref() { # NAME SIZE [ARGS]...
	name=$1 size=$2
	shift 2
	$kiosk -q --backend $offscreen --size "$size" --matcap matcaps/gold.png --lod-pixels 0 "$@" \
		--output "$out/ref/$name.png" || echo "not ok reference $name rendered"
}
ref knot-1024x768 1024x768
ref knot-1024x768-rot90 1024x768 --rotate 90
ref knot-800x600 800x600
# [caption] (kms.sh): the font goes to the guest in the share.
cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "$out/ref/"
ref knot-1024x768-caption 1024x768 --caption 'Amphora,\nכד' \
	--caption-font "$out/ref/DejaVuSans.ttf" --caption-drift off
# The caption on an overlay plane (kms.sh): the model's frame is fitted
# above the caption's box and holds no caption; an invisible caption of
# the same size is that frame.
ref knot-1024x768-caption-room 1024x768 --caption 'Amphora,\nכד' \
	--caption-font "$out/ref/DejaVuSans.ttf" --caption-color '#00000000' --caption-box '#00000000'
ref knot-1024x768-half 1024x768 --render-scale 0.5
# The fit (its zoom and the outline's centring) is the start view's, so
# the turned picture is a stop at pitch 65 of the start yaw: --stop draws
# it as the kiosk would after the drag.
ref knot-800x600-pitch65 800x600 --stops '-30 65 1' --stop 1
ref knot-800x600-rot90-pitch65 800x600 --rotate 90 --stops '-30 65 1' --stop 1
# antialias = 4 (kms.sh): multisampled by EGL headless, on llvmpipe too.
$kiosk -q --backend egl-headless --size 1024x768 --matcap matcaps/gold.png --lod-pixels 0 \
	--antialias 4 --output "$out/ref/knot-1024x768-aa4.png" ||
	echo "not ok reference knot-1024x768-aa4 rendered"
# Two outputs of one card (kms-outputs.sh, on the board's virtio-gpu:
# run.sh --outputs 2 names its connectors Virtual-2 and Virtual-3, vkms
# having Virtual-1): one settings file for the guest and the references,
# each output drawn as --as-output says it shows the scene.
printf '[display]\noutputs = Virtual-2, Virtual-3\nmode = 640x480\n\n[output.Virtual-3]\nview = mirror\n' \
	>"$out/ref/outputs.ini"
for o in Virtual-2 Virtual-3; do
	ref "outputs-$o" 640x480 --config "$out/ref/outputs.ini" --as-output "$o"
done

# boot: the board with $bins, running $script, its files in $share.
boot() {
	# shellcheck disable=SC2086
	tests/vm/run.sh --quiet --timeout "$limit" $bins --share "$share" \
		${VM_RUN_FLAGS:-} $board -- "$script" >"$share/run.log" 2>&1
}

complete=1
for script in "$@"; do
	name=$(basename "$script" .sh)
	share=$out/$name
	rm -rf "$share"
	mkdir -p "$share"
	cp -r "$out/ref" "$share/ref"
	bins="--bin $kiosk --bin $imgdiff"
	# hues counts the camera's colour bars in a screenshot; cec_power
	# sends the kiosk's CEC messages; clock_set sets the board's clock;
	# touch_inject is a uinput touchscreen; mkmodels writes the test models.
	tools=$(dirname "$imgdiff")
	for b in ${E2E_BINS:-$tools/hues $tools/cec_power $tools/clock_set $tools/touch_inject $tools/knob_inject $tools/mkmodels}; do
		bins="$bins --bin $b"
	done
	# hands-board.sh plugs in USB sticks: ext2 images made here.
	[ "$name" = hands-board ] && bins="$bins $(sh tests/e2e/sticks.sh "$out/sticks")"
	# kms-outputs.sh drives two outputs of one card: a virtio-gpu beside vkms.
	board="" limit=${VM_TIMEOUT:-240}
	# Two outputs: two of everything, and modetest takes seconds on
	# virtio-gpu's long mode lists: more time than one output's scripts.
	[ "$name" = kms-outputs ] && board="--outputs 2" limit=$((limit * 3 / 2))
	boot
	rc=$?
	# A board that stopped answering boots once more: 124 is the host's
	# timeout, when the guest did not even stop its own script at
	# --timeout (143), the whole guest silent (seen once in many runs,
	# in cec.sh, under software emulation). The first run's logs are
	# kept and the result says so. A script that fails, or that the
	# guest itself timed out, is never run again.
	if [ $rc = 124 ] && ! grep -q '^vm: [0-9]* passed' "$share/console.log" 2>/dev/null; then
		mv "$share/console.log" "$share/console-1.log"
		mv "$share/run.log" "$share/run-1.log"
		boot
		rc=$?
		echo "ok $name: booted a second time, the first board silent until the host's" \
			"timeout (its console: $share/console-1.log)"
	fi
	# The guest's check lines: "ok   - NAME" and "FAIL - NAME".
	sed -n -e "s/^ok   - \(.*\)/ok $name: \1/p" -e "s/^FAIL - \(.*\)/not ok $name: \1/p" \
		"$share/console.log" 2>/dev/null
	if ! grep -q '^vm: [0-9]* passed, [0-9]* failed' "$share/console.log" 2>/dev/null; then
		echo "not ok $name: the script ran to its end (exit $rc; see $share/console.log)"
		{ tail -15 "$share/run.log"; tail -25 "$share/console.log"; } >&2
		complete=0
	fi
done
[ "$complete" = 1 ] && echo "ok every script ran"
