/* The settings files as src/config/options.c reads them: relative paths from
 * the file's folder, quotes, ~ and folders refused, kiosk.ini.d/ drop-ins
 * in name order with their origins, an include with errors; --check-config's
 * verdicts (src/ops/check.c); a reload's cause (src/app/reload.c); and a
 * USB stick's paths made the content folder's (src/ops/import_ini.c). */
#include "ops/check.h"
#include "ops/import_ini.h"
#include "config/options.h"
#include "app/reload.h"
#include "config/settings.h"
#include "util/log.h"

#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

static char root[64];

static int make_root(void **state)
{
	(void)state;
	strcpy(root, "/tmp/mk-settings-XXXXXX");
	return mkdtemp(root) ? 0 : -1;
}

static int remove_root(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", root);
	return system(cmd) == 0 ? 0 : -1;
}

/* put("a/kiosk.ini", text): the file under root, its folders made. */
static const char *put(const char *name, const char *text)
{
	static char path[PATH_MAX];
	char dir[PATH_MAX];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", root, name);
	for (char *p = strchr(path + strlen(root) + 1, '/'); p; p = strchr(p + 1, '/')) {
		snprintf(dir, sizeof(dir), "%.*s", (int)(p - path), path);
		mkdir(dir, 0755);
	}
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
	return path;
}

static char *under(const char *name)
{
	static char path[PATH_MAX];

	snprintf(path, sizeof(path), "%s/%s", root, name);
	return path;
}

static enum options_status read_at(struct options *o, const char *name)
{
	char path[PATH_MAX];

	snprintf(path, sizeof(path), "%s/%s", root, name);
	option_defaults(o);
	return options_read_file(o, path);
}

static const struct option_def *def(const char *name)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (!strcmp(option_defs[i].name, name))
			return &option_defs[i];
	fail_msg("no option --%s", name);
	return NULL;
}

static void relative_paths_from_the_file(void **state)
{
	struct options o;
	char want[PATH_MAX * 2];

	(void)state;
	put("b/inc.ini", "[scene]\nmodel = x.glb, sub/z.glb\n");
	put("a/kiosk.ini", "[scene]\nmodel = m.glb\nmatcap = mc\n[display]\nposter = p.png\n"
			   "device = /dev/dri/card1\n[material]\ndetail_map = ../d.png\n"
			   "[kiosk]\ninclude = ../b/inc.ini\n");
	assert_int_equal(read_at(&o, "a/kiosk.ini"), OPTIONS_OK);
	snprintf(want, sizeof(want), "%s/a/../b/x.glb, %s/a/../b/sub/z.glb", root, root);
	/* The included file's from its own folder, however it was named (a
	 * stick's: no absolute path, test_stranger_settings.c). */
	assert_string_equal(o.content.model, want);
	assert_string_equal(o.content.matcap, under("a/mc"));
	assert_string_equal(o.poster, under("a/p.png"));
	assert_string_equal(o.content.material.detail_map, under("a/../d.png"));
	assert_string_equal(o.include, under("a/../b/inc.ini"));
	assert_string_equal(o.display.device, "/dev/dri/card1");
	options_release(&o);
}

static void command_line_paths_stay(void **state)
{
	const char *path = put("c/kiosk.ini", "[scene]\nmatcap = mc\n");
	const char *argv[] = {"mk", "--config", path, "--model", "m.glb"};
	struct options o;

	(void)state;
	assert_int_equal(options_parse(&o, 5, (char **)argv), OPTIONS_OK);
	assert_string_equal(o.content.model, "m.glb");
	assert_string_equal(o.content.matcap, under("c/mc"));
	assert_string_equal(options_origin(&o, def("model")).file, "the command line");
	assert_int_equal(options_origin(&o, def("model")).line, 0);
	assert_string_equal(options_origin(&o, def("matcap")).file, under("c/kiosk.ini"));
	assert_int_equal(options_origin(&o, def("matcap")).line, 2);
	options_release(&o);
}

