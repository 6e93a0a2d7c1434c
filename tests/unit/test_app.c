/* The app state with made-up timestamps: turning, taps, attract mode,
 * matcap cycling, and a rotation that stays a rotation. */
#include "app/app.h"

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
    .matcap_count = 3,
};

static void event(struct app *a, uint64_t t, enum app_action action, bool pressed)
{
	struct app_event ev = {.time_ns = t, .action = action, .pressed = pressed};

	app_handle(a, &ev);
}

/* The angle of a rotation about the vertical axis, signed. */
static double yaw_of(struct quat q)
{
	return 2.0 * atan2(q.y, q.w);
}

static double norm(struct quat q)
{
	return sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
}

static void idle_is_silent(void **state)
{
	struct app a;

	(void)state;
	app_init(&a, &base, 0);
	assert_true(a.dirty); /* the first frame */
	a.dirty = false;
	/* Nothing pressed and no attract mode: no deadline, no frames. */
	assert_int_equal(app_advance(&a, 1 * SEC), CLOCK_NEVER);
	assert_int_equal(app_advance(&a, 3600 * SEC), CLOCK_NEVER);
	assert_false(a.dirty);
	assert_false(app_moving(&a));
}

static void hold_turns_at_speed(void **state)
{
	struct app a;
	uint64_t next;

	(void)state;
	app_init(&a, &base, 0);
	event(&a, 1 * SEC, ACTION_TURN_RIGHT, true);
	/* While held: a frame at the display's rate. */
	next = app_advance(&a, 1 * SEC + 500 * MS);
	assert_true(next > 1 * SEC + 500 * MS && next <= 1 * SEC + 517 * MS);
	assert_true(a.dirty);
	event(&a, 3 * SEC, ACTION_TURN_RIGHT, false);
	assert_float_equal(yaw_of(a.orientation), 180 * DEG, 1e-9);
	/* Released after the tap's minimum: it stops at once. */
	a.dirty = false;
	assert_int_equal(app_advance(&a, 4 * SEC), CLOCK_NEVER);
	assert_false(a.dirty);
	assert_float_equal(yaw_of(a.orientation), 180 * DEG, 1e-9);
}

static void tap_turns_one_step_smoothly(void **state)
{
	struct app a;
	double half;

	(void)state;
	app_init(&a, &base, 0);
	event(&a, 0, ACTION_TURN_LEFT, true);
	event(&a, 1 * MS, ACTION_TURN_LEFT, false);
	/* 5 degrees at 90 degrees/s take 55.6 ms; half way at 27.8 ms. */
	app_advance(&a, 27777778);
	half = yaw_of(a.orientation);
	assert_float_equal(half, -2.5 * DEG, 1e-6);
	assert_true(app_moving(&a));
	app_advance(&a, 40 * MS);
	assert_int_equal(app_advance(&a, 100 * MS), CLOCK_NEVER);
	assert_float_equal(yaw_of(a.orientation), -5 * DEG, 1e-9);
}

static void up_and_down_tilt(void **state)
{
	struct app a;

	(void)state;
	app_init(&a, &base, 0);
	event(&a, 0, ACTION_TURN_DOWN, true);
	event(&a, 1 * SEC, ACTION_TURN_DOWN, false);
	/* 90 degrees about x: w = cos 45, x = sin 45. */
	assert_float_equal(a.orientation.w, cos(M_PI / 4), 1e-9);
	assert_float_equal(a.orientation.x, sin(M_PI / 4), 1e-9);
	assert_float_equal(a.orientation.y, 0, 1e-12);
	/* Left and right together cancel. */
	event(&a, 2 * SEC, ACTION_TURN_LEFT, true);
	event(&a, 2 * SEC, ACTION_TURN_RIGHT, true);
	app_advance(&a, 3 * SEC);
	assert_float_equal(a.orientation.w, cos(M_PI / 4), 1e-9);
}

/* A key and a button both holding "left": letting go of one keeps it. */
static void two_sources_hold_one_turn(void **state)
{
	struct app a;

	(void)state;
	app_init(&a, &base, 0);
	event(&a, 0, ACTION_TURN_LEFT, true);
	event(&a, 100 * MS, ACTION_TURN_LEFT, true);
	event(&a, 200 * MS, ACTION_TURN_LEFT, false);
	app_advance(&a, 1 * SEC);
	assert_float_equal(yaw_of(a.orientation), -90 * DEG, 1e-9);
	event(&a, 1 * SEC, ACTION_TURN_LEFT, false);
	/* A release nobody pressed (a key held at start) is ignored. */
	event(&a, 1 * SEC, ACTION_TURN_LEFT, false);
	assert_false(app_moving(&a));
	event(&a, 2 * SEC, ACTION_TURN_LEFT, true);
	assert_true(app_moving(&a));
}

