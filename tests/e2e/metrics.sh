#!/bin/sh
# [status] metrics as a dashboard gets them: a live kiosk (the ASan build,
# offscreen) writes its metrics file into a folder, and a real
# node_exporter (Debian's prometheus-node-exporter, only its textfile
# collector, listening on 127.0.0.1 alone) is scraped over HTTP: the
# kiosk's metrics must be there with the kiosk's values (a matcap folder
# whose name has a double quote and a backslash, reloads that fail and
# succeed, the error and its time, up 0 after SIGTERM), and the collector
# must report no parse error (node_textfile_scrape_error 0).
#   metrics.sh KIOSK MODEL DIR [NODE_EXPORTER]
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end. Bounded: each wait
# is at most 15 s (the file is written every 5 s), the exporter is stopped
# at the end whatever happened.
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa}
kiosk=$1
dir=$3
exporter=${4:-prometheus-node-exporter}
rm -rf "$dir"
mkdir -p "$dir/textfile" "$dir/models"
dir=$(cd "$dir" && pwd)
# A copy of its own: the test replaces it, and the kiosk loads it again.
cp "$2" "$dir/models/model.glb"
model=$dir/models/model.glb
# A label value must be escaped: a folder name with a quote and a backslash.
mc="$dir/mc \"q\" \\b"
mkdir -p "$mc"
cp matcaps/gold.png "$mc/"
prom=$dir/textfile/matcap-kiosk.prom
printf '[scene]\nmode = view\n[status]\nmetrics = %s\n' "$prom" >"$dir/kiosk.ini"

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@"; then echo "ok $name"; else echo "not ok $name"; fi
}
# until_true COMMAND...: until it succeeds, 15 s at most.
until_true() {
	i=0
	until "$@"; do
		i=$((i + 1))
		[ $i -gt 150 ] && return 1
		sleep 0.1
	done
}
scrape() { curl -fsS --max-time 5 "http://127.0.0.1:$port/metrics" >"$dir/scrape.txt" 2>"$dir/curl.err"; }
# value NAME_WITH_LABELS: its value in the last scrape, as printed there.
value() { awk -v m="$1" 'substr($0, 1, length(m) + 1) == m " " { print $NF }' "$dir/scrape.txt"; }
# same NAME EXPECTED: the scraped value equals EXPECTED as a number.
same() { awk -v a="$(value "$1")" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 == b + 0) }'; }
# in_file LINE: the metrics file has that whole line now.
in_file() { grep -qxF -- "$1" "$prom" 2>/dev/null; }
# scraped LINE: the last scrape has that whole line.
scraped() { grep -qxF -- "$1" "$dir/scrape.txt"; }
file_value() { awk -v m="$1" '$1 == m { print $2 }' "$prom"; }

cleanup() {
	[ -n "${exporter_pid:-}" ] && kill "$exporter_pid" 2>/dev/null && wait "$exporter_pid" 2>/dev/null
	[ -n "${kiosk_pid:-}" ] && kill "$kiosk_pid" 2>/dev/null && wait "$kiosk_pid" 2>/dev/null
}
trap cleanup EXIT

ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
	"$kiosk" --backend "$offscreen" --size 64x64 --config "$dir/kiosk.ini" --matcap "$mc" \
	2>"$dir/stderr" &
kiosk_pid=$!
step "the kiosk writes the metrics file at the start" until_true in_file "matcap_kiosk_up 1"

# A port of its own on 127.0.0.1 (another test or program may hold one):
# the first of a few that the exporter keeps.
port=""
for p in $(seq 19170 19189); do
	"$exporter" --web.listen-address="127.0.0.1:$p" --collector.disable-defaults \
		--collector.textfile --collector.textfile.directory="$dir/textfile" \
		>"$dir/exporter.log" 2>&1 &
	exporter_pid=$!
	port=$p
	if until_true sh -c "curl -fs --max-time 1 -o /dev/null http://127.0.0.1:$p/metrics ||
		! kill -0 $exporter_pid 2>/dev/null" && kill -0 $exporter_pid 2>/dev/null; then
		break
	fi
	wait $exporter_pid 2>/dev/null
	exporter_pid="" port=""
done
step "node_exporter listens on 127.0.0.1:$port" [ -n "$port" ]
step "... on 127.0.0.1 alone" sh -c "! grep -q 'Listening on.*:::$port\|0.0.0.0:$port' '$dir/exporter.log'"

step "scraped" scrape
step "no textfile parse error (node_textfile_scrape_error 0)" same node_textfile_scrape_error 0
step "matcap_kiosk_up 1" scraped "matcap_kiosk_up 1"
version=$("$kiosk" --version | awk '{ print $2 }')
step "build info with the kiosk's version ($version)" \
	scraped "matcap_kiosk_build_info{version=\"$version\"} 1"
# The exporter sorts labels by name and escapes as the file did.
esc_mc=$(printf '%s/gold.png' "$mc" | sed 's/\\/\\\\/g; s/"/\\"/g')
step "what is shown, the label escaped" \
	scraped "matcap_kiosk_shown_info{matcap=\"$esc_mc\",mode=\"view\",model=\"built-in\"} 1"
step "frames drawn as the file says" same matcap_kiosk_frames_drawn_total \
	"$(file_value matcap_kiosk_frames_drawn_total)"
