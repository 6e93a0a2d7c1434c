#!/bin/sh
# The USB sticks of tests/e2e/hands-board.sh, as ext2 images made with
# mke2fs -d (e2fsprogs; no root, no loop device): GOOD carries a model and
# a kiosk.ini in matcap-kiosk/, BROKEN a truncated model. Prints the
# tests/vm/run.sh options that plug them in.
#   sticks.sh DIR
set -eu
dir=$1
rm -rf "$dir"
mkdir -p "$dir/good/matcap-kiosk" "$dir/broken/matcap-kiosk"
cp tests/fuzz/corpus/gltf/sphere.glb "$dir/good/matcap-kiosk/"
printf '[scene]\nyaw = 30\n' >"$dir/good/matcap-kiosk/kiosk.ini"
head -c 500 tests/fuzz/corpus/gltf/sphere.glb >"$dir/broken/matcap-kiosk/sphere.glb"
for s in good broken; do
	mke2fs -q -F -t ext2 -L "$s" -d "$dir/$s" "$dir/$s.img" 2M >/dev/null
done
echo "--usb $dir/good.img:GOOD --usb $dir/broken.img:BROKEN"
