/* Line breaking (scene/text/caption_wrap.c) with every character 10
 * units wide: Latin breaks between words (the spaces at a line's end
 * not counted), Japanese between characters but never before a closing
 * mark, a word longer than the line between its characters, and a mark
 * stays with its letter. */
#include "scene/text/caption_wrap.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#define MAX 64

struct wrapped {
	uint32_t u[MAX];
	int len;
	struct caption_span span[8];
	int n;
};

/* UTF-8 to code points (the tests' texts are valid). */
static int decode(const char *s, uint32_t *u)
{
	int n = 0;

	for (const unsigned char *p = (const unsigned char *)s; *p;) {
		int extra = *p >= 0xf0 ? 3 : *p >= 0xe0 ? 2 : *p >= 0xc0 ? 1 : 0;
		uint32_t c = extra ? *p & (0x3f >> extra) : *p;

		for (p++; extra--; p++)
			c = c << 6 | (*p & 0x3f);
		u[n++] = c;
	}
	return n;
}

static void wrap(const char *text, const char *lang, long max, struct wrapped *w)
{
	long adv[MAX];

	w->len = decode(text, w->u);
	for (int i = 0; i < w->len; i++)
		adv[i] = 10;
	w->n = caption_wrap(w->u, adv, w->len, lang, max, w->span, 8);
}

/* Line i of w as UTF-8 code points compared with expected's. */
static void line_is(const struct wrapped *w, int i, const char *expected)
{
	uint32_t e[MAX];
	int n = decode(expected, e);

	assert_true(i < w->n);
	assert_int_equal(w->span[i].end - w->span[i].start, n);
	assert_memory_equal(w->u + w->span[i].start, e, (size_t)n * sizeof(*e));
}

static void latin_between_words(void **state)
{
	struct wrapped w;

	(void)state;
	caption_wrap_init();
	/* 10 characters a line: "Lent by" (7) + " the" would be 11. */
	wrap("Lent by the city museum", "en", 100, &w);
	assert_int_equal(w.n, 3);
	line_is(&w, 0, "Lent by");
	line_is(&w, 1, "the city");
	line_is(&w, 2, "museum");
	/* The next line starts at the word, after the space. */
	assert_int_equal(w.span[1].start, 8);
	/* A line's trailing space is not counted: "Lent by " fits 70. */
	wrap("Lent by the", "en", 70, &w);
	assert_int_equal(w.n, 2);
	line_is(&w, 0, "Lent by");
	/* A hyphen is a place to break after. */
	wrap("well-known", "en", 60, &w);
	line_is(&w, 0, "well-");
	line_is(&w, 1, "known");
}

static void japanese_between_characters(void **state)
{
	struct wrapped w;

	(void)state;
	/* Japanese has no spaces: it breaks between any two characters. */
	wrap("伊万里焼の花瓶", "ja", 30, &w);
	assert_int_equal(w.n, 3);
	line_is(&w, 0, "伊万里");
	line_is(&w, 1, "焼の花");
	line_is(&w, 2, "瓶");
	/* Never before a full stop or a closing bracket: "花瓶。" at 20
	 * moves 瓶 down with its 。 (the line is one character short). */
	wrap("花瓶。", "ja", 20, &w);
	assert_int_equal(w.n, 2);
	line_is(&w, 0, "花");
	line_is(&w, 1, "瓶。");
	/* Nor after an opening bracket: "（花）瓶" at 30 keeps （花） whole. */
	wrap("（花）瓶", "ja", 30, &w);
	assert_int_equal(w.n, 2);
	line_is(&w, 0, "（花）");
	line_is(&w, 1, "瓶");
}

static void a_word_longer_than_the_line(void **state)
{
	struct wrapped w;

	(void)state;
	wrap("Donaudampfschiff ist", "de", 60, &w);
	assert_int_equal(w.n, 4);
	line_is(&w, 0, "Donaud");
	line_is(&w, 1, "ampfsc");
	line_is(&w, 2, "hiff");
	line_is(&w, 3, "ist");
	/* Narrower than one character: one a line, never none. */
	wrap("abc", "en", 5, &w);
	assert_int_equal(w.n, 3);
	line_is(&w, 0, "a");
	/* A combining accent stays with its letter ("e\u0301" is é). */
	wrap("ee\xcc\x81"
	     "e",
	     "fr", 10, &w);
	assert_int_equal(w.n, 3);
	line_is(&w, 1, "e\xcc\x81");
}

/* Past the lines asked for, the lines are counted, not kept. */
static void counted_to_the_room(void **state)
{
	struct wrapped w;
	long adv[MAX];

	(void)state;
	w.len = decode("a b c d e f g h i j k l", w.u);
	for (int i = 0; i < w.len; i++)
		adv[i] = 10;
	assert_int_equal(caption_wrap(w.u, adv, w.len, NULL, 10, w.span, 3), 12);
	assert_int_equal(w.span[2].start, 4); /* "c" */
	assert_int_equal(caption_wrap(w.u, adv, w.len, NULL, 1000, w.span, 3), 1);
	assert_int_equal(caption_wrap(w.u, adv, 0, NULL, 1000, w.span, 3), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(latin_between_words),
	    cmocka_unit_test(japanese_between_characters),
	    cmocka_unit_test(a_word_longer_than_the_line),
	    cmocka_unit_test(counted_to_the_room),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
