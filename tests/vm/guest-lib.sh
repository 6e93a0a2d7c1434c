# Shell functions for guest scripts on the virtual board (busybox sh).
#   . "$VM_LIB"        (run.sh puts this file at /vm/guest-lib.sh)
# Paths in the guest: /repo = the repository (read-only), /share = the
# --share directory (read-write, the guest script's cwd), /vm = job files.

GPIOSIM_CFS=/sys/kernel/config/gpio-sim

vm_log() { echo "[guest] $*"; }
vm_die() { echo "[guest] error: $*" >&2; exit 1; }

# wait_for PATH [TIMEOUT_S=10]: until PATH exists; 1 on timeout.
wait_for() {
	_wf_n=$(( ${2:-10} * 20 ))
	while [ ! -e "$1" ]; do
		_wf_n=$((_wf_n - 1))
		[ $_wf_n -gt 0 ] || { echo "[guest] timed out waiting for $1" >&2; return 1; }
		sleep 0.05
	done
}

# wait_until TIMEOUT_S CMD [ARGS]...: until CMD succeeds; 1 on timeout.
wait_until() {
	_wu_n=$(( $1 * 10 )); shift
	until "$@" >/dev/null 2>&1; do
		_wu_n=$((_wu_n - 1))
		[ $_wu_n -gt 0 ] || { echo "[guest] timed out waiting for: $*" >&2; return 1; }
		sleep 0.1
	done
}

# ---- checks with a closing "N passed, N failed" line
VM_PASSED=0 VM_FAILED=0
# vm_check DESCRIPTION CMD [ARGS]...: run CMD, print ok/FAIL, count it.
vm_check() {
	_d=$1; shift
	if "$@"; then VM_PASSED=$((VM_PASSED + 1)); echo "ok   - $_d"
	else VM_FAILED=$((VM_FAILED + 1)); echo "FAIL - $_d"; fi
}
# vm_summary: print the totals, return 1 if anything failed.
vm_summary() {
	echo "vm: $VM_PASSED passed, $VM_FAILED failed"
	[ "$VM_FAILED" = 0 ]
}

# ---- gpio-sim (configfs)
# gpiosim_make NAME NLINES [LINE_NAME]...: create and enable a simulated chip
# with one bank; prints its chip name (gpiochipN, i.e. /dev/gpiochipN).
gpiosim_make() {
	_n=$1 _lines=$2; shift 2
	[ -d "$GPIOSIM_CFS" ] || vm_die "gpio-sim configfs not there (module loaded? configfs mounted?)"
	mkdir "$GPIOSIM_CFS/$_n" "$GPIOSIM_CFS/$_n/bank0" || vm_die "gpiosim_make: cannot create $_n"
	echo "$_lines" >"$GPIOSIM_CFS/$_n/bank0/num_lines"
	echo "$_n" >"$GPIOSIM_CFS/$_n/bank0/label"
	_i=0
	for _ln in "$@"; do
		mkdir "$GPIOSIM_CFS/$_n/bank0/line$_i"
		echo "$_ln" >"$GPIOSIM_CFS/$_n/bank0/line$_i/name"
		_i=$((_i + 1))
	done
	echo 1 >"$GPIOSIM_CFS/$_n/live" || vm_die "gpiosim_make: cannot enable $_n"
	_chip=$(cat "$GPIOSIM_CFS/$_n/bank0/chip_name")
	wait_for "/dev/$_chip" 5 || vm_die "gpiosim_make: /dev/$_chip did not appear"
	echo "$_chip"
}

# gpiosim_sysfs NAME|gpiochipN: the chip's sysfs dir (sim_gpioN/{value,pull}).
gpiosim_sysfs() {
	for _d in "$GPIOSIM_CFS"/*/; do
		_d=${_d%/}
		[ -f "$_d/live" ] || continue
		if [ "${_d##*/}" = "$1" ] || [ "$(cat "$_d/bank0/chip_name" 2>/dev/null)" = "$1" ]; then
			echo "/sys/devices/platform/$(cat "$_d/dev_name")/$(cat "$_d/bank0/chip_name")"
			return 0
		fi
	done
	vm_die "no gpio-sim chip '$1'"
}

# gpiosim_pull CHIP LINE up|down: what an outside circuit does to an input
# (a pressed button to ground = down).  A consumer's edge events follow.
gpiosim_pull() {
	case $3 in up|down) ;; *) vm_die "gpiosim_pull: up or down, not '$3'" ;; esac
	echo "pull-$3" >"$(gpiosim_sysfs "$1")/sim_gpio$2/pull"
}

# gpiosim_get CHIP LINE: the line's level as the simulator sees it (0/1):
# what a consumer drives on an output, or the pull on an input.
gpiosim_get() { cat "$(gpiosim_sysfs "$1")/sim_gpio$2/value"; }

# gpiosim_remove NAME: disable and delete a chip.
gpiosim_remove() {
	echo 0 >"$GPIOSIM_CFS/$1/live"
	for _l in "$GPIOSIM_CFS/$1"/bank0/line*; do [ -d "$_l" ] && rmdir "$_l"; done
	rmdir "$GPIOSIM_CFS/$1/bank0" "$GPIOSIM_CFS/$1"
}

# gpiomockup_load RANGES: the older gpio-mockup ("-1,8" = one chip of 8
# lines); values and pulls are under /sys/kernel/debug/gpio-mockup/.
gpiomockup_load() { modprobe gpio-mockup gpio_mockup_ranges="$1" gpio_mockup_named_lines=1; }

