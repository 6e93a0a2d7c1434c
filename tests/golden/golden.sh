#!/bin/sh
# The golden scenes, rendered through OSMesa into DIR as SCENE.png: every
# mode on the built-in torus knot and on a sphere, then the material
# features. Used by `make golden` (into tests/golden), by tests/run.sh (into
# a scratch folder, then compared) and by `make check T=SCENE` (one scene).
#   golden.sh DIR [SCENE]...       (every scene when none is named)
# Environment: KIOSK, TOOLS (mkmodels), MODELS (where the models go).
set -eu
# The offscreen backend: osmesa, or egl-headless where Mesa has no OSMesa
# (the Makefile sets OFFSCREEN_BACKEND from what the build has).
offscreen=${OFFSCREEN_BACKEND:-osmesa}
out=$1
shift
models=${MODELS:-tests/out/models}
scenes="knot-normal knot-view knot-sem-vertex knot-sem-fragment"
scenes="$scenes sphere-normal sphere-view sphere-sem-vertex sphere-sem-fragment"
scenes="$scenes knot-iridescence knot-iridescence-ramp knot-detail-map sphere-detail-gltf"
scenes="$scenes sphere-beetle-gltf sphere-displaced sphere-lit sphere-lit-beside"
scenes="$scenes sphere-vertex-color sphere-base-map sphere-base-map-off"
scenes="$scenes background-color background-gradient background-image fit-long fit-long-half"
scenes="$scenes fit-above-caption preview-stop-2"
scenes="$scenes parts-textures parts-mask parts-blend parts-leaf parts-normals parts-iridescence"
scenes="$scenes parts-unlit parts-unlit-shade parts-emissive parts-emissive-sem-vertex parts-specgloss"
scenes="$scenes parts-emissive-uv1"
scenes="$scenes variant-blue first-coloured first-uncoloured"
scenes="$scenes caption-latin caption-rtl caption-logo caption-wrap caption-de caption-ja"
scenes="$scenes frame-up frame-start-view frame-own-look"
scenes="$scenes render-scale-half normals-flat normals-smooth"
scenes="$scenes morph-t1 morph-t3 morph-pingpong skin-t1 nodes-t1.7"
scenes="$scenes hotspots-yaw0 hotspots-yaw180 hotspot-stop"
scenes="$scenes wall-2x2 outputs-mirror outputs-slice"
mkdir -p "$out" "$models"
"$TOOLS/mkmodels" "$models" >/dev/null

# hot_ini FILE: the three hotspots of the hotspot scenes.
hot_ini() {
	printf '%s\n' '[hotspot.rim]' 'point = 2 0 0.866' 'normal = 0.125 0 0.866' \
		'look = badge' 'color = #ffcc00' 'text = The rim' \
		'[hotspot.glaze]' 'point = -2 0.5 0.707' 'look = badge' 'color = #40c0ff' \
		'text = The glaze, a point without a normal' \
		'[hotspot.foot]' 'point = 0 0 -1' 'normal = 0 0 -1' 'look = badge' \
		'color = #ff4060' 'text = The foot' >"$1"
}

