/* The backlight through a sysfs folder of the test's own: found, switched
 * off and on, and no device or no permission said, not fatal. */
#include "display/backlight.h"

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

static void read_file(const char *path, char *buf, size_t size)
{
	FILE *f = fopen(path, "r");

	assert_non_null(f);
	assert_non_null(fgets(buf, (int)size, f));
	fclose(f);
}

static void test_off_and_on(void **state)
{
	char dir[] = "/tmp/mk-backlight-XXXXXX", path[256], value[16];
	struct backlight *b;
	FILE *f;

	(void)state;
	assert_non_null(mkdtemp(dir));
	/* No device: NULL, the caller goes on without. */
	assert_null(backlight_new(dir));
	snprintf(path, sizeof(path), "%s/rpi_backlight", dir);
	assert_int_equal(mkdir(path, 0755), 0);
	snprintf(path, sizeof(path), "%s/rpi_backlight/bl_power", dir);
	f = fopen(path, "w");
	fputs("0", f); /* sysfs takes a write in place, as this file does */
	fclose(f);
	b = backlight_new(dir);
	assert_non_null(b);
	assert_int_equal(backlight_power(b, false), 0);
	read_file(path, value, sizeof(value));
	assert_string_equal(value, "4");
	assert_int_equal(backlight_power(b, true), 0);
	read_file(path, value, sizeof(value));
	assert_string_equal(value, "0");
	/* The file gone (or not writable): an error, not a crash. */
	unlink(path);
	snprintf(path, sizeof(path), "%s/rpi_backlight", dir);
	rmdir(path);
	assert_true(backlight_power(b, false) < 0);
	backlight_free(b);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {cmocka_unit_test(test_off_and_on)};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
