/* Touch gestures in the app state, with made-up timestamps: a drag turns
 * as the arrows do, a pinch zooms within bounds, a double tap resets, a
 * long press does what it is set to; nothing that changes nothing asks
 * for a frame. And the zoom as the renderer applies it. */
#include "state/app.h"
#include "render/render.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define MS  1000000ull
#define SEC 1000000000ull
#define DEG (M_PI / 180.0)

static const struct app_config base = {
    .turn_speed = 90 * DEG,
    .turn_step = 5 * DEG,
    .attract_after_s = 0,
    .attract_speed = 15 * DEG,
    .rest = {1, 0, 0, 0},
    .mode = SHADING_VIEW,
    .drag_speed = 180 * DEG,
    .long_press = ACTION_NEXT_MATCAP,
};

#define MATCAPS 3

static void gesture(struct app *a, enum gesture_kind kind, uint64_t t, double dx, double dy,
		    double scale)
{
	struct app_msg m = {
	    .kind = APP_TOUCH,
	    .touch = {.kind = kind, .time_ns = t, .dx = dx, .dy = dy, .scale = scale}};

	app_apply(a, &m);
}

static void key(struct app *a, uint64_t t, enum app_action action, bool pressed)
{
	struct app_msg m = {.kind = APP_INPUT,
			    .input = {.time_ns = t, .action = action, .pressed = pressed}};

	app_apply(a, &m);
}

static void drawn(struct app *a)
{
	struct app_msg m = {.kind = APP_FRAME_SHOWN};

	app_apply(a, &m);
}

static double yaw_of(struct quat q)
{
	return 2.0 * atan2(q.y, q.w);
}

static double pitch_of(struct quat q)
{
	return 2.0 * atan2(q.x, q.w);
}

static void drag_turns_like_the_arrows(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0), *b = app_new(&base, MATCAPS, 0);

	(void)state;
	drawn(a);
	/* A tenth of the screen to the right: 18 degrees at 180 per screen. */
	gesture(a, GESTURE_DRAG, 10 * MS, 0.1, 0, 0);
	assert_true(app_state(a)->dirty);
	assert_float_equal(yaw_of(app_state(a)->orientation), 18 * DEG, 1e-9);
	/* The same way round as the right arrow. */
	key(b, 0, ACTION_TURN_RIGHT, true);
	key(b, 10 * MS, ACTION_TURN_RIGHT, false);
	app_advance(b, SEC);
	assert_true(yaw_of(app_state(b)->orientation) > 0);
	/* Down is the down arrow's way. */
	app_free(b);
	b = app_new(&base, MATCAPS, 0);
	gesture(b, GESTURE_DRAG, 10 * MS, 0, 0.05, 0);
	assert_float_equal(pitch_of(app_state(b)->orientation), 9 * DEG, 1e-9);
	/* A drag that did not move changes nothing: no frame. */
	drawn(a);
	gesture(a, GESTURE_DRAG, 20 * MS, 0, 0, 0);
	assert_false(app_state(a)->dirty);
	gesture(a, GESTURE_END, 30 * MS, 0, 0, 0);
	gesture(a, GESTURE_TAP, 40 * MS, 0, 0, 0);
	assert_false(app_state(a)->dirty);
	assert_false(app_moving(a));
	app_free(a);
	app_free(b);
}

static void pinch_zooms_within_bounds(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0);

	(void)state;
	assert_float_equal(app_state(a)->zoom, 1.0, 0);
	drawn(a);
	gesture(a, GESTURE_PINCH, 10 * MS, 0, 0, 1.5);
	assert_true(app_state(a)->dirty);
	assert_float_equal(app_state(a)->zoom, 1.5, 1e-12);
	for (int i = 0; i < 20; i++)
		gesture(a, GESTURE_PINCH, (20 + (uint64_t)i) * MS, 0, 0, 2.0);
	assert_float_equal(app_state(a)->zoom, APP_ZOOM_MAX, 0);
	/* At the bound a pinch outwards changes nothing: no frame. */
	drawn(a);
	gesture(a, GESTURE_PINCH, 50 * MS, 0, 0, 1.2);
	assert_false(app_state(a)->dirty);
	for (int i = 0; i < 20; i++)
		gesture(a, GESTURE_PINCH, (60 + (uint64_t)i) * MS, 0, 0, 0.5);
	assert_float_equal(app_state(a)->zoom, APP_ZOOM_MIN, 0);
	/* Nonsense scales are ignored. */
	drawn(a);
	gesture(a, GESTURE_PINCH, 90 * MS, 0, 0, 0);
	gesture(a, GESTURE_PINCH, 91 * MS, 0, 0, -2);
	gesture(a, GESTURE_PINCH, 92 * MS, 0, 0, NAN);
	assert_false(app_state(a)->dirty);
	assert_float_equal(app_state(a)->zoom, APP_ZOOM_MIN, 0);
	app_free(a);
}

