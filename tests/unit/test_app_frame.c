/* [frame] in the app state (state/app.c, state/view.c): limits obeyed by
 * every input and by attract mode, the glide home before attract's turn,
 * the sway, and the guided stops; the angle and its speed sampled as the
 * loop samples them, and found continuous. */
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

static struct app_config config(void)
{
	struct app_config c = {
	    .turn_speed = 90 * DEG,
	    .turn_step = 5 * DEG,
	    .attract_speed = 15 * DEG,
	    .drag_speed = 180 * DEG,
	    .rest = {1, 0, 0, 0},
	    .mode = SHADING_VIEW,
	};
	struct frame_config f;
	char err[200];

	frame_config_defaults(&f);
	assert_int_equal(frame_to_app(&f, 0, 0, &c.frame, err, sizeof(err)), 0);
	return c;
}

static void frame_of(struct app_config *c, const struct frame_config *f)
{
	char err[200];

	assert_int_equal(frame_to_app(f, 0, 0, &c->frame, err, sizeof(err)), 0);
}

static void press(struct app *a, uint64_t t, enum app_action act, bool down)
{
	struct app_msg m = {.kind = APP_INPUT,
			    .input = {.time_ns = t, .action = act, .pressed = down}};

	app_apply(a, &m);
}

static void drag(struct app *a, uint64_t t, double dx, double dy)
{
	struct app_msg m = {.kind = APP_TOUCH,
			    .touch = {.kind = GESTURE_DRAG, .time_ns = t, .dx = dx, .dy = dy}};

	app_apply(a, &m);
}

static void pinch(struct app *a, uint64_t t, double scale)
{
	struct app_msg m = {.kind = APP_TOUCH,
			    .touch = {.kind = GESTURE_PINCH, .time_ns = t, .scale = scale}};

	app_apply(a, &m);
}

/* Buttons, keys (the same actions), touch and attract mode stop at the
 * limits; the orientation is the yaw and pitch it says. */
static void limits_hold_for_every_input(void **state)
{
	struct app_config c = config();
	struct frame_config f;
	struct app *a;

	(void)state;
	frame_config_defaults(&f);
	f.yaw_min = -30;
	f.yaw_max = 40;
	f.pitch_min = -10;
	f.pitch_max = 20;
	f.zoom_min = 0.8;
	f.zoom_max = 2;
	frame_of(&c, &f);
	c.attract_after_s = 5;
	a = app_new(&c, 3, 0);
	press(a, 0, ACTION_TURN_RIGHT, true);
	app_advance(a, 2 * SEC); /* 180 degrees asked */
	press(a, 2 * SEC, ACTION_TURN_RIGHT, false);
	assert_float_equal(app_state(a)->yaw, 40 * DEG, 1e-12);
	drag(a, 3 * SEC, -1.0, 0); /* 180 degrees left */
	assert_float_equal(app_state(a)->yaw, -30 * DEG, 1e-12);
	drag(a, 3 * SEC, 0, 1.0);
	assert_float_equal(app_state(a)->pitch, 20 * DEG, 1e-12);
	press(a, 3 * SEC, ACTION_TURN_UP, true);
	app_advance(a, 5 * SEC);
	press(a, 5 * SEC, ACTION_TURN_UP, false);
	assert_float_equal(app_state(a)->pitch, -10 * DEG, 1e-12);
	pinch(a, 5 * SEC, 10);
	assert_float_equal(app_state(a)->zoom, 2, 1e-12);
	pinch(a, 5 * SEC, 0.01);
	assert_float_equal(app_state(a)->zoom, 0.8, 1e-12);
	/* Attract mode: a turntable between the limits, never past them. */
	for (uint64_t t = 10 * SEC; t < 100 * SEC; t += 33 * MS) {
		app_advance(a, t);
		assert_true(app_state(a)->yaw >= -30 * DEG - 1e-12);
		assert_true(app_state(a)->yaw <= 40 * DEG + 1e-12);
	}
	assert_true(app_moving(a));
	/* The orientation is pitch after yaw. */
	{
		struct quat q = quat_multiply(quat_from_axis_angle(1, 0, 0, app_state(a)->pitch),
					      quat_from_axis_angle(0, 1, 0, app_state(a)->yaw));

		assert_float_equal(
		    fabs(q.w * app_state(a)->orientation.w + q.x * app_state(a)->orientation.x +
			 q.y * app_state(a)->orientation.y + q.z * app_state(a)->orientation.z),
		    1, 1e-9);
	}
	app_free(a);
}

