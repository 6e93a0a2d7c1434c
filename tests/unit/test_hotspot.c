/* Hotspots' pure decisions (state/hotspot.c): the words a value is read
 * from and the errors for bad ones, which hotspot comes next, the yaw and
 * pitch that bring a point to face the visitor (checked by turning the
 * point with the view's own quaternions, as content_view composes them),
 * and the renderer's fade at the silhouette and label kept on screen. */
#include "content/content.h"
#include "render/hotspot_gl.h"
#include "state/app.h"
#include "state/hotspot.h"
#include "util/math3d.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

static void test_vectors_and_errors(void **state)
{
	double v[3];
	char err[160] = "";

	(void)state;
	assert_int_equal(hotspot_parse_vec3(" 0.1 -2 3e-1 ", v, err, sizeof(err)), 0);
	assert_true(fabs(v[0] - 0.1) < 1e-12 && v[1] == -2 && fabs(v[2] - 0.3) < 1e-12);
	assert_int_equal(hotspot_parse_vec3("1 2", v, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "three numbers X Y Z"));
	assert_int_equal(hotspot_parse_vec3("1 2 3 4", v, err, sizeof(err)), -1);
	assert_int_equal(hotspot_parse_vec3("1 2 nan", v, err, sizeof(err)), -1);
	assert_int_equal(hotspot_parse_vec3("a b c", v, err, sizeof(err)), -1);
	assert_int_equal(hotspot_parse_normal("0 0 2", v, err, sizeof(err)), 0);
	assert_true(v[2] == 1 && v[0] == 0);
	assert_int_equal(hotspot_parse_normal("0 0 0", v, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "not 0 0 0"));
}

static void test_look_and_colour(void **state)
{
	enum hotspot_look look;
	float c[4];
	char err[160];

	(void)state;
	assert_int_equal(hotspot_parse_look("badge", &look, err, sizeof(err)), 0);
	assert_int_equal(look, HOTSPOT_BADGE);
	assert_int_equal(hotspot_parse_look("dot", &look, err, sizeof(err)), 0);
	assert_int_equal(look, HOTSPOT_DOT);
	assert_int_equal(hotspot_parse_look("star", &look, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "dot or badge"));
	assert_int_equal(hotspot_parse_color("#ff8000", c, err, sizeof(err)), 0);
	assert_true(c[0] == 1 && fabsf(c[1] - 128 / 255.0f) < 1e-6f && c[2] == 0 && c[3] == 1);
	assert_int_equal(hotspot_parse_color("#FF800080", c, err, sizeof(err)), 0);
	assert_true(fabsf(c[3] - 128 / 255.0f) < 1e-6f);
	assert_int_equal(hotspot_parse_color("ff8000", c, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "#rrggbb"));
	assert_int_equal(hotspot_parse_color("#ff80", c, err, sizeof(err)), -1);
	assert_int_equal(hotspot_parse_color("#gg0000", c, err, sizeof(err)), -1);
}

static void test_find_and_next(void **state)
{
	struct hotspot_set s = {0};

	(void)state;
	assert_int_equal(hotspot_next(s.count, -1), -1);
	hotspot_init(&s.items[0], "signature", 3);
	hotspot_init(&s.items[1], "valve", 9);
	hotspot_init(&s.items[2], "foot", 14);
	s.count = 3;
	assert_int_equal(hotspot_find(&s, "valve"), 1);
	assert_int_equal(hotspot_find(&s, "lid"), -1);
	assert_int_equal(hotspot_next(s.count, -1), 0);
	assert_int_equal(hotspot_next(s.count, 0), 1);
	assert_int_equal(hotspot_next(s.count, 2), 0);		  /* wraps */
	assert_int_equal(hotspot_next(s.count, -FRAME_STOPS), 0); /* from a stop */
	assert_string_equal(hotspot_text(&s.items[0], NULL, NULL), "");
	strcpy(s.items[0].text, "The painter's signature");
	assert_string_equal(hotspot_text(&s.items[0], "de", NULL), "The painter's signature");
}

/* dir turned as the view turns the model: pitch about x after yaw about
 * y (content_view), through the renderer's own matrix maker. */
static void turned(const double dir[3], double yaw, double pitch, double out[3])
{
	struct quat q =
	    quat_multiply(quat_from_axis_angle(1, 0, 0, pitch), quat_from_axis_angle(0, 1, 0, yaw));
	float m[16];

	mat4_from_quat(m, q);
	for (int r = 0; r < 3; r++)
		out[r] = m[r] * dir[0] + m[4 + r] * dir[1] + m[8 + r] * dir[2];
}

