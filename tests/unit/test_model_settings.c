/* A model's own NAME.ini (config/model_settings.h): its keys over the
 * kiosk's, the keys refused with file and line, and what the content
 * loader makes of it (content_settings, content_app_frame). */
#include "config/model_settings.h"
#include "config/settings.h"
#include "content/content.h"
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

static char dir[] = "/tmp/mk-model-settings-XXXXXX";

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

static void base(struct options *o)
{
	option_defaults(o);
	o->content.fit = 0.5;
}

static void paths(void **state)
{
	char out[64];

	(void)state;
	assert_true(model_settings_path("/m/vase.glb", out, sizeof(out)));
	assert_string_equal(out, "/m/vase.ini");
	assert_true(model_settings_path("/m/Cup.GLTF", out, sizeof(out)));
	assert_string_equal(out, "/m/Cup.ini");
	assert_false(model_settings_path("/m/readme.txt", out, sizeof(out)));
	assert_false(model_settings_path(NULL, out, sizeof(out)));
	assert_true(model_settings_allowed("frame", "stops"));
	assert_true(model_settings_allowed("material", "detail_map"));
	assert_true(model_settings_allowed("scene", "fit"));
	assert_false(model_settings_allowed("scene", "model"));
	assert_true(model_settings_allowed("scene", "matcap"));
	assert_true(model_settings_allowed("display", "background"));
	assert_false(model_settings_allowed("display", "rotation"));
	assert_false(model_settings_allowed("kiosk", "attract_after"));
}

/* Its keys go over the kiosk's; the rest stay the kiosk's. */
static void good_file(void **state)
{
	struct options o;
	char m[256];

	(void)state;
	base(&o);
	write_file("vase.ini", "[frame]\nup = +z\nyaw = 45\nyaw_min = -30\nyaw_max = 60\n"
			       "stops = 10 0 1 \"Front\"; 90 0 2\n\n[scene]\nmode = normal\n");
	model(m, sizeof(m), "vase.glb");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	assert_int_equal(o.content.frame.up, FRAME_UP_Z);
	assert_float_equal(o.content.frame.yaw, 45, 0);
	assert_int_equal(o.content.mode, SHADING_NORMAL);
	assert_float_equal(o.content.fit, 0.5, 0); /* the kiosk's */
	assert_string_equal(o.content.frame.stops, "10 0 1 \"Front\"; 90 0 2");
	{
		struct app_frame f;
		struct quat rest;

		content_app_frame(&o.content, &f, &rest);
		assert_int_equal(f.stop_count, 2);
		assert_string_equal(f.stops[0].text, "Front");
		assert_true(f.yaw_limited);
		assert_float_equal(f.yaw0, 45 * M_PI / 180, 1e-12);
	}
	/* No file: nothing changes, no error. */
	model(m, sizeof(m), "none.glb");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	options_release(&o);
}

/* Each bad key refused with its file and line; nothing of the file is
 * taken then. */
static void bad_keys(void **state)
{
	struct options o;
	char m[256], last[512];

	(void)state;
	base(&o);
	write_file("cup.ini", "[frame]\nyaw = 30\n[kiosk]\nattract_after = 5\n");
	model(m, sizeof(m), "cup.gltf");
	log_clear_last_error();
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_CONFIG);
	log_last_error(last, sizeof(last));
	assert_non_null(
	    strstr(last, "cup.ini:4: [kiosk] attract_after cannot be set from a model's own file"));
	assert_non_null(strstr(last, "it takes [frame], [material], [scene] mode, [scene] fit"));
	assert_true(isnan(o.content.frame.yaw));
	write_file("cup.ini", "[frame]\nup = sideways\n");
	log_clear_last_error();
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_CONFIG);
	log_last_error(last, sizeof(last));
	assert_non_null(strstr(last, "cup.ini:2: [frame] up = 'sideways' is not valid"));
	write_file("cup.ini", "[frame]\nyaw_max = 10\nyaw_min = 20\n");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_CONFIG);
	log_last_error(last, sizeof(last));
	assert_non_null(strstr(last, "cup.ini:2: [frame] yaw_max is not valid: yaw_min is above"));
	write_file("cup.ini", "[frame]\n\nstops = 1 2\n");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_CONFIG);
	log_last_error(last, sizeof(last));
	assert_non_null(strstr(last, "cup.ini:3: [frame] stops is not valid"));
	write_file("cup.ini", "[frame]\norientation = 1 2\n");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_CONFIG);
	log_last_error(last, sizeof(last));
	assert_non_null(strstr(last, "cup.ini:2: [frame] orientation = '1 2' is not valid"));
	options_release(&o);
}

