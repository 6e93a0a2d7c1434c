/* Settings a stranger brings (issue 32's findings, each as it was
 * reported): a line past 199 bytes and a ' ;' inside a value read whole; a
 * padded line that smuggled a [display] past the import; a stick's
 * kiosk.ini, the include and a stick's NAME.ini held to a stick's rules;
 * settings files anyone may write, FIFOs and huge files refused without
 * hanging; nine stops on the command line refused by name. */
#include "config/model_settings.h"
#include "config/options.h"
#include "config/settings.h"
#include "ops/import_ini.h"
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
	strcpy(root, "/tmp/mk-stranger-XXXXXX");
	return mkdtemp(root) ? 0 : -1;
}

static int remove_root(void **state)
{
	char cmd[256];

	(void)state;
	snprintf(cmd, sizeof(cmd), "chmod -R u+w '%s'; rm -rf '%s'", root, root);
	return system(cmd) == 0 ? 0 : -1;
}

static const char *under(const char *name)
{
	static char path[PATH_MAX];

	snprintf(path, sizeof(path), "%s/%s", root, name);
	return path;
}

/* put("a/kiosk.ini", text): the file under root, its folders made. */
static const char *put(const char *name, const char *text)
{
	const char *path = under(name);
	char dir[PATH_MAX];
	FILE *f;

	for (const char *p = strchr(path + strlen(root) + 1, '/'); p; p = strchr(p + 1, '/')) {
		snprintf(dir, sizeof(dir), "%.*s", (int)(p - path), path);
		mkdir(dir, 0755);
	}
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
	return path;
}

static enum options_status read_at(struct options *o, const char *name)
{
	option_defaults(o);
	return options_read_file(o, under(name));
}

/* [display] size as no file set it. */
static int default_width(void)
{
	struct options d;
	int w;

	option_defaults(&d);
	w = d.display.width;
	options_release(&d);
	return w;
}

static bool last_error_has(const char *text)
{
	char last[2048];

	log_last_error(last, sizeof(last));
	return strstr(last, text) != NULL;
}

/* A curator's long lines: a 72-character Japanese caption (216 bytes) and
 * five stops with their texts, each past libinih's 199 bytes. */
static void long_lines_read_whole(void **state)
{
	char text[4096], caption[512] = "", stops[1024] = "";
	struct options o;

	(void)state;
	for (int i = 0; i < 72; i++)
		strcat(caption, "\xe5\xa3\xba"); /* 壺 */
	for (int i = 0; i < 5; i++) {
		char one[128];

		snprintf(one, sizeof(one),
			 "%s%d 0 1 \"Stop %d: the painter's signature, under "
			 "the handle\"",
			 i ? "; " : "", 72 * i, i);
		strcat(stops, one);
	}
	snprintf(text, sizeof(text), "[caption]\ntext = %s\n[frame]\nstops = %s\n", caption, stops);
	assert_true(strlen(caption) > 199 && strlen(stops) > 199);
	put("long/kiosk.ini", text);
	assert_int_equal(read_at(&o, "long/kiosk.ini"), OPTIONS_OK);
	assert_string_equal(o.content.caption.text, caption);
	assert_string_equal(o.content.frame.stops, stops);
	options_release(&o);
}

/* ' ;' started a comment: "Amphora" was shown, and '; banana' passed. */
static void a_semicolon_is_part_of_the_value(void **state)
{
	struct options o;

	(void)state;
	put("semi/kiosk.ini", "; a comment line\n[caption]\ntext = Amphora ; Attic, 5th c. BC\n");
	assert_int_equal(read_at(&o, "semi/kiosk.ini"), OPTIONS_OK);
	assert_string_equal(o.content.caption.text, "Amphora ; Attic, 5th c. BC");
	options_release(&o);
	put("semi/kiosk.ini", "[frame]\nstops = 0 0 1 \"Front\"; 90 0 1 ; banana\n");
	log_clear_last_error();
	assert_int_equal(read_at(&o, "semi/kiosk.ini"), OPTIONS_CONFIG);
	assert_true(last_error_has("kiosk.ini:2: [frame] stops is not valid"));
	options_release(&o);
}

/* The reproducer: in [scene], matcap = a,a,a.png ; padded with x to 380
 * bytes, [display] over bytes 181-189, ';' at 199, then size = 77x55. It
 * imported a [display] size once the rewrite split it anew. */
static void a_padded_line_smuggles_nothing(void **state)
{
	char line[512], text[600];
	struct options a, b;
	char *out = NULL;
	size_t n = 0;

	(void)state;
	snprintf(line, sizeof(line), "matcap = a,a,a.png ;");
	memset(line + strlen(line), 'x', 380 - strlen(line));
	line[380] = '\0';
	memcpy(line + 181, "[display]", 9);
	line[199] = ';';
	snprintf(text, sizeof(text), "[scene]\n%ssize = 77x55\n", line);
	option_defaults(&a);
	assert_int_equal(options_read_text(&a, "stick/kiosk.ini", NULL, text, strlen(text),
					   &options_rules_stick),
			 OPTIONS_OK);
	assert_int_equal(a.display.width, default_width());
	assert_int_equal(import_ini_rebase(text, strlen(text), &out, &n), 0);
	option_defaults(&b);
	assert_int_equal(
	    options_read_text(&b, "content/kiosk.ini", "/content", out, n, &options_rules_stick),
	    OPTIONS_OK);
	assert_int_equal(b.display.width, default_width());
	assert_non_null(strstr(b.content.matcap, "size = 77x55"));
	free(out);
	options_release(&a);
	options_release(&b);
}

