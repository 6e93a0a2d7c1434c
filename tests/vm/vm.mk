# Virtual board targets; included from the top-level Makefile:
#   include tests/vm/vm.mk
#
#   make vm-build    build/refresh the cached kernel modules and initramfs
#   make vm-smoke    boot the board and prove display, writeback, GPIO, camera
#                    and Mesa-on-KMS work (outputs in $(VM_SMOKE_OUT))
#   make vm-test     run every guest script in VM_TESTS, each in a fresh boot,
#                    with VM_BINS on the guest's PATH; outputs per script in
#                    $(VM_OUT)/<script name>/
#   make vm-e2e      the board tests as `make test` runs them (tests/e2e/host.sh:
#                    the display, tests/e2e/kms*.sh, then the GPIO buttons and
#                    the camera), with their OSMesa references; one script
#                    alone: make check T=kms (tests/check.sh)
#   make vm-systemd  the installed unit in a Debian root booted with systemd
#                    (tests/vm/systemd-test.sh), with a reload that outlasts
#                    WatchdogSec=3s; in `make test` as make check T=systemd-board
#                    (about 2 min: its Debian 12 root is made of this
#                    machine's installed packages, nothing downloaded)
#   make vm-clean    drop the cache (next build downloads and rebuilds)
#
# Knobs: VM_TESTS (guest scripts), VM_BINS (host binaries to carry in),
# VM_TIMEOUT (seconds per guest script; VM_SMOKE_TIMEOUT for vm-smoke),
# VM_RUN_FLAGS (extra run.sh options, e.g. --quiet).

VM_DIR := $(patsubst %/,%,$(dir $(lastword $(MAKEFILE_LIST))))
VM_CACHE ?= $(VM_DIR)/cache
VM_OUT ?= $(VM_CACHE)/out
VM_SMOKE_OUT ?= $(VM_OUT)/smoke
VM_TESTS ?= $(VM_DIR)/smoke.sh
VM_BINS ?=
VM_TIMEOUT ?= 300
VM_SMOKE_TIMEOUT ?= 120
VM_RUN_FLAGS ?=

VM_BIN_FLAGS = $(foreach b,$(VM_BINS),--bin $(b))

.PHONY: vm-build vm-smoke vm-test vm-clean

vm-build:
	VM_CACHE=$(abspath $(VM_CACHE)) $(VM_DIR)/build.sh $(VM_BIN_FLAGS) >/dev/null

vm-smoke:
	VM_CACHE=$(abspath $(VM_CACHE)) $(VM_DIR)/run.sh --timeout $(VM_SMOKE_TIMEOUT) --share $(VM_SMOKE_OUT) \
		$(VM_RUN_FLAGS) -- $(VM_DIR)/smoke.sh

# Each script boots its own board, so one test cannot leave state for the next.
vm-test:
	@fail=0; for t in $(VM_TESTS); do \
		n=$$(basename $$t .sh); \
		echo "== vm-test $$n"; \
		VM_CACHE=$(abspath $(VM_CACHE)) $(VM_DIR)/run.sh --timeout $(VM_TIMEOUT) $(VM_BIN_FLAGS) \
			--share $(VM_OUT)/$$n $(VM_RUN_FLAGS) -- $$t || { echo "== vm-test $$n FAILED"; fail=1; }; \
	done; exit $$fail

vm-clean:
	rm -rf $(VM_CACHE)

# The board tests as `make test` runs them (tests/e2e/host.sh): the real
# kiosk on vkms against OSMesa references rendered here, its GPIO buttons
# and the camera (whose colour bars hues counts); each script's frames and
# logs in tests/out/check/board/e2e/<script>/. The same as make check T=board.
vm-e2e: $(KIOSK) $(TOOLS_DIR)/imgdiff $(TOOLS_DIR)/hues $(TOOLS_DIR)/mkmodels
	$(TEST_ENV) sh tests/check.sh board

# The kiosk as a systemd service on the virtual board: a Debian root booted
# with systemd (a few minutes the first time).
vm-systemd: $(KIOSK)
	sh tests/vm/systemd-test.sh $(BUILD)/vm-systemd/out

.PHONY: vm-e2e vm-systemd
