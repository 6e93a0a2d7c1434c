/* Where each setting came from: the file and line that set it last, and
 * the files read in order (kiosk.ini, its kiosk.ini.d/ files, the
 * include), so that --check-config and the messages can name them. And
 * the one precedence: the command line over a model's NAME.ini over the
 * drop-ins over kiosk.ini (the files' order is the reading's; the command
 * line's values are marked here and kept over a NAME.ini read later). */
#include "config/settings.h"

#include <errno.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

_Static_assert(OPTION_DEFS <= 8 * CONTENT_CLI_BYTES, "a bit for every setting");

struct options_origins {
	char **files; /* each file read, once */
	int file_count;
	struct options_origin at[OPTION_DEFS];
};

static struct options_origins *origins_of(struct options *o)
{
	if (!o->origins)
		o->origins = calloc(1, sizeof(*o->origins));
	return o->origins;
}

const char *options_origin_file(struct options *o, const char *file)
{
	struct options_origins *g = origins_of(o);
	char **grown, *copy;

	if (!g)
		return NULL;
	for (int i = 0; i < g->file_count; i++)
		if (!strcmp(g->files[i], file))
			return g->files[i];
	grown = realloc(g->files, sizeof(*grown) * (size_t)(g->file_count + 1));
	if (!grown)
		return NULL;
	g->files = grown;
	if (!(copy = strdup(file)))
		return NULL;
	g->files[g->file_count++] = copy;
	return copy;
}

int options_origin_set(struct options *o, const struct option_def *d, const char *file, int line)
{
	struct options_origins *g = origins_of(o);
	const char *name = file ? options_origin_file(o, file) : "the command line";

	size_t i = (size_t)(d - option_defs);

	if (!g || !name)
		return -ENOMEM;
	g->at[i] = (struct options_origin){name, file ? line : 0};
	if (!file)
		o->content.from_cli[i / 8] |= (unsigned char)(1u << (i % 8));
	return 0;
}

bool content_config_from_cli(const struct content_config *c, const struct option_def *d)
{
	size_t i = (size_t)(d - option_defs);

	return c->from_cli[i / 8] & (1u << (i % 8));
}

/* d's field inside struct content_config, or (size_t)-1 when it is not
 * in it (a [kiosk] or [buttons] setting). */
static size_t content_at(const struct option_def *d)
{
	size_t at = offsetof(struct options, content);

	if (d->offset < at || d->offset >= at + sizeof(struct content_config))
		return (size_t)-1;
	return d->offset - at;
}

int content_config_keep_cli(struct content_config *dst, const struct content_config *cli)
{
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];
		size_t at = content_at(d);
		char *old, *s;

		if (at == (size_t)-1 || !content_config_from_cli(cli, d))
			continue;
		if (d->kind != K_STRING) { /* WxH: two ints side by side */
			memcpy((char *)dst + at, (const char *)cli + at,
			       OPTION_TWO_INTS(d) ? 2 * sizeof(int) : d->size);
			continue;
		}
		memcpy(&s, (const char *)cli + at, sizeof(s));
		if (s && !(s = strdup(s)))
			return -ENOMEM;
		memcpy(&old, (char *)dst + at, sizeof(old));
		free(old);
		memcpy((char *)dst + at, &s, sizeof(s));
	}
	return 0;
}

struct options_origin options_origin(const struct options *o, const struct option_def *d)
{
	return o->origins ? o->origins->at[d - option_defs] : (struct options_origin){NULL, 0};
}

int options_files_read(const struct options *o, const char *const **files)
{
	*files = o->origins ? (const char *const *)o->origins->files : NULL;
	return o->origins ? o->origins->file_count : 0;
}

void options_origins_free(struct options *o)
{
	if (!o->origins)
		return;
	for (int i = 0; i < o->origins->file_count; i++)
		free(o->origins->files[i]);
	free(o->origins->files);
	free(o->origins);
	o->origins = NULL;
}