/* Written plainly, each key a stick may not set is refused by name, and
 * each path that leaves the stick. */
static void a_stick_keeps_to_its_keys_and_paths(void **state)
{
	static const char *const bad[] = {
	    "[display]\nsize = 77x55\n",
	    "[power]\nschedule = Mon 00:00-00:01\n",
	    "[status]\nmetrics = /tmp/m.prom\n",
	    "[kiosk]\ninclude = x.ini\n",
	    "[scene]\nmatcap = /usr/share/pixmaps\n",
	    "[scene]\nmodel = a.glb, ../../etc/x.glb\n",
	    "[material]\ndetail_map = ../d.png\n",
	    "[scene]\nmatcap = matcaps/../../x\n",
	};
	static const char good[] = "[scene]\nmodel = a.glb, sub/b..c.glb\nmatcap = matcaps\n"
				   "[kiosk]\nattract_after = 30\n";
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		option_defaults(&o);
		log_clear_last_error();
		assert_int_equal(options_read_text(&o, "stick/kiosk.ini", NULL, bad[i],
						   strlen(bad[i]), &options_rules_stick),
				 OPTIONS_CONFIG);
		assert_true(last_error_has("stick/kiosk.ini:2: ["));
		options_release(&o);
	}
	assert_true(last_error_has("a USB stick's paths must be relative"));
	option_defaults(&o);
	assert_int_equal(options_read_text(&o, "stick/kiosk.ini", NULL, good, strlen(good),
					   &options_rules_stick),
			 OPTIONS_OK);
	options_release(&o);
}

/* The live kiosk reads the include with a stick's rules, whoever wrote
 * it: a restricted key there is named, and the include ignored. */
static void the_include_is_a_sticks(void **state)
{
	static const char *const bad[] = {
	    "[display]\nsize = 77x55\n",
	    "[power]\nschedule = Mon 00:00-00:01\n",
	    "[scene]\nmatcap = /usr/share/pixmaps\n",
	    "[scene]\nmatcap = ../../usr/share/pixmaps\n",
	};
	struct options o;
	char text[PATH_MAX + 64];

	(void)state;
	put("inc/kiosk.ini", "[kiosk]\ninclude = content/kiosk.ini\n[scene]\nyaw = 5\n");
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		put("inc/content/kiosk.ini", bad[i]);
		log_clear_last_error();
		assert_int_equal(read_at(&o, "inc/kiosk.ini"), OPTIONS_OK);
		assert_true(o.include_ignored);
		assert_int_equal(o.display.width, default_width());
		assert_true(o.content.yaw == 5);
		assert_null(o.content.matcap);
		options_release(&o);
	}
	/* What an import wrote before: absolute paths inside its folder. */
	snprintf(text, sizeof(text), "[scene]\nmatcap = %s/matcaps\nmodel = model/a.glb\n",
		 under("inc/content"));
	put("inc/content/kiosk.ini", text);
	assert_int_equal(read_at(&o, "inc/kiosk.ini"), OPTIONS_OK);
	assert_false(o.include_ignored);
	assert_string_equal(o.content.matcap, under("inc/content/matcaps"));
	options_release(&o);
}

/* A stick's NAME.ini showed the kiosk's own files on the public screen. */
static void a_sticks_model_file_keeps_to_the_stick(void **state)
{
	static const char *const bad[] = {
	    "[scene]\nmatcap = /usr/share/pixmaps\n",
	    "[display]\nbackground = /usr/share/images/desktop-base/a.png\n",
	    "[caption]\nlogo = ../../../../usr/share/pixmaps/debian-logo.png\n",
	    "[caption]\nfont = /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf\n",
	    "[material]\ndetail_map = /etc/passwd\n",
	};
	char model[PATH_MAX];
	struct options o;

	(void)state;
	snprintf(model, sizeof(model), "%s", under("m/vase.glb"));
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		put("m/vase.ini", bad[i]);
		option_defaults(&o);
		log_clear_last_error();
		assert_int_equal(model_settings_read_stick(&o.content, model), OPTIONS_CONFIG);
		assert_true(last_error_has("a USB stick's paths must be relative"));
		/* Installed by the owner, the same file is the owner's choice. */
		assert_int_equal(model_settings_read(&o.content, model), OPTIONS_OK);
		options_release(&o);
	}
	put("m/vase.ini", "[caption]\nlogo = logo.png\ntext = Vase\n[scene]\nmatcap = mc\n");
	option_defaults(&o);
	assert_int_equal(model_settings_read_stick(&o.content, model), OPTIONS_OK);
	assert_string_equal(o.content.caption.logo, under("m/logo.png"));
	options_release(&o);
}