/* An event stamped before the state's time counts at the state's time. */
static void late_event_counts_now(void **state)
{
	struct app a;

	(void)state;
	app_init(&a, &base, 0);
	app_advance(&a, 10 * SEC);
	event(&a, 9 * SEC, ACTION_TURN_RIGHT, true);
	app_advance(&a, 11 * SEC);
	assert_float_equal(yaw_of(a.orientation), 90 * DEG, 1e-9);
	assert_int_equal(a.last_input_ns, 10 * SEC);
}

static void attract_starts_and_stops(void **state)
{
	struct app_config cfg = base;
	struct app a;

	(void)state;
	cfg.attract_after_s = 60;
	app_init(&a, &cfg, 0);
	a.dirty = false;
	/* Idle: the next change is attract mode, at 60 s. */
	assert_int_equal(app_advance(&a, 30 * SEC), 60 * SEC);
	assert_false(a.attract);
	assert_false(a.dirty);
	assert_int_equal(app_advance(&a, 59 * SEC), 60 * SEC);
	/* Turning from 60 s on, at its own speed, frame by frame. */
	assert_int_equal(app_advance(&a, 62 * SEC), 62 * SEC + 16666667);
	assert_true(a.attract);
	assert_true(a.dirty);
	assert_float_equal(yaw_of(a.orientation), 30 * DEG, 1e-9);
	/* Any press stops it where it is, and acts. */
	event(&a, 63 * SEC, ACTION_NEXT_MATCAP, true);
	assert_false(a.attract);
	assert_int_equal(a.matcap, 1);
	assert_float_equal(yaw_of(a.orientation), 45 * DEG, 1e-9);
	event(&a, 63 * SEC + 100 * MS, ACTION_NEXT_MATCAP, false);
	/* And it starts again 60 s after the last input. */
	assert_int_equal(app_advance(&a, 64 * SEC), 123 * SEC + 100 * MS);
	assert_float_equal(yaw_of(a.orientation), 45 * DEG, 1e-9);
	app_advance(&a, 124 * SEC + 100 * MS);
	assert_true(a.attract);
	assert_float_equal(yaw_of(a.orientation), 60 * DEG, 1e-9);
}

/* A held button is input: no attract mode while it is down. */
static void no_attract_while_held(void **state)
{
	struct app_config cfg = base;
	struct app a;

	(void)state;
	cfg.attract_after_s = 1;
	cfg.turn_speed = 0.0001;
	app_init(&a, &cfg, 0);
	event(&a, 0, ACTION_TURN_LEFT, true);
	app_advance(&a, 10 * SEC);
	assert_false(a.attract);
	event(&a, 10 * SEC, ACTION_TURN_LEFT, false);
	app_advance(&a, 12 * SEC);
	assert_true(a.attract);
}

static void matcaps_and_camera(void **state)
{
	struct app a;

	(void)state;
	app_init(&a, &base, 0);
	event(&a, 1, ACTION_PREV_MATCAP, true);
	assert_int_equal(a.matcap, 2);
	event(&a, 2, ACTION_NEXT_MATCAP, true);
	event(&a, 3, ACTION_NEXT_MATCAP, true);
	assert_int_equal(a.matcap, 1);
	/* No camera: the toggle changes nothing and draws nothing. */
	a.dirty = false;
	event(&a, 4, ACTION_TOGGLE_CAMERA, true);
	assert_false(a.camera_on);
	assert_false(a.dirty);
	app_set_camera_available(&a, true);
	event(&a, 5, ACTION_TOGGLE_CAMERA, true);
	assert_true(a.camera_on);
	assert_true(a.dirty);
	/* The camera is the last entry of the cycle: next wraps to the first. */
	event(&a, 6, ACTION_NEXT_MATCAP, true);
	assert_false(a.camera_on);
	assert_int_equal(a.matcap, 0);
	event(&a, 7, ACTION_TOGGLE_CAMERA, true);
	app_set_camera_available(&a, false);
	assert_false(a.camera_on);
	/* Fewer matcaps than the index: back to the first. */
	app_set_matcap_count(&a, 1);
	assert_int_equal(a.matcap, 0);
	event(&a, 8, ACTION_NEXT_MATCAP, true);
	assert_int_equal(a.matcap, 0);
}

/* Three buttons reach every matcap and the camera: it is one more entry
 * of the cycle, after the images, only while a camera is there. */
