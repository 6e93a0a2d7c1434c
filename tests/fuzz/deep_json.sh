#!/bin/sh
# A glTF whose JSON nests DEPTH levels: {"asset":{...,"extras":[[...]]}},
# the attack of tests/fuzz/regressions/README.md written on demand (the
# 30,000-deep file is 60 KB of brackets; a script is 30 lines).
#   deep_json.sh DEPTH gltf|glb >FILE
# DEPTH counts every level: the outer object and "asset" are 2 of them.
set -eu
depth=$1
n=$((depth - 2))
json() {
	printf '{"asset":{"version":"2.0","extras":'
	# awk, not a shell loop: 30,000 levels in a blink.
	awk -v n="$n" 'BEGIN { s = ""; for (i = 0; i < n; i++) s = s "["; t = s; gsub(/\[/, "]", t); printf "%s%s", s, t }'
	printf '}}'
}
# le32 N: N as 4 bytes, little-endian (a GLB's header fields).
le32() {
	# shellcheck disable=SC2059 # the format is the four octal escapes
	printf "$(printf '\\%03o\\%03o\\%03o\\%03o' $(($1 & 255)) $(($1 >> 8 & 255)) \
		$(($1 >> 16 & 255)) $(($1 >> 24 & 255)))"
}
case $2 in
gltf) json ;;
glb)
	text=$(json)
	len=${#text}
	pad=$(((4 - len % 4) % 4))
	chunk=$((len + pad))
	printf 'glTF'
	le32 2
	le32 $((12 + 8 + chunk))
	le32 $chunk
	printf 'JSON%s%*s' "$text" $pad ''
	;;
*)
	echo "usage: deep_json.sh DEPTH gltf|glb" >&2
	exit 2
	;;
esac
