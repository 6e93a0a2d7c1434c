/* The touch gesture state machine with made-up touches and times: drags,
 * pinches, taps, double taps and long presses, and the panel's rotation,
 * no touchscreen. */
#include "input/gesture.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define MS 1000000ull

struct log {
	struct gesture ev[64];
	int n;
};

static void frame(struct gesture_state *g, struct log *l, uint64_t t_ms, int n, ...)
{
	struct gesture_point pts[GESTURE_MAX_POINTS];
	va_list ap;

	va_start(ap, n);
	for (int i = 0; i < n; i++) {
		pts[i].id = va_arg(ap, int);
		pts[i].x = va_arg(ap, double);
		pts[i].y = va_arg(ap, double);
	}
	va_end(ap);
	/* As the main loop does: a deadline that passed is serviced first. */
	if (gesture_deadline(g) <= t_ms * MS)
		l->n += gesture_timeout(g, gesture_deadline(g), l->ev + l->n);
	l->n += gesture_frame(g, t_ms * MS, pts, n, l->ev + l->n);
	assert_true(l->n < 60);
}

static int count(const struct log *l, enum gesture_kind k)
{
	int c = 0;

	for (int i = 0; i < l->n; i++)
		c += l->ev[i].kind == k;
	return c;
}

static void setup(struct gesture_state *g, struct log *l)
{
	struct gesture_config cfg;

	gesture_config_defaults(&cfg);
	gesture_init(g, &cfg);
	memset(l, 0, sizeof(*l));
}

static void test_tap_and_double_tap(void **state)
{
	struct gesture_state g;
	struct log l;

	(void)state;
	setup(&g, &l);
	frame(&g, &l, 0, 1, 7, 0.5, 0.5);
	frame(&g, &l, 80, 1, 7, 0.505, 0.5); /* a tremble inside the slop */
	frame(&g, &l, 100, 0);
	assert_int_equal(l.n, 1);
	assert_int_equal(l.ev[0].kind, GESTURE_TAP);
	frame(&g, &l, 300, 1, 8, 0.51, 0.5);
	frame(&g, &l, 380, 0);
	assert_int_equal(l.n, 2);
	assert_int_equal(l.ev[1].kind, GESTURE_DOUBLE_TAP);
	/* A third tap starts over: a tap, not another double tap. */
	frame(&g, &l, 500, 1, 9, 0.5, 0.5);
	frame(&g, &l, 560, 0);
	assert_int_equal(l.ev[2].kind, GESTURE_TAP);
	assert_int_equal(count(&l, GESTURE_DOUBLE_TAP), 1);
}

static void test_slow_taps_are_not_double(void **state)
{
	struct gesture_state g;
	struct log l;

	(void)state;
	setup(&g, &l);
	frame(&g, &l, 0, 1, 1, 0.2, 0.2);
	frame(&g, &l, 100, 0);
	frame(&g, &l, 1000, 1, 2, 0.2, 0.2);
	frame(&g, &l, 1100, 0);
	assert_int_equal(count(&l, GESTURE_TAP), 2);
	assert_int_equal(count(&l, GESTURE_DOUBLE_TAP), 0);
	/* Held too long for a tap, too short for a long press: nothing. */
	frame(&g, &l, 2000, 1, 3, 0.2, 0.2);
	frame(&g, &l, 2400, 0);
	assert_int_equal(l.n, 2);
}

static void test_drag(void **state)
{
	struct gesture_state g;
	struct log l;
	double sx = 0, sy = 0;

	(void)state;
	setup(&g, &l);
	frame(&g, &l, 0, 1, 4, 0.5, 0.5);
	frame(&g, &l, 16, 1, 4, 0.51, 0.5); /* inside the slop: nothing yet */
	assert_int_equal(l.n, 0);
	for (int i = 2; i <= 10; i++)
		frame(&g, &l, 16 * (uint64_t)i, 1, 4, 0.5 + 0.01 * i, 0.5 - 0.005 * i);
	frame(&g, &l, 200, 0);
	for (int i = 0; i < l.n; i++)
		if (l.ev[i].kind == GESTURE_DRAG) {
			sx += l.ev[i].dx;
			sy += l.ev[i].dy;
		}
	/* From the first frame beyond the slop on, every step is reported:
	 * the model follows the finger, it does not jump by the slop. */
	assert_int_equal(count(&l, GESTURE_DRAG), 9);
	assert_float_equal(sx, 0.09, 1e-9);
	assert_float_equal(sy, -0.05, 1e-9);
	assert_int_equal(l.ev[l.n - 1].kind, GESTURE_END);
	assert_int_equal(count(&l, GESTURE_TAP), 0);
	/* No long press after a drag however long it is held. */
	assert_int_equal(gesture_deadline(&g), CLOCK_NEVER);
}

