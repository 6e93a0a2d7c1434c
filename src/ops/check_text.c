/* The texts a visitor reads (check_text.h): [caption] text and the
 * stops' texts, plain and in each language, each drawn through the
 * caption's fonts as the kiosk would find them (caption_missing). */
#include "ops/check_text.h"
#include "scene/text/caption_font.h"
#include "util/log.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

/* Characters named at most, per text. */
#define SHOWN 8

/* "U+1F600 😀 (fonts-symbola), ..." for the n (of count) characters. */
static void list_chars(const uint32_t *c, int n, int count, char *buf, size_t size)
{
	size_t len = 0;

	buf[0] = '\0';
	for (int i = 0; i < n && len + 1 < size; i++) {
		char utf8[8] = "";

		/* The character itself, for a reader who has the font. */
		if (c[i] < 0x80)
			snprintf(utf8, sizeof(utf8), "%c", (char)c[i]);
		else if (c[i] < 0x800)
			snprintf(utf8, sizeof(utf8), "%c%c", 0xc0 | c[i] >> 6,
				 0x80 | (c[i] & 0x3f));
		else if (c[i] < 0x10000)
			snprintf(utf8, sizeof(utf8), "%c%c%c", 0xe0 | c[i] >> 12,
				 0x80 | (c[i] >> 6 & 0x3f), 0x80 | (c[i] & 0x3f));
		else
			snprintf(utf8, sizeof(utf8), "%c%c%c%c", 0xf0 | c[i] >> 18,
				 0x80 | (c[i] >> 12 & 0x3f), 0x80 | (c[i] >> 6 & 0x3f),
				 0x80 | (c[i] & 0x3f));
		len += (size_t)snprintf(buf + len, size - len, "%sU+%04X %s (%s)", i ? ", " : "",
					(unsigned)c[i], utf8, caption_font_package(c[i]));
	}
	if (count > n && len + 1 < size)
		snprintf(buf + len, size - len, " and %d more", count - n);
}

/* One text: said when a character has no font; 1 then, else 0. */
static int check_one(const char *font, const char *where, const char *what, const char *lang,
		     const char *text)
{
	uint32_t c[SHOWN];
	char list[512];
	int n;

	if (!text || !*text || !strcmp(text, "auto"))
		return 0;
	n = caption_missing(font, lang, text, c, SHOWN);
	if (n <= 0)
		return 0; /* a font that does not open is said by the caption's check */
	list_chars(c, n < SHOWN ? n : SHOWN, n, list, sizeof(list));
	log_err("%s: %s: no installed font has %d of its characters, a visitor would see empty "
		"boxes: %s; install the package named (apt install PACKAGE) or write the text "
		"without them",
		where, what, n, list);
	return 1;
}

/* Whether lang is one of the n codes. */
static bool listed(char codes[LANG_MAX][LANG_CODE_MAX], int n, const char *lang)
{
	for (int i = 0; i < n; i++)
		if (!strcasecmp(codes[i], lang))
			return true;
	return false;
}

int check_texts(const struct options *o, const char *caption_at, const char *stops_at)
{
	const struct lang_texts *t = &o->content.texts;
	const struct content_config *c = &o->content;
	char first[LANG_MAX][LANG_CODE_MAX], err[128], what[96];
	int n = lang_list_parse(c->caption.languages, first, err, sizeof(err));
	const char *lang = n > 0 ? first[0] : NULL;
	int bad = 0;

	bad += check_one(c->caption.font, caption_at, "[caption] text", lang, c->caption.text);
	bad += check_one(c->caption.font, stops_at, "[frame] stops", lang, c->frame.stops);
	for (int i = 0; i < t->count; i++) {
		snprintf(what, sizeof(what), "[%s] %s[%s]",
			 !strcmp(t->e[i].key, "caption.text") ? "caption" : "frame",
			 !strcmp(t->e[i].key, "caption.text") ? "text" : "stops", t->e[i].lang);
		bad += check_one(c->caption.font, t->e[i].origin ? t->e[i].origin : "the settings",
				 what, t->e[i].lang, t->e[i].value);
		if (!listed(first, n > 0 ? n : 0, t->e[i].lang))
			log_warn("%s: %s: %s is not one of [caption] languages (%s): never shown",
				 t->e[i].origin ? t->e[i].origin : "the settings", what,
				 t->e[i].lang, n > 0 ? c->caption.languages : "none named");
	}
	return bad + check_hotspot_texts(c, NULL, NULL);
}

/* Whether h is one of skip's, the same in every field. */
static bool checked(const struct hotspot_set *skip, const struct hotspot *h)
{
	int at = skip ? hotspot_find(skip, h->name) : -1;

	return at >= 0 && !memcmp(&skip->items[at], h, sizeof(*h));
}

int check_hotspot_texts(const struct content_config *c, const struct hotspot_set *skip,
			const char *path)
{
	char first[LANG_MAX][LANG_CODE_MAX], err[128], what[128], where[512];
	int n = lang_list_parse(c->caption.languages, first, err, sizeof(err)), bad = 0;

	for (int i = 0; i < c->hotspots.count; i++) {
		const struct hotspot *h = &c->hotspots.items[i];

		if (checked(skip, h))
			continue;
		snprintf(what, sizeof(what), "[hotspot.%s] text", h->name);
		snprintf(where, sizeof(where), "%s:%d", path ? path : "the settings", h->line);
		bad += check_one(c->caption.font, where, what, n > 0 ? first[0] : NULL, h->text);
		for (int l = 0; l < h->lang_count; l++) {
			snprintf(what, sizeof(what), "[hotspot.%s] text[%s]", h->name,
				 h->langs[l].lang);
			snprintf(where, sizeof(where), "%s:%d", path ? path : "the settings",
				 h->langs[l].line);
			bad += check_one(c->caption.font, where, what, h->langs[l].lang,
					 h->langs[l].text);
			if (!listed(first, n > 0 ? n : 0, h->langs[l].lang))
				log_warn("%s: %s: %s is not one of [caption] languages (%s): never "
					 "shown",
					 where, what, h->langs[l].lang,
					 n > 0 ? c->caption.languages : "none named");
		}
	}
	return bad;
}
