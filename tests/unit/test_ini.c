/* The settings files' syntax (src/util/ini.c): whole lines at any length,
 * comments on lines of their own, a ';' inside a value kept, and every
 * bad line named by its number. */
#include "util/ini.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

struct seen {
	char text[8192]; /* "line:section:key=value|" for each key */
	int bad[8], bad_count;
};

static int on_key(void *user, int line, const char *section, const char *key, const char *value)
{
	struct seen *s = user;
	size_t n = strlen(s->text);

	snprintf(s->text + n, sizeof(s->text) - n, "%d:%s:%s=%s|", line, section, key, value);
	return 0;
}

static void on_bad(void *user, int line, const char *why)
{
	struct seen *s = user;

	assert_non_null(why);
	if (s->bad_count < 8)
		s->bad[s->bad_count++] = line;
}

static const struct ini_handler handler = {on_key, on_bad};

static int parse(const char *text, size_t n, struct seen *s)
{
	memset(s, 0, sizeof(*s));
	return ini_parse(text, n, &handler, s);
}

static void keys_sections_and_comments(void **state)
{
	static const char t[] = "\xEF\xBB\xBF# top\n; also a comment\n  [scene]  \r\n"
				"  model = a.glb  \r\nmode=view\n[ caption ] ; a note\n"
				"text = Amphora ; Attic, 5th c. BC\nlogo = # not a comment\n"
				"empty =\n\n";
	struct seen s;

	(void)state;
	assert_int_equal(parse(t, sizeof(t) - 1, &s), 0);
	assert_string_equal(s.text, "4:scene:model=a.glb|5:scene:mode=view|"
				    "7:caption:text=Amphora ; Attic, 5th c. BC|"
				    "8:caption:logo=# not a comment|9:caption:empty=|");
}

/* libinih read 199 bytes of a line and the rest as a line of its own: a
 * padded value could put a [display] at a line's start. */
static void no_line_is_too_long(void **state)
{
	char t[6000], want[6100];
	struct seen *s = malloc(sizeof(*s));
	int len;

	(void)state;
	assert_non_null(s);
	/* The attack's line: "[display]" at byte 181, ';' at 199. */
	len = sprintf(t, "[scene]\nmatcap = a,a,a.png ;");
	memset(t + len, 'x', 5000);
	memcpy(t + 8 + 181, "[display]", 9);
	t[8 + 199] = ';';
	len += 5000;
	len += sprintf(t + len, "size = 77x55\n");
	assert_int_equal(parse(t, (size_t)len, s), 0);
	/* One key, on line 2, holding the whole rest of the line. */
	snprintf(want, sizeof(want), "2:scene:matcap=%.*s|", len - 8 - 9 - 1, t + 8 + 9);
	assert_string_equal(s->text, want);
	free(s);
}

static void every_bad_line_is_named(void **state)
{
	static const char t[] = "[scene\nyaw = 3\nno equals here\n[display] size = 7x5\n"
				"= value\nok = 1\nnul\0byte = 2\n";
	struct seen s;

	(void)state;
	assert_int_equal(parse(t, sizeof(t) - 1, &s), 5);
	assert_int_equal(s.bad[0], 1);
	assert_int_equal(s.bad[1], 3);
	assert_int_equal(s.bad[2], 4);
	assert_int_equal(s.bad[3], 5);
	assert_int_equal(s.bad[4], 7);
	/* The key before a section has none; the others are still read. */
	assert_string_equal(s.text, "2::yaw=3|6::ok=1|");
}

static int stop_at_two(void *user, int line, const char *section, const char *key,
		       const char *value)
{
	(void)user;
	(void)section;
	(void)key;
	(void)value;
	return line == 2 ? -7 : 0;
}

static void a_key_callback_can_stop(void **state)
{
	static const char t[] = "a = 1\nb = 2\nc = 3\n";

	(void)state;
	assert_int_equal(
	    ini_parse(t, sizeof(t) - 1, &(struct ini_handler){stop_at_two, NULL}, NULL), -7);
	assert_int_equal(ini_parse("", 0, &handler, &(struct seen){0}), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(keys_sections_and_comments),
	    cmocka_unit_test(no_line_is_too_long),
	    cmocka_unit_test(every_bad_line_is_named),
	    cmocka_unit_test(a_key_callback_can_stop),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