/* Samples the yaw every ms from t0 to t1: no jump in the angle nor in
 * its difference quotient (the speed). Returns the last speed. */
static double sample(struct app *a, uint64_t t0, uint64_t t1, double max_step, double max_accel)
{
	double prev = NAN, speed = NAN, v = 0;

	for (uint64_t t = t0; t <= t1; t += 1 * MS) {
		double y;

		app_advance(a, t);
		y = app_state(a)->yaw;
		if (!isnan(prev)) {
			v = (y - prev) / 1e-3;
			assert_true(fabs(y - prev) <= max_step);
			if (!isnan(speed))
				assert_true(fabs(v - speed) <= max_accel * 1e-3);
			speed = v;
		}
		prev = y;
	}
	return v;
}

/* After input, attract mode glides home (no snap), then turns at its
 * speed: angle and speed continuous through the hand-over. */
static void attract_glides_home_then_turns(void **state)
{
	struct app_config c = config();
	struct app *a;

	(void)state;
	c.attract_after_s = 1;
	c.attract_fps = 0; /* every sample */
	c.frame.yaw0 = 10 * DEG;
	a = app_new(&c, 3, 0);
	drag(a, 0, 0.5, 0.1); /* 90 degrees right, 18 down */
	assert_float_equal(app_state(a)->yaw, 100 * DEG, 1e-12);
	/* Attract from 1 s: a glide of at most 4 s, then turning. */
	app_advance(a, 1 * SEC);
	/* 15 degrees/s: 0.26 rad/s; the glide's speed stays below ~1 rad/s,
	 * its acceleration below ~1 rad/s^2. */
	assert_float_equal(sample(a, 1 * SEC, 8 * SEC, 2e-3, 1.0), 15 * DEG, 1e-6);
	/* Home was reached: pitch back at 0, yaw turned on from 10. */
	assert_float_equal(app_state(a)->pitch, 0, 1e-12);
	assert_float_equal(app_state(a)->yaw, 10 * DEG + 3 * 15 * DEG, 1e-6);
	app_free(a);
	/* attract_direction left: the speed is the other way. */
	c.frame.direction = -1;
	a = app_new(&c, 3, 0);
	app_advance(a, 1 * SEC);
	assert_float_equal(sample(a, 1 * SEC, 3 * SEC, 2e-3, 1.0), -15 * DEG, 1e-6);
	app_free(a);
}

/* attract_sway: a swing about the start view, within the limits, with
 * continuous angle and speed; its peak speed is attract_speed. */
static void sway_is_smooth_and_bounded(void **state)
{
	struct app_config c = config();
	struct frame_config f;
	struct app *a;
	double lo = 1e9, hi = -1e9;

	(void)state;
	frame_config_defaults(&f);
	f.attract_sway = 20;
	f.yaw_min = -15;
	f.yaw_max = 90;
	f.yaw = 0;
	frame_of(&c, &f);
	c.attract_after_s = 1;
	c.attract_fps = 0;
	a = app_new(&c, 3, 0);
	drag(a, 0, 0.2, 0);
	app_advance(a, 1 * SEC);
	sample(a, 1 * SEC, 30 * SEC, 2e-3, 1.0);
	/* Past the glide, never faster than attract_speed. */
	sample(a, 6 * SEC, 30 * SEC, 15 * DEG * 1e-3 + 1e-9, 1.0);
	for (uint64_t t = 30 * SEC; t < 60 * SEC; t += 10 * MS) {
		app_advance(a, t);
		lo = fmin(lo, app_state(a)->yaw);
		hi = fmax(hi, app_state(a)->yaw);
	}
	/* 20 each way, but yaw_min is 15 away: 15 each way. */
	assert_float_equal(lo, -15 * DEG, 1e-3);
	assert_float_equal(hi, 15 * DEG, 1e-3);
	app_free(a);
}

/* next-stop and prev-stop glide to the stops and say their text; attract
 * mode plays them in turn. */
