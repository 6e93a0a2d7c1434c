#include "app/options.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static int parse(struct options *o, int argc, const char **argv)
{
	return options_parse(o, argc, (char **)argv);
}

static char *write_ini(const char *text)
{
	static char path[64];
	int fd;

	strcpy(path, "/tmp/mk-ini-XXXXXX");
	fd = mkstemp(path);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
	close(fd);
	return path;
}

static void defaults(void **state)
{
	const char *argv[] = {"matcap-kiosk"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 1, argv), 0);
	assert_int_equal(o.backend, BACKEND_AUTO);
	assert_int_equal(o.size[0], 1280);
	assert_int_equal(o.size[1], 720);
	assert_int_equal(o.mode, SHADING_VIEW);
	assert_int_equal(o.frames, 1);
	assert_int_equal(o.log_level, VERBOSITY_INFO);
	assert_null(o.model);
	options_release(&o);
}

static void full_line(void **state)
{
	const char *argv[] = {"mk",	 "--backend",
			      "osmesa",	 "--model",
			      "m.glb",	 "--matcap",
			      "p.png",	 "--size",
			      "640x480", "--output",
			      "f.png",	 "--rotate",
			      "90",	 "--mode=sem-fragment",
			      "--ortho", "-q"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 16, argv), 0);
	assert_int_equal(o.backend, BACKEND_OSMESA);
	assert_string_equal(o.model, "m.glb");
	assert_string_equal(o.matcap, "p.png");
	assert_string_equal(o.output, "f.png");
	assert_int_equal(o.size[0], 640);
	assert_int_equal(o.size[1], 480);
	assert_int_equal(o.mode, SHADING_SEM_FRAGMENT);
	assert_int_equal(o.rotation, 90);
	assert_true(o.ortho);
	assert_int_equal(o.log_level, VERBOSITY_WARNING);
	options_release(&o);
}

static void rejects_bad_values(void **state)
{
	static const char *bad[][3] = {
	    {"mk", "--size", "1280"}, {"mk", "--size", "0x720"},   {"mk", "--size", "12x9999"},
	    {"mk", "--size", "axb"},  {"mk", "--mode", "phong"},   {"mk", "--backend", "x11"},
	    {"mk", "--rotate", "45"}, {"mk", "--frames", "0"},	   {"mk", "--frames", "3x"},
	    {"mk", "--yaw", "north"}, {"mk", "stray", "argument"}, {"mk", "--no-such", "1"},
	};
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		assert_int_equal(parse(&o, 3, bad[i]), OPTIONS_USAGE);
		options_release(&o);
	}
}

static void config_file_then_command_line(void **state)
{
	const char *path = write_ini("; comment\n[display]\nbackend = osmesa\nrotation = 180\n"
				     "[scene]\nmodel = a.glb\nmode = sem-vertex\northo = yes\n"
				     "[kiosk]\nlog_level = debug\n");
	const char *argv[] = {"mk", "--mode", "normal", "--config", path};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 5, argv), 0);
	assert_int_equal(o.backend, BACKEND_OSMESA);
	assert_int_equal(o.rotation, 180);
	assert_string_equal(o.model, "a.glb");
	assert_true(o.ortho);
	assert_int_equal(o.log_level, VERBOSITY_DEBUG);
	/* The command line wins over the file, wherever --config stands. */
	assert_int_equal(o.mode, SHADING_NORMAL);
	options_release(&o);
	unlink(path);
}

/* Every class of config error stops the start with OPTIONS_CONFIG (78). */
static void config_errors(void **state)
{
	static const char *texts[] = {
	    "[scene]\nfoo = 1\n",		     /* unknown key */
	    "[screen]\nsize = 10x10\n",		     /* unknown section */
	    "[scene]\nmode = phong\n",		     /* bad choice */
	    "[display]\nrotation = 45\n",	     /* bad step */
	    "[display]\nsize = 100000x2\n",	     /* out of range */
	    "[scene]\northo = maybe\n",		     /* bad flag */
	    "[scene]\nmode = view\nmode = normal\n", /* duplicate */
	    "[scene]\nmode = phong\nmode = view\n",  /* duplicate after a bad value */
	    "[scene\nmode = view\n",		     /* syntax */
	    "[display]\nbackend\n",		     /* no value */
	};
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(texts) / sizeof(texts[0]); i++) {
		const char *path = write_ini(texts[i]);
		const char *argv[] = {"mk", "--config", path};

		if (parse(&o, 3, argv) != OPTIONS_CONFIG)
			fail_msg("accepted: %s", texts[i]);
		options_release(&o);
		unlink(path);
	}
	const char *argv[] = {"mk", "--config", "/nonexistent/kiosk.ini"};
	assert_int_equal(parse(&o, 3, argv), OPTIONS_CONFIG);
	options_release(&o);
}

/* Indented keys are keys, not continuations of the line above. */
static void indented_lines(void **state)
{
	const char *path = write_ini("[scene]\n  mode = normal\n\tyaw = 10\n  [kiosk]\n"
				     "    log_level = debug\n");
	const char *argv[] = {"mk", "--config", path};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), 0);
	assert_int_equal(o.mode, SHADING_NORMAL);
	assert_true(o.yaw == 10.0);
	assert_int_equal(o.log_level, VERBOSITY_DEBUG);
	options_release(&o);
	unlink(path);
}

static void shipped_example_parses(void **state)
{
	const char *argv[] = {"mk", "--config", "config/kiosk.ini"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), 0);
	options_release(&o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(defaults),
	    cmocka_unit_test(full_line),
	    cmocka_unit_test(rejects_bad_values),
	    cmocka_unit_test(config_file_then_command_line),
	    cmocka_unit_test(config_errors),
	    cmocka_unit_test(indented_lines),
	    cmocka_unit_test(shipped_example_parses),
	};
	return cmocka_run_group_tests_name("options", tests, NULL, NULL);
}
