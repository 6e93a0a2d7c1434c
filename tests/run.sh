#!/bin/sh
# Runs every test of `make test` and ends with one "N passed, N failed"
# line. The tests themselves are in tests/suite.sh, which `make check
# T=NAME` (tests/check.sh) runs one by one.
# Environment (the Makefile's TEST_ENV): KIOSK, ASAN_KIOSK, UNIT_DIR,
# UNIT_TESTS, TOOLS, BAKE, FUZZ_DIR, FUZZ_SECONDS; VM_E2E=0 leaves the
# virtual board out.
# shellcheck disable=SC2119 # every test function runs in full here
set -u
out=tests/out
# shellcheck source=tests/suite.sh
. tests/suite.sh
# Each group says how long it took (CI has a time budget: tests/README.md).
timed() {
	t0=$(date +%s)
	"$@"
	echo "TIME $1 $(($(date +%s) - t0)) s"
}

# 1. The layers of src/ (no include goes up a layer), and their checker.
timed test_layers
# 2. Unit tests (cmocka), built with ASan and UBSan.
timed test_unit
# 3. Golden images through OSMesa, with a stated tolerance: a pixel differs
#    when a channel is off by more than 8/255, and at most 0.5% may differ.
timed test_golden
# 4. The same scenes through EGL headless; what each material feature
#    compiles and binds; the renderer against the C mirror of the shaders.
timed test_egl
timed test_program_check
timed test_mirror_check
timed test_base_color_check
# 5. A sphere under an orthographic camera reproduces the matcap disk.
timed test_ortho
# 5b. A lopsided model's outline centred in the frame and above a caption.
timed test_fit
# 5c. --stop and --at: the still of a moment the kiosk would show.
timed test_preview
timed test_wall_seam
# 6. Loader variants that must work from the command line.
timed test_loaders
# 7. Malformed input, through the ASan binary: exit status 1, one error
#    line that names the file, and no sanitizer report.
timed test_bad_input
# 7a. Content a stranger brings: textures that decode to gigabytes, a full
#     cache file system, a caption larger than the frame.
timed test_limits
# 7b. What is not a file (a FIFO) where content is expected: refused, no hang.
timed test_not_a_file
# 7b. The glTF corpus: files nobody on the project wrote, and files that
#     gltfpack and Draco's tools make, through the ASan build.
timed test_corpus
# 8. The command line itself; every config key documented in the example.
timed test_cli
timed test_config_doc
timed test_man
timed test_doc_claims
# 9. The shipped matcaps regenerate byte for byte from the baker.
timed test_baker
# 10. The live loop as systemd runs it, through the ASan binary.
timed test_live
# 10a. The same live loop and the unit tests under ThreadSanitizer.
[ "${TSAN:-1}" = 0 ] || timed test_tsan
# 10b. Hands-off operation: --status, the poster, --import of a USB stick.
timed test_hands
# 10c. Content by sync: rsync and Syncthing's temporary names.
timed test_sync
# 10c'. Kiosks in step on a shared clock: two live kiosks, one moment.
timed test_in_step
# 10d. Metrics for Prometheus, scraped from a real node_exporter.
timed test_metrics
timed test_mqtt
# 11. make install honours PREFIX and DESTDIR; the systemd unit, checked
#     offline.
timed test_install
timed test_systemd
# 12. Hostile input: libFuzzer on the glTF loader, the image decoder and
#     the config reader, FUZZ_SECONDS each; then every regression input.
timed test_fuzz
# 13. No leak, no drift: the soak test, and valgrind on a short run.
timed test_soak
# 14. No camera: said once, and the kiosk runs on.
timed test_no_camera
# 15. Fullscreen on DRM/KMS, the GPIO buttons and the camera, on the
#     virtual board (tests/vm: qemu); about 6 minutes. VM_E2E=0 leaves it
#     out of a local run; CI runs it.
if [ "${VM_E2E:-1}" != 0 ]; then
	# VM_E2E_SCRIPTS: only these guest scripts (names of tests/e2e or
	# tests/vm, without .sh); test-trixie boots the ones whose libraries
	# Debian 13 changes (Mesa, libgpiod, libcamera).
	scripts=
	for s in ${VM_E2E_SCRIPTS:-}; do
		if [ -f "tests/e2e/$s.sh" ]; then scripts="$scripts tests/e2e/$s.sh"; else scripts="$scripts tests/vm/$s.sh"; fi
	done
	# shellcheck disable=SC2086 # a list of paths
	timed test_board $scripts
	# VM_SYSTEMD=0 (test-trixie) leaves out the systemd board: a Debian 12
	# root, the same code as here.
	[ "${VM_SYSTEMD:-1}" = 0 ] || timed test_systemd_board
else
	echo "NOTE the virtual-board display tests were left out (VM_E2E=0)"
fi

summary
