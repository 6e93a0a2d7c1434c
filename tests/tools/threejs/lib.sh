# shellcheck shell=sh disable=SC2034,SC2154 # size comes from, zoom goes to, the sourcing script
# Shared by compare.sh and anim-compare.sh (sourced, not run): the kiosk's
# picture and three.js's (render.js in headless chromium) of one model.
# In: size (WxH). Sets top, work, www, out, port, w, h; serves $www over
# HTTP until the sourcing script exits. three.js is installed into
# build/threejs/ at run time (npm); none of it is kept in the tree.
#
# Environment: CHROMIUM (default chromium), THREE_VERSION (default
# 0.187.0), MATCAP (default matcaps/pearl.png), MAPFILTER (linear, the
# default: three.js filters sRGB maps in linear light; stored: as the
# kiosk, the bytes filtered and decoded after; render.js).

cd "$(dirname "$0")/../../.." || exit 2
w=${size%x*}
h=${size#*x}
chromium=${CHROMIUM:-chromium}
version=${THREE_VERSION:-0.187.0}
matcap=${MATCAP:-matcaps/pearl.png}
top=$PWD
work=$top/build/threejs
www=$work/www
out=$work/out

for tool in "$chromium" npm python3; do
	command -v "$tool" >/dev/null || {
		echo "$(basename "$0"): needs $tool (apt-get install chromium npm python3)" >&2
		exit 2
	}
done
make -s -j2 matcap-kiosk build/tools/mkmodels build/tools/imgdiff

mkdir -p "$work/npm" "$out"
if [ ! -f "$work/npm/node_modules/three/package.json" ] ||
	! grep -q "\"version\": \"$version\"" "$work/npm/node_modules/three/package.json"; then
	npm install --prefix "$work/npm" --no-audit --no-fund --silent "three@$version"
fi

# The page, three.js, the models and the matcap under one folder served
# over HTTP: module scripts do not load from file:// URLs.
rm -rf "$www"
mkdir -p "$www/models"
ln -s "$top/tests/tools/threejs/index.html" "$top/tests/tools/threejs/render.js" "$www/"
ln -s "$work/npm/node_modules" "$www/node_modules"
cp "$matcap" "$www/matcap.png"

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server --bind 127.0.0.1 --directory "$www" "$port" >"$out/http.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT INT TERM
python3 - "$port" <<'PY'
import sys, time, urllib.request
for _ in range(50):
    try:
        urllib.request.urlopen("http://127.0.0.1:%s/index.html" % sys.argv[1]); break
    except OSError:
        time.sleep(0.1)
PY

# three NAME QUERY: the page's picture, read back from the text it leaves
# in its <pre> (the canvas's own bytes, not a screenshot through the
# compositor).
three() {
	"$chromium" --headless=new --no-sandbox --user-data-dir="$work/profile" \
		--use-angle=swiftshader --enable-unsafe-swiftshader --virtual-time-budget=20000 \
		--dump-dom "http://127.0.0.1:$port/index.html?matcap=matcap.png&w=$w&h=$h&mapfilter=${MAPFILTER:-linear}&$2" \
		2>"$out/$1.chromium.log" >"$out/$1.html"
	sed -n 's/.*<pre id="out">data:image\/png;base64,\([^<]*\)<.*/\1/p' "$out/$1.html" |
		base64 -d >"$out/$1-three.png"
	if [ ! -s "$out/$1-three.png" ]; then
		echo "$(basename "$0"): $1: no picture from chromium: $(grep -o '<pre id="out">[^<]*' "$out/$1.html")" >&2
		return 1
	fi
}

# kiosk NAME ARGS: the kiosk's picture at the resting view, every triangle
# drawn (three.js draws the whole mesh); zoom: the scale [scene] fit chose
# for it (src/render/framing.c), which the page's camera takes as its zoom.
kiosk() {
	name=$1
	shift
	zoom=
	./matcap-kiosk -v -b osmesa --size "$size" -c "$matcap" --lod-pixels 0 \
		--output "$out/$name-kiosk.png" "$@" 2>"$out/$name-kiosk.log" || {
		echo "$(basename "$0"): $name: the kiosk failed: $(grep -v '^\[' "$out/$name-kiosk.log" | tail -1)" >&2
		return 1
	}
	zoom=$(sed -n 's/.*framing: zoom \([0-9.]*\).*/\1/p' "$out/$name-kiosk.log")
	# The fit's shift of the outline's centre to the room's (clip space,
	# x += s w; render_matrices): its x is logged in sphere_fit_x_unit,
	# the frame's aspect divided out here.
	shift=$(sed -n "s/.*framing: zoom \([0-9.]*\), the outline's centre (\([-0-9.]*\), \([-0-9.]*\)) to (\([-0-9.]*\), \([-0-9.]*\)).*/\1 \2 \3 \4 \5/p" \
		"$out/$name-kiosk.log" | tail -n 1 |
		awk -v size="$size" '{ split(size, wh, "x"); a = wh[1] / wh[2];
			printf "&sx=%.6f&sy=%.6f", $4 - $1 * $2 / a, $5 - $1 * $3 }')
}