step "... and at least one" awk -v v="$(value matcap_kiosk_frames_drawn_total)" 'BEGIN { exit !(v >= 1) }'
step "screen on" same matcap_kiosk_screen_on 1
step "start time: this run's" awk -v t="$(value matcap_kiosk_start_time_seconds)" \
	-v now="$(date +%s)" 'BEGIN { exit !(t > now - 120 && t <= now + 1) }'
step "no error yet" same matcap_kiosk_last_error_timestamp_seconds 0
step "counters start at 0" sh -c "grep -qx 'matcap_kiosk_reloads_total{result=\"done\"} 0' '$dir/scrape.txt' &&
	grep -qx 'matcap_kiosk_reloads_total{result=\"failed\"} 0' '$dir/scrape.txt' &&
	grep -qx 'matcap_kiosk_model_loads_total{result=\"shown\"} 0' '$dir/scrape.txt'"
step "HELP and TYPE kept" sh -c "grep -q '^# TYPE matcap_kiosk_frames_drawn_total counter' '$dir/scrape.txt' &&
	grep -q '^# HELP matcap_kiosk_up ' '$dir/scrape.txt'"
step "the file is readable by others (node_exporter's user)" sh -c "ls -l '$prom' | grep -q '^-rw-r--r--'"
step "no temporary file left beside it" sh -c "[ \$(ls -A '$dir/textfile' | wc -l) -eq 1 ]"

# A reload that fails: counted, and the error with its time.
before=$(date +%s)
printf '[scene]\nmodel = %s/no-such-model.glb\n[status]\nmetrics = %s\n' "$dir" "$prom" >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a failed reload is counted in the file" until_true \
	in_file 'matcap_kiosk_reloads_total{result="failed"} 1'
step "scraped again" scrape
step "... no textfile parse error" same node_textfile_scrape_error 0
step "... reloads failed 1" scraped 'matcap_kiosk_reloads_total{result="failed"} 1'
step "... the error's time is now" awk -v t="$(value matcap_kiosk_last_error_timestamp_seconds)" \
	-v b="$before" -v now="$(date +%s)" 'BEGIN { exit !(t >= b && t <= now + 1) }'
last=$(sed -n 's/^matcap-kiosk: error: //p' "$dir/stderr" | tail -n 1 | sed 's/\\/\\\\/g; s/"/\\"/g')
step "... the error is the last one logged ($last)" \
	scraped "matcap_kiosk_last_error_info{error=\"$last\"} 1"

# A good reload with a model: counted as done.
printf '[scene]\nmode = normal\nmodel = %s\n[status]\nmetrics = %s\n' "$model" "$prom" >"$dir/kiosk.ini"
kill -HUP $kiosk_pid
step "a good reload is counted" until_true in_file 'matcap_kiosk_reloads_total{result="done"} 1'
step "scraped again" scrape
step "... reloads done 1, failed still 1" sh -c "
	grep -qx 'matcap_kiosk_reloads_total{result=\"done\"} 1' '$dir/scrape.txt' &&
	grep -qx 'matcap_kiosk_reloads_total{result=\"failed\"} 1' '$dir/scrape.txt'"
step "... the error cleared by the good reload" same matcap_kiosk_last_error_timestamp_seconds 0
step "... and its _info gone" sh -c "! grep -q '^matcap_kiosk_last_error_info' '$dir/scrape.txt'"
step "... the model shown, in the new mode" scraped \
	"matcap_kiosk_shown_info{matcap=\"$esc_mc\",mode=\"normal\",model=\"$model\"} 1"
step "... uptime grows" awk -v t="$(value matcap_kiosk_uptime_seconds)" 'BEGIN { exit !(t > 0) }'

# The model replaced (as a sync tool does: a temporary name, renamed into
# place): loaded while running, and counted.
cp "$model" "$dir/models/.model.glb.tmp"
mv "$dir/models/.model.glb.tmp" "$model"
step "a model loaded while running is counted" until_true \
	in_file 'matcap_kiosk_model_loads_total{result="shown"} 1'
step "scraped again" scrape
step "... model loads shown 1, failed 0" sh -c "
	grep -qx 'matcap_kiosk_model_loads_total{result=\"shown\"} 1' '$dir/scrape.txt' &&
	grep -qx 'matcap_kiosk_model_loads_total{result=\"failed\"} 0' '$dir/scrape.txt'"
printf 'not a glb' >"$dir/models/.model.glb.tmp"
mv "$dir/models/.model.glb.tmp" "$model"
step "a model that fails to load is counted" until_true \
	in_file 'matcap_kiosk_model_loads_total{result="failed"} 1'
step "scraped again" scrape
step "... model loads shown 1, failed 1" sh -c "
	grep -qx 'matcap_kiosk_model_loads_total{result=\"shown\"} 1' '$dir/scrape.txt' &&
	grep -qx 'matcap_kiosk_model_loads_total{result=\"failed\"} 1' '$dir/scrape.txt'"

kill -TERM $kiosk_pid
wait $kiosk_pid
status=$?
kiosk_pid=""
step "SIGTERM exits 0 (status $status)" [ $status -eq 0 ]
step "scraped after the stop" scrape
step "... matcap_kiosk_up 0" scraped "matcap_kiosk_up 0"
step "... no textfile parse error" same node_textfile_scrape_error 0
step "no sanitizer report" sh -c "! grep -qE 'Sanitizer|runtime error' '$dir/stderr'"

kill "$exporter_pid"
wait "$exporter_pid" 2>/dev/null
step "node_exporter stopped" sh -c "! kill -0 $exporter_pid 2>/dev/null"
exporter_pid=""
echo "ok every step ran"
