#!/bin/sh
# Every key of the settings table (as tests/tools/mkman lists them) must
# appear in the documented example config/kiosk.ini, set or commented out,
# in its section, and in the generated kiosk.ini(5) under that section;
# and what --help says a reload does with each section must be said, in
# the same words, under that section in both.
#   tests/e2e/config_doc.sh KIOSK MKMAN [INI] [PAGE5]
set -eu
kiosk=$1
mkman=$2
ini=${3:-config/kiosk.ini}
page=${4:-build/man/kiosk.ini.5}
bad=0
keys=$($mkman keys)
[ "$(echo "$keys" | wc -l)" -gt 100 ] || { echo "$mkman keys: too few keys"; exit 1; }
# in_section FILE HEADER PATTERN [LINE]: a line matching the extended
# regular expression PATTERN (or, with LINE, that very line) under HEADER.
# Through the environment: awk -v would take the backslashes as escapes.
in_section() {
	S=$2 P=$3 L=${4:-} awk '
		/^\[/ || /^\.SS / { in_s = ($0 == ENVIRON["S"]) }
		in_s && (ENVIRON["L"] != "" ? $0 == ENVIRON["L"] : $0 ~ ENVIRON["P"]) { found = 1 }
		END { exit !found }' "$1"
}
while read -r section key; do
	if ! in_section "$ini" "[$section]" "^;?$key *="; then
		echo "undocumented in $ini: [$section] $key"
		bad=1
	fi
	if ! in_section "$page" ".SS [$section]" '^\\fB'"$key"'\\fR = '; then
		echo "missing from $page: [$section] $key"
		bad=1
	fi
done <<EOF
$keys
EOF
rules=$($kiosk --help | sed -n 's/^  \[\([a-z]*\)\] *\(.*\)$/\1 \2/p')
[ "$(echo "$rules" | wc -l)" -eq 15 ] || { echo "no reload rule per section in --help"; exit 1; }
while read -r section says; do
	if ! in_section "$ini" "[$section]" "" "; On reload: $says."; then
		echo "$ini: [$section] does not say what --help says a reload does: $says"
		bad=1
	fi
	if ! in_section "$page" ".SS [$section]" "" "On reload: $says."; then
		echo "$page: [$section] does not say what --help says a reload does: $says"
		bad=1
	fi
done <<EOF
$rules
EOF
exit $bad
