/* The screen's power state machine with a clock the test controls:
 * schedules, blank_after, waking by input, an unsynchronised clock, and a
 * whole week minute by minute. */
#include "state/power.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

enum { SUN, MON, TUE, WED, THU, FRI, SAT };
#define S 1000000000ull

/* Monday 00:00 of the test's week is monotonic time 1000 s. */
static struct power_clock at(uint64_t minutes_into_week, int extra_s, bool synced)
{
	return (struct power_clock){.now_ns = (1000 + minutes_into_week * 60 + extra_s) * S,
				    .wday = (int)((MON + minutes_into_week / 1440) % 7),
				    .minute = (int)(minutes_into_week % 1440),
				    .synced = synced};
}

static void config(struct power_config *cfg, const char *schedule, double blank_after_s)
{
	char err[128];

	memset(cfg, 0, sizeof(*cfg));
	if (schedule)
		assert_int_equal(schedule_parse(&cfg->schedule, schedule, err, sizeof(err)), 0);
	cfg->blank_after_s = blank_after_s;
}

static void test_always_on(void **state)
{
	struct power_config cfg;
	struct power_state p;
	struct power_clock c = at(0, 0, true);

	(void)state;
	config(&cfg, NULL, 0);
	power_init(&p, &cfg, &c);
	assert_true(p.on);
	assert_int_equal(p.reason, POWER_ALWAYS);
	assert_int_equal(power_deadline(&p), CLOCK_NEVER);
	c = at(7 * 1440 - 1, 0, false);
	assert_int_equal(power_update(&p, &c), 0);
	assert_true(p.on);
}

static void test_blank_after_idle(void **state)
{
	struct power_config cfg;
	struct power_state p;
	struct power_clock c = at(0, 0, true);

	(void)state;
	config(&cfg, NULL, 300);
	power_init(&p, &cfg, &c);
	assert_int_equal(power_deadline(&p), c.now_ns + 300 * S);
	c = at(4, 59, true);
	assert_int_equal(power_update(&p, &c), 0);
	c = at(5, 0, true);
	assert_int_equal(power_update(&p, &c), POWER_CHANGED);
	assert_false(p.on);
	assert_int_equal(p.reason, POWER_IDLE);
	assert_int_equal(power_deadline(&p), CLOCK_NEVER); /* off: nothing to wait for */
	c = at(6, 40, true);
	assert_int_equal(power_input(&p, &c), POWER_CHANGED);
	assert_true(p.on);
	assert_int_equal(power_deadline(&p), c.now_ns + 300 * S);
}

static void test_schedule_and_waking(void **state)
{
	struct power_config cfg;
	struct power_state p;
	struct power_clock c = at(7 * 60 + 59, 0, true); /* Monday 07:59 */

	(void)state;
	config(&cfg, "Mon-Fri 08:00-20:00", 0);
	power_init(&p, &cfg, &c);
	assert_false(p.on);
	assert_int_equal(p.reason, POWER_SCHEDULED_OFF);
	c = at(8 * 60, 0, true);
	assert_int_equal(power_update(&p, &c), POWER_CHANGED);
	assert_int_equal(p.reason, POWER_SCHEDULED_ON);
	c = at(20 * 60, 0, true);
	assert_int_equal(power_update(&p, &c), POWER_CHANGED);
	assert_false(p.on);
	/* A button at 21:00 wakes it for a minute (blank_after is 0). */
	c = at(21 * 60, 0, true);
	assert_int_equal(power_input(&p, &c), POWER_CHANGED);
	assert_int_equal(p.reason, POWER_WOKEN);
	assert_int_equal(power_deadline(&p), c.now_ns + 60 * S);
	c = at(21 * 60, 59, true);
	assert_int_equal(power_update(&p, &c), 0);
	c = at(21 * 60 + 1, 0, true);
	assert_int_equal(power_update(&p, &c), POWER_CHANGED);
	assert_int_equal(p.reason, POWER_SCHEDULED_OFF);
}

