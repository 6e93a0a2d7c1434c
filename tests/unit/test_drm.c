/* The pure parts of the KMS output: the mode setting's syntax and the
 * connector names the kernel and the messages use. */
#include "display/drm.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

static void mode_good(void **state)
{
	int w, h, hz;

	(void)state;
	assert_true(drm_parse_mode("1920x1080", &w, &h, &hz));
	assert_int_equal(w, 1920);
	assert_int_equal(h, 1080);
	assert_int_equal(hz, 0); /* any rate */
	assert_true(drm_parse_mode("800x600@56", &w, &h, &hz));
	assert_int_equal(w, 800);
	assert_int_equal(h, 600);
	assert_int_equal(hz, 56);
}

static void mode_bad(void **state)
{
	static const char *const bad[] = {"",		"1920",		 "1920x",      "x1080",
					  "1920x1080@", "1920x1080@60x", "0x600",      "800x0",
					  "-800x600",	"800x600@0",	 "800x600 60", "800*600"};
	int w, h, hz;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		if (drm_parse_mode(bad[i], &w, &h, &hz))
			fail_msg("'%s' was taken for a mode", bad[i]);
}

static void connector_names(void **state)
{
	drmModeConnector c = {.connector_type = DRM_MODE_CONNECTOR_HDMIA, .connector_type_id = 2};
	char name[32];

	(void)state;
	drm_connector_name(&c, name, sizeof(name));
	assert_string_equal(name, "HDMI-A-2");
	c.connector_type = DRM_MODE_CONNECTOR_DSI;
	c.connector_type_id = 1;
	drm_connector_name(&c, name, sizeof(name));
	assert_string_equal(name, "DSI-1");
	c.connector_type = DRM_MODE_CONNECTOR_VIRTUAL;
	drm_connector_name(&c, name, sizeof(name));
	assert_string_equal(name, "Virtual-1");
	drm_connector_name(&c, name, 4); /* cut short, still a string */
	assert_string_equal(name, "Vir");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(mode_good),
	    cmocka_unit_test(mode_bad),
	    cmocka_unit_test(connector_names),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
