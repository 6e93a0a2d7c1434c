# The Ansible role (contrib/ansible) applied to a fresh Debian root through
# Ansible's chroot connection (included from the top-level Makefile):
#   make test-ansible   the package of `make deb` (built first when there is
#                       none), then tests/cross/ansible.sh into build/ansible-root
# As root (the root is a chroot); ANSIBLE_SUITE picks the root's release
# (this machine's by default: the package is built against its libraries).
ANSIBLE_DEB   = build/deb/matcap-kiosk_$(VERSION)_$(shell dpkg --print-architecture 2>/dev/null).deb
ANSIBLE_SUITE ?=

test-ansible:
	@[ -e $(ANSIBLE_DEB) ] || $(MAKE) --no-print-directory deb
	sh tests/cross/ansible.sh $(ANSIBLE_DEB) build/ansible-root $(ANSIBLE_SUITE)

.PHONY: test-ansible