static void test_unsynchronised_clock(void **state)
{
	struct power_config cfg;
	struct power_state p;
	struct power_clock c = at(2 * 60, 0, false); /* 02:00, or so the clock says */

	(void)state;
	config(&cfg, "Mon-Fri 08:00-20:00", 0);
	power_init(&p, &cfg, &c);
	assert_true(p.on);
	assert_int_equal(p.reason, POWER_NO_CLOCK);
	/* Said once, not once a minute. */
	assert_int_equal(power_update(&p, &c), POWER_SAY_UNSYNCED);
	c = at(2 * 60 + 1, 0, false);
	assert_int_equal(power_update(&p, &c), 0);
	/* NTP answers: now the schedule counts. */
	c = at(2 * 60 + 2, 0, true);
	assert_int_equal(power_update(&p, &c), POWER_CHANGED);
	assert_false(p.on);
}

/* A week, minute by minute: on exactly the scheduled minutes, and blank
 * after ten idle minutes inside them. */
static void test_whole_week(void **state)
{
	struct power_config cfg;
	struct power_state p;
	struct power_clock c = at(0, 0, true);
	int on = 0, changes = 0;

	(void)state;
	config(&cfg, "Fri 18:00-02:00, Sun 10:00-12:00", 0);
	power_init(&p, &cfg, &c);
	for (uint64_t m = 0; m < 7 * 1440; m++) {
		c = at(m, 0, true);
		changes += (power_update(&p, &c) & POWER_CHANGED) != 0;
		on += p.on;
	}
	assert_int_equal(on, 8 * 60 + 2 * 60);
	assert_int_equal(changes, 4);
	config(&cfg, "daily 00:00-24:00", 600);
	c = at(0, 0, true);
	power_init(&p, &cfg, &c);
	on = 0;
	for (uint64_t m = 0; m < 60; m++) {
		c = at(m, 0, true);
		if (m == 30)
			power_input(&p, &c);
		power_update(&p, &c);
		on += p.on;
	}
	assert_int_equal(on, 20); /* minutes 0-9 and 30-39 */
}

/* Remote control's "screen off" (MQTT): off at once, held against the
 * schedule and the idle timer (no deadline wakes it), until an input or
 * "screen on"; "screen on" outside the schedule wakes it as an input. */
static void test_remote_off_and_on(void **state)
{
	struct power_config cfg;
	struct power_state p;
	struct power_clock c = at(9 * 60, 0, true); /* Monday 09:00, inside */

	(void)state;
	config(&cfg, "Mon-Fri 08:00-20:00", 300);
	power_init(&p, &cfg, &c);
	assert_true(p.on);
	assert_int_equal(power_remote(&p, &c, false), POWER_CHANGED);
	assert_false(p.on);
	assert_int_equal(p.reason, POWER_REMOTE_OFF);
	assert_int_equal(power_deadline(&p), CLOCK_NEVER);
	c = at(10 * 60, 0, true); /* an hour on, still inside: still off */
	assert_int_equal(power_update(&p, &c), 0);
	assert_false(p.on);
	assert_int_equal(power_input(&p, &c), POWER_CHANGED); /* a visitor's touch */
	assert_true(p.on);
	assert_int_equal(p.reason, POWER_SCHEDULED_ON);
	assert_int_equal(power_remote(&p, &c, false), POWER_CHANGED);
	assert_int_equal(power_remote(&p, &c, true), POWER_CHANGED);
	assert_true(p.on);
	c = at(21 * 60, 0, true); /* 21:00, outside: off by the schedule */
	power_update(&p, &c);
	assert_false(p.on);
	assert_int_equal(power_remote(&p, &c, true), POWER_CHANGED);
	assert_int_equal(p.reason, POWER_WOKEN);
	assert_string_equal(power_reason_name(POWER_REMOTE_OFF),
			    "off by remote control until an input or 'screen on'");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_always_on),		cmocka_unit_test(test_blank_after_idle),
	    cmocka_unit_test(test_schedule_and_waking), cmocka_unit_test(test_unsynchronised_clock),
	    cmocka_unit_test(test_whole_week),		cmocka_unit_test(test_remote_off_and_on),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
