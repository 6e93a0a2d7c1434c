#!/bin/sh
# [mqtt] remote control against a real broker (Debian's mosquitto, on
# 127.0.0.1, a free port, started and stopped here): a live kiosk (the
# ASan build, offscreen) takes every command from mosquitto_pub, keeps its
# state retained, ignores malformed payloads (a path, control bytes, an
# unknown word) and lives on, survives a broker restart, leaves its last
# will "offline" when killed with SIGKILL, and talks TLS with a test
# certificate (openssl, made here) and a password from systemd's
# credentials folder. A broker that is not there at the start is said
# once and the kiosk draws on.
#   mqtt.sh KIOSK MODELS DIR
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end. Bounded: each wait
# is at most 15 s; every process started here is stopped at the end.
set -u
offscreen=${OFFSCREEN_BACKEND:-osmesa}
kiosk=$1
models=$2
dir=$3
rm -rf "$dir"
mkdir -p "$dir/models" "$dir/cred"
dir=$(cd "$dir" && pwd)
cp "$models/sphere.glb" "$models/knot.glb" "$dir/models/"
topic=kiosk/e2e

step() { # NAME COMMAND...: one result line
	name=$1
	shift
	if "$@"; then echo "ok $name"; else echo "not ok $name"; fi
}
until_true() { # COMMAND...: until it succeeds, 15 s at most
	i=0
	until "$@"; do
		i=$((i + 1))
		[ $i -gt 150 ] && return 1
		sleep 0.1
	done
}
pids=""
cleanup() {
	for p in $pids; do kill -9 "$p" 2>/dev/null; done
	wait 2>/dev/null
}
trap cleanup EXIT

# broker CONF LOG: mosquitto on its config; its pid in broker_pid.
broker() {
	: >"$2"
	mosquitto -c "$1" >>"$2" 2>&1 &
	broker_pid=$!
	pids="$pids $broker_pid"
	until_true grep -q "Opening ipv4 listen socket" "$2" && kill -0 "$broker_pid" 2>/dev/null
}
# A free port: the first of a range that a broker keeps.
for p in $(seq 19270 19299); do
	port=$p
	printf 'listener %d 127.0.0.1\nallow_anonymous true\n' "$port" >"$dir/broker.conf"
	broker "$dir/broker.conf" "$dir/broker.log" && break
	kill -9 "$broker_pid" 2>/dev/null
done
step "a broker listens on 127.0.0.1:$port" kill -0 "$broker_pid"

pub() { mosquitto_pub -h 127.0.0.1 -p "$port" -t "$topic/command" -m "$1"; }
# retained TOPIC: the retained message there (or nothing after 2 s).
retained() { mosquitto_sub -h 127.0.0.1 -p "$port" -t "$1" -C 1 -W 2 2>/dev/null; }
state_has() { retained "$topic/state" | grep -qF -- "$1"; }
# state_lacks TEXT: there is a state, and TEXT is not in it.
state_lacks() {
	s=$(retained "$topic/state")
	[ -n "$s" ] && ! echo "$s" | grep -qF -- "$1"
}
available() { [ "$(retained "$topic/availability")" = "$1" ]; }
logged() { grep -qF -- "$1" "$dir/kiosk.log"; }
count() { grep -cF -- "$1" "$dir/kiosk.log"; }
at_least() { [ "$(count "$2")" -ge "$1" ]; }

# fresh_log: the next kiosk's log empty, the last one's kept in kiosk-all.log.
fresh_log() {
	cat "$dir/kiosk.log" >>"$dir/kiosk-all.log" 2>/dev/null
	: >"$dir/kiosk.log"
}
# start_kiosk INI: a live kiosk on that config; its pid in kiosk_pid.
start_kiosk() {
	ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
		"$kiosk" --backend "$offscreen" --size 64x64 --config "$1" --matcap matcaps \
		>>"$dir/kiosk.log" 2>&1 &
	kiosk_pid=$!
	pids="$pids $kiosk_pid"
}

