/* Several outputs of one board: [display] outputs' names
 * (display_outputs_parse), [output.NAME] sections (config/output_settings.c:
 * each bad value said and refused, a stick refused) and what each view
 * does to the frame's view (render/output_view.c). */
#include "config/options.h"
#include "config/output_settings.h"
#include "config/settings.h"
#include "display/display.h"
#include "render/output_view.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

static void names_are_split_and_checked(void **state)
{
	char names[KMS_OUTPUTS_MAX][32], err[160];

	(void)state;
	assert_int_equal(display_outputs_parse("HDMI-A-1, HDMI-A-2", names, 4, err, sizeof(err)),
			 2);
	assert_string_equal(names[0], "HDMI-A-1");
	assert_string_equal(names[1], "HDMI-A-2");
	assert_int_equal(display_outputs_parse(" DSI-1,,\tHDMI-A-1 ", names, 4, err, sizeof(err)),
			 2);
	assert_string_equal(names[0], "DSI-1");
	/* Refused, each with its reason. */
	assert_int_equal(display_outputs_parse("HDMI-A-1, HDMI-A-1", names, 4, err, sizeof(err)),
			 -1);
	assert_non_null(strstr(err, "named twice"));
	assert_int_equal(display_outputs_parse("A, B, C, D, E", names, 4, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "more than 4"));
	assert_int_equal(display_outputs_parse("HDMI-A-1-an-overly-long-connector-name", names, 4,
					       err, sizeof(err)),
			 -1);
	assert_non_null(strstr(err, "too long"));
	assert_int_equal(display_outputs_parse(" , ", NULL, 4, err, sizeof(err)), -1);
	assert_non_null(strstr(err, "no connector"));
}

static void sections_are_read(void **state)
{
	struct output_views set = {0};
	const struct output_view *o;

	(void)state;
	assert_true(output_settings_key(&set, "k.ini", 3, "output.HDMI-A-2", "view", "yaw"));
	assert_true(output_settings_key(&set, "k.ini", 4, "output.HDMI-A-2", "yaw", "-45.5"));
	assert_true(output_settings_key(&set, "k.ini", 5, "output.HDMI-A-2", "rotation", "90"));
	assert_true(output_settings_key(&set, "k.ini", 6, "output.HDMI-A-2", "caption", "no"));
	assert_true(
	    output_settings_key(&set, "k.ini", 7, "output.HDMI-A-2", "background", "#ff8000"));
	assert_true(output_settings_key(&set, "k.ini", 9, "output.DSI-1", "view", "slice"));
	assert_true(output_settings_key(&set, "k.ini", 10, "output.DSI-1", "position", "2,1"));
	assert_int_equal(set.count, 2);
	o = output_view_find(&set, "HDMI-A-2");
	assert_non_null(o);
	assert_int_equal(o->look, OUTPUT_YAW);
	assert_float_equal(o->yaw, -45.5, 0);
	assert_int_equal(o->rotation, 90);
	assert_false(o->caption);
	assert_true(o->has_background);
	assert_float_equal(o->background[0], 1, 1e-6);
	assert_float_equal(o->background[1], 128 / 255.0, 1e-3);
	o = output_view_find(&set, "DSI-1");
	assert_int_equal(o->look, OUTPUT_SLICE);
	assert_int_equal(o->column, 2);
	assert_int_equal(o->row, 1);
	assert_int_equal(o->rotation, -1); /* [display] rotation */
	assert_true(o->caption);
	assert_null(output_view_find(&set, "HDMI-A-1"));
}

static void bad_values_are_refused(void **state)
{
	static const char *const bad[][2] = {{"view", "behind"},
					     {"yaw", "ninety"},
					     {"yaw", "400"},
					     {"position", "0,1"},
					     {"position", "2"},
					     {"position", "2,1,1"},
					     {"rotation", "45"},
					     {"rotation", "90.5"},
					     {"caption", "maybe"},
					     {"background", "red"},
					     {"background", "/etc/passwd"},
					     {"background", "#000000, #ffffff"},
					     {"colour", "#fff"}};
	struct output_views set = {0};

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		assert_false(output_settings_key(&set, "k.ini", (int)i + 1, "output.HDMI-A-2",
						 bad[i][0], bad[i][1]));
	/* The section stands with its defaults. */
	assert_int_equal(set.count, 1);
	assert_int_equal(set.items[0].look, OUTPUT_SAME);
	assert_false(set.items[0].has_background);
	/* A name no connector has, and a fifth output. */
	assert_false(output_settings_key(&set, "k.ini", 20, "output.HDMI A/2", "view", "same"));
	assert_false(output_settings_key(&set, "k.ini", 21, "output.", "view", "same"));
	for (int i = 0; i < 3; i++) {
		char section[32];

		snprintf(section, sizeof(section), "output.X-%d", i);
		assert_true(output_settings_key(&set, "k.ini", 22 + i, section, "view", "same"));
	}
	assert_false(output_settings_key(&set, "k.ini", 30, "output.X-9", "view", "same"));
	assert_int_equal(set.count, OUTPUT_VIEWS_MAX);
}

