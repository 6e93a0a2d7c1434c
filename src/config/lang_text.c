/* The curator's texts in each language (lang_text.h): a small table
 * searched by key and language, as few as a label has. */
#include "config/lang_text.h"
#include "state/view.h"
#include "util/log.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What a language code may be: letters, digits and '-', starting with
 * two or three letters ("de", "pt-BR", "zh-Hant"), as BCP 47 has them. */
static bool lang_code(const char *s, size_t len)
{
	size_t letters = 0;

	if (!len || len >= LANG_CODE_MAX)
		return false;
	while (letters < len && isalpha((unsigned char)s[letters]))
		letters++;
	if (letters < 2 || letters > 3)
		return false;
	for (size_t i = letters; i < len; i++)
		if (!isalnum((unsigned char)s[i]) && s[i] != '-')
			return false;
	return letters == len || s[letters] == '-';
}

int lang_list_parse(const char *text, char out[LANG_MAX][LANG_CODE_MAX], char *err, size_t n)
{
	int count = 0;

	for (const char *p = text; p && *p;) {
		size_t len;

		p += strspn(p, " \t,");
		len = strcspn(p, " \t,");
		if (!len)
			break;
		if (!lang_code(p, len) || count == LANG_MAX) {
			snprintf(err, n,
				 count == LANG_MAX
				     ? "at most %d languages"
				     : "'%.*s' is not a language code; expected codes "
				       "such as en de fr pt-BR",
				 count == LANG_MAX ? LANG_MAX : (int)len, p);
			return -1;
		}
		memcpy(out[count], p, len);
		out[count++][len] = '\0';
		p += len;
	}
	return count;
}

void lang_list_check(const char *text, const char *path, int line, int *errors)
{
	char codes[LANG_MAX][LANG_CODE_MAX], err[128];

	if (!line || lang_list_parse(text, codes, err, sizeof(err)) >= 0)
		return;
	log_err("%s:%d: [caption] languages = '%s': %s", path, line, text, err);
	(*errors)++;
}

bool lang_key_split(const char *key, char *base, size_t base_n, char *lang, size_t lang_n)
{
	const char *open = strchr(key, '[');
	size_t len = strlen(key);

	if (!open || open == key || len < 3 || key[len - 1] != ']')
		return false;
	snprintf(base, base_n, "%.*s", (int)(open - key), key);
	snprintf(lang, lang_n, "%.*s", (int)(key + len - 1 - open - 1), open + 1);
	return true;
}

/* The keys whose value a visitor reads (a later one, such as a
 * hotspot's text, joins here and reads its text with lang_text_get). */
bool lang_key_translatable(const char *section, const char *key)
{
	return (!strcmp(section, "caption") && !strcmp(key, "text")) ||
	       (!strcmp(section, "frame") && !strcmp(key, "stops"));
}

static struct lang_entry *find(const struct lang_texts *t, const char *key, const char *lang)
{
	for (int i = 0; i < t->count; i++)
		if (!strcmp(t->e[i].key, key) && !strcasecmp(t->e[i].lang, lang))
			return (struct lang_entry *)&t->e[i];
	return NULL;
}

int lang_texts_set(struct lang_texts *t, const char *section, const char *key, const char *lang,
		   const char *value)
{
	char full[sizeof(t->e[0].key)];
	struct lang_entry *e;
	char *copy;

	if (!lang_code(lang, strlen(lang)))
		return -EINVAL;
	snprintf(full, sizeof(full), "%s.%s", section, key);
	e = find(t, full, lang);
	if (!e && t->count == LANG_TEXTS_MAX)
		return -ENOSPC;
	if (!(copy = strdup(value)))
		return -ENOMEM;
	if (!e) {
		e = &t->e[t->count++];
		snprintf(e->key, sizeof(e->key), "%s", full);
		snprintf(e->lang, sizeof(e->lang), "%s", lang);
	} else {
		free(e->value);
		free(e->origin);
	}
	e->value = copy;
	e->origin = NULL;
	return 0;
}

const char *lang_text_get(const struct lang_texts *t, const char *section, const char *key,
			  const char *lang, const char *first)
{
	char full[sizeof(t->e[0].key)];
	const struct lang_entry *e = NULL;

	snprintf(full, sizeof(full), "%s.%s", section, key);
	if (lang)
		e = find(t, full, lang);
	if ((!e || !*e->value) && first)
		e = find(t, full, first);
	return e && *e->value ? e->value : NULL;
}

