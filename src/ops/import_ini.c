/* A USB stick's kiosk.ini, its paths made the content folder's. Lines
 * are split as util/ini.c splits them (at newlines only, blanks before a
 * key dropped, the key up to the first '='), and the result is read again
 * with a stick's rules before it is installed (ops/import.c). */
#include "ops/import_ini.h"
#include "util/ini.h"

#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

struct buf {
	char *p;
	size_t n, cap;
};

static int put(struct buf *b, const char *s, size_t n)
{
	if (b->n + n + 1 > b->cap) {
		size_t cap = (b->n + n + 1) * 2;
		char *grown = realloc(b->p, cap);

		if (!grown)
			return -ENOMEM;
		b->p = grown;
		b->cap = cap;
	}
	memcpy(b->p + b->n, s, n);
	b->n += n;
	b->p[b->n] = '\0';
	return 0;
}

static bool is_path_key(const char *key, size_t n)
{
	static const char *const keys[] = {"model",	 "matcap",	     "iridescence_ramp",
					   "detail_map", "displacement_map", NULL};

	for (const char *const *k = keys; *k; k++)
		if (strlen(*k) == n && !strncmp(key, *k, n))
			return true;
	return false;
}

/* Blanks at the start of s[0..n), as util/ini.c counts them. */
static size_t lead_blanks(const char *s, size_t n)
{
	size_t i = 0;

	while (i < n && ini_blank(s[i]))
		i++;
	return i;
}

/* One path of a value (blanks around it kept as they were). */
static int rebase_item(struct buf *b, const char *s, size_t n)
{
	size_t lead = lead_blanks(s, n), len = n - lead;
	bool keep = !len || (len >= 7 && !strncmp(s + lead, "matcaps", 7) &&
			     (len == 7 || s[lead + 7] == '/'));
	int ret = put(b, s, lead);

	if (!ret && !keep)
		ret = put(b, "model/", 6);
	return ret ? ret : put(b, s + lead, len);
}

/* The value (all of it: a ';' inside is part of it), its path rebased,
 * or each of a list's (only model takes a list, as options_file.c reads
 * it: a matcap named "a,b.png" is one file). */
static int rebase_value(struct buf *b, const char *v, size_t n, bool list)
{
	size_t end = n, at = 0;
	int ret = 0;

	while (end > 0 && (ini_blank(v[end - 1]) || v[end - 1] == '\n'))
		end--;
	for (size_t i = 0; i <= end && !ret; i++)
		if (i == end || (list && v[i] == ',')) {
			ret = rebase_item(b, v + at, i - at);
			if (!ret && i < end)
				ret = put(b, ",", 1);
			at = i + 1;
		}
	return ret ? ret : put(b, v + end, n - end);
}

/* One line of n bytes (its newline included where it has one), read
 * within those bytes only: the text need not end in a NUL. */
static int rebase_line(struct buf *b, const char *line, size_t n)
{
	size_t lead = lead_blanks(line, n), key_end, n_key;
	const char *eq = memchr(line, '=', n);
	int ret;

	if (!eq || lead == n || strchr(";#[", line[lead]))
		return put(b, line, n);
	key_end = (size_t)(eq - line);
	while (key_end > lead && ini_blank(line[key_end - 1]))
		key_end--;
	if (!is_path_key(line + lead, key_end - lead))
		return put(b, line, n);
	n_key = (size_t)(eq + 1 - line);
	ret = put(b, line, n_key);
	return ret ? ret
		   : rebase_value(b, eq + 1, n - n_key,
				  key_end - lead == 5 && !strncmp(line + lead, "model", 5));
}

int import_ini_rebase(const char *ini, size_t size, char **out, size_t *out_size)
{
	struct buf b = {0};
	int ret = put(&b, "", 0);

	for (size_t at = 0; at < size && !ret;) {
		const char *nl = memchr(ini + at, '\n', size - at);
		size_t n = nl ? (size_t)(nl - (ini + at)) + 1 : size - at;

		ret = rebase_line(&b, ini + at, n);
		at += n;
	}
	if (ret) {
		free(b.p);
		return ret;
	}
	*out = b.p;
	*out_size = b.n;
	return 0;
}
