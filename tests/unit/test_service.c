/* What the kiosk tells systemd, read from a socket set as NOTIFY_SOCKET:
 * READY=1 once, the watchdog's cadence, and no ping while the display is
 * stuck, so systemd restarts the service. */
#include "util/log.h"
#include "ops/service.h"

#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <cmocka.h>

#define MS 1000000ull

struct listener {
	int fd;
	char path[64];
};

static int listen_setup(void **state)
{
	static struct listener l;
	struct sockaddr_un addr = {.sun_family = AF_UNIX};

	snprintf(l.path, sizeof(l.path), "/tmp/mk-notify-%d", (int)getpid());
	unlink(l.path);
	strcpy(addr.sun_path, l.path);
	l.fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (l.fd < 0 || bind(l.fd, (struct sockaddr *)&addr, sizeof(addr)))
		return -1;
	setenv("NOTIFY_SOCKET", l.path, 1);
	*state = &l;
	return 0;
}

static int listen_teardown(void **state)
{
	struct listener *l = *state;

	close(l->fd);
	unlink(l->path);
	unsetenv("NOTIFY_SOCKET");
	return 0;
}

/* The next message, or "" when none came. */
static const char *next_message(struct listener *l)
{
	static char msg[512];
	struct pollfd p = {.fd = l->fd, .events = POLLIN};
	ssize_t n = 0;

	if (poll(&p, 1, 100) > 0)
		n = recv(l->fd, msg, sizeof(msg) - 1, 0);
	msg[n > 0 ? n : 0] = '\0';
	return msg;
}

static void set_watchdog(const char *usec, pid_t pid)
{
	char p[32];

	snprintf(p, sizeof(p), "%d", (int)pid);
	setenv("WATCHDOG_USEC", usec, 1);
	setenv("WATCHDOG_PID", p, 1);
}

static void ready_once_then_status(void **state)
{
	struct listener *l = *state;
	struct service s;

	unsetenv("WATCHDOG_USEC");
	service_init(&s, 0);
	service_ready(&s, false);
	assert_string_equal(next_message(l), "READY=1\nSTATUS=waiting for a display");
	service_ready(&s, false);
	assert_string_equal(next_message(l), "");
	service_ready(&s, true);
	assert_string_equal(next_message(l), "READY=1\nSTATUS=showing the scene");
	service_ready(&s, true);
	service_ready(&s, false);
	assert_string_equal(next_message(l), "");
}

static void watchdog_at_half_the_interval(void **state)
{
	struct listener *l = *state;
	struct service s;

	set_watchdog("2000000", getpid()); /* 2 s */
	service_init(&s, 1000 * MS);
	assert_int_equal(s.ping_ns, 1000 * MS);
	assert_int_equal(service_deadline(&s), 1000 * MS);
	service_ping(&s, 1000 * MS, true);
	assert_string_equal(next_message(l), "WATCHDOG=1");
	assert_int_equal(service_deadline(&s), 2000 * MS);
	service_ping(&s, 1500 * MS, true); /* not due */
	assert_string_equal(next_message(l), "");
	service_ping(&s, 2000 * MS, true);
	assert_string_equal(next_message(l), "WATCHDOG=1");
	/* Before a reload: now, whatever the schedule. */
	service_keepalive(&s, 2100 * MS);
	assert_string_equal(next_message(l), "WATCHDOG=1");
	assert_int_equal(service_deadline(&s), 3100 * MS);
}

static void no_ping_while_the_display_is_stuck(void **state)
{
	struct listener *l = *state;
	struct service s;

	set_watchdog("2000000", getpid());
	service_init(&s, 0);
	service_ping(&s, 0, false);
	assert_string_equal(next_message(l), "");
	/* The deadline still moves on: the loop must not spin. */
	assert_int_equal(service_deadline(&s), 1000 * MS);
	service_ping(&s, 1000 * MS, true);
	assert_string_equal(next_message(l), "WATCHDOG=1");
}

static void watchdog_only_for_its_own_pid(void **state)
{
	struct listener *l = *state;
	struct service s;

	set_watchdog("2000000", getpid() + 1);
	service_init(&s, 0);
	assert_int_equal(s.ping_ns, 0);
	assert_true(service_deadline(&s) == UINT64_MAX);
	service_ping(&s, 5000 * MS, true);
	assert_string_equal(next_message(l), "");
	unsetenv("WATCHDOG_USEC");
	unsetenv("WATCHDOG_PID");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test_setup_teardown(ready_once_then_status, listen_setup, listen_teardown),
	    cmocka_unit_test_setup_teardown(watchdog_at_half_the_interval, listen_setup,
					    listen_teardown),
	    cmocka_unit_test_setup_teardown(no_ping_while_the_display_is_stuck, listen_setup,
					    listen_teardown),
	    cmocka_unit_test_setup_teardown(watchdog_only_for_its_own_pid, listen_setup,
					    listen_teardown),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests_name("service", tests, NULL, NULL);
}
