#!/bin/sh
# The curator's picture of a toured model (docs/curator.md): what the
# attract tour shows 7.5 s after it begins, drawn offscreen by --at
# (issue 33): its second stop, its view and its text. Run by `make readme`
# and checked by the preview tests (tests/suite.sh).
#   tour.sh KIOSK BACKEND OUT.png
set -eu
"$1" -q --backend "$2" --size 480x360 --model tests/corpus/blender/suzanne-colors.glb \
	--matcap matcaps/pearl.png --caption-position bottom \
	--stops '-30 10 1 "The face, painted by vertex"; 90 0 1.1 "The left ear"; 200 20 1 "The back of the head"' \
	--stop-seconds 4 --attract-speed 360 --at 7.5 --output "$3"