static void test_facing(void **state)
{
	static const double dirs[][3] = {{1, 0, 0},	   {-1, 0, 0},	      {0, 0, -1},
					 {0.3, 0.8, -0.5}, {-0.2, -0.9, 0.1}, {0, 1, 0}};

	(void)state;
	for (size_t i = 0; i < sizeof(dirs) / sizeof(dirs[0]); i++) {
		double yaw, pitch, out[3], len = sqrt(vec3_dot(dirs[i], dirs[i]));

		hotspot_facing(dirs[i], &yaw, &pitch);
		turned(dirs[i], yaw, pitch, out);
		/* Straight at the visitor: +z, the same length. */
		assert_true(fabs(out[0]) < 1e-6);
		assert_true(fabs(out[1]) < 1e-6);
		assert_true(fabs(out[2] - len) < 1e-6);
	}
	/* A point already in front needs no turn; one on the right (+x) turns
	 * by a quarter to the left (negative yaw). */
	{
		double yaw, pitch;

		hotspot_facing((const double[3]){0, 0, 1}, &yaw, &pitch);
		assert_true(fabs(yaw) < 1e-12 && fabs(pitch) < 1e-12);
		hotspot_facing((const double[3]){1, 0, 0}, &yaw, &pitch);
		assert_true(fabs(yaw + M_PI / 2) < 1e-12);
		hotspot_facing((const double[3]){0, 0, 0}, &yaw, &pitch);
		assert_true(yaw == 0 && pitch == 0);
	}
}

static void test_fade(void **state)
{
	const double eye[3] = {0, 0, 1};
	double edge[3] = {1, 0, 0}, slant[3] = {sin(1.4), 0, cos(1.4)}; /* 80 degrees */

	(void)state;
	assert_true(hotspot_fade((const double[3]){0, 0, 1}, eye) == 1);
	assert_true(hotspot_fade((const double[3]){0, 0, -1}, eye) == 0);
	assert_true(hotspot_fade(edge, eye) == 0);
	assert_true(hotspot_fade(slant, eye) > 0 && hotspot_fade(slant, eye) < 1);
}

static void test_label_stays_on_screen(void **state)
{
	int at[2];

	(void)state;
	/* Room on the right: beside it, centred on it. */
	hotspot_label_place(100, 200, 10, 120, 30, 640, 480, 8, at);
	assert_int_equal(at[0], 100 + 10 + 8);
	assert_int_equal(at[1], 200 - 15);
	/* At the right edge: on the left. */
	hotspot_label_place(600, 200, 10, 120, 30, 640, 480, 8, at);
	assert_int_equal(at[0], 600 - 18 - 120);
	/* At the top and bottom: moved in. */
	hotspot_label_place(300, 2, 10, 120, 30, 640, 480, 8, at);
	assert_int_equal(at[1], 8);
	hotspot_label_place(300, 479, 10, 120, 30, 640, 480, 8, at);
	assert_int_equal(at[1], 480 - 30 - 8);
	/* Too wide for either side: below, centred on it; at the bottom,
	 * above. */
	hotspot_label_place(320, 200, 10, 400, 30, 640, 480, 8, at);
	assert_int_equal(at[0], 120);
	assert_int_equal(at[1], 200 + 18);
	hotspot_label_place(320, 460, 10, 400, 30, 640, 480, 8, at);
	assert_int_equal(at[1], 460 - 18 - 30);
	/* Wider than the screen: its start on it. */
	hotspot_label_place(300, 200, 10, 900, 30, 640, 480, 8, at);
	assert_int_equal(at[0], 8);
}

/* [frame] stops' hotspot=NAME, in any order with the other words. */
static void stop_words(void **state)
{
	struct frame_stop st[FRAME_STOPS];
	char err[300] = "";

	(void)state;
	assert_int_equal(frame_stops_parse("0 0 1 \"Here\" hotspot=rim variant=blue; 90 0 2 "
					   "hotspot=foot animation=open",
					   st, FRAME_STOPS, err, sizeof(err)),
			 2);
	assert_string_equal(st[0].hotspot, "rim");
	assert_string_equal(st[0].variant, "blue");
	assert_string_equal(st[0].text, "Here");
	assert_string_equal(st[1].hotspot, "foot");
	assert_string_equal(st[1].animation, "open");
	assert_int_equal(frame_stops_parse("0 0 1 hotspot=", st, FRAME_STOPS, err, sizeof(err)),
			 -1);
	assert_non_null(strstr(err, "hotspot= names a hotspot of the model"));
	assert_int_equal(
	    frame_stops_parse("0 0 1 hotspot=a hotspot=b", st, FRAME_STOPS, err, sizeof(err)), -1);
}

/* A stop at a hotspot: the app is given the yaw and pitch that face it
 * (the point is on the model's right, off its centre: the fit's centre
 * counts) and, having no text, the hotspot's. */
