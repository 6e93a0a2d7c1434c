#!/bin/sh
# Every ```ini block of the given Markdown files, read by the kiosk as a
# settings file: none may hold a line the reader takes otherwise than it
# reads (a ' ;' after a value is part of the value, not a comment). The
# files a block names need not exist here: only the reader's warnings
# about the lines themselves count. One line per offending block.
#   ini_claims.sh KIOSK FILE.md...
set -u
kiosk=$1
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0
for doc in "$@"; do
	awk -v dir="$tmp" -v doc="$(basename "$doc")" '
		/^```ini$/ { n++; f = sprintf("%s/%s-%d.ini", dir, doc, n); start = NR; next }
		/^```/ && f { close(f); print f, start; f = ""; next }
		f { print >f }' "$doc" >"$tmp/blocks"
	while read -r f line; do
		"$kiosk" --check-config --config "$f" >"$f.log" 2>&1
		if grep -q "is part of the value now" "$f.log"; then
			echo "$doc:$line: an ini block the reader takes otherwise:"
			grep "is part of the value now" "$f.log"
			bad=1
		fi
	done <"$tmp/blocks"
done
exit $bad
