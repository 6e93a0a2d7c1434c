/* The app state with made-up timestamps: turning, taps, attract mode,
 * matcap cycling, and a rotation that stays a rotation. */
#include "state/app.h"

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
};

#define MATCAPS 3 /* image matcaps in the cycle */

static void event(struct app *a, uint64_t t, enum app_action action, bool pressed)
{
	struct app_msg m = {.kind = APP_INPUT,
			    .input = {.time_ns = t, .action = action, .pressed = pressed}};

	app_apply(a, &m);
}

static const struct app_state *st(const struct app *a)
{
	return app_state(a);
}

/* The loop drew the state. */
static void drawn(struct app *a)
{
	struct app_msg m = {.kind = APP_FRAME_SHOWN};

	app_apply(a, &m);
}

static void camera(struct app *a, bool available, bool frame)
{
	struct app_msg m = {.kind = APP_CAMERA, .camera = {available, frame}};

	app_apply(a, &m);
}

static void matcaps(struct app *a, int count, int shown)
{
	struct app_msg m = {.kind = APP_MATCAPS, .matcaps = {count, shown}};

	app_apply(a, &m);
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
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	assert_true(st(a)->dirty); /* the first frame */
	drawn(a);
	/* Nothing pressed and no attract mode: no deadline, no frames. */
	assert_int_equal(app_advance(a, 1 * SEC), CLOCK_NEVER);
	assert_int_equal(app_advance(a, 3600 * SEC), CLOCK_NEVER);
	assert_false(st(a)->dirty);
	assert_false(app_moving(a));
	app_free(a);
}

static void hold_turns_at_speed(void **state)
{
	struct app *a;
	uint64_t next;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	event(a, 1 * SEC, ACTION_TURN_RIGHT, true);
	/* While held: a frame at the display's rate. */
	next = app_advance(a, 1 * SEC + 500 * MS);
	assert_true(next > 1 * SEC + 500 * MS && next <= 1 * SEC + 517 * MS);
	assert_true(st(a)->dirty);
	event(a, 3 * SEC, ACTION_TURN_RIGHT, false);
	assert_float_equal(yaw_of(st(a)->orientation), 180 * DEG, 1e-9);
	/* Released after the tap's minimum: it stops at once. */
	drawn(a);
	assert_int_equal(app_advance(a, 4 * SEC), CLOCK_NEVER);
	assert_false(st(a)->dirty);
	assert_float_equal(yaw_of(st(a)->orientation), 180 * DEG, 1e-9);
	app_free(a);
}

static void tap_turns_one_step_smoothly(void **state)
{
	struct app *a;
	double half;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	event(a, 0, ACTION_TURN_LEFT, true);
	event(a, 1 * MS, ACTION_TURN_LEFT, false);
	/* 5 degrees at 90 degrees/s take 55.6 ms; half way at 27.8 ms. */
	app_advance(a, 27777778);
	half = yaw_of(st(a)->orientation);
	assert_float_equal(half, -2.5 * DEG, 1e-6);
	assert_true(app_moving(a));
	app_advance(a, 40 * MS);
	assert_int_equal(app_advance(a, 100 * MS), CLOCK_NEVER);
	assert_float_equal(yaw_of(st(a)->orientation), -5 * DEG, 1e-9);
	app_free(a);
}

static void up_and_down_tilt(void **state)
{
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	event(a, 0, ACTION_TURN_DOWN, true);
	event(a, 1 * SEC, ACTION_TURN_DOWN, false);
	/* 90 degrees about x: w = cos 45, x = sin 45. */
	assert_float_equal(st(a)->orientation.w, cos(M_PI / 4), 1e-9);
	assert_float_equal(st(a)->orientation.x, sin(M_PI / 4), 1e-9);
	assert_float_equal(st(a)->orientation.y, 0, 1e-12);
	/* Left and right together cancel. */
	event(a, 2 * SEC, ACTION_TURN_LEFT, true);
	event(a, 2 * SEC, ACTION_TURN_RIGHT, true);
	app_advance(a, 3 * SEC);
	assert_float_equal(st(a)->orientation.w, cos(M_PI / 4), 1e-9);
	app_free(a);
}

