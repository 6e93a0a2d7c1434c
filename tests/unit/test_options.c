#include "options.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

static int parse(struct options *o, int argc, const char **argv)
{
	return options_parse(o, argc, (char **)argv);
}

static void defaults(void **state)
{
	const char *argv[] = {"matcap-kiosk"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 1, argv), 0);
	assert_int_equal(o.backend, BACKEND_AUTO);
	assert_int_equal(o.width, 1280);
	assert_int_equal(o.height, 720);
	assert_int_equal(o.mode, SHADING_VIEW);
	assert_int_equal(o.frames, 1);
	assert_null(o.model);
}

static void full_line(void **state)
{
	const char *argv[] = {"mk",	  "--backend", "osmesa", "--model",
			      "m.glb",	  "--matcap",  "p.png",	 "--size",
			      "640x480",  "--output",  "f.png",	 "--mode=sem-fragment",
			      "--rotate", "90",	       "--ortho"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 15, argv), 0);
	assert_int_equal(o.backend, BACKEND_OSMESA);
	assert_string_equal(o.model, "m.glb");
	assert_string_equal(o.matcap, "p.png");
	assert_string_equal(o.output, "f.png");
	assert_int_equal(o.width, 640);
	assert_int_equal(o.height, 480);
	assert_int_equal(o.mode, SHADING_SEM_FRAGMENT);
	assert_int_equal(o.rotation, 90);
	assert_true(o.ortho);
}

static void rejects_bad_values(void **state)
{
	static const char *bad[][3] = {
	    {"mk", "--size", "1280"}, {"mk", "--size", "0x720"},   {"mk", "--size", "12x9999"},
	    {"mk", "--size", "axb"},  {"mk", "--mode", "phong"},   {"mk", "--backend", "x11"},
	    {"mk", "--rotate", "45"}, {"mk", "--frames", "0"},	   {"mk", "--frames", "3x"},
	    {"mk", "--yaw", "north"}, {"mk", "stray", "argument"},
	};
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		assert_int_not_equal(parse(&o, 3, bad[i]), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(defaults),
	    cmocka_unit_test(full_line),
	    cmocka_unit_test(rejects_bad_values),
	};
	return cmocka_run_group_tests_name("options", tests, NULL, NULL);
}
