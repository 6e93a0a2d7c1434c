#!/bin/sh
# Every key the program accepts in the config file (as --help lists them)
# must appear in config/kiosk.ini, set or commented out, in its section.
set -eu
kiosk=$1
ini=${2:-config/kiosk.ini}
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