/* A key and a button both holding "left": letting go of one keeps it. */
static void two_sources_hold_one_turn(void **state)
{
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	event(a, 0, ACTION_TURN_LEFT, true);
	event(a, 100 * MS, ACTION_TURN_LEFT, true);
	event(a, 200 * MS, ACTION_TURN_LEFT, false);
	app_advance(a, 1 * SEC);
	assert_float_equal(yaw_of(st(a)->orientation), -90 * DEG, 1e-9);
	event(a, 1 * SEC, ACTION_TURN_LEFT, false);
	/* A release nobody pressed (a key held at start) is ignored. */
	event(a, 1 * SEC, ACTION_TURN_LEFT, false);
	assert_false(app_moving(a));
	event(a, 2 * SEC, ACTION_TURN_LEFT, true);
	assert_true(app_moving(a));
	app_free(a);
}

/* An event stamped before the state's time counts at the state's time. */
static void late_event_counts_now(void **state)
{
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	app_advance(a, 10 * SEC);
	event(a, 9 * SEC, ACTION_TURN_RIGHT, true);
	app_advance(a, 11 * SEC);
	assert_float_equal(yaw_of(st(a)->orientation), 90 * DEG, 1e-9);
	assert_int_equal(st(a)->last_input_ns, 10 * SEC);
	app_free(a);
}

static void attract_starts_and_stops(void **state)
{
	struct app_config cfg = base;
	struct app *a;

	(void)state;
	cfg.attract_after_s = 60;
	a = app_new(&cfg, MATCAPS, 0);
	drawn(a);
	/* Idle: the next change is attract mode, at 60 s. */
	assert_int_equal(app_advance(a, 30 * SEC), 60 * SEC);
	assert_false(app_moving(a));
	assert_false(st(a)->dirty);
	assert_int_equal(app_advance(a, 59 * SEC), 60 * SEC);
	/* Turning from 60 s on, at its own speed, frame by frame. */
	assert_int_equal(app_advance(a, 62 * SEC), 62 * SEC + 16666667);
	assert_true(app_moving(a));
	assert_true(st(a)->dirty);
	assert_float_equal(yaw_of(st(a)->orientation), 30 * DEG, 1e-9);
	/* Any press stops it where it is, and acts. */
	event(a, 63 * SEC, ACTION_NEXT_MATCAP, true);
	assert_false(app_moving(a));
	assert_int_equal(st(a)->matcap, 1);
	assert_float_equal(yaw_of(st(a)->orientation), 45 * DEG, 1e-9);
	event(a, 63 * SEC + 100 * MS, ACTION_NEXT_MATCAP, false);
	/* And it starts again 60 s after the last input. */
	assert_int_equal(app_advance(a, 64 * SEC), 123 * SEC + 100 * MS);
	assert_float_equal(yaw_of(st(a)->orientation), 45 * DEG, 1e-9);
	/* It glides home first (no snap), then turns from there: 45
	 * degrees back at 15 a second take the longest glide, 4 s. */
	app_advance(a, 124 * SEC + 100 * MS);
	assert_true(app_moving(a));
	assert_true(yaw_of(st(a)->orientation) < 45 * DEG);
	assert_true(yaw_of(st(a)->orientation) > 0);
	app_advance(a, 128 * SEC + 100 * MS);
	assert_float_equal(yaw_of(st(a)->orientation), 15 * DEG, 1e-9);
	app_free(a);
}

static void models(struct app *a, int count, int shown)
{
	struct app_msg m = {.kind = APP_MODELS, .models = {count, shown}};

	app_apply(a, &m);
}

/* next/prev-model wrap around the models; with one model they do nothing.
 * The model shown (one was passed over) is where the next step starts. */
