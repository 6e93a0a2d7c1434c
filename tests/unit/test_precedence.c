/* The one precedence (issue 33, point 5): the command line over a model's
 * NAME.ini over the drop-ins over kiosk.ini, every pair of the four
 * layers; and where each value in effect came from, as --check-config -v
 * prints it. Before, a NAME.ini beside the model won over --yaw 90
 * --caption X --background '#ff0000' (a byte-identical frame). */
#include "config/model_settings.h"
#include "config/options.h"
#include "config/settings.h"
#include "util/log.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

static char dir[] = "/tmp/mk-precedence-XXXXXX";

enum layer { KIOSK_INI, DROP_IN, NAME_INI, COMMAND_LINE, LAYERS };

static const char *const layer_names[LAYERS] = {"kiosk.ini", "a drop-in", "NAME.ini",
						"the command line"};

static void path_of(char *out, size_t n, const char *name)
{
	snprintf(out, n, "%s/%s", dir, name);
}

static void write_file(const char *name, const char *text)
{
	char path[256];
	FILE *f;

	path_of(path, sizeof(path), name);
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

/* [scene] yaw = 10 (kiosk.ini), 20 (the drop-in), 30 (NAME.ini) or 40
 * (--yaw) in each layer of set; the settings read as the kiosk reads
 * them for the model vase.glb. */
static double yaw_with(unsigned set)
{
	char ini[256], model[256], yaw[16], text[64];
	char *argv[] = {"mk", "--config", ini, "--yaw", yaw, NULL};
	int argc = set & (1u << COMMAND_LINE) ? 5 : 3;
	const char *names[] = {"kiosk.ini", "kiosk.ini.d/10-site.ini", "vase.ini"};
	struct options o;
	double got;

	path_of(ini, sizeof(ini), "kiosk.ini");
	path_of(model, sizeof(model), "vase.glb");
	snprintf(yaw, sizeof(yaw), "%d", 10 * (COMMAND_LINE + 1));
	for (int l = KIOSK_INI; l < COMMAND_LINE; l++) {
		if (set & (1u << l))
			snprintf(text, sizeof(text), "[scene]\nyaw = %d\n", 10 * (l + 1));
		else
			snprintf(text, sizeof(text), "[scene]\n");
		write_file(names[l], text);
	}
	assert_int_equal(options_parse(&o, argc, argv), OPTIONS_OK);
	assert_int_equal(model_settings_read(&o.content, model), OPTIONS_OK);
	got = o.content.yaw;
	options_release(&o);
	return got;
}

/* Of every two layers that set the same key, the higher's value is in
 * effect; and with all four, the command line's. */
static void every_pair(void **state)
{
	(void)state;
	for (int lo = KIOSK_INI; lo < LAYERS; lo++)
		for (int hi = lo + 1; hi < LAYERS; hi++) {
			double got = yaw_with(1u << lo | 1u << hi);

			if (got != 10 * (hi + 1))
				fail_msg("%s and %s: yaw %g, expected %s's %d", layer_names[lo],
					 layer_names[hi], got, layer_names[hi], 10 * (hi + 1));
		}
	for (int l = KIOSK_INI; l < LAYERS; l++)
		assert_float_equal(yaw_with(1u << l), 10 * (l + 1), 0);
	assert_float_equal(yaw_with((1u << LAYERS) - 1), 40, 0);
	assert_float_equal(yaw_with(0), -30, 0); /* the default */
}

/* The issue's own command: each of the three over NAME.ini's, while what
 * the command line did not name stays NAME.ini's. */
static void issue_command(void **state)
{
	char ini[256], model[256];
	char *argv[] = {"mk", "--config",     ini,	 "--yaw", "90", "--caption",
			"X",  "--background", "#ff0000", NULL};
	struct options o;

	(void)state;
	path_of(ini, sizeof(ini), "kiosk.ini");
	path_of(model, sizeof(model), "vase.glb");
	write_file("kiosk.ini", "[scene]\n");
	write_file("kiosk.ini.d/10-site.ini", "[scene]\n");
	write_file("vase.ini", "[scene]\nyaw = 10\npitch = 5\n[caption]\ntext = Vase\n"
			       "[display]\nbackground = #00ff00\n");
	assert_int_equal(options_parse(&o, 9, argv), OPTIONS_OK);
	assert_int_equal(model_settings_read(&o.content, model), OPTIONS_OK);
	assert_float_equal(o.content.yaw, 90, 0);
	assert_string_equal(o.content.caption.text, "X");
	assert_string_equal(o.content.background, "#ff0000");
	assert_float_equal(o.content.pitch, 5, 0);
	options_release(&o);
}

/* What --check-config -v prints: each value with its file and line, "the
 * command line" or the default, and a NAME.ini's values under the command
 * line's. */
static void origins_said(void **state)
{
	char ini[256], model[256], drop[256], own[256], want[400], *text = NULL;
	char *argv[] = {"mk", "--config", ini, "--yaw", "90", NULL};
	struct options o;
	struct options_origin at;
	size_t size = 0;
	FILE *out;

	(void)state;
	path_of(ini, sizeof(ini), "kiosk.ini");
	path_of(model, sizeof(model), "vase.glb");
	path_of(drop, sizeof(drop), "kiosk.ini.d/10-site.ini");
	path_of(own, sizeof(own), "vase.ini");
	write_file("kiosk.ini", "[scene]\nfit = 0.5\n");
	write_file("kiosk.ini.d/10-site.ini", "# the site\n[scene]\n\npitch = 12\n");
	write_file("vase.ini", "[scene]\nyaw = 10\npitch = 5\n");
	assert_int_equal(options_parse(&o, 5, argv), OPTIONS_OK);
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];

		at = options_origin(&o, d);
		if (d->name && !strcmp(d->name, "fit")) {
			assert_string_equal(at.file, ini);
			assert_int_equal(at.line, 2);
		} else if (d->name && !strcmp(d->name, "pitch")) {
			assert_string_equal(at.file, drop);
			assert_int_equal(at.line, 4);
		} else if (d->name && !strcmp(d->name, "yaw")) {
			assert_string_equal(at.file, "the command line");
			assert_int_equal(at.line, 0);
		} else if (d->name && !strcmp(d->name, "mode")) {
			assert_null(at.file); /* the default */
		}
	}
	out = open_memstream(&text, &size);
	assert_non_null(out);
	assert_int_equal(model_settings_read_listed(&o.content, model, false, out), OPTIONS_OK);
	fclose(out);
	snprintf(want, sizeof(want), "[scene] yaw = 90 (the command line, over %s:2)", own);
	assert_non_null(strstr(text, want));
	snprintf(want, sizeof(want), "[scene] pitch = 5 (%s:3)", own);
	assert_non_null(strstr(text, want));
	free(text);
	options_release(&o);
}

