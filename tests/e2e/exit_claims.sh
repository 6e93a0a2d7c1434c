#!/bin/sh
# What the documents say of the exit status, held to the program's one
# list (src/config/exit_codes.h, as tests/tools/mkman exit-codes prints
# it): every status a document states ("exits 1", "exit status 69",
# "(exit 78)", and the list that follows one: "0 on success, 2 for ...")
# must be one the program returns, and one whose row has the words the
# document uses for that case ("a display that fails" is 69, 75 or 77;
# "busy" is 75). The words of a claim are those after its number, up to
# the next number; where they name no case and the number follows "exit"
# (not a list's), those before it since the last ';'.
#   tests/e2e/exit_claims.sh MKMAN FILE...
# Prints FILE:LINE: what is wrong, for each claim that is, and exits 1 when
# there is any. Code blocks (``` fences) are left out.
set -eu
mkman=$1
shift
table=$($mkman exit-codes)
[ -n "$table" ] || { echo "$mkman exit-codes: no table"; exit 1; }
TABLE=$table awk '
BEGIN {
	n = split(ENVIRON["TABLE"], rows, "\n")
	for (i = 1; i <= n; i++) {
		split(rows[i], f, "\t")
		code[i] = f[1]; name[i] = f[2]; words[i] = f[3]
		known[f[1]] = 1
	}
	rows_n = n
	trig = "[Ee]xit(s|ed)?( (status|code)(es)?)?( (is|of|with|was))? [(]?[0-9]+"
	list = "([,;] (and |or )?|,? (and|or) )[0-9]+"
	bad = 0
}
# The number at the end of a match.
function number_of(m) {
	match(m, /[0-9]+$/)
	return substr(m, RSTART, RLENGTH) + 0
}
# The codes whose words the text uses, " 69 75 77 " ("" when none).
function cases(text,    i, out) {
	text = tolower(text)
	out = ""
	for (i = 1; i <= rows_n; i++)
		if (words[i] != "" && text ~ words[i])
			out = out " " code[i]
	return out == "" ? "" : out " "
}
function judge(num, before, after, file, line,    c, said, cut) {
	if (!(num in known)) {
		printf "%s:%d: exit status %d: the program has no such status (%s)\n",
			file, line, num, "src/config/exit_codes.h"
		bad++
		return
	}
	said = after
	c = cases(after)
	while ((cut = index(before, ";")) > 0)
		before = substr(before, cut + 1)
	if (c == "" && before != "") {
		said = before
		c = cases(before)
	}
	if (c != "" && index(c, " " num " ") == 0) {
		sub(/ $/, "", c)
		printf "%s:%d: exit status %d for \"%s\": the program returns%s for that\n",
			file, line, num, substr(said, 1, 90), c
		bad++
	}
}
# One sentence: each claim in it, in order, with its words.
function sentence(s, file, line,    inlist, k, pos, len, num, ends, starts, nums, i, a, b, t, l, ts, tl, ls, ll, rest, off, trig_at) {
	k = 0
	inlist = 0
	rest = s
	off = 0
	while (1) {
		t = match(rest, trig); ts = RSTART; tl = RLENGTH
		l = inlist ? match(rest, list) : 0; ls = RSTART; ll = RLENGTH
		if (!t && !l)
			break
		k++
		if (t && (!l || ts <= ls)) { pos = ts; len = tl; trig_at[k] = 1 } else { pos = ls; len = ll; trig_at[k] = 0 }
		num = number_of(substr(rest, pos, len))
		nums[k] = num
		starts[k] = off + pos
		ends[k] = off + pos + len
		inlist = 1
		off += pos + len - 1
		rest = substr(rest, pos + len)
	}
	for (i = 1; i <= k; i++) {
		a = i < k ? substr(s, ends[i], starts[i + 1] - ends[i]) : substr(s, ends[i])
		b = i > 1 ? substr(s, ends[i - 1], starts[i] - ends[i - 1]) : substr(s, 1, starts[i] - 1)
		if (!trig_at[i])
			b = ""
		judge(nums[i], b, a, file, line)
	}
}
function paragraph(p, file, line,    n, parts, i) {
	n = split(p, parts, /\. +/)
	for (i = 1; i <= n; i++)
		sentence(parts[i], file, line)
}
FNR == 1 { if (text != "") paragraph(text, prev_file, start); text = ""; fence = 0 }
/^ *```/ { fence = !fence; next }
fence { next }
/^[ \t]*$/ { if (text != "") paragraph(text, FILENAME, start); text = ""; next }
{
	if (text == "") start = FNR
	text = text " " $0
	prev_file = FILENAME
}
END {
	if (text != "") paragraph(text, prev_file, start)
	exit bad > 0
}' "$@"