static void models_cycle(void **state)
{
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	event(a, 1 * SEC, ACTION_NEXT_MODEL, true);
	assert_int_equal(st(a)->model, 0);
	models(a, 3, 0);
	event(a, 2 * SEC, ACTION_NEXT_MODEL, true);
	assert_int_equal(st(a)->model, 1);
	assert_int_equal(st(a)->model_step, 1);
	event(a, 3 * SEC, ACTION_PREV_MODEL, true);
	event(a, 4 * SEC, ACTION_PREV_MODEL, true);
	assert_int_equal(st(a)->model, 2);
	assert_int_equal(st(a)->model_step, -1);
	/* The second was broken: the loop showed the first instead. */
	drawn(a);
	models(a, 3, 0);
	assert_int_equal(st(a)->model, 0);
	assert_true(st(a)->dirty);
	/* A folder that shrank: the wanted one stays in it. */
	event(a, 5 * SEC, ACTION_PREV_MODEL, true);
	models(a, 2, -1);
	assert_int_equal(st(a)->model, 0);
	app_free(a);
}

/* Attract mode draws at attract_fps, not at every vblank; the turn is
 * still as fast, and any input stops it at once. */
static void attract_frame_rate_capped(void **state)
{
	struct app_config cfg = base;
	struct app *a;

	(void)state;
	cfg.attract_after_s = 1;
	cfg.attract_fps = 10;
	a = app_new(&cfg, MATCAPS, 0);
	drawn(a);
	assert_int_equal(app_advance(a, 500 * MS), 1 * SEC);
	/* Starting at 1 s: the first frame a tenth of a second later. */
	assert_int_equal(app_advance(a, 1 * SEC), 1 * SEC + 100 * MS);
	assert_false(st(a)->dirty);
	/* A vblank 16 ms on: nothing to draw yet. */
	assert_int_equal(app_advance(a, 1 * SEC + 16 * MS), 1 * SEC + 100 * MS);
	assert_false(st(a)->dirty);
	assert_int_equal(app_advance(a, 1 * SEC + 100 * MS), 1 * SEC + 200 * MS);
	assert_true(st(a)->dirty);
	assert_float_equal(yaw_of(st(a)->orientation), 1.5 * DEG, 1e-9);
	drawn(a);
	app_advance(a, 2 * SEC);
	assert_float_equal(yaw_of(st(a)->orientation), 15 * DEG, 1e-9);
	event(a, 2 * SEC + 10 * MS, ACTION_NEXT_MATCAP, true);
	assert_false(app_moving(a));
	assert_float_equal(yaw_of(st(a)->orientation), 15 * DEG, 1e-9);
	app_free(a);
}

/* attract_model_seconds: attract mode steps through the models; input
 * stops that too. */
static void attract_steps_models(void **state)
{
	struct app_config cfg = base;
	struct app *a;

	(void)state;
	cfg.attract_after_s = 10;
	cfg.attract_fps = 30;
	cfg.attract_model_s = 5;
	a = app_new(&cfg, MATCAPS, 0);
	models(a, 3, 0);
	app_advance(a, 12 * SEC);
	assert_int_equal(st(a)->model, 0);
	/* Due at 15 s: the deadline says so even between frames. */
	assert_true(app_advance(a, 14 * SEC + 990 * MS) <= 15 * SEC);
	app_advance(a, 15 * SEC);
	assert_int_equal(st(a)->model, 1);
	app_advance(a, 20 * SEC);
	assert_int_equal(st(a)->model, 2);
	app_advance(a, 25 * SEC);
	assert_int_equal(st(a)->model, 0);
	event(a, 26 * SEC, ACTION_TURN_UP, true);
	event(a, 26 * SEC, ACTION_TURN_UP, false);
	app_advance(a, 34 * SEC);
	assert_int_equal(st(a)->model, 0);
	app_free(a);
}

/* A held button is input: no attract mode while it is down. */
static void no_attract_while_held(void **state)
{
	struct app_config cfg = base;
	struct app *a;

	(void)state;
	cfg.attract_after_s = 1;
	cfg.turn_speed = 0.0001;
	a = app_new(&cfg, MATCAPS, 0);
	event(a, 0, ACTION_TURN_LEFT, true);
	app_advance(a, 10 * SEC);
	/* Only the held turn's 0.001 radians, no attract turn. */
	assert_float_equal(yaw_of(st(a)->orientation), -0.001, 1e-9);
	event(a, 10 * SEC, ACTION_TURN_LEFT, false);
	app_advance(a, 12 * SEC);
	assert_true(app_moving(a));
	assert_true(yaw_of(st(a)->orientation) > 0.1);
	app_free(a);
}

