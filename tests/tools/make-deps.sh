#!/bin/sh
# The README's first command: make itself, then `make deps` (what building
# and running need), on a fresh Debian 12 or 13, as root (an image without
# sudo) or as a user with sudo. The test bench is `make deps-test`, the
# README's test command. Other targets can be named instead: the quick
# start's `deps-pkg` (what `make deb` needs on the Pi).
#   sh tests/tools/make-deps.sh [TARGET...]
set -eu
cd "$(dirname "$0")/../.."
sudo=
[ "$(id -u)" = 0 ] || sudo=sudo
if ! command -v make >/dev/null; then
	# A fresh image may have no package lists yet.
	$sudo apt-get -o DPkg::Lock::Timeout=600 update -qq
	$sudo env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends make
fi
[ $# -gt 0 ] || set -- deps
# The deps targets read no library, but the Makefile asks pkg-config for
# them as it is read: on a fresh machine, where neither is there yet, that
# is a screenful of "pkg-config: not found" before apt says anything.
make PKG_CONFIG=true "$@"
