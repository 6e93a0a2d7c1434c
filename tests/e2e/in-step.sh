#!/bin/sh
# Kiosks in step ([kiosk] clock = shared): two live kiosks (offscreen, as
# two screens of a wall on one machine, so one clock), started 1.3 s
# apart, draw attract mode at 20 frames a second. Every frame logs the
# moment of the shared clock it shows, its pose and when it was presented
# (debug level). Every moment both drew must show the same pose, on the
# clock's grid of 1/20 s, also after one of them reloaded its settings
# midway (SIGHUP: a state change on one screen only); and the times the
# two presented the same moment are printed (median and worst, against
# the 50 ms of a frame): a measure, not a pass mark. Then, where Debian's
# mosquitto is installed, a state change shared by both: a leader and a
# follower ([mqtt] sync) on a broker on 127.0.0.1, and the leader's next
# matcap from MQTT midway: both stop attract mode at the press and begin
# it again together (to the follower's taking it: the poses are compared
# within 0.02 rad then, and the largest difference printed); and the
# follower restarted after the press: it takes the retained step from the
# state as it was then, and is in step with the leader again.
#   in-step.sh KIOSK DIR [SECONDS]
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end.
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa}
kiosk=$1
dir=$2
seconds=${3:-16}
rm -rf "$dir"
mkdir -p "$dir"
# Leaks: see tests/e2e/live.sh (OSMesa's, at unload).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@"; then echo "ok $name"; else echo "not ok $name"; fi
}
start() { # NAME [OPTION...]: a kiosk on the shared clock, its log NAME.log
	name=$1
	shift
	"$kiosk" --backend "$offscreen" --size 96x64 --keyboard none --camera off \
		--clock shared --attract-after 1 --attract-fps 20 --log-level debug "$@" \
		>"$dir/$name.log" 2>&1 &
}
# stop_both: the second half of the run, then both kiosks stopped; their
# exit statuses in both_rc.
stop_both() {
	sleep $((seconds - seconds / 2))
	kill -TERM $a_pid $b_pid
	wait $a_pid
	a_rc=$?
	wait $b_pid
	both_rc=$a_rc$?
}
# frames NAME: "MOMENT YAW PRESENTED" per frame, from the log.
frames() {
	sed -n 's/.*clock: frame [0-9]* shows \([0-9.]*\) s, yaw \([-0-9.]*\), stop [-0-9]*, presented at \([0-9.]*\) s$/\1 \2 \3/p' \
		"$dir/$1.log" | sort -k1,1 >"$dir/$1.frames"
}

start a
a_pid=$!
sleep 1.3
start b
b_pid=$!
sleep $((seconds / 2))
# The moment of the reload, on the shared clock (the kiosks' own).
reload_at=$(date +%s.%N)
kill -HUP $b_pid
stop_both
step "both kiosks end cleanly" test "$both_rc" = 00
step "the second one read its settings again midway" grep -q "reload" "$dir/b.log"
frames a
frames b
join "$dir/a.frames" "$dir/b.frames" >"$dir/both.frames"
common=$(wc -l <"$dir/both.frames")
echo "# $(wc -l <"$dir/a.frames") and $(wc -l <"$dir/b.frames") frames drawn, $common moments drawn by both"
step "both drew the same moments, 200 and more" test "$common" -ge 200
step "every moment is on the shared clock's grid of 1/20 s" \
	awk '{ ms = $1 * 1000; if ((ms + 0.5) % 50 >= 1) bad++ } END { exit bad > 0 }' "$dir/both.frames"
step "the same moment shows the same pose on both" \
	awk '{ d = $2 - $4; if (d < 0) d = -d; if (d > 2e-6) { print "  differ:", $0; bad++ } } END { exit bad > 0 }' \
	"$dir/both.frames"
step "after the reload too, 50 moments and more" \
	awk -v t="$reload_at" '$1 > t + 1 { n++ } END { exit n < 50 }' "$dir/both.frames"
step "the pose moved (attract mode turned the model)" \
	awk 'NR == 1 { y = $2 } $2 != y { moved = 1 } END { exit !moved }' "$dir/both.frames"
# How far apart the two presented each moment: median and worst, in ms.
# The first 2 s both drew left out: a kiosk's first frames wait for its
# shaders and its first upload.
awk 'NR > 40 { d = ($3 - $5) * 1000; if (d < 0) d = -d; print d }' "$dir/both.frames" |
	sort -n >"$dir/apart.ms"
n=$(wc -l <"$dir/apart.ms")
median=$(sed -n "$(((n + 1) / 2))p" "$dir/apart.ms")
worst=$(tail -n 1 "$dir/apart.ms")
after=$(awk -v t="$reload_at" '$1 > t + 1 { d = ($3 - $5) * 1000; if (d < 0) d = -d; print d }' \
	"$dir/both.frames" | sort -n | awk '{ v[NR] = $1 } END { printf "%.1f ms median, %.1f ms worst", v[int((NR + 1) / 2)], v[NR] }')