static void quotes_tilde_and_folders_refused(void **state)
{
	static const char *const bad[] = {
	    "[scene]\nmodel = \"/srv/a b.glb\"\n", "[scene]\nmatcap = '/srv/mc'\n",
	    "[scene]\nmode = \"view\"\n",	   "[scene]\nmodel = ~/m.glb\n",
	    "[scene]\nmodel = a.glb, ~/m.glb\n",   "[display]\nposter = ~\n",
	};
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		put("q.ini", bad[i]);
		assert_int_equal(read_at(&o, "q.ini"), OPTIONS_CONFIG);
		options_release(&o);
	}
	/* A quote inside a value is the user's: kept. */
	put("q.ini", "[scene]\nmodel = /srv/it's.glb\n");
	assert_int_equal(read_at(&o, "q.ini"), OPTIONS_OK);
	assert_string_equal(o.content.model, "/srv/it's.glb");
	options_release(&o);
	mkdir(under("folder.ini"), 0755);
	assert_int_equal(read_at(&o, "folder.ini"), OPTIONS_CONFIG);
	options_release(&o);
}

static void dropins_in_name_order(void **state)
{
	struct options o;
	const char *const *files;

	(void)state;
	put("d/kiosk.ini", "[scene]\nmode = view\nyaw = 5\n");
	put("d/kiosk.ini.d/20-b.ini", "[scene]\nmode = normal\n");
	put("d/kiosk.ini.d/10-a.ini", "; site\n[scene]\nmode = sem-vertex\npitch = 3\n");
	put("d/kiosk.ini.d/30-c.ini.dpkg-old", "[scene]\nyaw = 99\n");
	put("d/kiosk.ini.d/.hidden.ini", "[scene]\nyaw = 98\n");
	assert_int_equal(read_at(&o, "d/kiosk.ini"), OPTIONS_OK);
	assert_int_equal(o.content.mode, SHADING_NORMAL); /* the last file's */
	assert_true(o.content.pitch == 3);
	assert_true(o.content.yaw == 5); /* other names are not read */
	assert_string_equal(options_origin(&o, def("mode")).file, under("d/kiosk.ini.d/20-b.ini"));
	assert_int_equal(options_origin(&o, def("mode")).line, 2);
	assert_string_equal(options_origin(&o, def("pitch")).file, under("d/kiosk.ini.d/10-a.ini"));
	assert_int_equal(options_origin(&o, def("pitch")).line, 4);
	assert_string_equal(options_origin(&o, def("yaw")).file, under("d/kiosk.ini"));
	assert_null(options_origin(&o, def("ortho")).file); /* its default */
	assert_int_equal(options_files_read(&o, &files), 3);
	assert_string_equal(files[0], under("d/kiosk.ini"));
	assert_string_equal(files[1], under("d/kiosk.ini.d/10-a.ini"));
	assert_string_equal(files[2], under("d/kiosk.ini.d/20-b.ini"));
	options_release(&o);
	/* Within one file a key is set once; every file is read. */
	put("d/kiosk.ini.d/40-dup.ini", "[scene]\nyaw = 1\nyaw = 2\n");
	assert_int_equal(read_at(&o, "d/kiosk.ini"), OPTIONS_CONFIG);
	assert_int_equal(options_files_read(&o, &files), 4);
	options_release(&o);
}

static void include_with_errors_is_ignored(void **state)
{
	struct options o;

	(void)state;
	put("e/kiosk.ini", "[kiosk]\ninclude = stick.ini\n[scene]\nyaw = 5\n");
	put("e/kiosk.ini.d/10-a.ini", "[scene]\npitch = 3\n");
	put("e/stick.ini", "[scene]\nmodle = x.glb\nyaw = 7\n");
	assert_int_equal(read_at(&o, "e/kiosk.ini"), OPTIONS_OK);
	assert_true(o.include_ignored);
	assert_true(o.content.yaw == 5);   /* the installed files alone... */
	assert_true(o.content.pitch == 3); /* ...drop-ins included */
	options_release(&o);
	put("e/stick.ini", "[scene]\nyaw = 7\n");
	assert_int_equal(read_at(&o, "e/kiosk.ini"), OPTIONS_OK);
	assert_false(o.include_ignored);
	assert_true(o.content.yaw == 7);
	options_release(&o);
}