# ---- display (vkms)
# drm_card: /dev/dri/cardN of vkms.
drm_card() {
	for _c in /sys/class/drm/card[0-9]*; do
		case $_c in *-*) continue ;; esac
		# vkms is a bare platform device called "vkms" (no driver link).
		[ "$(basename "$(readlink -f "$_c/device")")" = vkms ] && { echo "/dev/dri/${_c##*/}"; return 0; }
	done
	return 1
}

# drm_connector_status NAME: "connected"/"disconnected"/... of e.g. Virtual-1
# or Writeback-1.
drm_connector_status() {
	for _s in /sys/class/drm/card*-"$1"/status; do [ -r "$_s" ] && cat "$_s" && return 0; done
	return 1
}

# drm_card_of DRIVER: /dev/dri/cardN of the card whose device, or the virtio
# device under it (virtio-gpu: the card's device is the PCI function, the
# driver is bound to its virtioN child), DRIVER drives; by driver, never by
# number. E.g. drm_card_of virtio_gpu (run.sh --outputs 2).
drm_card_of() {
	for _c in /sys/class/drm/card[0-9]*; do
		case $_c in *-*) continue ;; esac
		for _d in "$_c/device/driver" "$_c"/device/virtio*/driver; do
			[ "$(basename "$(readlink -f "$_d" 2>/dev/null)")" = "$1" ] &&
				{ echo "/dev/dri/${_c##*/}"; return 0; }
		done
	done
	return 1
}

# drm_crtc_of CARD CONNECTOR: the id of the first CRTC that CONNECTOR's
# encoder can drive (modetest's possible_crtcs bit, in its CRTC order), for
# vm-grab -D CARD -c ID. Ask before the program under test opens CARD:
# modetest becomes DRM master for a moment if no one is.
drm_crtc_of() {
	modetest -D "$1" -c -e -p 2>/dev/null | awk -v want="$2" '
		/^Encoders:/ { s = "e"; next } /^Connectors:/ { s = "c"; next }
		/^CRTCs:/ { s = "r"; next } /^Planes:/ { s = "" }
		s == "e" && /^[0-9]+\t/ { mask[$1] = $4 }
		s == "c" && /^[0-9]+\t/ && $4 == want { enc = $NF }
		s == "r" && /^[0-9]+\t/ { crtc[n++] = $1 }
		END {
			m = mask[enc] + 0
			if (mask[enc] ~ /^0x/) { m = 0; h = substr(mask[enc], 3)
				for (i = 1; i <= length(h); i++) m = m * 16 + index("0123456789abcdef", tolower(substr(h, i, 1))) - 1 }
			for (i = 0; i < n; i++) { if (m % 2) { print crtc[i]; exit 0 } m = int(m / 2) }
			exit 1
		}'
}

# vm_grab OUT.ppm [vm-grab options]: read back what the CRTC scans out now
# (the front buffer, while the program that set it still runs).
vm_grab() { _o=$1; shift; vm-grab "$@" -o "$_o"; }
# crtc_fb: the framebuffer the CRTC scans out now (no master needed).
crtc_fb() { vm-grab 2>/dev/null | sed -n 's/.* fb \([0-9]*\) .*/\1/p'; }

# ---- the kiosk under test (its pid in KPID)
# cpu: its user + system time so far, in clock ticks.
cpu() { awk '{ print $14 + $15 }' "/proc/$KPID/stat"; }
# quiet: it used no CPU for a second, so it is done drawing (llvmpipe under
# TCG on a busy host may take seconds a frame); false after two minutes.
quiet() {
	_i=0
	_a=$(cpu)
	while [ $_i -lt 120 ]; do
		sleep 1
		_b=$(cpu)
		[ "$_a" = "$_b" ] && return 0
		_a=$_b
		_i=$((_i + 1))
	done
	return 1
}
# still OUT: the screen, read back once the kiosk has nothing left to draw.
still() { quiet && vm-grab -o "$1" >/dev/null 2>&1; }

# ---- keyboard (uinput)
VKBD_FIFO=/run/vm-key.fifo
# vkbd_start: create the virtual keyboard "vm-key keyboard"; sets VKBD_DEV
# (/dev/input/eventN) and VKBD_PID.  Start it before the program that scans
# for keyboards.  Not in $(...): the daemon would hold the substitution open.
vkbd_start() {
	rm -f "$VKBD_FIFO"
	vm-key -f "$VKBD_FIFO" >&2 &
	VKBD_PID=$!
	wait_until 10 vkbd_dev || vm_die "vkbd_start: the uinput keyboard did not appear"
	VKBD_DEV=$(vkbd_dev)
	wait_for "$VKBD_DEV" 5 && wait_for "$VKBD_FIFO" 5
}
# vkbd_dev: /dev/input/eventN of the virtual keyboard.
vkbd_dev() {
	for _n in /sys/class/input/event*/device/name; do
		[ "$(cat "$_n" 2>/dev/null)" = "vm-key keyboard" ] || continue
		_e=${_n%/device/name}; echo "/dev/input/${_e##*/}"; return 0
	done
	return 1
}
# vkbd_press KEY... : press and release keys (ESC, ENTER, LEFT, Q, ...);
# "sleep MS" between them is allowed.
vkbd_press() { [ -p "$VKBD_FIFO" ] || vm_die "vkbd_press: no vkbd_start"; echo "$*" >"$VKBD_FIFO"; }
vkbd_stop() { [ -p "$VKBD_FIFO" ] && echo quit >"$VKBD_FIFO"; wait "${VKBD_PID:-}" 2>/dev/null; rm -f "$VKBD_FIFO"; }

# ---- camera (vimc)
# vimc_ready: vimc's media device exists and udev has seen its video nodes.
vimc_ready() {
	for _m in /sys/bus/media/devices/media*/model; do
		[ "$(cat "$_m" 2>/dev/null)" = "VIMC MDEV" ] && return 0
	done
	return 1
}