static void matcaps_and_camera(void **state)
{
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	event(a, 1, ACTION_PREV_MATCAP, true);
	assert_int_equal(st(a)->matcap, 2);
	event(a, 2, ACTION_NEXT_MATCAP, true);
	event(a, 3, ACTION_NEXT_MATCAP, true);
	assert_int_equal(st(a)->matcap, 1);
	/* No camera: the toggle changes nothing and draws nothing. */
	drawn(a);
	event(a, 4, ACTION_TOGGLE_CAMERA, true);
	assert_false(st(a)->camera_on);
	assert_false(st(a)->dirty);
	/* The first camera found is shown at once; the toggle switches. */
	camera(a, true, false);
	assert_true(st(a)->camera_on);
	event(a, 5, ACTION_TOGGLE_CAMERA, true);
	assert_false(st(a)->camera_on);
	drawn(a);
	event(a, 5, ACTION_TOGGLE_CAMERA, true);
	assert_true(st(a)->camera_on);
	assert_true(st(a)->dirty);
	/* The camera is the last entry of the cycle: next wraps to the first. */
	event(a, 6, ACTION_NEXT_MATCAP, true);
	assert_false(st(a)->camera_on);
	assert_int_equal(st(a)->matcap, 0);
	event(a, 7, ACTION_TOGGLE_CAMERA, true);
	camera(a, false, false);
	assert_false(st(a)->camera_on);
	/* Fewer matcaps than the index: back to the first. */
	matcaps(a, 1, -1);
	assert_int_equal(st(a)->matcap, 0);
	event(a, 8, ACTION_NEXT_MATCAP, true);
	assert_int_equal(st(a)->matcap, 0);
	app_free(a);
}

/* Three buttons reach every matcap and the camera: it is one more entry
 * of the cycle, after the images, only while a camera is there. */
static void camera_is_one_more_entry_in_the_cycle(void **state)
{
	struct app *a;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	camera(a, true, false);
	event(a, 0, ACTION_TOGGLE_CAMERA, true); /* shown when found: off again */
	event(a, 1, ACTION_NEXT_MATCAP, true);
	event(a, 2, ACTION_NEXT_MATCAP, true);
	assert_int_equal(st(a)->matcap, 2);
	assert_false(st(a)->camera_on);
	event(a, 3, ACTION_NEXT_MATCAP, true);
	assert_true(st(a)->camera_on);
	event(a, 4, ACTION_NEXT_MATCAP, true);
	assert_false(st(a)->camera_on);
	assert_int_equal(st(a)->matcap, 0);
	event(a, 5, ACTION_PREV_MATCAP, true);
	assert_true(st(a)->camera_on);
	event(a, 6, ACTION_PREV_MATCAP, true);
	assert_false(st(a)->camera_on);
	assert_int_equal(st(a)->matcap, 2);
	/* Unplugged: the cycle has the images only. */
	camera(a, false, false);
	event(a, 7, ACTION_NEXT_MATCAP, true);
	assert_false(st(a)->camera_on);
	assert_int_equal(st(a)->matcap, 0);
	app_free(a);
}

static void mode_and_reset(void **state)
{
	struct app_config cfg = base;
	struct app *a;

	(void)state;
	cfg.rest = quat_from_axis_angle(1, 0, 0, 20 * DEG);
	a = app_new(&cfg, MATCAPS, 0);
	event(a, 0, ACTION_NEXT_MODE, true);
	assert_int_equal(st(a)->mode, SHADING_SEM_VERTEX);
	for (int i = 0; i < SHADING_MODE_COUNT - 1; i++)
		event(a, 0, ACTION_NEXT_MODE, true);
	assert_int_equal(st(a)->mode, SHADING_VIEW);
	event(a, 0, ACTION_NEXT_MODE, true);
	event(a, 0, ACTION_TURN_LEFT, true);
	event(a, 10 * MS, ACTION_TURN_LEFT, false); /* coasting on to 55 ms */
	event(a, 20 * MS, ACTION_RESET, true);
	app_advance(a, 1 * SEC);
	assert_int_equal(st(a)->mode, SHADING_VIEW);
	assert_float_equal(st(a)->orientation.w, cfg.rest.w, 1e-12);
	assert_float_equal(st(a)->orientation.x, cfg.rest.x, 1e-12);
	assert_float_equal(st(a)->orientation.y, 0, 1e-12);
	app_free(a);
}

