/* Greedy line breaking over UAX #14's break opportunities: each line
 * takes as many words as fit (as a reader expects of a label, and as
 * browsers do), so a line's end never depends on the lines after it. */
#include "scene/text/caption_wrap.h"

#include <errno.h>
#include <hb.h>
#include <linebreak.h>
#include <stdlib.h>

void caption_wrap_init(void)
{
	init_linebreak();
}

static bool blank(uint32_t c)
{
	return c == ' ' || c == '\t' || c == 0x3000;
}

/* A mark belongs to the letter before it: a line never starts with one. */
static bool mark(uint32_t c)
{
	hb_unicode_general_category_t g =
	    hb_unicode_general_category(hb_unicode_funcs_get_default(), c);

	return g == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
	       g == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
	       g == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK || c == 0x200d ||
	       (c >= 0xfe00 && c <= 0xfe0f);
}

/* The end of the line drawn from start to a break at end: without the
 * blanks the line ends with. */
static int drawn_end(const uint32_t *u, int start, int end)
{
	while (end > start && blank(u[end - 1]))
		end--;
	return end;
}

/* A word wider than the line: as many of its characters as fit, at least
 * one (with its marks). */
static int by_characters(const uint32_t *u, const long *adv, int start, int len, long max)
{
	long w = adv[start];
	int i = start + 1;

	while (i < len && (mark(u[i]) || w + adv[i] <= max))
		w += adv[i++];
	return i;
}

/* Where the line from start breaks: after the last opportunity whose
 * line (less its blanks) fits, or at a mandatory break. The width drawn
 * only grows along the line (a blank adds none until a letter follows
 * it), so the first character past max ends the search: a line costs
 * its own length, and a text of 100,000 letters is laid out whole. */
static int line_break(const uint32_t *u, const long *adv, const char *brks, int start, int len,
		      long max)
{
	long w = 0, tail = 0; /* the line's width; its trailing blanks' */
	int ok = -1;

	for (int i = start; i < len; i++) {
		w += adv[i];
		tail = blank(u[i]) ? tail + adv[i] : 0;
		if (w - tail > max)
			break;
		/* The text's end ends a line whatever libunibreak says of it
		 * (1.1 says must-break there, Debian 13's 6.1 need not). */
		if (i < len - 1 && brks[i] != LINEBREAK_MUSTBREAK &&
		    brks[i] != LINEBREAK_ALLOWBREAK)
			continue;
		ok = i + 1;
		if (i == len - 1 || brks[i] == LINEBREAK_MUSTBREAK)
			break;
	}
	return ok > start ? ok : by_characters(u, adv, start, len, max);
}

int caption_wrap(const uint32_t *u, const long *adv, int len, const char *lang, long max,
		 struct caption_span *out, int cap)
{
	char *brks = malloc(len > 0 ? (size_t)len : 1);
	int n = 0, start = 0;

	if (!brks)
		return -ENOMEM;
	set_linebreaks_utf32((const utf32_t *)u, (size_t)len, lang, brks);
	while (start < len) {
		int next = line_break(u, adv, brks, start, len, max);

		if (n < cap)
			out[n] = (struct caption_span){start, drawn_end(u, start, next), next};
		n++;
		start = next;
	}
	free(brks);
	return n;
}