/* The file changed while the model is shown: read again, it gives the
 * new values (the loop reloads the model when its NAME.ini changes). */
static void changed_file(void **state)
{
	struct options o;
	char m[256];

	(void)state;
	base(&o);
	model(m, sizeof(m), "vase.glb");
	write_file("vase.ini", "[frame]\nzoom = 1.5\n");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	assert_float_equal(o.content.frame.zoom, 1.5, 0);
	options_release(&o);
	base(&o);
	write_file("vase.ini", "[frame]\nzoom = 0.8\n");
	assert_int_equal(model_settings_read(&o.content, m), OPTIONS_OK);
	assert_float_equal(o.content.frame.zoom, 0.8, 0);
	options_release(&o);
}

/* A model's own matcap and background (NAME.ini): decoded with the model
 * where they differ from those on screen, swapped in with it; a model
 * without them brings kiosk.ini's back; the same look decodes nothing. */
static void own_look(void **state)
{
	struct options o;
	struct content_config own;
	struct content_look kiosk = {0};
	struct content shown = {0}, fresh = {0}, old, back = {0}, same = {0};
	char m[256], png[300], cmd[700];

	(void)state;
	base(&o);
	snprintf(png, sizeof(png), "%s/shiny.png", dir);
	snprintf(cmd, sizeof(cmd), "cp matcaps/black-shiny.png '%s'", png);
	assert_int_equal(system(cmd), 0);
	write_file("vase.ini", "[scene]\nmatcap = shiny.png\n[display]\nbackground = #102030\n");
	model(m, sizeof(m), "vase.glb");
	assert_int_equal(content_config_copy(&own, &o.content), 0);
	assert_int_equal(model_settings_read(&own, m), OPTIONS_OK);
	assert_string_equal(own.matcap, png); /* from the NAME.ini's folder */
	assert_int_equal(content_look_set(&kiosk, &o.content), 0);

	fresh.model_path = strdup(m);
	assert_int_equal(content_load_look(&fresh, &own, &kiosk), 0);
	assert_int_equal(fresh.own_look, CONTENT_OWN_MATCAP | CONTENT_OWN_BACKGROUND);
	assert_int_equal(matcap_set_count(fresh.set), 1);
	assert_string_equal(matcap_set_path(fresh.set, 0), png);
	assert_true(fresh.matcap.width > 0);
	assert_int_equal(fresh.background.kind, BACKGROUND_COLOR);

	/* Swapped in: the model's look is shown's, the kiosk's goes to old. */
	assert_int_equal(content_look_copy(&shown.look, &kiosk), 0);
	shown.matcap_path = strdup("kiosk-matcaps");
	content_take_model(&shown, &fresh, &old);
	assert_string_equal(shown.matcap_path, png);
	assert_string_equal(shown.look.matcap, png);
	assert_string_equal(shown.look.background, "#102030");
	assert_string_equal(old.matcap_path, "kiosk-matcaps");
	assert_null(old.look.matcap);
	assert_null(fresh.set);
	content_release(&old);

	/* Back to a model without its own: kiosk.ini's, decoded again. */
	back.model_path = strdup("cup.glb");
	assert_int_equal(content_load_look(&back, &o.content, &shown.look), 0);
	assert_int_equal(back.own_look, CONTENT_OWN_MATCAP | CONTENT_OWN_BACKGROUND);
	assert_null(back.look.matcap);
	assert_null(back.look.background);
	assert_true(back.matcap.width > 0); /* the shipped folder, or the clay */
	assert_int_equal(back.background.kind, BACKGROUND_COLOR); /* the default grey */

	/* Another model with the look on screen: nothing decoded. */
	same.model_path = strdup("jug.glb");
	assert_int_equal(content_load_look(&same, &own, &shown.look), 0);
	assert_int_equal(same.own_look, 0);
	assert_null(same.set);
	assert_int_equal(same.matcap.width, 0);

	content_release(&same);
	content_release(&back);
	content_release(&shown);
	content_look_release(&kiosk);
	content_config_release(&own);
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
	    cmocka_unit_test(paths),	    cmocka_unit_test(good_file), cmocka_unit_test(bad_keys),
	    cmocka_unit_test(changed_file), cmocka_unit_test(own_look),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
