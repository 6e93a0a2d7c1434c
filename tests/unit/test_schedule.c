/* [power] schedule: the parser's words for bad input, and which minutes of
 * the week are inside, across midnight and across DST changes. */
#include "state/schedule.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <cmocka.h>

enum { SUN, MON, TUE, WED, THU, FRI, SAT };
#define HM(h, m) ((h)*60 + (m))

static void parse_ok(struct schedule *s, const char *text)
{
	char err[160] = "";

	assert_int_equal(schedule_parse(s, text, err, sizeof(err)), 0);
	assert_string_equal(err, "");
}

static void test_weekdays_and_saturday(void **state)
{
	struct schedule s;

	(void)state;
	parse_ok(&s, "Mon-Fri 08:00-20:00, Sat 10:00-16:00");
	assert_true(schedule_on(&s, MON, HM(8, 0)));
	assert_false(schedule_on(&s, MON, HM(7, 59)));
	assert_true(schedule_on(&s, FRI, HM(19, 59)));
	assert_false(schedule_on(&s, FRI, HM(20, 0))); /* the end is outside */
	assert_true(schedule_on(&s, SAT, HM(12, 0)));
	assert_false(schedule_on(&s, SAT, HM(9, 0)));
	assert_false(schedule_on(&s, SUN, HM(12, 0)));
	/* Without a schedule the screen is always on. */
	memset(&s, 0, sizeof(s));
	assert_true(schedule_on(&s, SUN, HM(3, 0)));
}

static void test_midnight_and_wrapping_days(void **state)
{
	struct schedule s;

	(void)state;
	parse_ok(&s, "Fri-Sat 18:00-02:00, sat-mon 11:00-12:00 13:00-24:00");
	assert_true(schedule_on(&s, FRI, HM(23, 59)));
	assert_true(schedule_on(&s, SAT, HM(1, 59))); /* Friday's night */
	assert_false(schedule_on(&s, SAT, HM(2, 0)));
	assert_true(schedule_on(&s, SUN, HM(1, 0)));  /* Saturday's night */
	assert_false(schedule_on(&s, FRI, HM(1, 0))); /* Thursday had none */
	/* Sat-Mon runs through the week's end; 24:00 ends the day. */
	assert_true(schedule_on(&s, MON, HM(11, 30)));
	assert_false(schedule_on(&s, MON, HM(12, 30)));
	assert_true(schedule_on(&s, SUN, HM(23, 59)));
	assert_false(schedule_on(&s, TUE, HM(11, 30)));
	parse_ok(&s, "daily 00:00-24:00");
	for (int d = SUN; d <= SAT; d++)
		assert_true(schedule_on(&s, d, HM(0, 0)) && schedule_on(&s, d, HM(23, 59)));
}

static void expect_error(const char *text, const char *words)
{
	struct schedule s;
	char err[160] = "";

	assert_int_equal(schedule_parse(&s, text, err, sizeof(err)), -22);
	if (!strstr(err, words))
		fail_msg("\"%s\": got \"%s\", expected it to say \"%s\"", text, err, words);
	assert_int_equal(s.count, 0); /* nothing half parsed */
}

static void test_errors_name_the_place(void **state)
{
	(void)state;
	expect_error("Mox-Fri 08:00-20:00", "at \"Mox-Fri 08:00-20:00\" (column 1): expected a "
					    "weekday");
	expect_error("Mon-Fir 08:00-20:00", "(column 5): expected the weekday that ends");
	expect_error("Mon 8:00-20:00", "expected a time HH:MM");
	expect_error("Mon 08:00-25:00", "(column 11): expected a time HH:MM from 00:00 to 24:00");
	expect_error("Mon 08:00", "expected '-' and the time the span ends");
	expect_error("Mon 08:00-08:00", "a span that is not empty");
	expect_error("Mon", "at the end: expected a span after the days");
	expect_error("Mon 08:00-09:00,", "at the end: expected a weekday");
	expect_error("Mon 08:00-09:00, Tue", "expected a span after the days");
	expect_error("", "at the end: expected a weekday");
}

static void local(time_t t, int *wday, int *minute)
{
	struct tm tm;

	localtime_r(&t, &tm);
	*wday = tm.tm_wday;
	*minute = tm.tm_hour * 60 + tm.tm_min;
}

/* Only the wall clock counts: on the day clocks go forward the span
 * starts at 03:00, the first local minute after 02:00; on the day they go
 * back an hour the span is simply inside twice. */
static void test_dst_days(void **state)
{
	struct schedule s;
	int wday, minute;
	/* 2026-03-29 00:59 UTC is 01:59 CET; a minute later it is 03:00 CEST. */
	time_t spring = 1774745940;
	/* 2026-10-25 00:30 UTC is 02:30 CEST; at 01:30 UTC it is 02:30 CET again. */
	time_t autumn = 1792888200;

	(void)state;
	setenv("TZ", "CET-1CEST,M3.5.0,M10.5.0/3", 1);
	tzset();
	parse_ok(&s, "Sun 02:30-03:30");
	local(spring, &wday, &minute);
	assert_int_equal(minute, HM(1, 59));
	assert_false(schedule_on(&s, wday, minute));
	local(spring + 60, &wday, &minute);
	assert_int_equal(minute, HM(3, 0));
	assert_true(schedule_on(&s, wday, minute));
	local(autumn, &wday, &minute);
	assert_int_equal(minute, HM(2, 30));
	assert_true(schedule_on(&s, wday, minute));
	local(autumn + 3600, &wday, &minute);
	assert_int_equal(minute, HM(2, 30));
	assert_true(schedule_on(&s, wday, minute));
	local(autumn + 2 * 3600, &wday, &minute);
	assert_int_equal(minute, HM(3, 30));
	assert_false(schedule_on(&s, wday, minute));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_weekdays_and_saturday),
	    cmocka_unit_test(test_midnight_and_wrapping_days),
	    cmocka_unit_test(test_errors_name_the_place),
	    cmocka_unit_test(test_dst_days),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
