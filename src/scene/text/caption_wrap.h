/* A caption's paragraph broken into lines that fit a width: at the
 * places UAX #14 allows (libunibreak: between words, and between
 * Chinese or Japanese characters, never before a closing mark), and a
 * word longer than the line broken between its characters. Pure: the
 * widths come from the caller (shaped, or counted in a test). */
#ifndef MK_CAPTION_WRAP_H
#define MK_CAPTION_WRAP_H

#include <stdbool.h>
#include <stdint.h>

/* One line: code points [start, end) are drawn (the spaces it ends with
 * left out); the next line starts at next. */
struct caption_span {
	int start, end, next;
};

/* Once, before any thread wraps (main.c): libunibreak's tables, or its
 * lookups are slow. Wrapping without it is correct, only slower. */
void caption_wrap_init(void);

/* The lines of u[0..len) (one paragraph: no '\n') within max, adv[i]
 * being code point i's advance (any unit), for the language lang (a
 * BCP 47 code such as "ja"; NULL: none). At most cap spans are written
 * to out (those past cap are counted, not kept); returns how many
 * lines there are, or -ENOMEM. A line holds at least one character,
 * even one wider than max. */
int caption_wrap(const uint32_t *u, const long *adv, int len, const char *lang, long max,
		 struct caption_span *out, int cap);

#endif