/* A million small turns about both axes, by taps and by frames: still a
 * unit quaternion, and still the rotation the sum of the turns gives. */
static void million_turns_stay_normalised(void **state)
{
	struct app *a;
	uint64_t t = 0;

	(void)state;
	a = app_new(&base, MATCAPS, 0);
	for (int i = 0; i < 1000000; i++) {
		enum app_action act = i % 2 ? ACTION_TURN_UP : ACTION_TURN_RIGHT;

		event(a, t, act, true);
		t += 1 * MS;
		event(a, t, act, false);
		t += 60 * MS; /* past the tap's 55.6 ms */
		app_advance(a, t);
		assert_true(fabs(norm(st(a)->orientation) - 1.0) < 1e-12);
	}
	assert_true(isfinite(st(a)->orientation.w));
	app_free(a);
	/* Held for a million frames of 1 ms. */
	a = app_new(&base, MATCAPS, 0);
	event(a, 0, ACTION_TURN_RIGHT, true);
	for (int i = 1; i <= 1000000; i++)
		app_advance(a, (uint64_t)i * MS);
	assert_true(fabs(norm(st(a)->orientation) - 1.0) < 1e-12);
	/* 1000 s at 90 degrees/s is 250 whole turns: back where it began. */
	assert_float_equal(fabs(st(a)->orientation.w), 1.0, 1e-6);
	app_free(a);
}

/* The camera feed only reports; the state decides. Lost while shown: the
 * image matcap, and the camera again when it is back. Switched off by
 * hand: it stays off when it comes back. Its frames draw only while
 * shown. */
static void camera_lost_and_back(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0);

	(void)state;
	event(a, 1, ACTION_NEXT_MATCAP, true);
	camera(a, true, false);
	assert_true(st(a)->camera_on);
	drawn(a);
	camera(a, true, true);
	assert_true(st(a)->dirty);
	drawn(a);
	camera(a, false, false);
	assert_false(st(a)->camera_on);
	assert_int_equal(st(a)->matcap, 1);
	assert_true(st(a)->dirty);
	camera(a, true, false);
	assert_true(st(a)->camera_on);
	event(a, 2, ACTION_TOGGLE_CAMERA, true);
	camera(a, false, false);
	camera(a, true, false);
	assert_false(st(a)->camera_on);
	drawn(a);
	camera(a, true, true);
	assert_false(st(a)->dirty);
	app_free(a);
}

/* The folder was read again: the picture shown stays, wherever it now is
 * in the order; when it is gone, the index stays if it still exists. */
static void rescanned_matcaps_keep_the_picture(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0);

	(void)state;
	event(a, 1, ACTION_NEXT_MATCAP, true);
	event(a, 2, ACTION_NEXT_MATCAP, true);
	assert_int_equal(st(a)->matcap, 2);
	drawn(a);
	matcaps(a, 5, 4); /* two files sorted in before it */
	assert_int_equal(st(a)->matcap, 4);
	assert_true(st(a)->dirty); /* it may be the very file rewritten */
	matcaps(a, 5, -1);
	assert_int_equal(st(a)->matcap, 4);
	matcaps(a, 2, -1);
	assert_int_equal(st(a)->matcap, 0);
	event(a, 3, ACTION_PREV_MATCAP, true);
	assert_int_equal(st(a)->matcap, 1);
	app_free(a);
}

/* A reload starts the state afresh from the new settings (the turns, the
 * pose, the mode), and a live camera stays on. */
