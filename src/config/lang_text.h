/* Every text a curator writes, in each language: one form everywhere,
 * KEY[LANG] = value beside KEY = value (the first language's), read
 * from any settings file, e.g.
 *     [caption] text = Vase          text[de] = Vase (Dt.)
 *     [frame]   stops = 0 0 1 "The front"; 90 0 1 "The mark"
 *               stops[de] = "Die Front"; "Das Zeichen"
 * (a stop's texts by its place, the views said once). [caption]
 * languages = en de fr names them in the order shown. A text missing in
 * a language is shown in the first. Plain data: hotspots and any later
 * text take the same entries under their own key. */
#ifndef MK_LANG_TEXT_H
#define MK_LANG_TEXT_H

#include <stdbool.h>
#include <stddef.h>

/* Languages at most ([caption] languages), and a code's length at most
 * (BCP 47's "zh-Hant-TW" and the like, with the NUL). */
#define LANG_MAX      6
#define LANG_CODE_MAX 16
/* Translated texts at most, all keys and languages together. */
#define LANG_TEXTS_MAX 96

struct lang_entry {
	char key[32]; /* "caption.text", "frame.stops" */
	char lang[LANG_CODE_MAX];
	char *value;
	char *origin; /* "file:line" it was read from, for --check-config; NULL: none */
};

struct lang_texts {
	struct lang_entry e[LANG_TEXTS_MAX];
	int count;
};

/* The languages of "en de fr": up to LANG_MAX codes into out; their
 * count, 0 for none (NULL or empty), -1 when a word is not a language
 * code (err says which and what is expected). */
int lang_list_parse(const char *text, char out[LANG_MAX][LANG_CODE_MAX], char *err, size_t n);

/* [caption] languages = text, set at path's line (0: not there, nothing
 * said): one error naming them when it does not parse, counted in
 * *errors. */
void lang_list_check(const char *text, const char *path, int line, int *errors);

/* Whether key ends in [LANG]; then base gets the key before it and lang
 * the code (both NUL-terminated, cut to their size). */
bool lang_key_split(const char *key, char *base, size_t base_n, char *lang, size_t lang_n);

/* Whether [section] key takes a [LANG] form. */
bool lang_key_translatable(const char *section, const char *key);

/* Set section.key's text in lang (a second one replaces the first: a
 * later file overrides an earlier one). 0, -EINVAL when lang is not a
 * language code, -ENOSPC when LANG_TEXTS_MAX are set, -ENOMEM. */
int lang_texts_set(struct lang_texts *t, const char *section, const char *key, const char *lang,
		   const char *value);

/* section.key's text in lang; else in first (the first language, NULL:
 * none named); else NULL (the caller's untranslated value). */
const char *lang_text_get(const struct lang_texts *t, const char *section, const char *key,
			  const char *lang, const char *first);

/* A stop's text of a translated [frame] stops: the index-th text of
 * '"A"; "B"' (quotes optional), malloc'd; NULL when there is none
 * there or it is empty. */
char *lang_stop_text(const char *stops, int index);

/* A settings file's line "KEY[LANG] = value" in [section]: stored, or
 * -1 after one error naming path, line, the key and what is expected. */
int lang_text_read(struct lang_texts *t, const char *path, int line, const char *section,
		   const char *key, const char *value);

int lang_texts_copy(struct lang_texts *dst, const struct lang_texts *src);
void lang_texts_release(struct lang_texts *t);
bool lang_texts_same(const struct lang_texts *a, const struct lang_texts *b);

#endif