static void stop_faces_its_hotspot(void **state)
{
	struct content s;
	struct content_config c = {0};
	struct app_frame f;
	struct quat rest;
	struct hotspot *h = &c.hotspots.items[0];
	double out[3], dir[3];

	(void)state;
	memset(&s, 0, sizeof(s));
	frame_config_defaults(&c.frame);
	c.frame.stops = strdup("0 0 1 hotspot=side; 10 20 1 \"Own\" hotspot=side");
	/* The file's model about (5, 0, 0), 2 units across: fit (5,0,0) 0.5. */
	s.mesh.fit[0] = 5, s.mesh.fit[3] = 0.5;
	hotspot_init(h, "side", 1);
	h->has_point = true;
	h->point[0] = 7, h->point[1] = 1, h->point[2] = 0; /* right and up of the centre */
	strcpy(h->text, "The handle");
	c.hotspots.count = 1;
	content_load_hotspots(&s, &c);
	assert_int_equal(s.hotspot_count, 1);
	content_app_frame_at(&s, &c, &f, &rest);
	assert_int_equal(f.stop_count, 2);
	dir[0] = 1, dir[1] = 0.5, dir[2] = 0;
	turned(dir, f.stops[0].yaw, f.stops[0].pitch, out);
	assert_true(fabs(out[0]) < 1e-6 && fabs(out[1]) < 1e-6 && out[2] > 0);
	assert_string_equal(f.stops[0].text, "The handle");
	assert_string_equal(f.stops[1].text, "Own");
	assert_true(fabs(f.stops[1].yaw - f.stops[0].yaw) < 1e-12);
	free(c.frame.stops);
}

/* next-hotspot glides to each hotspot's view in turn (wrapping), shows
 * its text, and next-stop from there starts at the first stop. */
static void next_hotspot_steps(void **state)
{
	struct app_config cfg = {.turn_speed = M_PI / 2, .rest = {1, 0, 0, 0}};
	struct app *a;
	const struct app_state *st;

	(void)state;
	cfg.frame.zoom0 = 1;
	cfg.frame.stop_count = 1;
	cfg.frame.stops[0] = (struct frame_stop){.yaw = 0.5, .pitch = 0, .zoom = 1};
	cfg.frame.hotspot_count = 2;
	cfg.frame.stops[FRAME_STOPS] = (struct frame_stop){.yaw = 1.0, .pitch = 0.2, .zoom = 1};
	strcpy(cfg.frame.stops[FRAME_STOPS].text, "The rim");
	cfg.frame.stops[FRAME_STOPS + 1] = (struct frame_stop){.yaw = -1.0, .pitch = 0, .zoom = 1};
	strcpy(cfg.frame.stops[FRAME_STOPS + 1].text, "The foot");
	a = app_new(&cfg, 1, 0);
	assert_non_null(a);
	st = app_state(a);
	app_apply(a, &(struct app_msg){
			 .kind = APP_INPUT,
			 .input = {.time_ns = 1, .action = ACTION_NEXT_HOTSPOT, .pressed = true}});
	assert_int_equal(st->stop, FRAME_STOPS);
	assert_string_equal(st->stop_text, "The rim");
	app_advance(a, 10ull * 1000000000ull);
	assert_true(fabs(st->yaw - 1.0) < 1e-6 && fabs(st->pitch - 0.2) < 1e-6);
	app_apply(a, &(struct app_msg){.kind = APP_INPUT,
				       .input = {.time_ns = 11ull * 1000000000ull,
						 .action = ACTION_NEXT_HOTSPOT,
						 .pressed = true}});
	assert_int_equal(st->stop, FRAME_STOPS + 1);
	assert_string_equal(st->stop_text, "The foot");
	app_apply(a, &(struct app_msg){.kind = APP_INPUT,
				       .input = {.time_ns = 12ull * 1000000000ull,
						 .action = ACTION_NEXT_HOTSPOT,
						 .pressed = true}});
	assert_int_equal(st->stop, FRAME_STOPS); /* wraps */
	app_apply(a, &(struct app_msg){.kind = APP_INPUT,
				       .input = {.time_ns = 13ull * 1000000000ull,
						 .action = ACTION_NEXT_STOP,
						 .pressed = true}});
	assert_int_equal(st->stop, 0);
	assert_string_equal(app_action_names[ACTION_NEXT_HOTSPOT], "next-hotspot");
	/* A tap on badge 2 (the loop's hit test said so): its view; a tap
	 * on no badge changes nothing. */
	app_apply(
	    a, &(struct app_msg){
		   .kind = APP_TOUCH,
		   .touch = {.kind = GESTURE_TAP, .time_ns = 14ull * 1000000000ull, .badge = 2}});
	assert_int_equal(st->stop, FRAME_STOPS + 1);
	app_apply(
	    a, &(struct app_msg){.kind = APP_TOUCH,
				 .touch = {.kind = GESTURE_TAP, .time_ns = 15ull * 1000000000ull}});
	assert_int_equal(st->stop, FRAME_STOPS + 1);
	app_free(a);
}