char *lang_stop_text(const char *stops, int index)
{
	const char *p = stops;
	size_t len;

	for (int i = 0; p && i < index; i++) {
		p = strchr(p, ';');
		p = p ? p + 1 : NULL;
	}
	if (!p)
		return NULL;
	p += strspn(p, " \t");
	len = strcspn(p, ";");
	while (len && (p[len - 1] == ' ' || p[len - 1] == '\t'))
		len--;
	if (len >= 2 && p[0] == '"' && p[len - 1] == '"') {
		p++;
		len -= 2;
	}
	return len ? strndup(p, len) : NULL;
}

/* A translated [frame] stops: as many texts as stops at most, each as
 * long as a stop's own may be. */
static bool stop_texts_fit(const char *value)
{
	int count = 0;

	for (const char *p = value; p; p = strchr(p, ';') ? strchr(p, ';') + 1 : NULL) {
		char *t = lang_stop_text(p, 0);
		size_t len = t ? strlen(t) : 0;

		free(t);
		if (len >= FRAME_STOP_TEXT || (++count > FRAME_STOPS && len))
			return false;
	}
	return true;
}

int lang_text_read(struct lang_texts *t, const char *path, int line, const char *section,
		   const char *key, const char *value)
{
	char base[64], lang[LANG_CODE_MAX + 8];
	int ret;

	lang_key_split(key, base, sizeof(base), lang, sizeof(lang));
	if (!lang_key_translatable(section, base)) {
		log_err("%s:%d: [%s] %s: only the texts a visitor reads take a [LANG]: [caption] "
			"text[LANG] and [frame] stops[LANG]",
			path, line, section, key);
		return -1;
	}
	if (!strcmp(base, "stops") && !stop_texts_fit(value)) {
		log_err("%s:%d: [%s] %s: a stop's text is longer than %d bytes, or there are more "
			"than %d; expected \"TEXT\"; \"TEXT\" ..., a text a stop",
			path, line, section, key, FRAME_STOP_TEXT - 1, FRAME_STOPS);
		return -1;
	}
	ret = lang_texts_set(t, section, base, lang, value);
	if (ret == -EINVAL)
		log_err("%s:%d: [%s] %s: '%s' is not a language code; expected one such as de, fr "
			"or pt-BR",
			path, line, section, key, lang);
	else if (ret == -ENOSPC)
		log_err("%s:%d: [%s] %s: more than %d translated texts; expected at most that many",
			path, line, section, key, LANG_TEXTS_MAX);
	else if (ret)
		log_err("%s:%d: [%s] %s: %s", path, line, section, key, strerror(-ret));
	if (!ret) {
		char full[96]; /* a translatable key's: short, as lang_texts_set stored it */
		struct lang_entry *e;

		snprintf(full, sizeof(full), "%s.%s", section, base);
		e = find(t, full, lang);
		/* Only --check-config reads it: none is no error. */
		if (e && asprintf(&e->origin, "%s:%d", path, line) < 0)
			e->origin = NULL;
	}
	return ret ? -1 : 0;
}

int lang_texts_copy(struct lang_texts *dst, const struct lang_texts *src)
{
	*dst = *src;
	for (int i = 0; i < dst->count; i++)
		dst->e[i].value = dst->e[i].origin = NULL;
	for (int i = 0; i < dst->count; i++) {
		dst->e[i].value = strdup(src->e[i].value);
		dst->e[i].origin = src->e[i].origin ? strdup(src->e[i].origin) : NULL;
		if (!dst->e[i].value || (src->e[i].origin && !dst->e[i].origin)) {
			lang_texts_release(dst);
			return -ENOMEM;
		}
	}
	return 0;
}

void lang_texts_release(struct lang_texts *t)
{
	for (int i = 0; i < t->count; i++) {
		free(t->e[i].value);
		free(t->e[i].origin);
	}
	t->count = 0;
}

bool lang_texts_same(const struct lang_texts *a, const struct lang_texts *b)
{
	if (a->count != b->count)
		return false;
	for (int i = 0; i < a->count; i++)
		if (strcmp(a->e[i].key, b->e[i].key) || strcmp(a->e[i].lang, b->e[i].lang) ||
		    strcmp(a->e[i].value, b->e[i].value))
			return false;
	return true;
}
