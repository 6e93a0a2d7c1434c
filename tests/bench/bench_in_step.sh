#!/bin/sh
# Kiosks in step, measured ([kiosk] clock = shared): two live kiosks of
# the -O2 build (OSMesa, the real poll loop, one machine so one clock)
# draw attract mode at 20 frames a second for IN_STEP_S seconds (default
# 30: some 600 frames each); printed, never asserted: how far apart (ms)
# they presented the same moment, median and worst, without a state
# change, after one's reload, and after a press shared over MQTT (where
# mosquitto is installed). tests/e2e/in-step.sh is the same scenario as a
# test, on the ASan build. Environment: KIOSK.
set -eu
out=tests/out/bench-in-step
sh tests/e2e/in-step.sh "$KIOSK" "$out" "${IN_STEP_S:-30}" >"$out.log" 2>&1 || true
echo "== kiosks in step: two processes on a shared clock, 20 frames a second"
grep '^#' "$out.log" | sed 's/^# /  /'
if grep -q '^not ok' "$out.log"; then
	echo "  (the scenario failed: $out.log)"
fi