static void reload_starts_afresh_but_keeps_the_camera(void **state)
{
	struct app_config cfg = base;
	struct app *a = app_new(&base, MATCAPS, 0);
	struct app_msg m = {.kind = APP_RELOADED, .reload = {&cfg, 2, 5 * SEC}};

	(void)state;
	cfg.mode = SHADING_NORMAL;
	cfg.rest = quat_from_axis_angle(0, 1, 0, 30 * DEG);
	camera(a, true, false);
	event(a, 1 * SEC, ACTION_TURN_LEFT, true);
	app_advance(a, 2 * SEC);
	drawn(a);
	app_apply(a, &m);
	assert_true(st(a)->dirty);
	assert_true(st(a)->camera_on);
	assert_int_equal(st(a)->mode, SHADING_NORMAL);
	assert_float_equal(yaw_of(st(a)->orientation), 30 * DEG, 1e-9);
	assert_int_equal(st(a)->last_input_ns, 5 * SEC);
	assert_false(app_moving(a)); /* the held turn is gone with the old state */
	/* Two matcaps now: the cycle is them and the camera. */
	event(a, 6 * SEC, ACTION_NEXT_MATCAP, true);
	event(a, 6 * SEC, ACTION_NEXT_MATCAP, true);
	assert_int_equal(st(a)->matcap, 1);
	event(a, 6 * SEC, ACTION_NEXT_MATCAP, true);
	assert_true(st(a)->camera_on);
	/* Without a camera, a reload leaves it off. */
	camera(a, false, false);
	app_apply(a, &m);
	assert_false(st(a)->camera_on);
	app_free(a);
}

/* A display plugged in (or back) wants everything drawn again. */
static void display_back_redraws(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0);
	struct app_msg back = {.kind = APP_DISPLAY_BACK};

	(void)state;
	drawn(a);
	assert_false(st(a)->dirty);
	app_apply(a, &back);
	assert_true(st(a)->dirty);
	drawn(a);
	assert_false(st(a)->dirty);
	app_free(a);
}

/* next-variant counts presses (the state holds no model's variants); the
 * kiosk steps the variant shown by them: each in turn, then the file's
 * default materials, then the first again, either way. */
static void next_variant_steps(void **state)
{
	struct app *a = app_new(&base, MATCAPS, 0);

	(void)state;
	assert_int_equal(st(a)->variant_step, 0);
	event(a, 0, ACTION_NEXT_VARIANT, true);
	event(a, 0, ACTION_NEXT_VARIANT, false); /* a release is no press */
	event(a, MS, ACTION_NEXT_VARIANT, true);
	assert_int_equal(st(a)->variant_step, 2);
	assert_null(st(a)->stop_variant);
	app_free(a);
	assert_int_equal(app_variant_step(-1, 2, 1), 0);
	assert_int_equal(app_variant_step(0, 2, 1), 1);
	assert_int_equal(app_variant_step(1, 2, 1), -1);
	assert_int_equal(app_variant_step(-1, 2, 3), -1);
	assert_int_equal(app_variant_step(-1, 2, -1), 1);
	assert_int_equal(app_variant_step(7, 2, 1), 0);	  /* one it lacks: from the default */
	assert_int_equal(app_variant_step(-1, 0, 1), -1); /* no variants: the default */
	assert_string_equal(app_action_names[ACTION_NEXT_VARIANT], "next-variant");
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
	    cmocka_unit_test(models_cycle),
	    cmocka_unit_test(attract_frame_rate_capped),
	    cmocka_unit_test(attract_steps_models),
	    cmocka_unit_test(matcaps_and_camera),
	    cmocka_unit_test(camera_is_one_more_entry_in_the_cycle),
	    cmocka_unit_test(mode_and_reset),
	    cmocka_unit_test(million_turns_stay_normalised),
	    cmocka_unit_test(camera_lost_and_back),
	    cmocka_unit_test(rescanned_matcaps_keep_the_picture),
	    cmocka_unit_test(reload_starts_afresh_but_keeps_the_camera),
	    cmocka_unit_test(display_back_redraws),
	    cmocka_unit_test(action_names_match_the_enum),
	    cmocka_unit_test(next_variant_steps),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
