/* [hotspot.NAME] sections (config/hotspot_settings.h): the keys, their
 * values through state/hotspot.c's words, and the checks a hotspot needs
 * whole (a point or a node, not both). */
#include "config/hotspot_settings.h"
#include "config/lang_text.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#define PREFIX "hotspot."

static const char *const hotspot_keys[] = {"point", "node", "normal", "text", "look", "color"};
#define KEYS (int)(sizeof(hotspot_keys) / sizeof(hotspot_keys[0]))

_Static_assert(HOTSPOT_LANGS == LANG_MAX && HOTSPOT_LANG_CODE == LANG_CODE_MAX,
	       "a hotspot's text in every language [caption] languages may name");

bool hotspot_settings_section(const char *section)
{
	return !strncmp(section, PREFIX, strlen(PREFIX));
}

/* Letters, digits, '_' and '-': a name a stop's hotspot=NAME can say. */
static bool good_name(const char *name)
{
	size_t n = strlen(name);

	if (!n || n >= HOTSPOT_NAME)
		return false;
	return strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") ==
	       n;
}

/* The index of the hotspot called name in this file, added at line when
 * new; -1 (said) when the name is bad or the file has too many. */
static int pending_of(struct hotspot_read *rd, const char *path, int line, const char *name)
{
	struct hotspot_set *s = &rd->pending;
	int i = hotspot_find(s, name);

	if (i >= 0)
		return i;
	if (!good_name(name)) {
		log_err("%s:%d: [hotspot.%s]: expected a name of letters, digits, '_' or '-' "
			"(at most %d), e.g. [hotspot.signature]; this hotspot is not shown",
			path, line, name, HOTSPOT_NAME - 1);
		return -1;
	}
	if (s->count >= HOTSPOTS) {
		if (!rd->full_said)
			log_err(
			    "%s:%d: [hotspot.%s]: a model has at most %d hotspots; this one and "
			    "any after it are not shown",
			    path, line, name, HOTSPOTS);
		rd->full_said = true;
		return -1;
	}
	hotspot_init(&s->items[s->count], name, line);
	return s->count++;
}

static int set_value(struct hotspot *h, int k, const char *value, char *err, size_t n)
{
	switch (k) {
	case 0:
		h->has_point = true;
		return hotspot_parse_vec3(value, h->point, err, n);
	case 1:
		if (!*value || strlen(value) >= sizeof(h->node)) {
			snprintf(err, n,
				 "expected the name of one of the model's nodes (at most %d "
				 "bytes)",
				 (int)sizeof(h->node) - 1);
			return -1;
		}
		snprintf(h->node, sizeof(h->node), "%s", value);
		return 0;
	case 2:
		h->has_normal = true;
		return hotspot_parse_normal(value, h->normal, err, n);
	case 3:
		if (strlen(value) >= sizeof(h->text)) {
			snprintf(err, n, "expected a short text (at most %d bytes)",
				 (int)sizeof(h->text) - 1);
			return -1;
		}
		snprintf(h->text, sizeof(h->text), "%s", value);
		return 0;
	case 4:
		return hotspot_parse_look(value, &h->look, err, n);
	default:
		return hotspot_parse_color(value, h->color, err, n);
	}
}

/* text[LANG] = value: the text in LANG (lang_text.h's one form). 0, or
 * -1 with err saying what was expected. */
static int set_translation(struct hotspot *h, const char *base, const char *lang, const char *value,
			   int line, char *err, size_t n)
{
	char codes[LANG_MAX][LANG_CODE_MAX], why[128];
	int ret;

	if (strcmp(base, "text")) {
		snprintf(err, n, "only text takes a [LANG], e.g. text[de] = Die Signatur");
		return -1;
	}
	if (lang_list_parse(lang, codes, why, sizeof(why)) != 1 || strcmp(codes[0], lang)) {
		snprintf(err, n,
			 "'%s' is not a language code; expected one such as de, fr or pt-BR", lang);
		return -1;
	}
	ret = hotspot_set_text(h, lang, value, line);
	if (ret == -EEXIST)
		snprintf(err, n, "text[%s] is set again", lang);
	else if (ret == -ENOSPC)
		snprintf(err, n, "expected at most %d languages", HOTSPOT_LANGS);
	else if (ret)
		snprintf(err, n, "expected a short text (at most %d bytes)", HOTSPOT_TEXT - 1);
	return ret ? -1 : 0;
}

void hotspot_settings_key(struct hotspot_read *rd, const char *path, int line, const char *section,
			  const char *key, const char *value)
{
	int i = pending_of(rd, path, line, section + strlen(PREFIX)), k;
	char err[200], base[16], lang[LANG_CODE_MAX + 8];

	if (i < 0)
		return;
	if (lang_key_split(key, base, sizeof(base), lang, sizeof(lang))) {
		if (set_translation(&rd->pending.items[i], base, lang, value, line, err,
				    sizeof(err))) {
			log_err("%s:%d: [%s] %s = '%s': %s; this hotspot is not shown", path, line,
				section, key, value, err);
			rd->bad[i] = true;
		}
		return;
	}
	for (k = 0; k < KEYS && strcmp(hotspot_keys[k], key); k++)
		;
	if (k == KEYS) {
		log_err("%s:%d: unknown key '%s' in [%s]; expected one of: point, node, normal, "
			"text, look, color; this hotspot is not shown",
			path, line, key, section);
		rd->bad[i] = true;
	} else if (rd->seen[i][k]) {
		log_err("%s:%d: [%s] %s is set again (first on line %d); this hotspot is not "
			"shown",
			path, line, section, key, rd->seen[i][k]);
		rd->bad[i] = true;
	} else if ((rd->seen[i][k] = line),
		   set_value(&rd->pending.items[i], k, value, err, sizeof(err))) {
		log_err("%s:%d: [%s] %s = '%s': %s; this hotspot is not shown", path, line, section,
			key, value, err);
		rd->bad[i] = true;
	}
}

/* Whether h says where it is, once; said when not. */
static bool placed(const struct hotspot *h, const char *path)
{
	if (h->has_point == !!h->node[0]) {
		log_err("%s:%d: [hotspot.%s]: expected one of point = X Y Z (the model's "
			"coordinates) or node = NAME (a node it follows), %s; this hotspot is not "
			"shown",
			path, h->line, h->name, h->has_point ? "not both" : "found neither");
		return false;
	}
	return true;
}

int hotspot_settings_finish(struct hotspot_read *rd, const char *path, struct hotspot_set *set)
{
	int dropped = 0;

	for (int i = 0; i < rd->pending.count; i++) {
		const struct hotspot *h = &rd->pending.items[i];
		int at = hotspot_find(set, h->name);

		if (rd->bad[i] || !placed(h, path)) {
			dropped++;
			continue;
		}
		if (at < 0 && set->count >= HOTSPOTS) {
			log_err("%s:%d: [hotspot.%s]: %d hotspots are set already (kiosk.ini's "
				"and the model's together); this one is not shown",
				path, h->line, h->name, HOTSPOTS);
			dropped++;
			continue;
		}
		at = at < 0 ? set->count++ : at;
		set->items[at] = *h;
		snprintf(set->items[at].file, sizeof(set->items[at].file), "%s", path);
	}
	return dropped;
}
