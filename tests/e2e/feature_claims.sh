#!/bin/sh
# What the documents say the loader ignores, held to the loader's one
# table (src/scene/gltf/gltf_features.c, as tests/tools/mkman
# gltf-features prints it): a clause that says "ignored" (or "ignores")
# must not name a feature the loader uses ("animations are ignored, the
# model is shown still" while the first clip plays). A clause is a
# paragraph's text up to a '.', ';', '!' or '?', a table's row as a
# whole (its cells: "| KHR_materials_variants | ignored |"); code blocks
# (``` fences) are left out.
#   tests/e2e/feature_claims.sh MKMAN FILE...
# Prints FILE:LINE: what is wrong, for each clause that is, and exits 1
# when there is any.
set -eu
mkman=$1
shift
table=$($mkman gltf-features)
[ -n "$table" ] || { echo "$mkman gltf-features: no table"; exit 1; }
TABLE=$table awk '
BEGIN {
	n = split(ENVIRON["TABLE"], rows, "\n")
	used_n = 0
	for (i = 1; i <= n; i++) {
		split(rows[i], f, "\t")
		if (f[1] != "used")
			continue
		used_n++
		name[used_n] = f[2]
		words[used_n] = f[3]
		ext[used_n] = f[4] == "-" ? "" : tolower(f[4])
	}
	bad = 0
}
function judge(text, file, line,    c, k, clause, lc) {
	c = split(text, clauses, /[.;!?]( |$)/)
	for (k = 1; k <= c; k++) {
		lc = tolower(clauses[k])
		if (lc !~ /ignor/)
			continue
		for (i = 1; i <= used_n; i++)
			if (lc ~ words[i] || (ext[i] != "" && index(lc, ext[i]))) {
				printf "%s:%d: says ignored of %s, which the loader uses " \
					"(src/scene/gltf/gltf_features.c): \"%s\"\n",
					file, line, name[i], clauses[k]
				bad++
			}
	}
}
FNR == 1 { if (para != "") judge(para, pfile, pline); para = ""; fence = 0 }
/^```/ { fence = !fence; next }
fence { next }
/^[ \t]*$/ { if (para != "") judge(para, FILENAME, pline); para = ""; next }
/^[ \t]*[|]/ {
	if (para != "") judge(para, FILENAME, pline)
	para = ""
	row = $0
	gsub(/[|]/, " ", row)
	judge(row, FILENAME, FNR)
	next
}
{
	if (para == "") { pline = FNR; pfile = FILENAME }
	para = para " " $0
}
END {
	if (para != "") judge(para, pfile, pline)
	exit bad > 0
}' "$@"