static void stops_step_and_play(void **state)
{
	struct app_config c = config();
	struct frame_config f;
	struct app *a;
	char stops[] = "90 10 1.5 \"The handle\"; -90 0 1 \"Maker's mark\" animation=open; "
		       "0 -20 2 animation=1";

	(void)state;
	frame_config_defaults(&f);
	f.stops = stops;
	f.stop_seconds = 10;
	frame_of(&c, &f);
	assert_int_equal(c.frame.stop_count, 3);
	a = app_new(&c, 3, 0);
	assert_null(app_state(a)->stop_text);
	assert_null(app_state(a)->stop_animation);
	press(a, 0, ACTION_NEXT_STOP, true);
	assert_string_equal(app_state(a)->stop_text, "The handle");
	assert_null(app_state(a)->stop_animation); /* the clip playing goes on */
	assert_true(app_moving(a));
	app_advance(a, 100 * MS);
	assert_true(app_state(a)->yaw > 0 && app_state(a)->yaw < 90 * DEG);
	app_advance(a, 5 * SEC);
	assert_false(app_moving(a));
	assert_float_equal(app_state(a)->yaw, 90 * DEG, 1e-12);
	assert_float_equal(app_state(a)->pitch, 10 * DEG, 1e-12);
	assert_float_equal(app_state(a)->zoom, 1.5, 1e-12);
	press(a, 6 * SEC, ACTION_PREV_STOP, true);
	app_advance(a, 11 * SEC);
	assert_int_equal(app_state(a)->stop, 2);
	assert_null(app_state(a)->stop_text);
	assert_string_equal(app_state(a)->stop_animation, "1");
	assert_float_equal(app_state(a)->zoom, 2, 1e-12);
	press(a, 11 * SEC, ACTION_NEXT_STOP, true);
	app_advance(a, 16 * SEC);
	assert_string_equal(app_state(a)->stop_text, "The handle");
	app_free(a);
	/* Attract mode: stop after stop, each stop_seconds. */
	c.attract_after_s = 1;
	a = app_new(&c, 3, 0);
	app_advance(a, 2 * SEC);
	assert_int_equal(app_state(a)->stop, 0);
	app_advance(a, 10 * SEC);
	assert_float_equal(app_state(a)->yaw, 90 * DEG, 1e-9);
	app_advance(a, 12 * SEC);
	assert_int_equal(app_state(a)->stop, 1);
	assert_string_equal(app_state(a)->stop_text, "Maker's mark");
	assert_string_equal(app_state(a)->stop_animation, "open");
	app_advance(a, 21 * SEC);
	assert_float_equal(app_state(a)->yaw, -90 * DEG, 1e-9);
	app_advance(a, 30 * SEC);
	assert_int_equal(app_state(a)->stop, 2);
	app_advance(a, 31 * SEC);
	assert_int_equal(app_state(a)->stop, 0);
	app_free(a);
}

static void stops_refused_with_reason(void **state)
{
	struct frame_stop s[FRAME_STOPS];
	char err[200];

	(void)state;
	assert_int_equal(frame_stops_parse("10 20", s, FRAME_STOPS, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "YAW PITCH ZOOM"));
	assert_int_equal(frame_stops_parse("1 2 3 \"open", s, FRAME_STOPS, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "closing quote"));
	assert_int_equal(frame_stops_parse("1 2 0", s, FRAME_STOPS, err, sizeof(err)), -1);
	assert_int_equal(
	    frame_stops_parse("1 2 1; ;3 4 1 \"a; b\"", s, FRAME_STOPS, err, sizeof(err)),
	    -1); /* a ; inside the text splits it: refused, not guessed */
	assert_int_equal(frame_stops_parse("1 2 1;3 4 1 \"ab\";", s, FRAME_STOPS, err, sizeof(err)),
			 2);
	assert_string_equal(s[1].text, "ab");
	/* animation= last, after the text or the numbers, to the stop's end
	 * (a clip's name may have spaces); a text may say "animation=" itself. */
	assert_int_equal(frame_stops_parse("1 2 1 animation=all; 3 4 1 \"x animation=y\" "
					   "animation=Take 1 ",
					   s, FRAME_STOPS, err, sizeof(err)),
			 2);
	assert_string_equal(s[0].animation, "all");
	assert_string_equal(s[1].text, "x animation=y");
	assert_string_equal(s[1].animation, "Take 1");
	assert_int_equal(frame_stops_parse("1 2 1 animation=", s, FRAME_STOPS, err, sizeof(err)),
			 -1);
	assert_non_null(strstr(err, "animation="));
	assert_int_equal(
	    frame_stops_parse("1 2 1 animation=a \"late text\"", s, FRAME_STOPS, err, sizeof(err)),
	    -1);
}

