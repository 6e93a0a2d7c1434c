#!/bin/sh
# The layers of src/, checked from its #include lines alone. Top to bottom:
#
#   app                          the loop: main, poll(), model switching, reload, signals
#   ops                          operator services: import, status, screen power, systemd
#   content                      the asset pipeline: content, model list and loader, matcap set
#   config                       the settings: one table, options, plain config structs
#   state                        pure decisions: app state, power, schedule
#   display   input   camera     (peers: none of the three includes another)
#   render
#   scene
#   util
#
# A file may include a header of its own layer or of a lower one; an
# include that goes up, or across to a peer, is how a lower module starts
# to know about the program around it. Also refused: a circle of includes
# between modules (x/a.c and x/a.h are module x/a; a includes b.h and b
# includes a.h, or a longer ring), a file outside the layer folders, and a
# source file over 700 lines (past that a file is no longer read as one
# piece).
#
# Also refused: a circle of calls between files. a.c calls a function (or
# reads a variable) that b.c defines while b.c calls one of a.c's, or a
# longer ring: the files are one piece that was cut in two, and neither can
# be read, tested or changed alone. Includes cannot show it (a file split
# for length often shares one private header), so the calls are read from
# the object files that make builds: each undefined symbol of a.o is
# resolved to the object that defines it (nm). A source with no object is
# named and skipped (gpio_v1.c or gpio_v2.c: one API is built); a tree with
# no object at all fails, as a checker that read nothing would pass.
#
#   tests/tools/layers.sh [SRC [OBJ]]   (SRC: src; OBJ: the build folder
#                                       beside SRC, build/ for src/)
#
# Prints one line per offence, FILE:LINE: what is wrong, and exits 1 when
# there is any (0 when there is none).
set -u
src=${1:-src}
obj=${2:-$(dirname "$src")/build}
obj=${obj#./}
max_lines=700
if [ ! -d "$src" ]; then
	echo "layers.sh: $src: no such folder" >&2
	exit 2
fi
# Depth-first search over adj[] for both graphs below (includes, calls);
# an edge to a node still on the stack closes a ring, which each awk
# program reports with its own ring(u, v).
dfs='
function visit(u,    list, n, i, v) {
	color[u] = 1
	stack[++depth] = u
	n = split(adj[u], list, " ")
	for (i = 1; i <= n; i++) {
		v = list[i]
		if (color[v] == 1)
			ring(u, v)
		else if (!color[v])
			visit(v)
	}
	depth--
	color[u] = 2
}'
files=$(find "$src" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cc' \) | sort)
if [ -z "$files" ]; then
	echo "layers.sh: $src: no source file" >&2
	exit 2
fi

includes_ok=0
# shellcheck disable=SC2086 # one word per path; src/ has no blanks in names
awk -v src="$src" -v max_lines="$max_lines" "$dfs"'
BEGIN {
	rank["app"] = 0
	rank["ops"] = 1
	rank["content"] = 2
	rank["config"] = 3
	rank["state"] = 4
	rank["display"] = 5; rank["input"] = 5; rank["camera"] = 5
	rank["render"] = 6
	rank["scene"] = 7
	rank["util"] = 8
	bad = 0
}
function offence(where, what) {
	print where ": " what
	bad++
}
function too_long(file, lines) {
	if (lines > max_lines)
		offence(file ":" lines, lines " lines, more than " max_lines)
}
function ring(u, v,    i, path) {
	for (i = depth; stack[i] != v; i--)
		;
	path = ""
	for (; i <= depth; i++)
		path = path stack[i] " -> "
	offence(eloc[u, v], "circle of includes: " path v)
}
FNR == 1 {
	if (file != "")
		too_long(file, lines)
	file = FILENAME
	rel = substr(file, length(src) + 2)
	n = split(rel, part, "/")
	# A layer may hold folders of its own (scene/gltf, scene/mesh ...).
	own = (n == 2 || n == 3) ? part[1] : ""
	module = rel
	sub(/\.(c|cc|h)$/, "", module)
	if (!(own in rank))
		offence(file ":1", "not in a layer folder (app, ops, content, config, state, display, input, camera, render, scene, util)")
}
{ lines = FNR }
/^[ \t]*#[ \t]*include[ \t]*"/ {
	inc = $0
	sub(/^[^"]*"/, "", inc)
	sub(/".*/, "", inc)
	ni = split(inc, ipart, "/")
	if (ni != 2 && ni != 3) {
		offence(file ":" FNR, "#include \"" inc "\" names no layer folder (write \"layer/file.h\")")
		next
	}
	to = ipart[1]
	if (!(to in rank)) {
		offence(file ":" FNR, "#include \"" inc "\": " to " is not a layer")
		next
	}
	if (own in rank) {
		if (rank[to] < rank[own])
			offence(file ":" FNR, "#include \"" inc "\" goes up, from " own " to " to)
		else if (rank[to] == rank[own] && to != own)
			offence(file ":" FNR, "#include \"" inc "\" goes across, from " own " to its peer " to)
	}
	target = inc
	sub(/\.h$/, "", target)
	if (target != module && !((module, target) in eloc)) {
		eloc[module, target] = file ":" FNR
		adj[module] = adj[module] " " target
		if (!(module in seen)) {
			seen[module] = 1
			order[++modules] = module
		}
	}
}
END {
	if (file != "")
		too_long(file, lines)
	for (m = 1; m <= modules; m++)
		if (!color[order[m]])
			visit(order[m])
	exit (bad > 0)
}' $files || includes_ok=1


# The call graph: "MAP OBJECT SOURCE" for each source built, then nm's
# portable listing of those objects ("OBJECT: SYMBOL TYPE ...").
objects=""
map=""
for f in $files; do
	case $f in *.h) continue ;; esac
	o=$obj/${f#"$src"/}
	o=${o%.*}.o
	if [ ! -f "$o" ]; then
		echo "layers.sh: $f: no object $o, its calls not checked" >&2
		continue
	fi
	objects="$objects $o"
	map="$map
MAP $o $f"
done
if [ -z "$objects" ]; then
	echo "$src: no object file in $obj: the calls between files cannot be checked (run make first)"
	exit 1
fi
# shellcheck disable=SC2086 # one word per path
circles=$({
	printf '%s\n' "$map"
	nm -A -P $objects
} | awk "$dfs"'
$1 == "MAP" { name[$2] = $3; order[++files] = $2; next }
{
	o = $1
	sub(/:$/, "", o)
	if ($3 == "U")
		used[++uses] = o SUBSEP $2
	else if ($3 ~ /^[TDBRC]$/) {
		# Defined twice (two programs in one tree): no edge.
		if (($2 in def) && def[$2] != o)
			twice[$2] = 1
		def[$2] = o
	}
}
# Each edge is named by one symbol it uses: where to start cutting.
function ring(u, v,    i, path) {
	for (i = depth; stack[i] != v; i--)
		;
	path = name[v]
	for (; i < depth; i++)
		path = path " -> " name[stack[i + 1]] " (" via[stack[i], stack[i + 1]] ")"
	print name[u] ": circle of calls: " path " -> " name[v] " (" via[u, v] ")"
	bad++
}
END {
	for (k = 1; k <= uses; k++) {
		split(used[k], p, SUBSEP)
		to = def[p[2]]
		if (to == "" || (p[2] in twice) || to == p[1] || ((p[1], to) in via))
			continue
		via[p[1], to] = p[2]
		adj[p[1]] = adj[p[1]] " " to
	}
	for (m = 1; m <= files; m++)
		if (!color[order[m]])
			visit(order[m])
	exit (bad > 0)
}')
calls_ok=$?
# C++ symbols as written in the source.
[ -z "$circles" ] || printf '%s\n' "$circles" | c++filt
[ $includes_ok = 0 ] && [ $calls_ok = 0 ]
