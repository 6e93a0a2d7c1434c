#!/bin/sh
# The Ansible role (contrib/ansible/roles/matcap_kiosk) as a fleet applies
# it: the example playbook (contrib/ansible/site.yml) run with Debian's
# ansible through its chroot connection against a fresh Debian root
# (mmdebstrap, with the python3 every Ansible host needs and systemd, as a
# Pi's image has), then checked from outside: the package installed from
# the copied .deb, the settings drop-in with its content (read after
# kiosk.ini by the installed kiosk's --check-config, which finds it all
# valid), the content copied, the service
# enabled (its symlink in multi-user.target.wants; nothing is started in
# a chroot), and a second run that changes nothing. Ends with one
# "N passed, N failed" line. Needs root (the root is a chroot) and the
# network (Debian's archive, for the root and the package's dependencies).
# Usage: tests/cross/ansible.sh DEB ROOT [SUITE]
#   SUITE: the root's Debian release, this machine's by default (the .deb
#   is built here, against this release's libraries).
set -u
deb=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$2
suite=${3:-$(. /etc/os-release && echo "$VERSION_CODENAME")}
here=$(cd "$(dirname "$0")/../.." && pwd)
CHECK_LOG=$root.log
# shellcheck source=../tools/checks.sh
. "$here/tests/tools/checks.sh"
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin "$@"; }

rm -rf "$root" "$root.work"
mkdir -p "$root.work/content"
root=$(cd "$(dirname "$root")" && pwd)/$(basename "$root")
work=$root.work
check "a fresh $suite root with python3 and systemd" mmdebstrap --quiet --variant=apt \
	--include=python3,python3-apt,systemd "$suite" "$root" \
	"deb http://deb.debian.org/debian $suite main"

# The content: two models made for the project's tests.
cp "$here/tests/corpus/blender/cube-textured.glb" "$here/tests/corpus/blender/sphere-material.glb" \
	"$work/content/"
cat >"$work/inventory.ini" <<EOF
[kiosks]
kiosk ansible_host=$root ansible_connection=community.general.chroot ansible_become=false ansible_python_interpreter=/usr/bin/python3
EOF
# play N: the example playbook, with this package and content; its output
# in $work/playN.log, the recap line in $work/recapN.
play() {
	t0=$(date +%s)
	ANSIBLE_ROLES_PATH=$here/contrib/ansible/roles ANSIBLE_NOCOLOR=1 ANSIBLE_RETRY_FILES_ENABLED=0 \
		ANSIBLE_HOST_KEY_CHECKING=0 ANSIBLE_LOCAL_TEMP=$work/tmp \
		ansible-playbook -i "$work/inventory.ini" "$here/contrib/ansible/site.yml" \
		-e "matcap_kiosk_deb=$deb" -e "matcap_kiosk_content_src=$work/content" \
		>"$work/play$1.log" 2>&1
	rc=$?
	echo "ansible-playbook run $1: exit $rc, $(($(date +%s) - t0)) s"
	grep -E '^kiosk +:' "$work/play$1.log" | tee "$work/recap$1"
	[ $rc -eq 0 ]
}
recap() { # N FIELD: a number of the recap line of run N
	sed -n "s/.* $2=\([0-9]*\).*/\1/p" "$work/recap$1"
}

play 1
played=$?
check "ansible-playbook contrib/ansible/site.yml through the chroot connection" \
	sh -c "[ $played = 0 ] || { cat '$work/play1.log'; false; }"
check "... no task failed or unreachable" sh -c "[ '$(recap 1 failed)' = 0 ] && [ '$(recap 1 unreachable)' = 0 ]"

version=$(dpkg-deb -f "$deb" Version)
check "the package is installed, version $version" sh -c \
	"[ \"\$(chroot '$root' dpkg-query -W -f='\${Status} \${Version}' matcap-kiosk)\" = 'install ok installed $version' ]"
check "... from the .deb copied over" test -s "$root/var/cache/matcap-kiosk/$(basename "$deb")"
dropin=$root/etc/matcap-kiosk/kiosk.ini.d/50-ansible.ini
check "the drop-in is there" test -s "$dropin"
# The example sets [display] rotation and [power] schedule; the role, the
# model and the metrics.
check "... with the model, the metrics path and the playbook's settings" awk '
	/^\[/ { s = $0 }
	s == "[scene]" && $0 == "model = /srv/matcap-kiosk" { n++ }
	s == "[status]" && $0 == "metrics = /var/lib/matcap-kiosk/matcap-kiosk.prom" { n++ }
	s == "[display]" && $0 == "rotation = 90" { n++ }
	s == "[power]" && $0 == "schedule = Mon-Fri 08:00-20:00, Sat 10:00-16:00" { n++ }
	END { exit n != 4 }' "$dropin"
check "... readable by the service (0644)" sh -c "stat -c %a '$dropin' | grep -qx 644"
# The kiosk as the service starts it: kiosk.ini, then the drop-ins.
check "... read by the installed kiosk after kiosk.ini, the model from it, all valid (--check-config)" \
	in_root sh -c 'out=$(/usr/bin/matcap-kiosk --config /etc/matcap-kiosk/kiosk.ini --check-config 2>&1)
	rc=$?
	echo "$out"
	[ $rc = 0 ] && echo "$out" | grep -q "read /etc/matcap-kiosk/kiosk.ini.d/50-ansible.ini" &&
		echo "$out" | grep -q "model = /srv/matcap-kiosk.*(/etc/matcap-kiosk/kiosk.ini.d/50-ansible.ini:[0-9]*): loads"'
for f in cube-textured.glb sphere-material.glb; do
	check "content copied: /srv/matcap-kiosk/$f" cmp "$work/content/$f" "$root/srv/matcap-kiosk/$f"
done
check "... readable by the service's user" in_root runuser -u matcap-kiosk -- \
	test -r /srv/matcap-kiosk/cube-textured.glb
check "the service is enabled (multi-user.target.wants)" sh -c "
	[ \"\$(readlink '$root/etc/systemd/system/multi-user.target.wants/matcap-kiosk.service')\" = \
		/lib/systemd/system/matcap-kiosk.service ] ||
	[ \"\$(readlink '$root/etc/systemd/system/multi-user.target.wants/matcap-kiosk.service')\" = \
		/usr/lib/systemd/system/matcap-kiosk.service ]"
check "... as systemctl says offline" sh -c "[ \"\$(systemctl --root='$root' is-enabled matcap-kiosk.service)\" = enabled ]"

play 2
played=$?
check "a second run" sh -c "[ $played = 0 ] || { cat '$work/play2.log'; false; }"
check "... changes nothing (changed=0)" sh -c "[ '$(recap 2 changed)' = 0 ] && [ '$(recap 2 failed)' = 0 ] ||
	{ cat '$work/play2.log'; false; }"
summary
