#!/bin/sh
# Runs one test, or one group of tests, by name, with the same code as
# `make test` (tests/suite.sh), and ends with one "N passed, N failed" line.
#   make check T=NAME          (builds what the test needs, then runs this)
#   tests/check.sh NAME        (environment as the Makefile's TEST_ENV sets it)
#   tests/check.sh --needs NAME   prints the make targets the test needs
#   tests/check.sh --list      prints the kinds of names and every name
# Its scratch folder is tests/out/check/NAME (one per name, so that two
# checks can run at once). An unknown name: the list of the kinds of names
# on stderr, and exit status 2.
set -u

groups="layers unit golden egl program_check mirror_check ortho fit preview loaders bad-input not-a-file corpus cli"
groups="$groups config_doc baker live metrics mqtt install systemd fuzz soak no-camera board hands"
groups="$groups base_color_check sync in-step tsan systemd-board limits man doc_claims wall_seam"

unit_names() { (cd tests/unit && ls test_*.c) | sed 's/^test_//; s/\.c$//'; }
golden_names() { (cd tests/golden && ls ./*.png) | sed 's|^\./||; s/\.png$//'; }
fuzz_names() { (cd tests/fuzz && ls fuzz_*.c) | sed 's/^fuzz_/fuzz-/; s/\.c$//'; }
# The board's guest scripts: those that end with vm_summary's totals.
board_path() { # NAME: the guest script of that name, if there is one
	for f in "tests/e2e/$1.sh" "tests/vm/$1.sh"; do
		if [ -f "$f" ] && grep -qx 'vm_summary' "$f"; then
			echo "$f"
			return 0
		fi
	done
	return 1
}
board_names() {
	for f in tests/e2e/*.sh tests/vm/*.sh; do
		grep -qx 'vm_summary' "$f" && basename "$f" .sh
	done
}
words() { paste -sd ' ' - | fold -s -w 60 | sed 's/ $//; 2,$s/^/                    /'; }

list() {
	cat <<EOF
Names for make check T=NAME (or tests/check.sh NAME):
  a group           $(echo "$groups" | tr ' ' '\n' | words)
                    (unit, golden, fuzz and board run every test of theirs;
                    the others are one check or a few, as make test runs them)
  a unit test       NAME or test_NAME (tests/unit/test_NAME.c):
                    $(unit_names | words)
  a golden scene    NAME (tests/golden/NAME.png), rendered and compared:
                    $(golden_names | words)
  a fuzzer          $(fuzz_names | words)
  a board script    NAME (tests/e2e/NAME.sh or tests/vm/NAME.sh, on the virtual
                    board under qemu; gpio is gpio-test):
                    $(board_names | words)
EOF
}

# resolve NAME: sets kind (the group's function) and args (what it runs).
resolve() {
	args=""
	case " $groups " in
	*" $1 "*)
		kind=$1
		return 0
		;;
	esac
	n=${1#test_}
	if [ -f "tests/unit/test_$n.c" ]; then
		kind=unit args=$n
	elif [ -f "tests/golden/${1%.png}.png" ]; then
		kind=golden args=${1%.png}
	elif [ "${1#fuzz-}" != "$1" ] && [ -f "tests/fuzz/fuzz_${1#fuzz-}.c" ]; then
		kind=fuzz args=${1#fuzz-}
	elif [ "$1" = gpio ] && board_path gpio-test >/dev/null; then
		kind=board args=$(board_path gpio-test)
	elif board_path "$1" >/dev/null; then
		kind=board args=$(board_path "$1")
	else
		return 1
	fi
}

# needs KIND [ARGS]: the make targets (of Makefile and tests/tests.mk) that
# the test runs.
needs() {
	case $1 in
	layers) echo all ;;
	unit) if [ -n "$2" ]; then echo "asan-test_$2"; else echo asan-unit; fi ;;
	golden) echo "all $TOOLS/mkmodels $TOOLS/imgdiff $TOOLS/stitch" ;;
	egl) echo "all $TOOLS/mkmodels $TOOLS/imgdiff" ;;
	program_check | mirror_check | base_color_check) echo "$TOOLS/$1" ;;
	ortho) echo "all $TOOLS/mkmodels $TOOLS/imgdiff" ;;
	fit) echo "all $TOOLS/mkmodels $TOOLS/silhouette" ;;
	preview) echo "all $TOOLS/mkmodels $TOOLS/imgdiff" ;;
	wall_seam) echo "all $TOOLS/mkmodels $TOOLS/imgdiff $TOOLS/stitch" ;;
	loaders) echo "all $TOOLS/mkmodels" ;;
	cli) echo "all asan-kiosk $TOOLS/mkmodels" ;;
	config_doc | install | systemd | no-camera) echo all ;;
	man | doc_claims) echo "all $MKMAN" ;;
	bad-input | not-a-file) echo "asan-kiosk $TOOLS/mkmodels" ;;
	limits) echo "all $TOOLS/mkmodels" ;;
	corpus) echo "asan-kiosk fuzzers $TOOLS/mkmodels $TOOLS/silhouette $TOOLS/imgdiff" ;;
	baker) echo "$BAKE" ;;
	live) echo "asan-kiosk $TOOLS/mkmodels $TOOLS/notify_listen" ;;
	tsan) echo "tsan $TOOLS/mkmodels $TOOLS/notify_listen" ;;
	metrics | mqtt) echo "asan-kiosk $TOOLS/mkmodels" ;;
	hands) echo "asan-kiosk $TOOLS/mkmodels $TOOLS/imgdiff $TOOLS/notify_listen" ;;
	sync) echo "asan-kiosk $TOOLS/mkmodels" ;;
	in-step) echo asan-kiosk ;;
	fuzz) echo fuzzers ;;
	soak) echo "$TOOLS/soak" ;;
	systemd-board) echo all ;;
	board) echo "all $TOOLS/imgdiff $TOOLS/hues $TOOLS/cec_power $TOOLS/clock_set $TOOLS/touch_inject $TOOLS/knob_inject $TOOLS/mkmodels" ;;
	esac
}

mode=run
case ${1:-} in
--needs)
	mode=needs
	shift
	;;
--list)
	list
	exit 0
	;;
esac
if [ $# -ne 1 ] || ! resolve "$1"; then
	if [ $# -ne 1 ] || [ -z "$1" ]; then
		echo "check.sh: which test? make check T=NAME, where NAME is one of these." >&2
	else
		echo "check.sh: no test named '$1'." >&2
	fi
	list >&2
	exit 2
fi
if [ $mode = needs ]; then
	needs "$kind" "$args"
	exit 0
fi

out=tests/out/check/$1
# shellcheck source=tests/suite.sh
. tests/suite.sh
# shellcheck disable=SC2086 # args: none, or one word
"test_$(echo "$kind" | tr - _)" $args
summary
