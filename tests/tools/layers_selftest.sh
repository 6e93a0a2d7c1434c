#!/bin/sh
# Checks the layer checker (tests/tools/layers.sh) on small fake src/ trees
# in a scratch folder: a clean tree passes; one upward include, one include
# across peers, one circle of includes, one file over 700 lines or one file
# outside the layer folders each make it fail, naming the file and line.
# So do two files that call each other, or a ring of three, compiled into
# the tree's build/ (the checker reads the calls from the objects), and a
# tree with no object at all. A checker that passes everything would
# otherwise look like a clean src/.
#   tests/tools/layers_selftest.sh
# Prints one "ok" or "not ok" line per case; exits 1 when any case failed.
set -u
layers=$(cd "$(dirname "$0")" && pwd)/layers.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0

# A clean tree: every layer, each file including its own layer and lower ones.
clean() {
	rm -rf "$tmp/src"
	for d in app ops content config state display input camera render scene util; do
		mkdir -p "$tmp/src/$d"
	done
	printf '/* the bottom layer */\n' >"$tmp/src/util/log.h"
	printf '#include "util/log.h"\n' >"$tmp/src/scene/mesh.h"
	printf '#include "scene/mesh.h"\n#include "util/log.h"\n' >"$tmp/src/render/render.h"
	printf '#include "render/render.h"\n' >"$tmp/src/display/display.h"
	printf '#include "render/render.h"\n' >"$tmp/src/input/button.h"
	printf '#include "render/render.h"\n' >"$tmp/src/camera/camera.h"
	printf '#include "input/button.h"\n' >"$tmp/src/state/app.h"
	printf '#include "state/app.h"\n#include "display/display.h"\n' >"$tmp/src/config/settings.h"
	printf '#include "config/settings.h"\n' >"$tmp/src/content/content.h"
	printf '#include "content/content.h"\n#include "camera/camera.h"\n' >"$tmp/src/ops/import.h"
	printf '#include "ops/import.h"\n#include "app/kiosk.h"\n#include "state/app.h"\n' \
		>"$tmp/src/app/main.c"
	printf '#include "content/content.h"\n' >"$tmp/src/app/kiosk.h"
}
# objects: every source of the tree compiled into $tmp/build, as make
# does; one that does not compile (an include of a missing header) has no
# object, which the checker says and skips.
objects() {
	rm -rf "$tmp/build"
	for c in $(cd "$tmp/src" && find . -name '*.c'); do
		mkdir -p "$(dirname "$tmp/build/$c")"
		${CC:-cc} -std=c11 -I"$tmp/src" -c -o "$tmp/build/${c%.c}.o" "$tmp/src/$c" 2>/dev/null
	done
}
# expect pass|fail NAME [PATTERN]: run the checker on the tree; on a failure
# its output must contain PATTERN (the file and line of the offence).
expect() {
	[ -n "${no_objects:-}" ] || objects
	sh "$layers" "$tmp/src" >"$tmp/out" 2>&1
	rc=$?
	if { [ "$1" = pass ] && [ $rc = 0 ]; } ||
		{ [ "$1" = fail ] && [ $rc = 1 ] && grep -qF -- "$3" "$tmp/out"; }; then
		echo "ok $2"
	else
		echo "not ok $2 (exit $rc):"
		sed 's/^/  /' "$tmp/out"
		failed=1
	fi
}

clean
expect pass "a clean tree passes"
printf '#include "util/log.h"\n#include "render/render.h"\n' >"$tmp/src/scene/lod.c"
expect fail "an upward include fails" "src/scene/lod.c:2: #include \"render/render.h\" goes up"
rm "$tmp/src/scene/lod.c"
expect pass "the same tree without it passes again"

clean
printf '#include "content/content.h"\n' >>"$tmp/src/config/settings.h"
expect fail "configuration including content fails" "src/config/settings.h:3: #include \"content/content.h\" goes up"

clean
printf '#include "input/button.h"\n' >>"$tmp/src/display/display.h"
expect fail "an include across peers fails" "src/display/display.h:2: #include \"input/button.h\" goes across"

clean
printf '#include "scene/lod.h"\n' >"$tmp/src/scene/mesh.c"
printf '#include "scene/mesh.h"\n' >"$tmp/src/scene/lod.c"
expect fail "a circle between two files fails" "circle of includes: scene/"

clean
awk 'BEGIN { for (i = 0; i < 701; i++) print "/* line */" }' >"$tmp/src/util/long.c"
expect fail "a file over 700 lines fails" "src/util/long.c:701: 701 lines"

clean
printf '#include "util/log.h"\n' >"$tmp/src/flat.c"
expect fail "a file outside the layer folders fails" "src/flat.c:1: not in a layer folder"

# Calls: a file that calls a function of another, which calls one of its
# own back. Neither includes the other's header (as when both share one
# private header): only the objects show it.
clean
printf 'int lod_level(int n);\nint mesh_size(int n) { return n > 0 ? lod_level(n - 1) : 0; }\n' \
	>"$tmp/src/scene/mesh.c"
printf 'int lod_other(void) { return 1; }\n' >"$tmp/src/scene/lod.c"
expect pass "calls one way pass"
printf 'int mesh_size(int n);\nint lod_level(int n) { return mesh_size(n); }\n' >>"$tmp/src/scene/lod.c"
expect fail "a circle of calls between two files fails" \
	"circle of calls: $tmp/src/scene/lod.c -> $tmp/src/scene/mesh.c (mesh_size) -> $tmp/src/scene/lod.c (lod_level)"

clean
printf 'int b(void);\nint a(void) { return b(); }\n' >"$tmp/src/render/ra.c"
printf 'int c(void);\nint b(void) { return c(); }\n' >"$tmp/src/render/rb.c"
printf 'int a(void);\nint c(void) { return a(); }\n' >"$tmp/src/render/rc.c"
expect fail "a ring of calls through three files fails" \
	"circle of calls: $tmp/src/render/ra.c -> $tmp/src/render/rb.c (b) -> $tmp/src/render/rc.c (c) -> $tmp/src/render/ra.c (a)"
printf 'int c(void) { return 3; }\n' >"$tmp/src/render/rc.c"
expect pass "the ring cut in one place passes"

clean
printf 'int f(void) { return 0; }\n' >"$tmp/src/util/f.c"
rm -rf "$tmp/build"
no_objects=1
expect fail "a tree with no object fails (nothing read is nothing checked)" "no object file in $tmp/build"
no_objects=

exit $failed
