/* Where each setting came from: the file and line that set it last, and
 * the files read in order (kiosk.ini, its kiosk.ini.d/ files, the
 * include), so that --check-config and the messages can name them. */
#include "config/settings.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

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

	if (!g || !name)
		return -ENOMEM;
	g->at[d - option_defs] = (struct options_origin){name, file ? line : 0};
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