cat >"$dir/kiosk.ini" <<EOF
[scene]
model = $dir/models
[frame]
stops = 0 0 1 "front"; 90 0 1 "side"; 180 0 1 "back"
[caption]
text = Vase
text[de] = Die Vase
languages = en de
[mqtt]
broker = 127.0.0.1:$port
topic = $topic
home_assistant = yes
EOF
fresh_log
start_kiosk "$dir/kiosk.ini"
step "the kiosk connects" until_true logged "mqtt: connected to 127.0.0.1:$port"
step "its state is retained" until_true state_has '"screen":"on"'
step "it is online (retained)" until_true available online
ha_switch() {
	retained homeassistant/switch/kiosk_e2e/screen/config |
		grep -qF "\"command_topic\":\"$topic/command\""
}
step "Home Assistant discovery: the screen switch is announced" until_true ha_switch

# Every command, and what the state then says.
third=$(cd matcaps && LC_ALL=C ls ./*.png | sed -n 3p | sed 's|^\./||')
pub "matcap 3"
step "matcap 3: the third matcap by name ($third)" until_true state_has "\"matcap\":\"$third\""
pub "matcap next"
step "matcap next: another matcap" until_true state_lacks "\"matcap\":\"$third\""
pub "matcap prev"
step "matcap prev: back to the third" until_true state_has "\"matcap\":\"$third\""
first=$(retained "$topic/state" | sed -n 's/.*"model":"\([^"]*\)".*/\1/p')
pub "model next"
other_model() { state_has '.glb"' && state_lacks "\"model\":\"$first\""; }
step "model next: the other model ($first before)" until_true other_model
pub "model prev"
step "model prev: the first again" until_true state_has "\"model\":\"$first\""
pub "stop 2"
step "stop 2" until_true state_has '"stop":2'
pub "stop next"
step "stop next: 3" until_true state_has '"stop":3'
pub "stop prev"
step "stop prev: 2" until_true state_has '"stop":2'
pub "screen off"
step "screen off" until_true state_has '"screen":"off"'
pub "screen on"
step "screen on" until_true state_has '"screen":"on"'
pub "variant next"
step "variant next: taken" until_true logged "mqtt: variant next"
pub "language de"
step "language de: shows de, the model's second language" until_true \
	logged "language: de shown"
pub "language fr"
step "language fr: not one of the model's languages, said and ignored" until_true \
	logged "'language fr': not one of this model's [caption] languages (2 named); ignored"
pub "language en"
step "language en: back to the first" until_true logged "language: en shown"
pub "reload"
step "reload: the settings read again" until_true logged "reload: done"

# Malformed payloads: logged, ignored, the kiosk lives on.
before=$(count "a payload of")
pub "matcap /etc/shadow"
pub "model ../../x.glb"
printf 'screen on\001' | mosquitto_pub -h 127.0.0.1 -p "$port" -t "$topic/command" -s
printf 'model next\000rm -rf /' | mosquitto_pub -h 127.0.0.1 -p "$port" -t "$topic/command" -s
head -c 4096 /dev/zero | tr '\0' 'a' | mosquitto_pub -h 127.0.0.1 -p "$port" -t "$topic/command" -s
mosquitto_pub -h 127.0.0.1 -p "$port" -t "$topic/command" -n
pub "stop 9"
step "six malformed payloads logged and ignored" until_true at_least $((before + 6)) "a payload of"
step "a stop out of range said and ignored" until_true logged "'stop 9': there are 3; ignored"
step "the state unchanged by them" state_has "\"model\":\"$first\""
step "the kiosk lives on" kill -0 "$kiosk_pid"
step "a path named in a payload is in no log line but the refusal" sh -c \
	"! grep -F '/etc/shadow' '$dir/kiosk.log' | grep -v 'ignored' | grep -q ."

# The broker restarts (no persistence: it forgot everything).
kill "$broker_pid"
wait "$broker_pid" 2>/dev/null
step "the loss is said once" until_true logged "the kiosk runs on without remote control"
broker "$dir/broker.conf" "$dir/broker2.log"
step "a broker restart survived: connected again" until_true at_least 2 "mqtt: connected to"
step "the state is retained again" until_true state_has "\"model\":\"$first\""
pub "matcap next"
step "commands after the restart" until_true state_lacks "\"matcap\":\"$third\""

# SIGKILL: the broker says the last will.
kill -9 "$kiosk_pid"
wait "$kiosk_pid" 2>/dev/null
step "last will after SIGKILL: offline (retained)" until_true available offline

# No broker at the start: said once, the kiosk draws on.
fresh_log
sed "s/^broker = .*/broker = 127.0.0.1:1/" "$dir/kiosk.ini" >"$dir/absent.ini"
start_kiosk "$dir/absent.ini"
step "no broker: the kiosk is ready all the same" until_true logged "ready: the first frame"
sleep 4 # retried after 1 and 2 s meanwhile
step "no broker: said once, not at each retry" [ "$(count 'runs on without remote control')" -eq 1 ]
kill "$kiosk_pid"
wait "$kiosk_pid"
step "no broker: the kiosk stops cleanly at SIGTERM" [ $? -eq 0 ]

# TLS with a test certificate, and a password from the credentials folder.
openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj "/CN=test CA" \
	-keyout "$dir/ca.key" -out "$dir/ca.pem" >/dev/null 2>&1
openssl req -newkey rsa:2048 -nodes -subj "/CN=127.0.0.1" -keyout "$dir/server.key" \
	-out "$dir/server.csr" >/dev/null 2>&1
printf 'subjectAltName=IP:127.0.0.1\n' >"$dir/san.ext"
openssl x509 -req -in "$dir/server.csr" -CA "$dir/ca.pem" -CAkey "$dir/ca.key" -CAcreateserial \
	-days 2 -extfile "$dir/san.ext" -out "$dir/server.pem" >/dev/null 2>&1
step "a test CA and server certificate" test -s "$dir/server.pem"
tport=$((port + 100))
: >"$dir/passwd"
mosquitto_passwd -b "$dir/passwd" kiosk 's3cret pass' 2>/dev/null
# Started as root, mosquitto reads its files as the user mosquitto.
chmod 644 "$dir/server.key" "$dir/passwd"
cat >"$dir/tls.conf" <<EOF
per_listener_settings true
listener $port 127.0.0.1
allow_anonymous true
listener $tport 127.0.0.1
cafile $dir/ca.pem
certfile $dir/server.pem
keyfile $dir/server.key
allow_anonymous false
password_file $dir/passwd
EOF
kill "$broker_pid"
wait "$broker_pid" 2>/dev/null
broker "$dir/tls.conf" "$dir/broker3.log"
sed "s/^broker = .*/broker = 127.0.0.1:$tport/; s|^\[mqtt\]|[mqtt]\ntls = yes\nca_file = $dir/ca.pem|" \
	"$dir/kiosk.ini" >"$dir/tls.ini"
# A wrong password: refused by the broker, said once, the kiosk draws on.
printf 'kiosk\nwrong\n' >"$dir/cred/mqtt"
fresh_log
CREDENTIALS_DIRECTORY=$dir/cred start_kiosk "$dir/tls.ini"
step "TLS: a wrong password refused" until_true logged "refused the connection"
sleep 4 # retried after 1 and 2 s meanwhile
step "TLS: the refusal said once, not at each retry" [ "$(count 'refused the connection')" -eq 1 ]
step "TLS: the kiosk draws on all the same" logged "ready: the first frame"
kill "$kiosk_pid"
wait "$kiosk_pid" 2>/dev/null
printf 'kiosk\ns3cret pass\n' >"$dir/cred/mqtt"
chmod 600 "$dir/cred/mqtt"
fresh_log
CREDENTIALS_DIRECTORY=$dir/cred start_kiosk "$dir/tls.ini"
step "TLS: connected with the test CA and the credential" until_true \
	logged "mqtt: connected to 127.0.0.1:$tport"
pub "screen off"
step "TLS: a command taken" until_true logged "mqtt: screen off"
kill "$kiosk_pid"
wait "$kiosk_pid" 2>/dev/null
step "TLS: a clean stop says offline" until_true available offline
step "TLS: the password is in no log" sh -c "! grep -q s3cret '$dir/kiosk.log'"
# A leader and a follower ([mqtt] sync): the follower shows the leader's
# model, matcap and stop from the wall-clock time the leader sent.
fresh_log
sed "s|^topic = .*|topic = kiosk/lead\nsync = leader\ngroup = kiosk/wall|" "$dir/kiosk.ini" \
	>"$dir/lead.ini"
sed "s|^topic = .*|topic = kiosk/follow\nsync = follower\ngroup = kiosk/wall|" "$dir/kiosk.ini" \
	>"$dir/follow.ini"
start_kiosk "$dir/lead.ini"
lead_pid=$kiosk_pid
start_kiosk "$dir/follow.ini"
follow_pid=$kiosk_pid
step "sync: the leader and the follower connect" until_true at_least 2 "mqtt: connected to"
# follows NAME TEXT: kiosk/NAME's state has TEXT.
follows() { retained "kiosk/$1/state" | grep -qF -- "$2"; }
# the_same: both states say the same model, matcap and stop.
the_same() {
	a=$(retained kiosk/lead/state | sed 's/,"screen".*//')
	[ -n "$a" ] && [ "$a" = "$(retained kiosk/follow/state | sed 's/,"screen".*//')" ]
}
mosquitto_pub -h 127.0.0.1 -p "$port" -t kiosk/lead/command -m "matcap 3"
step "sync: the leader shows matcap 3" until_true follows lead "\"matcap\":\"$third\""
step "sync: so does the follower" until_true follows follow "\"matcap\":\"$third\""
# The next model first: a model swapped in starts at no stop.
mosquitto_pub -h 127.0.0.1 -p "$port" -t kiosk/lead/command -m "model next"
lead_other() {
	retained kiosk/lead/state | grep -q '"model":"[a-z]*\.glb"' &&
		! retained kiosk/lead/state | grep -qF "\"model\":\"$first\""
}
step "sync: the leader's next model" until_true lead_other
mosquitto_pub -h 127.0.0.1 -p "$port" -t kiosk/lead/command -m "stop 2"
step "sync: the leader's stop 2" until_true follows lead '"stop":2'
step "sync: the follower shows the same model, matcap and stop" until_true the_same
step_is() { retained kiosk/wall/step | grep -qE "^at=[0-9]{13} model=[0-9]+ matcap=[0-9]+ stop=1\$"; }
step "sync: the step carries the leader's wall clock (ms) and what it shows" until_true step_is
mosquitto_pub -h 127.0.0.1 -p "$port" -t kiosk/wall/step -r -m "at=1 model=0 matcap=/etc/x stop=0"
step "sync: a malformed step ignored by the follower" until_true \
	logged "a leader's step of 33 bytes ignored"
step "sync: the follower lives on" kill -0 "$follow_pid"
# A leader a minute ahead (clocks not in step): shown at once, and said.
second=$(cd matcaps && LC_ALL=C ls ./*.png | sed -n 2p | sed 's|^\./||')
mosquitto_pub -h 127.0.0.1 -p "$port" -t kiosk/wall/step -r \
	-m "at=$(($(date +%s) * 1000 + 60000)) model=0 matcap=1 stop=-1"
step "sync: a step a minute ahead is said" until_true logged "s ahead of this clock: shown now"
step "sync: and shown at once ($second)" until_true follows follow "\"matcap\":\"$second\""
kill "$lead_pid" "$follow_pid"
wait "$lead_pid" "$follow_pid" 2>/dev/null

fresh_log
step "no sanitizer report in any kiosk's log" sh -c "! grep -E \
	'ERROR: AddressSanitizer|WARNING: ThreadSanitizer|runtime error' '$dir/kiosk-all.log'"

# --check-config says a bad [mqtt] line with its file and line: 78.
printf '[mqtt]\nbroker = 127.0.0.1:0\ntopic = kiosk/#\n' >"$dir/bad.ini"
"$kiosk" --check-config --config "$dir/bad.ini" >"$dir/check.out" 2>"$dir/check.err"
step "--check-config: a bad [mqtt] is a bad setting (78)" [ $? -eq 78 ]
step "--check-config: the broker's file, line and what was expected" \
	grep -qF "$dir/bad.ini:2: [mqtt] broker = '127.0.0.1:0': the port must be a number 1-65535" \
	"$dir/check.err"
step "--check-config: the topic's" grep -qF "$dir/bad.ini:3: [mqtt] topic = 'kiosk/#'" "$dir/check.err"
echo "ok every step ran"
