/* Touchscreen events as the kernel sends them (type-B slots, single
 * touch), replayed into the decoder and on into the gestures. */
#include "input/touch_decode.h"

#include <linux/input.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

static const int RX[2] = {0, 1000}, RY[2] = {0, 1000};

struct frames {
	struct gesture_point pts[GESTURE_MAX_POINTS];
	int n, reports;
};

static void ev(struct touch_decoder *d, struct frames *f, unsigned int type, unsigned int code,
	       int value)
{
	f->reports += touch_decoder_event(d, type, code, value, f->pts, &f->n);
}

static void test_multitouch_slots(void **state)
{
	struct touch_decoder d;
	struct frames f = {0};

	(void)state;
	touch_decoder_init(&d, true, RX, RY, 0);
	/* First finger in slot 0. */
	ev(&d, &f, EV_ABS, ABS_MT_SLOT, 0);
	ev(&d, &f, EV_ABS, ABS_MT_TRACKING_ID, 45);
	ev(&d, &f, EV_ABS, ABS_MT_POSITION_X, 100);
	ev(&d, &f, EV_ABS, ABS_MT_POSITION_Y, 200);
	ev(&d, &f, EV_SYN, SYN_REPORT, 0);
	assert_int_equal(f.reports, 1);
	assert_int_equal(f.n, 1);
	assert_int_equal(f.pts[0].id, 45);
	assert_float_equal(f.pts[0].x, 0.1, 1e-9);
	assert_float_equal(f.pts[0].y, 0.2, 1e-9);
	/* A second finger in slot 1; the first moves in x only (the
	 * kernel sends only what changed). */
	ev(&d, &f, EV_ABS, ABS_MT_SLOT, 1);
	ev(&d, &f, EV_ABS, ABS_MT_TRACKING_ID, 46);
	ev(&d, &f, EV_ABS, ABS_MT_POSITION_X, 900);
	ev(&d, &f, EV_ABS, ABS_MT_POSITION_Y, 800);
	ev(&d, &f, EV_ABS, ABS_MT_SLOT, 0);
	ev(&d, &f, EV_ABS, ABS_MT_POSITION_X, 150);
	ev(&d, &f, EV_SYN, SYN_REPORT, 0);
	assert_int_equal(f.n, 2);
	assert_float_equal(f.pts[0].x, 0.15, 1e-9);
	assert_float_equal(f.pts[0].y, 0.2, 1e-9);
	assert_int_equal(f.pts[1].id, 46);
	assert_float_equal(f.pts[1].y, 0.8, 1e-9);
	/* The first lifts: only the second is left. */
	ev(&d, &f, EV_ABS, ABS_MT_TRACKING_ID, -1);
	ev(&d, &f, EV_SYN, SYN_REPORT, 0);
	assert_int_equal(f.n, 1);
	assert_int_equal(f.pts[0].id, 46);
	/* A slot the decoder does not follow is ignored, not written. */
	ev(&d, &f, EV_ABS, ABS_MT_SLOT, 60);
	ev(&d, &f, EV_ABS, ABS_MT_TRACKING_ID, 47);
	ev(&d, &f, EV_SYN, SYN_REPORT, 0);
	assert_int_equal(f.n, 1);
}

static void test_single_touch(void **state)
{
	struct touch_decoder d;
	struct frames f = {0};

	(void)state;
	touch_decoder_init(&d, false, RX, RY, 180);
	ev(&d, &f, EV_ABS, ABS_X, 250);
	ev(&d, &f, EV_ABS, ABS_Y, 0);
	ev(&d, &f, EV_KEY, BTN_TOUCH, 1);
	ev(&d, &f, EV_SYN, SYN_REPORT, 0);
	assert_int_equal(f.n, 1);
	/* The panel is upside down: its top left quarter is the picture's
	 * bottom right. */
	assert_float_equal(f.pts[0].x, 0.75, 1e-9);
	assert_float_equal(f.pts[0].y, 1.0, 1e-9);
	ev(&d, &f, EV_KEY, BTN_TOUCH, 0);
	ev(&d, &f, EV_SYN, SYN_REPORT, 0);
	assert_int_equal(f.n, 0);
}

/* From the kernel's events to a gesture: two fingers spreading pinch. */
static void test_events_to_pinch(void **state)
{
	struct touch_decoder d;
	struct gesture_state g;
	struct gesture_config cfg;
	struct gesture out[GESTURE_MAX_EVENTS];
	struct frames f = {0};
	double scale = 1;

	(void)state;
	touch_decoder_init(&d, true, RX, RY, 0);
	gesture_config_defaults(&cfg);
	gesture_init(&g, &cfg);
	for (int step = 0; step < 5; step++) {
		ev(&d, &f, EV_ABS, ABS_MT_SLOT, 0);
		if (step == 0)
			ev(&d, &f, EV_ABS, ABS_MT_TRACKING_ID, 1);
		ev(&d, &f, EV_ABS, ABS_MT_POSITION_X, 400 - 50 * step);
		ev(&d, &f, EV_ABS, ABS_MT_POSITION_Y, 500);
		ev(&d, &f, EV_ABS, ABS_MT_SLOT, 1);
		if (step == 0)
			ev(&d, &f, EV_ABS, ABS_MT_TRACKING_ID, 2);
		ev(&d, &f, EV_ABS, ABS_MT_POSITION_X, 600 + 50 * step);
		ev(&d, &f, EV_ABS, ABS_MT_POSITION_Y, 500);
		ev(&d, &f, EV_SYN, SYN_REPORT, 0);
		if (gesture_frame(&g, (uint64_t)step * 10000000ull, f.pts, f.n, out) &&
		    out[0].kind == GESTURE_PINCH)
			scale *= out[0].scale;
	}
	assert_float_equal(scale, 600.0 / 200.0, 1e-9);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_multitouch_slots),
	    cmocka_unit_test(test_single_touch),
	    cmocka_unit_test(test_events_to_pinch),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