static void file_errors_count(void **state)
{
	static const char good[] = "[display]\noutputs = HDMI-A-1, HDMI-A-2\n"
				   "[output.HDMI-A-2]\nview = mirror\ncaption = no\n";
	static const char bad_list[] = "[display]\noutputs = HDMI-A-1, HDMI-A-1\n";
	static const char bad_key[] = "[output.HDMI-A-2]\nview = upside-down\n";
	static const char stick[] = "[output.HDMI-A-2]\nview = mirror\n";
	struct options o;

	(void)state;
	option_defaults(&o);
	assert_int_equal(
	    options_read_text(&o, "k.ini", NULL, good, sizeof(good) - 1, &options_rules_admin),
	    OPTIONS_OK);
	assert_string_equal(o.display.outputs, "HDMI-A-1, HDMI-A-2");
	assert_int_equal(o.outputs.count, 1);
	assert_int_equal(o.outputs.items[0].look, OUTPUT_MIRROR);
	assert_false(o.outputs.items[0].caption);
	options_release(&o);
	option_defaults(&o);
	assert_int_equal(options_read_text(&o, "k.ini", NULL, bad_list, sizeof(bad_list) - 1,
					   &options_rules_admin),
			 OPTIONS_CONFIG);
	options_release(&o);
	option_defaults(&o);
	assert_int_equal(options_read_text(&o, "k.ini", NULL, bad_key, sizeof(bad_key) - 1,
					   &options_rules_admin),
			 OPTIONS_CONFIG);
	options_release(&o);
	/* A stick may not say what a screen of the case shows. */
	option_defaults(&o);
	assert_int_equal(options_read_text(&o, "stick/kiosk.ini", NULL, stick, sizeof(stick) - 1,
					   &options_rules_stick),
			 OPTIONS_CONFIG);
	assert_int_equal(o.outputs.count, 0);
	options_release(&o);
}

/* Degrees of a turn about y, in [0, 360). */
static double angle_about_y(struct quat q)
{
	double a = fmod(2 * atan2(q.y, q.w) * 180 / M_PI, 360);

	return a < 0 ? a + 360 : a;
}

static void views_turn_the_frame(void **state)
{
	struct output_view o;
	struct view v = {.orientation = quat_from_axis_angle(0, 1, 0, 30 * M_PI / 180),
			 .rotation = 0,
			 .background = {0.1f, 0.1f, 0.1f},
			 .wall = {.columns = 2, .rows = 1, .column = 1, .row = 1}},
		    w;

	(void)state;
	w = v;
	output_view_apply(NULL, &w);
	assert_memory_equal(&w, &v, sizeof(v));
	output_view_defaults(&o, "HDMI-A-2");
	w = v;
	output_view_apply(&o, &w);
	assert_memory_equal(&w, &v, sizeof(v)); /* same */
	o.look = OUTPUT_MIRROR;
	w = v;
	output_view_apply(&o, &w);
	assert_float_equal(angle_about_y(w.orientation), 210, 1e-4);
	o.look = OUTPUT_YAW;
	o.yaw = -90;
	w = v;
	output_view_apply(&o, &w);
	assert_float_equal(angle_about_y(w.orientation), 300, 1e-4);
	/* A tilted model is turned about the world's vertical, after its
	 * tilt: the back's visitor sees it tilted away, as it stands. */
	v.orientation = quat_from_axis_angle(1, 0, 0, 20 * M_PI / 180);
	o.look = OUTPUT_MIRROR;
	w = v;
	output_view_apply(&o, &w);
	{
		struct quat want =
		    quat_multiply(quat_from_axis_angle(0, 1, 0, M_PI), v.orientation);

		assert_float_equal(w.orientation.x, want.x, 1e-6);
		assert_float_equal(w.orientation.y, want.y, 1e-6);
		assert_float_equal(w.orientation.z, want.z, 1e-6);
		assert_float_equal(w.orientation.w, want.w, 1e-6);
	}
	o.look = OUTPUT_SLICE;
	o.column = 2;
	o.row = 1;
	o.rotation = 270;
	o.has_background = true;
	o.background[0] = 1;
	w = v;
	output_view_apply(&o, &w);
	assert_int_equal(w.wall.column, 2);
	assert_int_equal(w.wall.columns, 2);
	assert_int_equal(w.rotation, 270);
	assert_true(w.plain_background);
	assert_float_equal(w.background[0], 1, 0);
	assert_memory_equal(&w.orientation, &v.orientation, sizeof(v.orientation));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(names_are_split_and_checked), cmocka_unit_test(sections_are_read),
	    cmocka_unit_test(bad_values_are_refused), cmocka_unit_test(file_errors_count),
	    cmocka_unit_test(views_turn_the_frame)};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
