/* Hotspots' pure decisions (state/hotspot.h): no GL, no file, no clock. */
#include "state/hotspot.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* h's own text[lang], or NULL. */
static const char *text_in(const struct hotspot *h, const char *lang)
{
	for (int i = 0; lang && i < h->lang_count; i++)
		if (!strcasecmp(h->langs[i].lang, lang) && h->langs[i].text[0])
			return h->langs[i].text;
	return NULL;
}

const char *hotspot_text(const struct hotspot *h, const char *lang, const char *first)
{
	const char *t;

	if (!h)
		return "";
	if (!(t = text_in(h, lang)) && !(t = text_in(h, first)))
		t = h->text;
	return t;
}

int hotspot_set_text(struct hotspot *h, const char *lang, const char *text, int line)
{
	struct hotspot_lang *l;

	for (int i = 0; i < h->lang_count; i++)
		if (!strcasecmp(h->langs[i].lang, lang))
			return -EEXIST;
	if (h->lang_count >= HOTSPOT_LANGS)
		return -ENOSPC;
	if (strlen(text) >= sizeof(l->text))
		return -E2BIG;
	l = &h->langs[h->lang_count++];
	snprintf(l->lang, sizeof(l->lang), "%s", lang);
	snprintf(l->text, sizeof(l->text), "%s", text);
	l->line = line;
	return 0;
}

void hotspot_init(struct hotspot *h, const char *name, int line)
{
	memset(h, 0, sizeof(*h));
	snprintf(h->name, sizeof(h->name), "%s", name);
	h->line = line;
	h->look = HOTSPOT_DOT;
	/* A warm white with a dark ring reads on every matcap. */
	h->color[0] = 1.0f;
	h->color[1] = 0.85f;
	h->color[2] = 0.3f;
	h->color[3] = 1.0f;
}

int hotspot_parse_vec3(const char *value, double out[3], char *err, size_t n)
{
	char *end = NULL;
	const char *at = value;

	for (int i = 0; i < 3; i++) {
		out[i] = strtod(at, &end);
		if (end == at || !isfinite(out[i]))
			goto bad;
		at = end;
	}
	while (isspace((unsigned char)*at))
		at++;
	if (*at)
		goto bad;
	return 0;
bad:
	snprintf(err, n, "expected three numbers X Y Z in the model's coordinates, e.g. 0.1 0.5 0");
	return -1;
}

int hotspot_parse_normal(const char *value, double out[3], char *err, size_t n)
{
	double len;

	if (hotspot_parse_vec3(value, out, err, n))
		return -1;
	len = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
	if (!(len > 1e-9)) {
		snprintf(err, n, "expected a direction X Y Z that is not 0 0 0");
		return -1;
	}
	for (int i = 0; i < 3; i++)
		out[i] /= len;
	return 0;
}

int hotspot_parse_look(const char *value, enum hotspot_look *out, char *err, size_t n)
{
	if (!strcmp(value, "dot"))
		*out = HOTSPOT_DOT;
	else if (!strcmp(value, "badge"))
		*out = HOTSPOT_BADGE;
	else {
		snprintf(err, n, "expected dot or badge (a numbered disc)");
		return -1;
	}
	return 0;
}

static int hex_byte(const char *s)
{
	int v = 0;

	for (int i = 0; i < 2; i++) {
		int c = tolower((unsigned char)s[i]);

		if (!isxdigit(c))
			return -1;
		v = v * 16 + (isdigit(c) ? c - '0' : c - 'a' + 10);
	}
	return v;
}

int hotspot_parse_color(const char *value, float out[4], char *err, size_t n)
{
	size_t len = strlen(value);
	int bytes[4] = {0, 0, 0, 255};

	if (value[0] != '#' || (len != 7 && len != 9))
		goto bad;
	for (size_t i = 0; i < (len - 1) / 2; i++)
		if ((bytes[i] = hex_byte(value + 1 + 2 * i)) < 0)
			goto bad;
	for (int i = 0; i < 4; i++)
		out[i] = (float)bytes[i] / 255.0f;
	return 0;
bad:
	snprintf(err, n, "expected a colour #rrggbb or #rrggbbaa, e.g. #ffcc00");
	return -1;
}

int hotspot_find(const struct hotspot_set *s, const char *name)
{
	for (int i = 0; i < s->count; i++)
		if (!strcmp(s->items[i].name, name))
			return i;
	return -1;
}

int hotspot_next(int count, int current)
{
	if (count <= 0)
		return -1;
	return current < 0 || current + 1 >= count ? 0 : current + 1;
}

/* Yaw about y first brings dir into the y-z plane in front (x = 0, z > 0),
 * then pitch about x lifts it onto +z. */
void hotspot_facing(const double dir[3], double *yaw, double *pitch)
{
	double flat = sqrt(dir[0] * dir[0] + dir[2] * dir[2]);

	*yaw = flat > 0 ? atan2(-dir[0], dir[2]) : 0;
	*pitch = flat > 0 || dir[1] != 0 ? atan2(dir[1], flat) : 0;
}