static int check_file(const char *text, const char *matcap)
{
	const char *path = put("f/kiosk.ini", text);
	const char *argv[] = {"mk", "--config", path, "--matcap", matcap};
	FILE *out = tmpfile();
	struct options o;
	int ret;

	assert_non_null(out);
	assert_int_equal(options_parse(&o, 5, (char **)argv), OPTIONS_OK);
	ret = check_config_run(&o, out);
	options_release(&o);
	fclose(out);
	return ret;
}

static void check_config_verdicts(void **state)
{
	char gold[PATH_MAX];

	(void)state;
	assert_non_null(realpath("matcaps/gold.png", gold));
	assert_int_equal(check_file("[scene]\nmode = view\n", gold), 0);
	assert_int_equal(check_file("[scene]\nmodel = /nonexistent/m.glb\n", gold), CHECK_BAD_FILE);
	assert_int_equal(check_file("", "/etc/passwd"), CHECK_BAD_FILE);
	assert_int_equal(check_file("[display]\nposter = none.png\n", gold), CHECK_BAD_FILE);
	assert_int_equal(check_file("[material]\ndetail_map = /etc/passwd\n", gold),
			 CHECK_BAD_FILE);
	put("f/bad.ini", "[scene]\nmodle = x\n");
	assert_int_equal(check_file("[kiosk]\ninclude = bad.ini\n", gold), CHECK_BAD_SETTINGS);
}

static void reload_names_its_cause(void **state)
{
	char last[1024];

	(void)state;
	log_err("an old error");
	log_clear_last_error();
	log_last_error(last, sizeof(last));
	assert_string_equal(last, "");
	log_err("a.ini:2: [scene] mode = 'phong' is not valid");
	reload_failed("the settings have errors");
	log_last_error(last, sizeof(last));
	assert_string_equal(last, "reload: the settings have errors; keeping the scene on screen "
				  "(a.ini:2: [scene] mode = 'phong' is not valid)");
	log_clear_last_error();
	reload_failed("the scene does not load");
	log_last_error(last, sizeof(last));
	assert_string_equal(last, "reload: the scene does not load; keeping the scene on screen");
	log_clear_last_error();
}

static void stick_paths_into_the_content_folder(void **state)
{
	static const char in[] = "[scene]\nmodel = a.glb, matcaps/x.glb ; two\n"
				 "matcap = matcaps\n  detail_map=d.png\r\nmode = view\n"
				 "; model = c.glb\n[material]\nramp =\niridescence_ramp = r.png";
	static const char want[] = "[scene]\nmodel = model/a.glb, matcaps/x.glb ; two\n"
				   "matcap = matcaps\n  detail_map=model/d.png\r\nmode = view\n"
				   "; model = c.glb\n[material]\nramp =\niridescence_ramp = "
				   "model/r.png";
	char *out = NULL;
	size_t n = 0;

	(void)state;
	assert_int_equal(import_ini_rebase(in, sizeof(in) - 1, &out, &n), 0);
	assert_string_equal(out, want);
	assert_int_equal(n, strlen(want));
	free(out);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(relative_paths_from_the_file),
	    cmocka_unit_test(command_line_paths_stay),
	    cmocka_unit_test(quotes_tilde_and_folders_refused),
	    cmocka_unit_test(dropins_in_name_order),
	    cmocka_unit_test(include_with_errors_is_ignored),
	    cmocka_unit_test(check_config_verdicts),
	    cmocka_unit_test(reload_names_its_cause),
	    cmocka_unit_test(stick_paths_into_the_content_folder),
	};

	log_set_level(LOG_WARN);
	return cmocka_run_group_tests(tests, make_root, remove_root);
}