# render SCENE: one scene into DIR/SCENE.png.
render() {
	k="$KIOSK -q --backend $offscreen --size 320x240"
	m=$models
	o=$out/$1.png
	case $1 in
	knot-normal | knot-view | knot-sem-vertex | knot-sem-fragment)
		$k --matcap matcaps/gold.png --mode "${1#knot-}" --output "$o"
		;;
	sphere-normal | sphere-view | sphere-sem-vertex | sphere-sem-fragment)
		$k --matcap matcaps/gold.png --mode "${1#sphere-}" --model "$m/sphere.glb" --output "$o"
		;;
	# The material features, each on a model that exercises it: glTF
	# textures (embedded; beside the model with TANGENT and
	# KHR_materials_iridescence), the settings' maps, displacement, lit.
	# The first two show those features alone, without the material's
	# baseColorFactor (the base colour scenes below show it).
	knot-iridescence)
		$k -c matcaps/black-shiny.png --iridescence on --output "$o"
		;;
	knot-iridescence-ramp)
		$k -c matcaps/black-shiny.png --iridescence on --iridescence-ramp "$m/ramp.png" \
			--output "$o"
		;;
	knot-detail-map)
		$k -c matcaps/pearl.png --detail-map "$m/detail.png" --iridescence on --output "$o"
		;;
	sphere-detail-gltf)
		$k -c matcaps/gold.png --model "$m/sphere-detail.glb" --base-color off --output "$o"
		;;
	sphere-beetle-gltf)
		$k -c matcaps/black-shiny.png --model "$m/sphere-beetle.gltf" --base-color off \
			--output "$o"
		;;
	sphere-displaced)
		$k -c matcaps/gold.png --model "$m/sphere-coarse.glb" --displacement-map "$m/height.png" \
			--displacement-scale 0.15 --output "$o"
		;;
	sphere-lit)
		$k --model "$m/sphere-detail.glb" --lit on --output "$o"
		;;
	sphere-lit-beside)
		$k -c matcaps/chrome-studio.png --model "$m/sphere-coarse.glb" \
			--displacement-map "$m/height.png" --displacement-scale 0.15 \
			--detail-map "$m/detail.png" --lit beside --output "$o"
		;;
	# The glTF base colour times the matcap: COLOR_0 alone; a base map
	# with a factor and a texture transform; the same with it off.
	sphere-vertex-color)
		$k -c matcaps/pearl.png --model "$m/sphere-vertex-color.glb" --output "$o"
		;;
	sphere-base-map)
		$k -c matcaps/pearl.png --model "$m/sphere-base-map.glb" --output "$o"
		;;
	sphere-base-map-off)
		$k -c matcaps/pearl.png --model "$m/sphere-base-map.glb" --base-color off --output "$o"
		;;
	# [display] background and [scene] fit: a colour (the clear alone), a
	# gradient and an image (wider than the frame: cropped left and right,
	# its top and bottom borders showing), and a long model filling 0.85
	# (the default) and 0.5 of the frame's width.
	background-color)
		$k -c matcaps/gold.png --background '#203a5c' --output "$o"
		;;
	background-gradient)
		$k -c matcaps/gold.png --background '#f2ead8, #5a4a3a' --output "$o"
		;;
	background-image)
		$k -c matcaps/gold.png --background "$m/backdrop.png" --output "$o"
		;;
	fit-long)
		$k -c matcaps/gold.png --model "$m/long.glb" --output "$o"
		;;
	fit-long-half)
		$k -c matcaps/gold.png --model "$m/long.glb" --fit 0.5 --output "$o"
		;;
	# The fit in the room a caption leaves (issue 33): a lopsided model
	# (a body and a tall fin at one end) centred by its outline at the
	# start view above a caption at the bottom, not behind it.
	# --stop 2 (issue 33): the still of the second of three stops, its
	# view (yaw 90, pitch 10, zoom 1.2) and its text for the caption, as
	# the kiosk shows it after a visitor's two next-stop presses.
	preview-stop-2)
		$k -c matcaps/gold.png --model "$m/lopsided.glb" --caption Lopsided \
			--stops '0 0 1 "Front"; 90 10 1.2 "The fin"; 200 -10 0.9 "Behind"' \
			--stop 2 --output "$o"
		;;
	fit-above-caption)
		$k -c matcaps/gold.png --model "$m/lopsided.glb" --caption "A lopsided model" \
			--caption-position bottom --output "$o"
		;;
	# [frame] from the model's own NAME.ini: the long model stood on its
	# end (up = +x, then a quarter roll), framed as turned (the fit
	# fills the height); and a start view of yaw, pitch and zoom.
	frame-up)
		cp "$m/long.glb" "$m/long-up.glb"
		printf '[frame]\nup = +x\norientation = 0 0 30\n' >"$m/long-up.ini"
		$k -c matcaps/gold.png --model "$m/long-up.glb" --output "$o"
		;;
	# [scene] matcap and [display] background from the model's own
	# NAME.ini, over kiosk.ini's: the pearl matcap on a blue grey, not
	# the gold one on the default grey. (Over kiosk.ini, not the command
	# line: the command line goes over NAME.ini, test_precedence.)
	frame-own-look)
		cp "$m/long.glb" "$m/long-look.glb"
		printf '[scene]\nmatcap = %s/matcaps/pearl.png\n[display]\nbackground = #304050\n' \
			"$PWD" >"$m/long-look.ini"
		printf '[scene]\nmatcap = %s/matcaps/gold.png\n' "$PWD" >"$m/look-kiosk.ini"
		$k --config "$m/look-kiosk.ini" --model "$m/long-look.glb" --output "$o"
		;;
	frame-start-view)
		$k -c matcaps/gold.png --model "$m/long.glb" --start-yaw 60 --start-pitch 45 \
			--start-zoom 0.7 --output "$o"
		;;
	# Several materials (tests/tools/parts_models.c): two halves each
	# with its own base map; a label cut by alpha MASK in front of a
	# body; two BLEND panes in front of an opaque body, the nearer over
	# the farther; a leaf seen from its hollow, shown by doubleSided;
	# two halves each with its own normal map (bumps above, smooth
	# below); two halves each with its own iridescent film.
	parts-textures | parts-mask | parts-blend | parts-leaf | parts-normals | parts-iridescence)
		$k -c matcaps/pearl.png --model "$m/$1.glb" --output "$o"
		;;
	# Issue 37: an unlit scan's top beside a shaded bottom (and shaded
	# anyway, [material] unlit = shade); a label glowing by its
	# emissive map on TEXCOORD_1 (in the default mode and sem-vertex); a
	# spec-gloss material's diffuse as its base colour.
	# parts-emissive-uv1: its base map on TEXCOORD_0, its emissive
	# label on TEXCOORD_1 (the mesh's second set), its band upright.
	parts-unlit | parts-emissive | parts-specgloss | parts-emissive-uv1)
		$k -c matcaps/gold.png --model "$m/$1.glb" --output "$o"
		;;
	parts-unlit-shade)
		$k -c matcaps/gold.png --model "$m/parts-unlit.glb" --unlit shade --output "$o"
		;;
	parts-emissive-sem-vertex)
		$k -c matcaps/gold.png --model "$m/parts-emissive.glb" --mode sem-vertex --output "$o"
		;;
	# KHR_materials_variants: the cube's "blue" variant (its default is red;
	# blue is a material only the variant uses).
	variant-blue)
		$k -c matcaps/pearl.png --model "$m/variants.gltf" --variant blue --output "$o"
		;;
	# The first picture with the defaults (no matcap named: the shipped
	# folder, matcap_first = auto): a model with colours of its own on
	# pearl, in its colours; one without on gold.
	first-coloured)
		$k --model "$m/sphere-base-map.glb" --output "$o"
		;;
	first-uncoloured)
		$k --model "$m/sphere.glb" --output "$o"
		;;
	# [caption]: Latin with kerning (AV, Te) and a ligature (fi) in two
	# lines; Hebrew (its brackets mirrored, a number left to right
	# inside) and Arabic (its letters joined) read right to left, top
	# right, in colour on a tinted box; a logo (blended by its alpha)
	# beside a line, centred at the bottom, no box.
	caption-latin)
		$k -c matcaps/gold.png --caption-size 16 \
			--caption 'AVATAR Te fine office\nLent by the city museum' --output "$o"
		;;
	caption-rtl)
		$k -c matcaps/gold.png --caption-size 16 --caption-position top-right \
			--caption-color '#ffe8a0' --caption-box '#30206080' \
			--caption 'כד עתיק (מאה 5)\nمزهرية أثرية' --output "$o"
		;;
	# A label longer than the frame is wide: wrapped between words
	# (UAX #14) into three lines, the box as high as they are.
	caption-wrap)
		$k -c matcaps/gold.png --caption-size 16 \
			--caption 'A museum label that is long enough to wrap over three lines at this width, by words' \
			--output "$o"
		;;
	# One label in three languages (text[de] =, text[ja] =), each drawn
	# by --lang; the Japanese from Noto Sans CJK, the fallback fontconfig
	# finds for what DejaVu lacks (fonts-noto-cjk, make deps-test), and
	# wrapped between its characters.
	caption-de | caption-ja)
		cat >"$m/languages.ini" <<-'EOF'
			[caption]
			size = 16
			languages = en de ja
			text = A vase with a painted signature, lent by the city museum
			text[de] = Vase mit gemalter Signatur, Leihgabe des Stadtmuseums Köln – Straße
			text[ja] = 江戸時代の伊万里焼の花瓶。有田で焼かれ、長崎からヨーロッパへ渡った。
		EOF
		$k -c matcaps/gold.png --config "$m/languages.ini" --lang "${1#caption-}" --output "$o"
		;;
	caption-logo)
		$k -c matcaps/gold.png --caption-size 16 --caption-position bottom --caption-box none \
			--logo "$m/logo.png" --caption 'Matcap & Co.' --output "$o"
		;;
	# Poses of Khronos's SimpleMorph (two targets, weights keyed each
	# second over 4 s) at fixed times: --time on its one clip; pingpong
	# at 5 s plays back to the pose at 3 s.
	morph-t1 | morph-t3)
		$k -c matcaps/gold.png --model tests/corpus/khronos/SimpleMorph.gltf \
			--time "${1#morph-t}" --output "$o"
		;;
	morph-pingpong)
		$k -c matcaps/gold.png --model tests/corpus/khronos/SimpleMorph.gltf \
			--time 5 --loop pingpong --output "$o"
		;;
	# A skin (RiggedSimple: two joints bend a cylinder) and node
	# animation of a rigid part (BoxAnimated: the inner box turns from
	# 1.25 s), as three.js's AnimationMixer poses them (tests/README).
	skin-t1)
		$k -c matcaps/pearl.png --model tests/corpus/khronos/RiggedSimple.gltf \
			--time 1 --output "$o"
		;;
	nodes-t1.7)
		$k -c matcaps/pearl.png --model tests/corpus/khronos/BoxAnimated.gltf \
			--time 1.7 --output "$o"
		;;
	# [display] render_scale 0.5: the knot drawn at 160x120 and scaled
	# up by the GL pass (render/render_scale.c), filtered linearly.
	normals-flat) # the default: flat where the file gives no normals
		$k -c matcaps/pearl.png --model "$m/cube-nonormals.glb" --output "$o"
		;;
	normals-smooth)
		$k -c matcaps/pearl.png --model "$m/cube-nonormals.glb" --normals smooth --output "$o"
		;;
	render-scale-half)
		$k -c matcaps/gold.png --render-scale 0.5 --output "$o"
		;;
	# Issue 33: three hotspots on the long model (its own NAME.ini; the
	# file's coordinates, off the unit sphere: the fit moves them too).
	# At yaw 0 badges 1 (the rim, with a normal) and 2 (the glaze, no
	# normal) in front, 3 (the foot, on the back) hidden; at yaw 180 3
	# in front, 1 and 2 behind: 2 hidden by the model's depth alone. The
	# stop at hotspot 2: the model turned so its point faces the visitor,
	# its text beside the badge (too wide for either side: below it).
	hotspots-yaw0 | hotspots-yaw180 | hotspot-stop)
		hot_ini "$m/long-hot.ini"
		cp "$m/long.glb" "$m/long-hot.glb"
		case $1 in
		hotspot-stop) view="--hotspot 2" ;;
		*) view="--start-yaw ${1#hotspots-yaw}" ;;
		esac
		# shellcheck disable=SC2086 # two words
		$k -c matcaps/gold.png --model "$m/long-hot.glb" $view --caption-size 14 --output "$o"
		;;
	# [wall]: a wall of 2x2 screens of 160x120 mm at 1 px a mm, with 8 mm
	# of frame between two pictures, each screen's slice drawn by its own
	# process, stitched with the bezels black (tests/tools/stitch): the
	# long model crosses every border as one object, shifted by the gaps.
	wall-2x2)
		for p in 1,1 2,1 1,2 2,2; do
			$k -c matcaps/gold.png --model "$m/long.glb" --start-yaw 35 --size 160x120 \
				--wall-columns 2 --wall-rows 2 --wall-position $p --wall-bezel 8 \
				--wall-screen-size 160x120 --output "$out/wall-2x2-$p.png"
		done
		"$TOOLS/stitch" "$o" 2 2 8 8 "$out/wall-2x2-1,1.png" "$out/wall-2x2-2,1.png" \
			"$out/wall-2x2-1,2.png" "$out/wall-2x2-2,2.png"
		rm -f "$out"/wall-2x2-?,?.png
		;;
	# Issue 36: two outputs of one board, each still drawn as that output
	# shows it (--as-output), side by side. outputs-mirror: the front
	# (the same view, the caption) and the back of a vitrine (mirror:
	# turned 180 degrees about the vertical, after the start view's
	# tilt; no caption, its own background). outputs-slice: two outputs
	# as the two halves of a [wall] of 2x1, which join into one picture.
	# The whole mesh (--lod-pixels 0): what is tested is each output's
	# view, not meshoptimizer's version (Debian 13's simplifies otherwise).
	outputs-mirror | outputs-slice)
		ini=$out/$1.ini
		case $1 in
		outputs-mirror)
			printf '%s\n' '[display]' 'outputs = HDMI-A-1, HDMI-A-2' '[caption]' \
				'text = The front' 'size = 10' '[output.HDMI-A-2]' 'view = mirror' 'caption = no' \
				'background = #203040' >"$ini" ;;
		outputs-slice)
			printf '%s\n' '[display]' 'outputs = HDMI-A-1, HDMI-A-2' '[wall]' \
				'columns = 2' 'rows = 1' '[output.HDMI-A-1]' 'view = slice' \
				'position = 1,1' '[output.HDMI-A-2]' 'view = slice' 'position = 2,1' \
				>"$ini" ;;
		esac
		for n in 1 2; do
			$k --config "$ini" -c matcaps/gold.png --model "$m/long.glb" --start-yaw 35 \
				--size 160x120 --lod-pixels 0 --as-output HDMI-A-$n \
				--output "$out/$1-$n.png"
		done
		"$TOOLS/stitch" "$o" 2 1 0 0 "$out/$1-1.png" "$out/$1-2.png"
		rm -f "$out/$1-1.png" "$out/$1-2.png" "$ini"
		;;
	*)
		echo "golden.sh: no scene named $1 (scenes: $scenes)" >&2
		exit 2
		;;
	esac
}

# shellcheck disable=SC2086 # one word per scene
[ $# -gt 0 ] || set -- $scenes
for scene in "$@"; do
	render "$scene"
done