static const struct option_def *def_named(const char *name)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].name && !strcmp(option_defs[i].name, name))
			return &option_defs[i];
	fail_msg("no option --%s", name);
	return NULL;
}

/* Each kind of value as a file writes it; none is left empty but a
 * string. */
static void values_written(void **state)
{
	char ini[256], buf[256];
	char *argv[] = {"mk",	       "--config", ini,	     "--size", "640x480",
			"--start-yaw", "45",	   "--mode", "normal", NULL};
	struct options o;

	(void)state;
	path_of(ini, sizeof(ini), "kiosk.ini");
	write_file("kiosk.ini", "[kiosk]\nlog_level = warning\n");
	assert_int_equal(options_parse(&o, 9, argv), OPTIONS_OK);
	option_value_text(&o, def_named("size"), buf, sizeof(buf));
	assert_string_equal(buf, "640x480");
	option_value_text(&o, def_named("start-yaw"), buf, sizeof(buf));
	assert_string_equal(buf, "45");
	option_value_text(&o, def_named("mode"), buf, sizeof(buf));
	assert_string_equal(buf, "normal");
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		option_value_text(&o, &option_defs[i], buf, sizeof(buf));
		if (option_defs[i].kind != K_STRING && !buf[0])
			fail_msg("--%s: no text for its value", option_defs[i].name);
	}
	options_release(&o);
}

static int setup(void **state)
{
	char sub[256];

	(void)state;
	log_set_level(LOG_ERR);
	if (!mkdtemp(dir))
		return -1;
	path_of(sub, sizeof(sub), "kiosk.ini.d");
	return mkdir(sub, 0755);
}

static int teardown(void **state)
{
	char cmd[300];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(every_pair),
	    cmocka_unit_test(issue_command),
	    cmocka_unit_test(origins_said),
	    cmocka_unit_test(values_written),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
