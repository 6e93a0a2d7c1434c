/* The settings files' syntax, read from memory: one reader for kiosk.ini,
 * its drop-ins, the include, a model's NAME.ini and a USB stick's files.
 *
 *   # a comment, or ; a comment     (whole lines only)
 *   [section]
 *   key = value                     (the value is the rest of the line)
 *
 * Blanks around a line, a key and a value are dropped. A ';' or '#' inside
 * a value is part of it ("Amphora ; Attic, 5th c. BC"). No line is too
 * long: a line ends at a newline and nowhere else (libinih cut lines at
 * 199 bytes and read the rest as a line of its own, so a padded value
 * could smuggle in a [section]). A NUL byte, a line that is none of the
 * above, or text after a [section]'s ']' is an error for that line; the
 * other lines are still read, so that every error is said at once. */
#ifndef MK_INI_H
#define MK_INI_H

#include <stdbool.h>
#include <stddef.h>

struct ini_handler {
	/* A key's line (counted from 1). A negative return stops the reading
	 * and is returned. */
	int (*key)(void *user, int line, const char *section, const char *key, const char *value);
	/* A line that is not INI, with why (a phrase). */
	void (*bad)(void *user, int line, const char *why);
};

/* Reads text (size bytes, need not end in a newline or NUL). Returns the
 * count of bad lines, a key callback's negative return, or -ENOMEM. */
int ini_parse(const char *text, size_t size, const struct ini_handler *h, void *user);

/* The blanks dropped around lines, keys and values (a rewriter of
 * settings text, ops/import_ini.c, splits them the same way). */
bool ini_blank(char c);

#endif