/* select (the knob's press) at second s; the view it chose. */
static int select_at(struct app *a, int s)
{
	app_apply(a, &(struct app_msg){.kind = APP_INPUT,
				       .input = {.time_ns = (uint64_t)s * 1000000000ull,
						 .action = ACTION_SELECT,
						 .pressed = true}});
	return app_state(a)->stop;
}

/* The knob's press (select) steps through a model's hotspots, each its
 * view and text, wrapping; a model without hotspots, its stops as
 * before; neither, nothing. */
static void select_steps_hotspots(void **state)
{
	struct app_config cfg = {.turn_speed = M_PI / 2, .rest = {1, 0, 0, 0}};
	struct app *a;

	(void)state;
	cfg.frame.zoom0 = 1;
	cfg.frame.stop_count = 2;
	cfg.frame.stops[0] = (struct frame_stop){.yaw = 0.5, .pitch = 0, .zoom = 1};
	cfg.frame.stops[1] = (struct frame_stop){.yaw = 1.5, .pitch = 0, .zoom = 1};
	cfg.frame.hotspot_count = 2;
	cfg.frame.stops[FRAME_STOPS] = (struct frame_stop){.yaw = 1.0, .pitch = 0.2, .zoom = 1};
	strcpy(cfg.frame.stops[FRAME_STOPS].text, "The rim");
	cfg.frame.stops[FRAME_STOPS + 1] = (struct frame_stop){.yaw = -1.0, .pitch = 0, .zoom = 1};
	strcpy(cfg.frame.stops[FRAME_STOPS + 1].text, "The foot");
	a = app_new(&cfg, 1, 0);
	assert_non_null(a);
	assert_int_equal(select_at(a, 1), FRAME_STOPS);
	assert_string_equal(app_state(a)->stop_text, "The rim");
	app_advance(a, 10ull * 1000000000ull);
	assert_true(fabs(app_state(a)->yaw - 1.0) < 1e-6 && fabs(app_state(a)->pitch - 0.2) < 1e-6);
	assert_int_equal(select_at(a, 11), FRAME_STOPS + 1);
	assert_string_equal(app_state(a)->stop_text, "The foot");
	assert_int_equal(select_at(a, 12), FRAME_STOPS); /* wraps */
	app_free(a);

	cfg.frame.hotspot_count = 0; /* no hotspots: the stops, as next-stop */
	a = app_new(&cfg, 1, 0);
	assert_non_null(a);
	assert_int_equal(select_at(a, 1), 0);
	assert_int_equal(select_at(a, 2), 1);
	assert_int_equal(select_at(a, 3), 0);
	app_free(a);

	cfg.frame.stop_count = 0; /* neither: the view stays */
	assert_int_equal(app_frame_hotspot_step(&cfg.frame, -1, true), -1);
	cfg.frame.hotspot_count = 2; /* next-hotspot never steps a stop */
	assert_int_equal(app_frame_hotspot_step(&cfg.frame, 1, false), FRAME_STOPS);
	cfg.frame.hotspot_count = 0;
	cfg.frame.stop_count = 2;
	assert_int_equal(app_frame_hotspot_step(&cfg.frame, 0, false), -1);
	assert_int_equal(app_frame_hotspot_step(&cfg.frame, FRAME_STOPS, true), 0);
}

/* A tap says where it was (a badge is hit-tested there). */
static void tap_has_its_place(void **state)
{
	struct gesture_config cfg;
	struct gesture_state g;
	struct gesture out[GESTURE_MAX_EVENTS];
	const struct gesture_point down = {.id = 1, .x = 0.3, .y = 0.6};

	(void)state;
	gesture_config_defaults(&cfg);
	gesture_init(&g, &cfg);
	assert_int_equal(gesture_frame(&g, 1000000, &down, 1, out), 0);
	assert_int_equal(gesture_frame(&g, 50000000, &down, 0, out), 1); /* lifted */
	assert_int_equal(out[0].kind, GESTURE_TAP);
	assert_true(out[0].x == 0.3 && out[0].y == 0.6);
	assert_int_equal(out[0].badge, 0); /* the loop's to say */
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_vectors_and_errors),
	    cmocka_unit_test(test_look_and_colour),
	    cmocka_unit_test(test_find_and_next),
	    cmocka_unit_test(test_facing),
	    cmocka_unit_test(test_fade),
	    cmocka_unit_test(test_label_stays_on_screen),
	    cmocka_unit_test(stop_words),
	    cmocka_unit_test(stop_faces_its_hotspot),
	    cmocka_unit_test(next_hotspot_steps),
	    cmocka_unit_test(select_steps_hotspots),
	    cmocka_unit_test(tap_has_its_place),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
