/* [hotspot.NAME] sections (config/hotspot_settings.c) in a model's
 * NAME.ini and in kiosk.ini: the good ones kept, each bad one dropped
 * alone with an error naming the file, the line and what was expected,
 * the rest of the file still applied; a model's own hotspot replaces
 * kiosk.ini's of the same name. */
#include "config/hotspot_settings.h"
#include "config/model_settings.h"
#include "config/settings.h"
#include "ops/check.h"
#include "util/log.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static char dir[] = "/tmp/mk-hotspot-settings-XXXXXX";

static void write_file(const char *name, const char *text)
{
	char path[256];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

static void model(char *out, size_t n, const char *name)
{
	snprintf(out, n, "%s/%s", dir, name);
}

static void good_hotspots(void **state)
{
	struct options o;
	char m[256];
	const struct hotspot *h;

	(void)state;
	option_defaults(&o);
	write_file("vase.ini",
		   "[frame]\nyaw = 45\n\n[hotspot.signature]\npoint = 0.1 0.5 -0.2\n"
		   "normal = 0 0 -2\ntext = The painter's signature ; 1780\nlook = badge\n"
		   "color = #ff000080\n\n[hotspot.lid]\nnode = Lid knob\n");
	model(m, sizeof(m), "vase.glb");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	assert_float_equal(o.content.frame.yaw, 45, 0);
	assert_int_equal(o.content.hotspots.count, 2);
	h = &o.content.hotspots.items[0];
	assert_string_equal(h->name, "signature");
	assert_true(h->has_point && h->point[1] == 0.5 && h->point[2] == -0.2);
	assert_true(h->has_normal && h->normal[2] == -1);
	assert_string_equal(hotspot_text(h, NULL, NULL), "The painter's signature ; 1780");
	assert_int_equal(h->look, HOTSPOT_BADGE);
	assert_true(h->color[0] == 1 && fabsf(h->color[3] - 128 / 255.0f) < 1e-6f);
	assert_int_equal(h->line, 5); /* its first key */
	h = &o.content.hotspots.items[1];
	assert_string_equal(h->node, "Lid knob");
	assert_false(h->has_point);
	assert_int_equal(h->look, HOTSPOT_DOT);
	options_release(&o);
}

/* Each file holds one bad hotspot and one good: the bad one is said with
 * its line and dropped, the good one and the file's [frame] kept. */
static void one_bad(const char *bad, const char *said)
{
	struct options o;
	char m[256], last[512], text[600];

	option_defaults(&o);
	snprintf(text, sizeof(text),
		 "[frame]\nyaw = 30\n[hotspot.good]\npoint = 0 1 0\n[hotspot.bad]\n%s\n", bad);
	write_file("cup.ini", text);
	model(m, sizeof(m), "cup.glb");
	log_clear_last_error();
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	log_last_error(last, sizeof(last));
	if (!strstr(last, said))
		fail_msg("expected '%s' in '%s'", said, last);
	assert_non_null(strstr(last, "this hotspot is not shown"));
	assert_float_equal(o.content.frame.yaw, 30, 0);
	assert_int_equal(o.content.hotspots.count, 1);
	assert_string_equal(o.content.hotspots.items[0].name, "good");
	/* Counted: --check-config calls the model's settings bad. */
	assert_int_equal(o.content.hotspots.dropped, 1);
	options_release(&o);
	option_defaults(&o);
	write_file("cup.glb", "");
	o.content.model = m;
	assert_int_equal(check_model_settings(&o.content, NULL, false), 1);
	o.content.model = NULL;
	options_release(&o);
}

static void bad_hotspots(void **state)
{
	(void)state;
	one_bad("point = 1 2", "cup.ini:6: [hotspot.bad] point = '1 2': expected three numbers "
			       "X Y Z in the model's coordinates");
	one_bad("point = 0 0 1\nnormal = 0 0 0",
		"cup.ini:7: [hotspot.bad] normal = '0 0 0': expected a direction");
	one_bad("point = 0 0 1\nlook = star", "cup.ini:7: [hotspot.bad] look = 'star': expected "
					      "dot or badge");
	one_bad("point = 0 0 1\ncolor = red",
		"cup.ini:7: [hotspot.bad] color = 'red': expected a colour #rrggbb or #rrggbbaa");
	one_bad("text = no place", "cup.ini:6: [hotspot.bad]: expected one of point = X Y Z (the "
				   "model's coordinates) or node = NAME (a node it follows), found "
				   "neither");
	one_bad("point = 0 0 1\nnode = Arm", "cup.ini:6: [hotspot.bad]: expected one of point = "
					     "X Y Z");
	one_bad("point = 0 0 1\nsize = 3",
		"cup.ini:7: unknown key 'size' in [hotspot.bad]; expected one of: point, node");
	one_bad("point = 0 0 1\npoint = 0 0 2",
		"cup.ini:7: [hotspot.bad] point is set again (first on line 6)");
	/* text[LANG]: a code as [caption] languages takes, once, text alone. */
	one_bad("point = 0 0 1\ntext[d e] = Zeichen",
		"cup.ini:7: [hotspot.bad] text[d e] = 'Zeichen': 'd e' is not a language code");
	one_bad("point = 0 0 1\ntext[1x] = Zeichen",
		"cup.ini:7: [hotspot.bad] text[1x] = 'Zeichen': '1x' is not a language code; "
		"expected one such as de");
	one_bad("point = 0 0 1\ntext[de] = A\ntext[DE] = B",
		"cup.ini:8: [hotspot.bad] text[DE] = 'B': text[DE] is set again");
	one_bad("point = 0 0 1\nlook[de] = badge",
		"cup.ini:7: [hotspot.bad] look[de] = 'badge': only text takes a [LANG]");
}

/* text[LANG] = beside text = : each language's own, a missing one the
 * first language's, else the plain text (lang_text_get's order). */
static void texts_per_language(void **state)
{
	struct options o;
	char m[256];
	const struct hotspot *h;

	(void)state;
	option_defaults(&o);
	write_file("urn.ini", "[caption]\nlanguages = en de fr\n[hotspot.mark]\npoint = 0 1 0\n"
			      "text = The mark\ntext[de] = Das Zeichen\n[hotspot.foot]\n"
			      "point = 0 -1 0\ntext[en] = The foot\ntext[fr] = Le pied\n");
	model(m, sizeof(m), "urn.glb");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	assert_int_equal(o.content.hotspots.count, 2);
	assert_int_equal(o.content.hotspots.dropped, 0);
	h = &o.content.hotspots.items[0];
	assert_string_equal(hotspot_text(h, "de", "en"), "Das Zeichen");
	assert_string_equal(hotspot_text(h, "DE", "en"), "Das Zeichen");
	assert_string_equal(hotspot_text(h, "fr", "en"), "The mark"); /* the first's */
	assert_string_equal(hotspot_text(h, "en", "en"), "The mark");
	assert_int_equal(h->langs[0].line, 6);
	h = &o.content.hotspots.items[1];
	assert_string_equal(hotspot_text(h, "fr", "en"), "Le pied");
	assert_string_equal(hotspot_text(h, "de", "en"), "The foot"); /* text[en], no plain */
	assert_string_equal(hotspot_text(h, NULL, NULL), "");
	options_release(&o);
}

static void bad_name_and_too_many(void **state)
{
	struct options o;
	char m[256], last[512], text[2000];
	size_t len = 0;

	(void)state;
	option_defaults(&o);
	write_file("jug.ini", "[hotspot.a b]\npoint = 0 0 1\n[hotspot.ok]\npoint = 0 0 1\n");
	model(m, sizeof(m), "jug.glb");
	log_clear_last_error();
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	log_last_error(last, sizeof(last));
	assert_non_null(strstr(last, "jug.ini:2: [hotspot.a b]: expected a name of letters"));
	assert_int_equal(o.content.hotspots.count, 1);
	options_release(&o);

	option_defaults(&o);
	for (int i = 0; i <= HOTSPOTS; i++)
		len += (size_t)snprintf(text + len, sizeof(text) - len,
					"[hotspot.h%d]\npoint = 0 0 1\n", i);
	write_file("jug.ini", text);
	log_clear_last_error();
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	log_last_error(last, sizeof(last));
	assert_non_null(strstr(last, "a model has at most 8 hotspots"));
	assert_int_equal(o.content.hotspots.count, HOTSPOTS);
	options_release(&o);
}

/* kiosk.ini's hotspot of a name is replaced by the model's own. */
static void model_over_kiosk(void **state)
{
	struct options o;
	char m[256], k[256];

	(void)state;
	option_defaults(&o);
	write_file("kiosk.ini", "[hotspot.logo]\npoint = 0 -1 0\ntext = kiosk\n"
				"[hotspot.base]\npoint = 0 -1 0\n");
	model(k, sizeof(k), "kiosk.ini");
	assert_int_equal(options_read_one(&o, k, &options_rules_admin), OPTIONS_OK);
	assert_int_equal(o.content.hotspots.count, 2);
	write_file("pot.ini", "[hotspot.logo]\npoint = 0 1 0\ntext = own\n[hotspot.rim]\n"
			      "point = 1 0 0\n");
	model(m, sizeof(m), "pot.glb");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	assert_int_equal(o.content.hotspots.count, 3);
	assert_string_equal(o.content.hotspots.items[0].text, "own");
	assert_string_equal(o.content.hotspots.items[2].name, "rim");
	options_release(&o);
}

static int setup(void **state)
{
	(void)state;
	log_set_level(LOG_ERR);
	return mkdtemp(dir) ? 0 : -1;
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
	    cmocka_unit_test(good_hotspots),	  cmocka_unit_test(bad_hotspots),
	    cmocka_unit_test(texts_per_language), cmocka_unit_test(bad_name_and_too_many),
	    cmocka_unit_test(model_over_kiosk),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