/* As sshd's StrictModes: a settings file anyone may write is refused. */
static void files_anyone_may_write_are_refused(void **state)
{
	struct options o;

	(void)state;
	put("ww/kiosk.ini", "[scene]\nyaw = 5\n");
	put("ww/kiosk.ini.d/10-a.ini", "[scene]\npitch = 3\n");
	assert_int_equal(read_at(&o, "ww/kiosk.ini"), OPTIONS_OK);
	options_release(&o);
	chmod(under("ww/kiosk.ini.d/10-a.ini"), 0666);
	log_clear_last_error();
	assert_int_equal(read_at(&o, "ww/kiosk.ini"), OPTIONS_CONFIG);
	assert_true(last_error_has("10-a.ini: refused: anyone may write"));
	options_release(&o);
	chmod(under("ww/kiosk.ini.d/10-a.ini"), 0644);
	chmod(under("ww/kiosk.ini.d"), 0777);
	assert_int_equal(read_at(&o, "ww/kiosk.ini"), OPTIONS_CONFIG);
	assert_true(last_error_has("kiosk.ini.d: refused: anyone may write"));
	options_release(&o);
	chmod(under("ww/kiosk.ini.d"), 0755);
	/* A folder where anyone may replace the file; /tmp's sticky bit
	 * stops that. */
	chmod(under("ww"), 0777);
	assert_int_equal(read_at(&o, "ww/kiosk.ini"), OPTIONS_CONFIG);
	assert_true(last_error_has("its folder"));
	options_release(&o);
	chmod(under("ww"), 01777);
	assert_int_equal(read_at(&o, "ww/kiosk.ini"), OPTIONS_OK);
	options_release(&o);
	chmod(under("ww"), 0755);
}

/* A FIFO hung the reader; a settings file of megabytes is no settings
 * file. alarm: a hang fails the test rather than the suite. */
static void fifos_and_huge_files_refused(void **state)
{
	struct options o;
	FILE *f;

	(void)state;
	put("ff/kiosk.ini", "[scene]\nyaw = 5\n");
	mkdir(under("ff/kiosk.ini.d"), 0755);
	assert_int_equal(mkfifo(under("ff/kiosk.ini.d/10-fifo.ini"), 0644), 0);
	alarm(10);
	/* A FIFO among the drop-ins is passed over (util/file.c says so). */
	assert_int_equal(read_at(&o, "ff/kiosk.ini"), OPTIONS_OK);
	assert_true(o.content.yaw == 5);
	options_release(&o);
	unlink(under("ff/kiosk.ini.d/10-fifo.ini"));
	/* A FIFO named as the include: refused by name, the include ignored. */
	put("ff/kiosk.ini", "[scene]\nyaw = 5\n[kiosk]\ninclude = inc.ini\n");
	assert_int_equal(mkfifo(under("ff/inc.ini"), 0644), 0);
	log_clear_last_error();
	assert_int_equal(read_at(&o, "ff/kiosk.ini"), OPTIONS_OK);
	assert_true(o.include_ignored);
	options_release(&o);
	unlink(under("ff/inc.ini"));
	put("ff/kiosk.ini", "[scene]\nyaw = 5\n");
	f = fopen(under("ff/kiosk.ini.d/20-big.ini"), "w");
	assert_non_null(f);
	for (int i = 0; i < 80000; i++)
		fputs("; fifteen bytes\n", f);
	fclose(f);
	assert_int_equal(read_at(&o, "ff/kiosk.ini"), OPTIONS_CONFIG);
	assert_true(last_error_has("20-big.ini: over 1024 KiB"));
	options_release(&o);
	alarm(0);
}

static void nine_stops_on_the_command_line(void **state)
{
	const char *argv[] = {"mk", "--stops",
			      "0 0 1; 10 0 1; 20 0 1; 30 0 1; 40 0 1; 50 0 1; 60 0 1; 70 0 1; "
			      "80 0 1"};
	struct options o;

	(void)state;
	log_clear_last_error();
	assert_int_equal(options_parse(&o, 3, (char **)argv), OPTIONS_USAGE);
	assert_true(last_error_has("--stops"));
	assert_true(last_error_has("more than 8 stops"));
	options_release(&o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(long_lines_read_whole),
	    cmocka_unit_test(a_semicolon_is_part_of_the_value),
	    cmocka_unit_test(a_padded_line_smuggles_nothing),
	    cmocka_unit_test(a_stick_keeps_to_its_keys_and_paths),
	    cmocka_unit_test(the_include_is_a_sticks),
	    cmocka_unit_test(a_sticks_model_file_keeps_to_the_stick),
	    cmocka_unit_test(files_anyone_may_write_are_refused),
	    cmocka_unit_test(fifos_and_huge_files_refused),
	    cmocka_unit_test(nine_stops_on_the_command_line),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, make_root, remove_root);
}
