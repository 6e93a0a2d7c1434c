#!/bin/sh
# Runs every test and ends with one "N passed, N failed" line.
# Environment (set by `make test`): KIOSK, ASAN_KIOSK, UNIT_DIR, TOOLS, BAKE.
set -u
out=tests/out
rm -rf "$out"
mkdir -p "$out/models" "$out/render" "$out/bad"
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
# check NAME COMMAND...: passes when the command exits 0.
check() {
	name=$1
	shift
	if "$@" >"$out/last.log" 2>&1; then ok "$name"; else cat "$out/last.log"; ko "$name"; fi
}

# 1. Unit tests (cmocka), built with ASan and UBSan.
for t in "$UNIT_DIR"/test_*; do
	check "unit $(basename "$t")" "$t"
done

# 2. Golden images through OSMesa, with a stated tolerance: a pixel differs
#    when a channel is off by more than 8/255, and at most 0.5% may differ.
check "models written" "$TOOLS/mkmodels" "$out/models"
MODELS=$out/models check "golden scenes rendered" sh tests/golden.sh "$out/render"
for g in tests/golden/*.png; do
	check "golden $(basename "$g")" "$TOOLS/imgdiff" --tol 8 --share 0.005 "$g" \
		"$out/render/$(basename "$g")"
done

# 3. The same scenes through EGL headless agree with OSMesa.
for mode in normal view sem-vertex sem-fragment; do
	check "egl-headless renders $mode" $KIOSK -q --backend egl-headless --size 320x240 \
		--matcap matcaps/gold.png --mode $mode --output "$out/render/egl-knot-$mode.png"
	check "egl-headless matches osmesa ($mode)" "$TOOLS/imgdiff" --tol 8 --share 0.005 \
		"$out/render/knot-$mode.png" "$out/render/egl-knot-$mode.png"
done

# 4. The classic check: a sphere in normal mode under an orthographic camera
#    reproduces the matcap disk itself (less a 3-pixel rim, where the
#    polygonal silhouette and the disk's edge differ).
for m in gold chrome-studio; do
	check "ortho sphere renders ($m)" $KIOSK -q --backend osmesa --size 256x256 --ortho \
		--mode normal --pitch 0 --yaw 0 --model "$out/models/sphere.glb" \
		--matcap matcaps/$m.png --output "$out/render/ortho-$m.png"
	check "ortho sphere reproduces the matcap ($m)" "$TOOLS/imgdiff" --disk --rim 3 \
		--tol 8 --share 0.002 "matcaps/$m.png" "$out/render/ortho-$m.png"
done

# 5. Loader variants that must work from the command line.
for f in sphere-nonormals.gltf sphere-datauri.gltf; do
	check "loads $f" $KIOSK -q --backend osmesa --size 64x64 --model "$out/models/$f" \
		--output "$out/render/$f.png"
done

# 6. Malformed input, through the ASan binary: exit status 1, one error
#    line that names the file, and no sanitizer report.
printf '' >"$out/bad/zero.png"
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\001\206\240\000\001\206\240\010\006\000\000\000\250\122\013\310' >"$out/bad/huge.png"
head -c 300 matcaps/gold.png >"$out/bad/truncated.png"
echo "not a picture" >"$out/bad/text.jpg"
bad_input() { # NAME OPTION FILE
	"$ASAN_KIOSK" --backend osmesa --size 64x64 "$2" "$3" --output "$out/bad/x.png" \
		>"$out/bad/stdout" 2>"$out/bad/stderr"
	status=$?
	lines=$(grep -c "error" "$out/bad/stderr")
	if [ $status -eq 1 ] && [ "$lines" -eq 1 ] && grep -qF "$3" "$out/bad/stderr" &&
		! grep -qE "Sanitizer|runtime error" "$out/bad/stderr"; then
		ok "$1: $(cat "$out/bad/stderr")"
	else
		echo "status $status, $lines error lines:"
		cat "$out/bad/stderr"
		ko "$1"
	fi
}
for f in "$out"/models/bad-*; do
	case $f in *.bin) continue ;; esac
	bad_input "bad model $(basename "$f")" --model "$f"
done
for f in zero.png huge.png truncated.png text.jpg; do
	bad_input "bad matcap $f" --matcap "$out/bad/$f"
done
bad_input "missing model" --model "$out/bad/no-such-model.glb"

# 7. The command line itself.
check "--help" sh -c "$KIOSK --help | grep -q '^Usage: matcap-kiosk'"
check "--version" sh -c "$KIOSK --version | grep -q '^matcap-kiosk [0-9]'"
check "bad option value exits 2 naming it" sh -c \
	"$KIOSK --size 12 2>&1 | grep -q -- '--size'; [ \$($KIOSK --size 12 2>/dev/null; echo \$?) -eq 2 ]"

# Every setting that the config file takes is documented in the example.
check "every config key documented in config/kiosk.ini" sh tests/config_doc.sh "$KIOSK"

# 8. The shipped matcaps regenerate byte for byte from the baker.
mkdir -p "$out/baked"
check "baker runs" "$BAKE" "$out/baked" 256
for f in matcaps/*.png; do
	check "matcap $(basename "$f") reproducible" cmp "$f" "$out/baked/$(basename "$f")"
done

# 9. make install honours PREFIX and DESTDIR.
check "make install" sh -c "make -s install DESTDIR=$PWD/$out/stage PREFIX=/usr SYSCONFDIR=/etc >/dev/null &&
	test -x $out/stage/usr/bin/matcap-kiosk &&
	test -f $out/stage/usr/share/matcap-kiosk/matcaps/gold.png &&
	test -f $out/stage/etc/matcap-kiosk/kiosk.ini"

[ -n "$failures" ] && echo "failed:$failures"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
