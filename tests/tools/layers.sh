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
#   tests/tools/layers.sh [SRC]      (SRC: src by default)
#
# Prints one line per offence, FILE:LINE: what is wrong, and exits 1 when
# there is any (0 when there is none).
set -u
src=${1:-src}
max_lines=700
if [ ! -d "$src" ]; then
	echo "layers.sh: $src: no such folder" >&2
	exit 2
fi
files=$(find "$src" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cc' \) | sort)
if [ -z "$files" ]; then
	echo "layers.sh: $src: no source file" >&2
	exit 2
fi

# shellcheck disable=SC2086 # one word per path; src/ has no blanks in names
awk -v src="$src" -v max_lines="$max_lines" '
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
# Depth-first search; an edge to a module still on the stack closes a ring.
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
	own = (n == 2) ? part[1] : ""
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
	if (split(inc, ipart, "/") != 2) {
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
}' $files