static void camera_is_one_more_entry_in_the_cycle(void **state)
{
	struct app a;

	(void)state;
	app_init(&a, &base, 0);
	app_set_camera_available(&a, true);
	event(&a, 1, ACTION_NEXT_MATCAP, true);
	event(&a, 2, ACTION_NEXT_MATCAP, true);
	assert_int_equal(a.matcap, 2);
	assert_false(a.camera_on);
	event(&a, 3, ACTION_NEXT_MATCAP, true);
	assert_true(a.camera_on);
	event(&a, 4, ACTION_NEXT_MATCAP, true);
	assert_false(a.camera_on);
	assert_int_equal(a.matcap, 0);
	event(&a, 5, ACTION_PREV_MATCAP, true);
	assert_true(a.camera_on);
	event(&a, 6, ACTION_PREV_MATCAP, true);
	assert_false(a.camera_on);
	assert_int_equal(a.matcap, 2);
	/* Unplugged: the cycle has the images only. */
	app_set_camera_available(&a, false);
	event(&a, 7, ACTION_NEXT_MATCAP, true);
	assert_false(a.camera_on);
	assert_int_equal(a.matcap, 0);
}

static void mode_and_reset(void **state)
{
	struct app_config cfg = base;
	struct app a;

	(void)state;
	cfg.rest = quat_from_axis_angle(1, 0, 0, 20 * DEG);
	app_init(&a, &cfg, 0);
	event(&a, 0, ACTION_NEXT_MODE, true);
	assert_int_equal(a.mode, SHADING_SEM_VERTEX);
	for (int i = 0; i < SHADING_MODE_COUNT - 1; i++)
		event(&a, 0, ACTION_NEXT_MODE, true);
	assert_int_equal(a.mode, SHADING_VIEW);
	event(&a, 0, ACTION_NEXT_MODE, true);
	event(&a, 0, ACTION_TURN_LEFT, true);
	event(&a, 10 * MS, ACTION_TURN_LEFT, false); /* coasting on to 55 ms */
	event(&a, 20 * MS, ACTION_RESET, true);
	app_advance(&a, 1 * SEC);
	assert_int_equal(a.mode, SHADING_VIEW);
	assert_float_equal(a.orientation.w, cfg.rest.w, 1e-12);
	assert_float_equal(a.orientation.x, cfg.rest.x, 1e-12);
	assert_float_equal(a.orientation.y, 0, 1e-12);
}

/* A million small turns about both axes, by taps and by frames: still a
 * unit quaternion, and still the rotation the sum of the turns gives. */
static void million_turns_stay_normalised(void **state)
{
	struct app a;
	uint64_t t = 0;

	(void)state;
	app_init(&a, &base, 0);
	for (int i = 0; i < 1000000; i++) {
		enum app_action act = i % 2 ? ACTION_TURN_UP : ACTION_TURN_RIGHT;

		event(&a, t, act, true);
		t += 1 * MS;
		event(&a, t, act, false);
		t += 60 * MS; /* past the tap's 55.6 ms */
		app_advance(&a, t);
		assert_true(fabs(norm(a.orientation) - 1.0) < 1e-12);
	}
	assert_true(isfinite(a.orientation.w));
	/* Held for a million frames of 1 ms. */
	app_init(&a, &base, 0);
	event(&a, 0, ACTION_TURN_RIGHT, true);
	for (int i = 1; i <= 1000000; i++)
		app_advance(&a, (uint64_t)i * MS);
	assert_true(fabs(norm(a.orientation) - 1.0) < 1e-12);
	/* 1000 s at 90 degrees/s is 250 whole turns: back where it began. */
	assert_float_equal(fabs(a.orientation.w), 1.0, 1e-6);
}

static void action_names_match_the_enum(void **state)
{
	(void)state;
	assert_string_equal(app_action_names[ACTION_NONE], "none");
	assert_string_equal(app_action_names[ACTION_TURN_LEFT], "turn-left");
	assert_string_equal(app_action_names[ACTION_TURN_DOWN], "turn-down");
	assert_string_equal(app_action_names[ACTION_NEXT_MATCAP], "next-matcap");
	assert_string_equal(app_action_names[ACTION_TOGGLE_CAMERA], "toggle-camera");
	assert_string_equal(app_action_names[ACTION_RESET], "reset");
	assert_null(app_action_names[ACTION_COUNT]);
	assert_true(app_action_is_turn(ACTION_TURN_UP));
	assert_false(app_action_is_turn(ACTION_NEXT_MATCAP));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(idle_is_silent),
	    cmocka_unit_test(hold_turns_at_speed),
	    cmocka_unit_test(tap_turns_one_step_smoothly),
	    cmocka_unit_test(up_and_down_tilt),
	    cmocka_unit_test(two_sources_hold_one_turn),
	    cmocka_unit_test(late_event_counts_now),
	    cmocka_unit_test(attract_starts_and_stops),
	    cmocka_unit_test(no_attract_while_held),
	    cmocka_unit_test(matcaps_and_camera),
	    cmocka_unit_test(camera_is_one_more_entry_in_the_cycle),
	    cmocka_unit_test(mode_and_reset),
	    cmocka_unit_test(million_turns_stay_normalised),
	    cmocka_unit_test(action_names_match_the_enum),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
