#!/bin/sh
# --check-config as a user meets it, and the paths rules and drop-ins it
# reports: each case's output (stdout and stderr, as the user sees them)
# is kept in DIR/NAME.out, and checked for its exit status and its words.
#   config_check.sh KIOSK MODELS DIR
# Prints one "ok NAME" or "not ok NAME" line per step; the last line is
# "ok every step ran" when the scenario got to its end.
set -u
kiosk=$1
case $kiosk in /*) ;; *) kiosk=$PWD/$kiosk ;; esac # the cases run in another folder
models=$2
dir=$3
rm -rf "$dir"
mkdir -p "$dir/etc/kiosk.ini.d" "$dir/srv/mc" "$dir/empty" "$dir/elsewhere"
dir=$(cd "$dir" && pwd)
models=$(cd "$models" && pwd)
cp matcaps/gold.png matcaps/pearl.png "$dir/srv/mc/"
cp "$models/sphere.glb" "$dir/srv/"
mc="--matcap $dir/srv/mc"
# Leaks: see tests/e2e/live.sh (OSMesa's, at unload); nothing here draws,
# but the ASan build is the one under test.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"

# case NAME STATUS PATTERN INI [ARGS...]: --check-config --config INI
# exits STATUS and prints a line matching PATTERN.
case_() {
	name=$1 status=$2 pattern=$3 ini=$4
	shift 4
	(cd "$dir/elsewhere" && "$kiosk" --check-config --config "$ini" "$@") >"$dir/$name.out" 2>&1
	rc=$?
	if [ $rc -eq "$status" ] && grep -q -- "$pattern" "$dir/$name.out"; then
		echo "ok $name (exit $rc)"
	else
		echo "not ok $name (exit $rc, expected $status and '$pattern'):"
		sed 's/^/    /' "$dir/$name.out"
	fi
}
w() { printf "$@"; } # w FORMAT ARGS... >FILE

w '[scene]\nmodel = %s/srv/sphere.glb\n' "$dir" >"$dir/good.ini"
case_ good 0 "good.ini: the settings are valid, and every file they name loads" "$dir/good.ini" $mc
case_ good-lists-origins 0 "model = $dir/srv/sphere.glb ($dir/good.ini:2): loads" "$dir/good.ini" $mc

w '[scene]\nmodel = /srv/kiosk/model.glb\n' >"$dir/missing.ini"
case_ missing-model 66 "missing.ini:2: \[scene\] model = '/srv/kiosk/model.glb': .*cannot open" \
	"$dir/missing.ini" $mc
case_ missing-model-verdict 66 "1 file they name does not load" "$dir/missing.ini" $mc

w '[scene]\nmatcap = /etc/passwd\n' >"$dir/passwd.ini"
case_ passwd-matcap 66 "passwd.ini:2: \[scene\] matcap = '/etc/passwd': .*not a PNG, JPEG or WebP" \
	"$dir/passwd.ini"

w '[scene]\nmodel = "/srv/with spaces.glb"\n' >"$dir/quoted.ini"
case_ quoted-path 78 "quoted.ini:2: \[scene\] model = \"/srv/with spaces.glb\": the quotes would be part" \
	"$dir/quoted.ini" $mc
case_ quoted-path-verdict 78 "quoted.ini: the settings are not valid" "$dir/quoted.ini" $mc

w '[scene]\nmodel = ~/model.glb\n' >"$dir/tilde.ini"
case_ tilde 78 "tilde.ini:2: \[scene\] model = '~/model.glb': '~' is not expanded" "$dir/tilde.ini" $mc

case_ folder-as-config 78 "empty: is a folder, not a settings file" "$dir/empty" $mc

w '[scene]\nmodel = %s/empty\n' "$dir" >"$dir/nomodels.ini"
case_ folder-without-models 66 "nomodels.ini:2: \[scene\] model = '$dir/empty': .*no .gltf or .glb" \
	"$dir/nomodels.ini" $mc

# A model's own NAME.ini: read and said; a key it may not hold refused
# with its file and line (exit 78, a settings error).
mkdir -p "$dir/own"
cp "$models/sphere.glb" "$dir/own/vase.glb"
w '[frame]\nup = +z\nyaw_min = -40\nyaw_max = 40\n' >"$dir/own/vase.ini"
w '[scene]\nmodel = %s/own/vase.glb\n' "$dir" >"$dir/own.ini"
case_ model-settings 0 "read $dir/own/vase.ini (the settings of $dir/own/vase.glb)" "$dir/own.ini" $mc
w '[frame]\nyaw = 10\n\n[kiosk]\nattract_after = 5\n' >"$dir/own/vase.ini"
case_ model-settings-bad-key 78 "vase.ini:5: \[kiosk\] attract_after cannot be set from a model's own file" \
	"$dir/own.ini" $mc
# A hotspot's text[LANG] in the model's own file, against the fonts: an
# Egyptian hieroglyph (no test package's font has it) named with the
# file, the line, the hotspot, the language and the package.
w '[caption]\nlanguages = en de\n[hotspot.mark]\npoint = 0 1 0\ntext = Mark\ntext[de] = Zeichen \360\223\200\200\n' \
	>"$dir/own/vase.ini"
case_ hotspot-text-boxes 78 \
	"vase.ini:6: \[hotspot.mark\] text\[de\]: no installed font has 1 of its characters.*U+13000 .* (fonts-noto-core)" \
	"$dir/own.ini" $mc
w '[caption]\nlanguages = en fr\n[hotspot.mark]\npoint = 0 1 0\ntext = Mark\ntext[de] = Zeichen\n' \
	>"$dir/own/vase.ini"
case_ hotspot-language-not-listed 0 \
	"vase.ini:6: \[hotspot.mark\] text\[de\]: de is not one of \[caption\] languages (en fr): never shown" \
	"$dir/own.ini" $mc

# The animations the settings name, against the model's clips (two in
# BoxAnimated, the first named "open" here): a clip it lacks is a bad
# setting with its file and line and the names there are; the kiosk
# would show the model still, or at a stop go on with the clip playing.
# A still model has nothing to play: a name is no error there.
mkdir -p "$dir/anim"
awk '/"channels": \[/ && !n++ { sub(/"channels"/, "\"name\": \"open\", \"channels\"") } { print }' \
	tests/corpus/khronos/BoxAnimated.gltf >"$dir/anim/box.gltf"
w '[scene]\nmodel = anim/box.gltf\nanimation = nope\n' >"$dir/anim.ini"
case_ animation-missing 78 "anim.ini:3: \[scene\] animation = 'nope': .*no animation \"nope\".*below 2.*\"open\"" \
	"$dir/anim.ini" $mc
case_ animation-missing-verdict 78 "anim.ini: 1 animation named is not in the model" "$dir/anim.ini" $mc
w '[scene]\nmodel = anim/box.gltf\n\n[frame]\nstops = 0 0 1 animation=open; 90 0 1 animation=close; 180 0 1 animation=all\n' \
	>"$dir/stops.ini"
case_ stop-animation-missing 78 "stops.ini:5: \[frame\] stops (stop 2) animation = 'close': .*box.gltf has no such animation, expected .*below 2.*\"open\"" \
	"$dir/stops.ini" $mc
w '[scene]\nmodel = anim/box.gltf\nanimation = 1\n\n[frame]\nstops = 0 0 1 animation=open; 90 0 1 animation=all\n' \
	>"$dir/anim-good.ini"
case_ animations-there 0 "anim-good.ini: the settings are valid" "$dir/anim-good.ini" $mc
# The model loads once as far as the journal tells: the clip's fit builds
# it at each of its samples, and each build said what the model is.
if [ "$(grep -c 'box.gltf: 2 materials' "$dir/animations-there.out")" = 1 ]; then
	echo "ok an animated model's load says what it is once"
else
	echo "not ok an animated model's load says what it is once:"
	sed 's/^/    /' "$dir/animations-there.out"
fi
w '[frame]\nstops = 0 0 1 animation=shut\n' >"$dir/anim/box.ini"
w '[scene]\nmodel = anim/box.gltf\n' >"$dir/anim-own.ini"
case_ stop-animation-missing-own 78 "$dir/anim/box.ini: \[frame\] stops (stop 1) animation = 'shut': .*box.gltf has no such animation" \
	"$dir/anim-own.ini" $mc
rm "$dir/anim/box.ini"
w '[scene]\nmodel = srv/sphere.glb\nanimation = nope\n' >"$dir/anim-still.ini"
case_ animation-on-a-still-model 0 "anim-still.ini: the settings are valid" "$dir/anim-still.ini" $mc

# KHR_materials_variants: a variant the model lacks, in [scene] variant or
# a stop's variant=, is named with its file and line and the model's
# variants (the kiosk would show its own materials, or keep those shown).
cp "$models/variants.gltf" "$dir/srv/"
w '[scene]\nmodel = srv/variants.gltf\nvariant = green\n\n[frame]\nstops = 0 0 1 variant=blue; 90 0 1 variant=teal\n' \
	>"$dir/variants.ini"
case_ variant-missing 78 "variants.ini:3: \[scene\] variant = 'green': .*variants.gltf has no such variant, .*(\"red\", \"blue\")" \
	"$dir/variants.ini" $mc
case_ stop-variant-missing 78 "variants.ini:6: \[frame\] stops (stop 2) variant = 'teal': .*variants.gltf has no such variant" \
	"$dir/variants.ini" $mc
case_ variant-missing-verdict 78 "variants.ini: 2 material variants named are not in the models" "$dir/variants.ini" $mc
w '[scene]\nmodel = srv/variants.gltf\nvariant = blue\n\n[frame]\nstops = 0 0 1 variant=red animation=open\n' \
	>"$dir/variants-good.ini"
case_ variants-there 0 "variants-good.ini: the settings are valid" "$dir/variants-good.ini" $mc

w '[kiosk]\ninclude = typo.ini\n' >"$dir/inc.ini"
w '[scene]\nmodle = x.glb\n' >"$dir/typo.ini"
case_ include-with-errors 78 "typo.ini:2: unknown key 'modle'" "$dir/inc.ini" $mc
case_ include-with-errors-not-valid 78 "inc.ini: the settings are not valid: an included file has errors" \
	"$dir/inc.ini" $mc
step_no_valid() {
	grep -q "not valid" "$dir/include-with-errors.out" && ! grep -q "are valid" "$dir/include-with-errors.out"
}
if step_no_valid; then echo "ok include-with-errors never says valid"; else echo "not ok include-with-errors says valid"; fi

w '[material]\ndetail_map = %s/corrupt.png\n' "$models" >"$dir/map.ini"
case_ broken-map 66 "map.ini:2: \[material\] detail_map = '$models/corrupt.png'" "$dir/map.ini" $mc

w '[display]\nposter = nothere.png\n' >"$dir/poster.ini"
case_ missing-poster 66 "poster.ini:2: \[display\] poster = '$dir/nothere.png'" "$dir/poster.ini" $mc

# Paths: a relative path is read from the file's folder, wherever the
# kiosk runs; an included file's from its own; the command line's from
# the current folder.
w '[scene]\nmodel = srv/sphere.glb\nmatcap = srv/mc\n' >"$dir/rel.ini"
case_ relative-from-the-file 0 "model = $dir/srv/sphere.glb ($dir/rel.ini:2): loads" "$dir/rel.ini"
mkdir -p "$dir/stick"
cp "$models/knot.glb" "$dir/stick/"
w '[scene]\nmodel = knot.glb\n' >"$dir/stick/kiosk.ini"
w '[kiosk]\ninclude = stick/kiosk.ini\n' >"$dir/increl.ini"
case_ relative-in-an-include 0 "model = $dir/stick/knot.glb ($dir/stick/kiosk.ini:2): loads" \
	"$dir/increl.ini" $mc
cp "$models/sphere.glb" "$dir/elsewhere/cwd.glb"
case_ command-line-from-cwd 0 "model = cwd.glb (the command line): loads" "$dir/good.ini" $mc \
	--model cwd.glb

# Every text a visitor reads, in each language (text[de] =), against the
# fonts installed: Japanese is drawn from Noto CJK (make deps-test), so
# valid; an emoji DejaVu lacks and an Egyptian hieroglyph (no font of the
# test packages has either) are each named with their file, line, key,
# language and the package that has them: empty boxes are not valid.
w '[caption]\nlanguages = en ja\ntext = Vase\ntext[ja] = 江戸時代の花瓶\n' >"$dir/japanese.ini"
case_ japanese-caption-valid 0 "japanese.ini: the settings are valid" "$dir/japanese.ini" $mc
w '[caption]\nlanguages = en de\ntext = A vase \360\237\217\272\ntext[de] = Vase \360\223\200\200\n' >"$dir/boxes.ini"
w '[frame]\nstops = 0 0 1 "Front"; 90 0 1 "Sign \342\230\272"\n' >>"$dir/boxes.ini"
case_ emoji-named-with-package 78 \
	"boxes.ini:3: \[caption\] text: no installed font has 1 of its characters.*U+1F3FA .* (fonts-symbola)" \
	"$dir/boxes.ini" $mc
case_ script-named-with-language 78 \
	"boxes.ini:4: \[caption\] text\[de\]: no installed font has 1 of its characters.*U+13000 .* (fonts-noto-core)" \
	"$dir/boxes.ini" $mc
case_ boxes-verdict 78 "boxes.ini: 2 texts would show empty boxes" "$dir/boxes.ini" $mc
w '[caption]\ntext[deutsch] = Vase\n' >"$dir/badlang.ini"
case_ not-a-language-code 78 "badlang.ini:2: \[caption\] text\[deutsch\]: 'deutsch' is not a language code" \
	"$dir/badlang.ini" $mc
w '[caption]\nlanguages = en fr\ntext = Vase\ntext[de] = Vase\n' >"$dir/unlisted.ini"
case_ language-not-listed 0 "unlisted.ini:4: \[caption\] text\[de\]: de is not one of \[caption\] languages (en fr): never shown" \
	"$dir/unlisted.ini" $mc
w '[scene]\nmodel[de] = x.glb\n' >"$dir/untranslatable.ini"
case_ key-not-translatable 78 "untranslatable.ini:2: \[scene\] model\[de\]: only the texts a visitor reads" \
	"$dir/untranslatable.ini" $mc

# Drop-ins: kiosk.ini.d/*.ini in name order after kiosk.ini, a later key
# overriding (a relative path from the drop-in's own folder); other names
# are not read; each value names its file.
w '[scene]\nmodel = nothere.glb\nmode = view\n' >"$dir/etc/kiosk.ini"
w '[scene]\nmodel = ../../srv/knot-missing.glb\n' >"$dir/etc/kiosk.ini.d/10-first.ini"
w '[scene]\nmodel = ../../srv/sphere.glb\n' >"$dir/etc/kiosk.ini.d/20-second.ini"
w '[scene]\nmodel = /nothing.glb\n' >"$dir/etc/kiosk.ini.d/30-off.ini.dpkg-old"
w '[scene]\nmodel = /nothing.glb\n' >"$dir/etc/kiosk.ini.d/.hidden.ini"
case_ dropins-last-wins 0 "model = $dir/etc/kiosk.ini.d/../../srv/sphere.glb ($dir/etc/kiosk.ini.d/20-second.ini:2): loads" \
	"$dir/etc/kiosk.ini" $mc
if sed -n 's/^  read //p' "$dir/dropins-last-wins.out" | tr '\n' ' ' |
	grep -qx "$dir/etc/kiosk.ini $dir/etc/kiosk.ini.d/10-first.ini $dir/etc/kiosk.ini.d/20-second.ini "; then
	echo "ok dropins read in name order, other names left out"
else
	echo "not ok dropins read in name order, other names left out:"
	sed 's/^/    /' "$dir/dropins-last-wins.out"
fi
w '[scene]\nmode = view\nmode = normal\n' >"$dir/etc/kiosk.ini.d/40-dup.ini"
case_ dropin-duplicate-in-one-file 78 "40-dup.ini:3: \[scene\] mode is set again (first on line 2)" \
	"$dir/etc/kiosk.ini" $mc
rm "$dir/etc/kiosk.ini.d/40-dup.ini"
w '[scene]\nmode = sideways\n' >"$dir/etc/kiosk.ini.d/50-bad.ini"
case_ dropin-error-names-its-file 78 "50-bad.ini:2: \[scene\] mode = 'sideways' is not valid" \
	"$dir/etc/kiosk.ini" $mc
echo "ok every step ran"
