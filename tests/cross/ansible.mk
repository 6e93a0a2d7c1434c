# The Ansible role (contrib/ansible) applied to a fresh Debian root through
# Ansible's chroot connection (included from the top-level Makefile):
#   make test-ansible   the amd64 package in build/deb/ (Debian 13's, as
#                       make test-deb leaves it; built in a clean root by
#                       make deb ARCH=... when there is none), then
#                       tests/cross/ansible.sh into build/ansible-root
# As root (the root is a chroot); ANSIBLE_SUITE is the root's release:
# Debian 13, the release build/deb/'s packages are built for.
ANSIBLE_ARCH  = $(shell dpkg --print-architecture 2>/dev/null)
ANSIBLE_DEB   = build/deb/matcap-kiosk_$(VERSION)_$(ANSIBLE_ARCH).deb
ANSIBLE_SUITE ?= trixie

test-ansible:
	@[ -e $(ANSIBLE_DEB) ] || $(MAKE) --no-print-directory deb ARCH=$(ANSIBLE_ARCH)
	sh tests/cross/ansible.sh $(ANSIBLE_DEB) build/ansible-root $(ANSIBLE_SUITE)

.PHONY: test-ansible
