#!/bin/sh
# Speed against error for [scene] normals: the bench's torus knots with
# their normals stripped (as a CAD or STL conversion has them), drawn with
# flat normals (file, the default: glTF's rule) and smooth ones (the old
# averaging). The split gives each triangle three vertices of its own: the
# rows say how many vertices that adds, before and after the level of
# detail, and what a frame costs (the median and 90th percentile of FRAMES
# frames, each finished with glFinish, in ROUNDS rounds alternating the
# two). No error column: flat is what the file asks for, smooth is another
# picture (tests/golden/normals-flat.png, normals-smooth.png). Printed as
# markdown, never asserted; bench_quality.sh appends it to
# tests/bench/report/speed-error.md.
#   sh tests/bench/bench_normals.sh [SIZE]   Environment: KIOSK, TOOLS, FRAMES, ROUNDS.
set -eu
size=${1:-1920x1080}
frames=${FRAMES:-10}
rounds=${ROUNDS:-3}
backend=${BACKEND:-osmesa}
out=tests/out/bench-normals
mkdir -p "$out"
"$TOOLS/mkmodels" "$out" --bench >/dev/null
# A cache of its own: the counts come from a load, never from an entry.
XDG_CACHE_HOME=$PWD/$out/cache # absolute: XDG ignores a relative one
export XDG_CACHE_HOME

# row MODEL: one row per [scene] normals.
row() {
	model=$out/$1
	k="$KIOSK --backend $backend --size $size --matcap matcaps/gold.png --model $model"
	: >"$out/times"
	for r in $(seq "$rounds"); do
		for n in file smooth; do
			echo "$n $($k -q --normals $n --frames "$frames" --stats)" >>"$out/times"
		done
	done
	for n in file smooth; do
		rm -rf "$XDG_CACHE_HOME"
		# The vertices loaded (lod_pixels 0: every one drawn), then drawn
		# after the level of detail at its default.
		loaded=$($k --normals $n --lod-pixels 0 --output "$out/frame.png" 2>&1 |
			sed -n 's/.*: \([0-9]*\) vertices, \([0-9]*\) triangles$/\1 | \2/p')
		# The first frame from a cold start (no cache entry): the program
		# started, the file read and prepared, the frame written.
		rm -rf "$XDG_CACHE_HOME"
		t0=$(date +%s%N)
		$k -q --normals $n --output "$out/frame.png"
		first=$((($(date +%s%N) - t0) / 1000000))
		rm -rf "$XDG_CACHE_HOME"
		drawn=$($k --log-level debug --normals $n --output "$out/frame.png" 2>&1 | sed -n \
			-e 's/.*lod: [0-9]* -> \([0-9]*\) triangles for .*, [0-9]* -> \([0-9]*\) vertices$/\2 | \1/p' \
			-e 's/.*lod: \([0-9]*\) triangles kept for .*, \([0-9]*\) vertices$/\2 | \1/p')
		median=$(awk -v n=$n '$1 == n { print $5 }' "$out/times" | sort -n |
			awk '{ m[NR] = $1 } END { printf "%.1f", m[int((NR + 1) / 2)] }')
		p90=$(awk -v n=$n '$1 == n && $7 > p { p = $7 } END { printf "%.1f", p }' "$out/times")
		label=$n
		[ $n = file ] && label="file (flat)"
		printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$1" "$label" "$loaded" "$drawn" "$first" \
			"$median" "$p90"
	done
}

cat <<EOT
## Flat normals ([scene] normals)

A primitive without normals is split at its faces (src/scene/gltf_flat.cc): three
vertices a triangle, each with its face's normal. The bench knots without normals,
drawn at $size with the default lod_pixels (4), flat (file) against smooth (the old
averaging): vertices and triangles as loaded, then as drawn after the level of detail
(which keeps flat triangles flat: src/scene/mesh/lod.c keep_flat), and the time of a frame
in ms (median of the rounds' medians of $frames frames, largest 90th percentile, the
first frame counted; $backend), after the first frame of a cold start (no cache
entry: started, read, prepared, drawn and written, in ms). Compare the rows of one
model with each other.

| model | normals | vertices loaded | triangles | vertices drawn | triangles drawn | first frame, cold | median ms | p90 ms |
|---|---|---|---|---|---|---|---|---|
EOT
row knot-10k-nonormals.glb
row knot-100k-nonormals.glb
