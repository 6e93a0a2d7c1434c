/* The settings files' syntax (util/ini.h): a line at a time from memory,
 * copied into one buffer that grows with the longest line. */
#include "util/ini.h"

#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

struct ini_state {
	const struct ini_handler *h;
	void *user;
	char *section;
	size_t section_cap;
	int line, bad;
};

bool ini_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/* s[0..*n) without the blanks around it: the new start. */
static char *trim(char *s, size_t *n)
{
	while (*n && ini_blank(*s)) {
		s++;
		(*n)--;
	}
	while (*n && ini_blank(s[*n - 1]))
		(*n)--;
	s[*n] = '\0';
	return s;
}

static void say_bad(struct ini_state *st, const char *why)
{
	st->bad++;
	if (st->h->bad)
		st->h->bad(st->user, st->line, why);
}

static int read_section(struct ini_state *st, char *s, size_t n)
{
	char *close = memchr(s, ']', n);
	size_t name_len, rest;
	char *name, *after;

	if (!close) {
		say_bad(st, "a [section] without its ']'");
		return 0;
	}
	after = close + 1;
	rest = n - (size_t)(after - s);
	after = trim(after, &rest);
	if (rest && *after != '#' && *after != ';') {
		say_bad(st,
			"text after a [section]'s ']'; put each key = value on a line of its own");
		return 0;
	}
	name_len = (size_t)(close - s) - 1;
	name = trim(s + 1, &name_len);
	if (name_len + 1 > st->section_cap) {
		char *grown = realloc(st->section, name_len + 1);

		if (!grown)
			return -ENOMEM;
		st->section = grown;
		st->section_cap = name_len + 1;
	}
	memcpy(st->section, name, name_len + 1);
	return 0;
}

static int read_key(struct ini_state *st, char *s, size_t n)
{
	char *eq = memchr(s, '=', n), *key, *value;
	size_t key_len, value_len;

	if (!eq) {
		say_bad(st, "not an INI line; expected [section], key = value or a comment "
			    "(a line starting with # or ;)");
		return 0;
	}
	key_len = (size_t)(eq - s);
	value_len = n - key_len - 1;
	key = trim(s, &key_len);
	value = trim(eq + 1, &value_len);
	if (!key_len) {
		say_bad(st, "a value without a key; expected key = value");
		return 0;
	}
	return st->h->key ? st->h->key(st->user, st->line, st->section, key, value) : 0;
}

/* One line, NUL-terminated in a copy of its own (s[n] is writable). */
static int read_line(struct ini_state *st, char *s, size_t n)
{
	if (memchr(s, '\0', n)) {
		say_bad(st, "a NUL byte; a settings file is text");
		return 0;
	}
	s = trim(s, &n);
	if (!n || *s == '#' || *s == ';')
		return 0;
	return *s == '[' ? read_section(st, s, n) : read_key(st, s, n);
}

int ini_parse(const char *text, size_t size, const struct ini_handler *h, void *user)
{
	struct ini_state st = {.h = h, .user = user};
	char *buf = NULL;
	size_t cap = 0, at = 0;
	int ret = 0;

	if (!(st.section = calloc(1, 1)))
		return -ENOMEM;
	st.section_cap = 1;
	/* A UTF-8 byte order mark, as some editors on Windows write. */
	if (size >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3))
		at = 3;
	while (at < size && ret >= 0) {
		const char *nl = memchr(text + at, '\n', size - at);
		size_t n = nl ? (size_t)(nl - (text + at)) : size - at;

		if (n + 1 > cap) {
			char *grown = realloc(buf, n + 1);

			if (!grown) {
				ret = -ENOMEM;
				break;
			}
			buf = grown;
			cap = n + 1;
		}
		memcpy(buf, text + at, n);
		buf[n] = '\0';
		st.line++;
		ret = read_line(&st, buf, n);
		at += n + 1;
	}
	free(buf);
	free(st.section);
	return ret < 0 ? ret : st.bad;
}
