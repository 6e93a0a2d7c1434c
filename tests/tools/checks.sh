# The counting every test runner shares (tests/suite.sh, tests/cross/run.sh,
# tests/cross/deb-install.sh): "PASS NAME" or "FAIL NAME" per check, and a
# closing "N passed, N failed" that tests/run.sh and .ci/run add up.
# Sourced; CHECK_LOG names the file a check's output goes to (shown when
# it fails).
passed=0
failed=0
failures=""

ok() {
	passed=$((passed + 1))
	echo "PASS $1"
}
ko() {
	failed=$((failed + 1))
	failures="$failures $1"
	echo "FAIL $1"
}
# check NAME COMMAND...: one check, passed when COMMAND exits 0.
check() {
	name=$1
	shift
	if "$@" >"$CHECK_LOG" 2>&1; then ok "$name"; else cat "$CHECK_LOG"; ko "$name"; fi
}
# summary: the failed checks, then "N passed, N failed"; false on a failure.
summary() {
	[ -n "$failures" ] && echo "failed:$failures"
	echo "$passed passed, $failed failed"
	[ "$failed" -eq 0 ]
}
