#!/bin/sh
# Every key the program accepts in the config file (as --help lists them)
# must appear in config/kiosk.ini, set or commented out, in its section;
# and what --help says a reload does with each section must be said, in
# the same words, under that section in kiosk.ini and in the README.
set -eu
kiosk=$1
ini=${2:-config/kiosk.ini}
readme=${3:-README.md}
missing=0
keys=$($kiosk --help | sed -n 's/.*\[\([a-z]*\)\] \([a-z_]*\) in the config file.*/\1 \2/p')
[ -n "$keys" ] || { echo "no keys found in --help"; exit 1; }
echo "$keys" | while read -r section key; do
	if ! awk -v s="[$section]" -v k="$key" '
		/^\[/ { in_s = ($0 == s) }
		in_s && ($0 ~ "^;?" k " *=") { found = 1 }
		END { exit !found }' "$ini"; then
		echo "undocumented in $ini: [$section] $key"
		exit 1
	fi
done
rules=$($kiosk --help | sed -n 's/^  \[\([a-z]*\)\] *\(.*\)$/\1 \2/p')
[ "$(echo "$rules" | wc -l)" -eq 12 ] || { echo "no reload rule per section in --help"; exit 1; }
echo "$rules" | while read -r section says; do
	if ! awk -v s="[$section]" -v line="; On reload: $says." '
		/^\[/ { in_s = ($0 == s) }
		in_s && $0 == line { found = 1 }
		END { exit !found }' "$ini"; then
		echo "$ini: [$section] does not say what --help says a reload does: $says"
		exit 1
	fi
	if ! grep -qF "[$section]" "$readme" || ! grep -qF "$says" "$readme"; then
		echo "$readme: the reload rule of [$section] is not as --help says: $says"
		exit 1
	fi
done
