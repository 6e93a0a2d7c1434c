#!/bin/sh
# Camera figures for `make bench`, printed and never asserted. The only
# camera here is vimc's Sensor B on the virtual board (tests/vm): the
# kiosk runs there on vkms (kms backend, llvmpipe) with --stats for
# $CAMERA_BENCH_S seconds (default 20) at two display sizes, and reports
#   - completion to flip: from the camera request's completion (stamped in
#     the libcamera helper) to the page flip that put the frame on screen;
#   - CPU per frame: the kiosk's main-thread CPU time to get one frame to
#     the GPU and converted, by path (upload; import where the driver has
#     it: never on llvmpipe, see src/camera/camera_texture.c).
# The board is emulated (qemu TCG, 2 vCPUs), so these are the emulator's
# times, not a Raspberry Pi's: they compare paths and sizes, nothing more.
# Environment: KIOSK (the binary to carry into the board).
set -u
kiosk=${KIOSK:-./matcap-kiosk}
secs=${CAMERA_BENCH_S:-20}

echo
echo "## camera (vimc on the virtual board, ${secs} s per run)"
echo
if ! command -v qemu-system-x86_64 >/dev/null 2>&1; then
	echo "skipped: no qemu-system-x86_64 for the virtual board (tests/vm/README.md)"
	exit 0
fi
dir=$(mktemp -d "${TMPDIR:-/tmp}/bench-camera.XXXXXX")
trap 'rm -rf "$dir"' EXIT
cat >"$dir/guest.sh" <<EOF
#!/bin/sh
. "\$VM_LIB"
for mode in 640x480 1024x768; do
	matcap-kiosk --backend kms --display-mode \$mode --attract-after 0 --stats \
		>stats-\$mode.txt 2>log-\$mode.txt &
	pid=\$!
	# From the first camera frame drawn (llvmpipe compiles its shaders
	# first, slowly under TCG).
	wait_until 180 grep -q "frames reach the GPU" log-\$mode.txt || true
	sleep $secs
	kill -TERM \$pid
	wait \$pid
	echo "\$mode \$(cat stats-\$mode.txt)"
done
EOF
if ! tests/vm/run.sh --quiet --bin "$kiosk" --share "$dir/share" --timeout $((secs * 2 + 420)) \
	-- "$dir/guest.sh" >"$dir/run.log" 2>&1; then
	echo "skipped: the virtual board did not run (tail of its log below)"
	tail -5 "$dir/run.log"
	exit 0
fi
echo "| display | camera frames shown | dropped (camera faster than the screen) | completion to flip median ms | p90 ms | path | CPU per frame median us | p90 us |"
echo "|---|---|---|---|---|---|---|---|"
for mode in 640x480 1024x768; do
	line=$(grep -h "^camera frames_shown" "$dir/share/stats-$mode.txt" 2>/dev/null)
	if [ -z "$line" ]; then
		echo "| $mode | no figures (see the kiosk's log) | | | | | | |"
		continue
	fi
	# shellcheck disable=SC2086
	set -- $line
	shift 2 # "camera frames_shown"
	shown=$1 dropped=$3 med=$5 p90=$7
	shift 7
	while [ $# -ge 6 ]; do
		path=${1%_frames}
		printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "$mode" "$shown" "$dropped" "$med" \
			"$p90" "$path" "$4" "$6"
		shift 6
	done
done
echo
echo "The camera: $(sed -n 's/.*camera: \(.* streams .*\)/\1/p' "$dir/share/log-640x480.txt" | head -1)."
echo "Frames reach the GPU by $(sed -n 's/.*frames reach the GPU by \(.*\)/\1/p' \
	"$dir/share/log-640x480.txt" | head -1)."
