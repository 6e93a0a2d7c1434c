/* --check-config: every text a visitor reads, in each language, against
 * the fonts installed: the characters none has (a visitor would see
 * empty boxes) named with the Debian package that would draw them. */
#ifndef MK_CHECK_TEXT_H
#define MK_CHECK_TEXT_H

#include "config/settings.h"

/* The texts of o with characters no installed font has, each said on
 * one line (file:line, the key with its [LANG], the characters, the
 * package); how many. caption_at, stops_at: where the plain [caption]
 * text and [frame] stops came from (file:line). */
int check_texts(const struct options *o, const char *caption_at, const char *stops_at);

/* The same of c's hotspots' texts (text and text[LANG]) but those of
 * skip (checked with the file they came from), said at path:line (NULL:
 * "the settings"); how many. */
int check_hotspot_texts(const struct content_config *c, const struct hotspot_set *skip,
			const char *path);

#endif