static void double_tap_returns_to_the_start_view(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0);

	(void)state;
	gesture(a, GESTURE_DRAG, 10 * MS, 0.3, 0.2, 0);
	gesture(a, GESTURE_PINCH, 20 * MS, 0, 0, 2.0);
	key(a, 30 * MS, ACTION_NEXT_MODE, true);
	drawn(a);
	gesture(a, GESTURE_DOUBLE_TAP, 40 * MS, 0, 0, 0);
	assert_true(app_state(a)->dirty);
	assert_float_equal(app_state(a)->zoom, 1.0, 0);
	assert_float_equal(app_state(a)->orientation.w, 1.0, 1e-12);
	assert_int_equal(app_state(a)->mode, SHADING_VIEW);
	/* The reset action also takes the zoom back. */
	gesture(a, GESTURE_PINCH, 50 * MS, 0, 0, 3.0);
	key(a, 60 * MS, ACTION_RESET, true);
	assert_float_equal(app_state(a)->zoom, 1.0, 0);
	app_free(a);
}

static void long_press_does_what_it_is_set_to(void **state)
{
	struct app_config cfg = base;
	struct app *a = app_new(&cfg, MATCAPS, 0);

	(void)state;
	drawn(a);
	gesture(a, GESTURE_LONG_PRESS, 700 * MS, 0, 0, 0);
	assert_int_equal(app_state(a)->matcap, 1);
	assert_true(app_state(a)->dirty);
	app_free(a);

	/* A turn: one step, as a tap of the button, and then still. */
	cfg.long_press = ACTION_TURN_LEFT;
	a = app_new(&cfg, MATCAPS, 0);
	gesture(a, GESTURE_LONG_PRESS, 700 * MS, 0, 0, 0);
	app_advance(a, 2 * SEC);
	assert_false(app_moving(a));
	assert_float_equal(yaw_of(app_state(a)->orientation), -5 * DEG, 1e-6);
	app_free(a);

	cfg.long_press = ACTION_NONE;
	a = app_new(&cfg, MATCAPS, 0);
	drawn(a);
	gesture(a, GESTURE_LONG_PRESS, 700 * MS, 0, 0, 0);
	assert_false(app_state(a)->dirty);
	assert_int_equal(app_state(a)->matcap, 0);
	app_free(a);
}

static void a_touch_is_an_input(void **state)
{
	struct app_config cfg = base;
	struct app *a;
	struct quat before;

	(void)state;
	cfg.attract_after_s = 1;
	a = app_new(&cfg, MATCAPS, 0);
	app_advance(a, 2 * SEC);
	assert_true(app_moving(a)); /* attract mode */
	gesture(a, GESTURE_TAP, 2 * SEC, 0, 0, 0);
	assert_false(app_moving(a));
	assert_int_equal(app_state(a)->last_input_ns, 2 * SEC);
	before = app_state(a)->orientation;
	app_advance(a, 2 * SEC + 500 * MS);
	assert_memory_equal(&before, &app_state(a)->orientation, sizeof(before));
	app_free(a);
}

/* Zoom 0 and 1 are the fitted picture (the golden images); 2 doubles it
 * about the centre. */
static void render_zooms_about_the_centre(void **state)
{
	struct view v = {.orientation = {1, 0, 0, 0}};
	float mv[16], p1[16], p0[16], p2[16];

	(void)state;
	render_matrices(&v, 640, 480, mv, p0);
	v.zoom = 1;
	render_matrices(&v, 640, 480, mv, p1);
	assert_memory_equal(p0, p1, sizeof(p0));
	v.zoom = 2;
	render_matrices(&v, 640, 480, mv, p2);
	for (int c = 0; c < 4; c++) {
		assert_float_equal(p2[4 * c], 2 * p1[4 * c], 1e-6);
		assert_float_equal(p2[4 * c + 1], 2 * p1[4 * c + 1], 1e-6);
		assert_float_equal(p2[4 * c + 2], p1[4 * c + 2], 0);
		assert_float_equal(p2[4 * c + 3], p1[4 * c + 3], 0);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(drag_turns_like_the_arrows),
	    cmocka_unit_test(pinch_zooms_within_bounds),
	    cmocka_unit_test(double_tap_returns_to_the_start_view),
	    cmocka_unit_test(long_press_does_what_it_is_set_to),
	    cmocka_unit_test(a_touch_is_an_input),
	    cmocka_unit_test(render_zooms_about_the_centre),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