static void test_pinch(void **state)
{
	struct gesture_state g;
	struct log l;
	double scale = 1;

	(void)state;
	setup(&g, &l);
	frame(&g, &l, 0, 1, 1, 0.4, 0.5);
	frame(&g, &l, 10, 2, 1, 0.4, 0.5, 2, 0.6, 0.5);
	frame(&g, &l, 20, 2, 1, 0.35, 0.5, 2, 0.65, 0.5);
	frame(&g, &l, 30, 2, 1, 0.3, 0.5, 2, 0.7, 0.5);
	for (int i = 0; i < l.n; i++)
		if (l.ev[i].kind == GESTURE_PINCH)
			scale *= l.ev[i].scale;
	assert_float_equal(scale, 2.0, 1e-9);
	/* One finger lifts: the other drags on from where it is, no jump. */
	frame(&g, &l, 40, 1, 2, 0.7, 0.5);
	frame(&g, &l, 50, 1, 2, 0.75, 0.5);
	assert_int_equal(l.ev[l.n - 1].kind, GESTURE_DRAG);
	assert_float_equal(l.ev[l.n - 1].dx, 0.05, 1e-9);
	frame(&g, &l, 60, 0);
	assert_int_equal(l.ev[l.n - 1].kind, GESTURE_END);
	assert_int_equal(count(&l, GESTURE_TAP) + count(&l, GESTURE_LONG_PRESS), 0);
	/* Two fingers on one spot: no division by zero, no pinch. */
	setup(&g, &l);
	frame(&g, &l, 0, 2, 1, 0.5, 0.5, 2, 0.5, 0.5);
	frame(&g, &l, 10, 2, 1, 0.5, 0.5, 2, 0.6, 0.5);
	assert_int_equal(count(&l, GESTURE_PINCH), 0);
}

static void test_long_press(void **state)
{
	struct gesture_state g;
	struct log l;

	(void)state;
	setup(&g, &l);
	frame(&g, &l, 1000, 1, 5, 0.5, 0.5);
	assert_int_equal(gesture_deadline(&g), 1700 * MS);
	assert_int_equal(gesture_timeout(&g, 1699 * MS, l.ev), 0);
	l.n += gesture_timeout(&g, 1700 * MS, l.ev + l.n);
	assert_int_equal(l.n, 1);
	assert_int_equal(l.ev[0].kind, GESTURE_LONG_PRESS);
	/* Once: no repeat, and its release is no tap. */
	assert_int_equal(gesture_deadline(&g), CLOCK_NEVER);
	frame(&g, &l, 2500, 0);
	assert_int_equal(l.n, 1);
}

static void test_map_rotation(void **state)
{
	const int rx[2] = {0, 4095}, ry[2] = {100, 2147};
	double x, y;

	(void)state;
	gesture_map(4095, 1123, rx, ry, 0, &x, &y); /* right edge, half way down */
	assert_float_equal(x, 1.0, 1e-9);
	assert_float_equal(y, 0.5, 1e-3);
	/* Turned 90: the picture's right is at the panel's top. */
	gesture_map(2047, 100, rx, ry, 90, &x, &y);
	assert_float_equal(x, 1.0, 1e-3);
	assert_float_equal(y, 0.5, 1e-3);
	gesture_map(0, 100, rx, ry, 180, &x, &y); /* panel's top left: picture's bottom right */
	assert_float_equal(x, 1.0, 1e-9);
	assert_float_equal(y, 1.0, 1e-9);
	gesture_map(0, 1123, rx, ry, 270, &x, &y); /* panel's left: picture's bottom */
	assert_float_equal(x, 0.5, 1e-3);
	assert_float_equal(y, 1.0, 1e-3);
	/* Out of range is clamped; an empty range is the centre. */
	gesture_map(-50, 99999, rx, (const int[2]){5, 5}, 0, &x, &y);
	assert_float_equal(x, 0.0, 1e-9);
	assert_float_equal(y, 0.5, 1e-9);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_tap_and_double_tap),
	    cmocka_unit_test(test_slow_taps_are_not_double),
	    cmocka_unit_test(test_drag),
	    cmocka_unit_test(test_pinch),
	    cmocka_unit_test(test_long_press),
	    cmocka_unit_test(test_map_rotation),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