/* variant= after the text, before or after animation=, each to the next
 * word or the stop's end; reaching the stop (by hand or the attract
 * tour) says which variant it shows. */
static void stops_show_variants(void **state)
{
	struct frame_stop s[FRAME_STOPS];
	struct app_config c = config();
	struct frame_config f;
	char err[200],
	    stops[] = "0 0 1 variant=blue; 90 0 1 \"Red\" variant=dark red animation=open";
	struct app *a;

	(void)state;
	assert_int_equal(frame_stops_parse(stops, s, FRAME_STOPS, err, sizeof(err)), 2);
	assert_string_equal(s[0].variant, "blue");
	assert_string_equal(s[0].animation, "");
	assert_string_equal(s[1].variant, "dark red");
	assert_string_equal(s[1].animation, "open");
	assert_string_equal(s[1].text, "Red");
	assert_int_equal(frame_stops_parse("1 2 1 animation=open variant=blue ", s, FRAME_STOPS,
					   err, sizeof(err)),
			 1);
	assert_string_equal(s[0].animation, "open");
	assert_string_equal(s[0].variant, "blue");
	assert_int_equal(frame_stops_parse("1 2 1 variant=", s, FRAME_STOPS, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "variant="));
	assert_int_equal(
	    frame_stops_parse("1 2 1 variant=a variant=b", s, FRAME_STOPS, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "once"));
	frame_config_defaults(&f);
	f.stops = stops;
	f.stop_seconds = 10;
	frame_of(&c, &f);
	c.attract_after_s = 1;
	a = app_new(&c, 3, 0);
	assert_null(app_state(a)->stop_variant);
	app_advance(a, 2 * SEC);
	assert_int_equal(app_state(a)->stop, 0);
	assert_string_equal(app_state(a)->stop_variant, "blue");
	app_advance(a, 13 * SEC);
	assert_int_equal(app_state(a)->stop, 1);
	assert_string_equal(app_state(a)->stop_variant, "dark red");
	app_free(a);
}

static void rotate(struct quat q, const double p[3], double out[3])
{
	struct quat v = {0, p[0], p[1], p[2]}, c = {q.w, -q.x, -q.y, -q.z};
	struct quat r = quat_multiply(quat_multiply(q, v), c);

	out[0] = r.x;
	out[1] = r.y;
	out[2] = r.z;
}

/* up and orientation turn the model before everything. */
static void orientation_turns_first(void **state)
{
	struct frame_config f;
	struct quat q;
	char err[200];
	double v[3];

	(void)state;
	frame_config_defaults(&f);
	f.up = FRAME_UP_Z;
	assert_int_equal(frame_base(&f, &q, err, sizeof(err)), 0);
	/* +z goes up. */
	rotate(q, (const double[3]){0, 0, 1}, v);
	assert_float_equal(v[1], 1, 1e-12);
	f.up = FRAME_UP_Y;
	f.orientation = (char *)"0 0 90";
	assert_int_equal(frame_base(&f, &q, err, sizeof(err)), 0);
	rotate(q, (const double[3]){1, 0, 0}, v);
	assert_float_equal(v[2], -1, 1e-12);
	f.orientation = (char *)"0 0";
	assert_int_equal(frame_base(&f, &q, err, sizeof(err)), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(limits_hold_for_every_input),
	    cmocka_unit_test(attract_glides_home_then_turns),
	    cmocka_unit_test(sway_is_smooth_and_bounded),
	    cmocka_unit_test(stops_step_and_play),
	    cmocka_unit_test(stops_refused_with_reason),
	    cmocka_unit_test(stops_show_variants),
	    cmocka_unit_test(orientation_turns_first),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
