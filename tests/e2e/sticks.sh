#!/bin/sh
# The USB sticks of tests/e2e/hands-board.sh, made without root or a loop
# device: GOOD, FAT as sticks come (mkfs.vfat and mcopy: dosfstools and
# mtools; ext2 where they are missing, said on stderr), carries a model whose
# buffer lies in a subfolder (buffers/, as Blender and Sketchfab lay out
# their files) and a kiosk.ini in matcap-kiosk/; BROKEN, ext2 (mke2fs -d: e2fsprogs), a
# good model and a truncated one, both named by its kiosk.ini, and a device
# node and a pipe (debugfs: made without root), which the import must pass
# over without opening (the stick is mounted nodev: opening the node fails).
# Prints the tests/vm/run.sh options that plug them in.
#   sticks.sh DIR
set -eu
dir=$1
rm -rf "$dir"
mkdir -p "$dir/good/matcap-kiosk/buffers" "$dir/broken/matcap-kiosk"
sed 's#"uri":"sphere-external.bin"#"uri":"buffers/sphere.bin"#' \
	tests/fuzz/corpus/gltf/sphere-external.gltf >"$dir/good/matcap-kiosk/sphere.gltf"
cp tests/fuzz/corpus/gltf/sphere-external.bin "$dir/good/matcap-kiosk/buffers/sphere.bin"
printf '[scene]\nyaw = 30\n' >"$dir/good/matcap-kiosk/kiosk.ini"
head -c 500 tests/fuzz/corpus/gltf/sphere.glb >"$dir/broken/matcap-kiosk/sphere.glb"
cp tests/fuzz/corpus/gltf/sphere.glb "$dir/broken/matcap-kiosk/a.glb"
printf '[scene]\nmodel = a.glb, sphere.glb\n' >"$dir/broken/matcap-kiosk/kiosk.ini"
ext2() { mke2fs -q -F -t ext2 -L "$1" -d "$dir/$1" "$dir/$1.img" 2M >/dev/null; }
if command -v mkfs.vfat >/dev/null && command -v mcopy >/dev/null; then
	mkfs.vfat -n GOOD -C "$dir/good.img" 2048 >/dev/null
	mcopy -i "$dir/good.img" -s "$dir/good/matcap-kiosk" ::
else
	echo "sticks.sh: no mkfs.vfat or mcopy (dosfstools, mtools): the good stick is ext2" >&2
	ext2 good
fi
ext2 broken
printf 'cd matcap-kiosk\nmknod null.png c 1 3\nsif null.png mode 020644\nmknod p.bin p\nsif p.bin mode 010644\n' |
	debugfs -w -f - "$dir/broken.img" >/dev/null 2>&1
echo "--usb $dir/good.img:GOOD --usb $dir/broken.img:BROKEN"