before=$(awk -v t="$reload_at" 'NR > 40 && $1 < t - 0.5 { d = ($3 - $5) * 1000; if (d < 0) d = -d; print d }' \
	"$dir/both.frames" | sort -n | awk '{ v[NR] = $1 } END { printf "%.1f ms median, %.1f ms worst", v[int((NR + 1) / 2)], v[NR] }')
echo "# presented apart over $n moments (after the first 2 s): median $median ms, worst $worst ms (a frame: 50 ms)"
echo "# before the reload: $before; after it: $after"

if ! command -v mosquitto >/dev/null || ! command -v mosquitto_pub >/dev/null; then
	echo "# mosquitto is not installed (make deps-test): the shared press is not tried"
	echo "ok every step ran"
	exit 0
fi
for p in $(seq 19300 19329); do
	port=$p
	printf 'listener %d 127.0.0.1\nallow_anonymous true\n' "$port" >"$dir/broker.conf"
	mosquitto -c "$dir/broker.conf" >"$dir/broker.log" 2>&1 &
	broker_pid=$!
	sleep 0.5
	kill -0 $broker_pid 2>/dev/null && break
done
for role in leader follower; do
	printf '[mqtt]\nbroker = 127.0.0.1:%d\ntopic = kiosk/%s\nsync = %s\ngroup = kiosk/wall\n' \
		"$port" "$role" "$role" >"$dir/$role.ini"
done
start leader --config "$dir/leader.ini" --matcap matcaps
a_pid=$!
start follower --config "$dir/follower.ini" --matcap matcaps
b_pid=$!
sleep $((seconds / 2))
press_at=$(date +%s.%N)
mosquitto_pub -h 127.0.0.1 -p "$port" -t kiosk/leader/command -m "matcap next"
# The follower restarted 4 s after the press (3 s past attract_after): it
# gets the retained step, and takes it as it was then.
sleep 4
kill -TERM $b_pid
wait $b_pid
b_rc=$?
restart_at=$(date +%s.%N)
start restarted --config "$dir/follower.ini" --matcap matcaps
b_pid=$!
stop_both
kill $broker_pid
wait $broker_pid 2>/dev/null
step "mqtt: the leader and the follower end cleanly" test "$b_rc$both_rc" = 000
step "mqtt: the restarted follower took the retained step" \
	grep -q "mqtt: the leader's step" "$dir/restarted.log"
frames leader
frames restarted
join "$dir/leader.frames" "$dir/restarted.frames" >"$dir/restart.frames"
step "mqtt: the restarted follower in step with the leader, 50 moments and more" \
	awk -v t="$restart_at" '$1 > t + 1 { n++ } END { exit n < 50 }' "$dir/restart.frames"
step "mqtt: ... the same pose within 0.02 rad" \
	awk -v t="$restart_at" '$1 > t + 1 { d = $2 - $4; if (d < 0) d = -d; if (d > 0.02) { print "  differ:", $0; bad++ } } END { exit bad > 0 }' \
	"$dir/restart.frames"
step "mqtt: the leader took the next matcap" grep -q "mqtt: matcap next" "$dir/leader.log"
step "mqtt: the follower took the leader's step" grep -q "mqtt: the leader's step" "$dir/follower.log"
frames follower
join "$dir/leader.frames" "$dir/follower.frames" >"$dir/press.frames"
step "mqtt: before the press, the same pose at the same moment" \
	awk -v t="$press_at" '$1 < t { n++; d = $2 - $4; if (d < 0) d = -d; if (d > 2e-6) bad++ } END { exit bad > 0 || n < 50 }' \
	"$dir/press.frames"
step "mqtt: attract mode again on both after the press, 40 moments and more" \
	awk -v t="$press_at" '$1 > t + 1.5 { n++ } END { exit n < 40 }' "$dir/press.frames"
step "mqtt: after it, the same pose within 0.02 rad" \
	awk -v t="$press_at" '$1 > t + 1.5 { d = $2 - $4; if (d < 0) d = -d; if (d > 0.02) bad++ } END { exit bad > 0 }' \
	"$dir/press.frames"
awk -v t="$press_at" '$1 > t + 1.5 { d = $2 - $4; if (d < 0) d = -d; if (d > m) m = d
	p = ($3 - $5) * 1000; if (p < 0) p = -p; print p >"/dev/stderr" } END { printf "# after the shared press: the poses differ by %.6f rad at most", m }' \
	"$dir/press.frames" 2>"$dir/press.ms"
sort -n "$dir/press.ms" | awk '{ v[NR] = $1 } END { printf "; presented apart %.1f ms median, %.1f ms worst over %d moments\n", v[int((NR + 1) / 2)], v[NR], NR }'
echo "ok every step ran"
