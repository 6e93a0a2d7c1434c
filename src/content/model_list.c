#include "content/model_list.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

struct model_entry {
	char *path;
	struct timespec mtime; /* a change of it clears bad */
	long long size;
	bool bad; /* did not load: passed over */
};

struct model_list {
	int count;
	struct model_entry *entries;
};

static const char *const model_exts[] = {"gltf", "glb", NULL};

bool model_spec_is_many(const char *spec)
{
	struct stat st;

	return spec && (strchr(spec, ',') || (stat(spec, &st) == 0 && S_ISDIR(st.st_mode)));
}

static int add_entry(struct model_list *l, const char *dir, const char *name)
{
	size_t n = strlen(dir) + strlen(name) + 2;
	struct model_entry *grown = realloc(l->entries, sizeof(*grown) * (size_t)(l->count + 1));
	struct model_entry *e;
	struct stat st;

	if (!grown)
		return -ENOMEM;
	l->entries = grown;
	e = memset(&l->entries[l->count], 0, sizeof(*e));
	e->path = malloc(n);
	if (!e->path)
		return -ENOMEM;
	snprintf(e->path, n, "%s%s%s", dir, dir[0] ? "/" : "", name);
	if (stat(e->path, &st) == 0) {
		e->mtime = st.st_mtim;
		e->size = (long long)st.st_size;
	}
	l->count++;
	return 0;
}

/* A folder's models in name order. */
static int scan_folder(struct model_list *l, const char *path)
{
	char **paths;
	int n, ret = file_list_folder(path, model_exts, &paths, &n);

	if (ret) {
		log_err("%s: cannot open folder: %s", path, strerror(-ret));
		return ret;
	}
	for (int i = 0; i < n && !ret; i++)
		ret = add_entry(l, "", paths[i]);
	file_list_free(paths, n);
	return ret;
}

/* One item of the spec: a folder's models, or the file as it is named. */
static int add_item(struct model_list *l, const char *item)
{
	struct stat st;

	if (stat(item, &st) == 0 && S_ISDIR(st.st_mode))
		return scan_folder(l, item);
	return add_entry(l, "", item);
}

static int add_spec(struct model_list *l, const char *spec)
{
	char *copy = strdup(spec), *save = NULL;
	int ret = copy ? 0 : -ENOMEM;

	for (char *t = copy ? strtok_r(copy, ",", &save) : NULL; t && !ret;
	     t = strtok_r(NULL, ",", &save)) {
		while (*t == ' ' || *t == '\t')
			t++;
		for (char *end = t + strlen(t); end > t && (end[-1] == ' ' || end[-1] == '\t');)
			*--end = '\0';
		if (*t)
			ret = add_item(l, t);
	}
	free(copy);
	return ret;
}

struct model_list *model_list_new(const char *spec)
{
	struct model_list *l = calloc(1, sizeof(*l));
	int ret = l ? add_spec(l, spec) : -ENOMEM;

	if (!ret && l->count == 0) {
		log_err("%s: no .gltf or .glb model there", spec);
		ret = -ENOENT;
	}
	if (ret) {
		model_list_free(l);
		return NULL;
	}
	return l;
}

void model_list_free(struct model_list *l)
{
	if (!l)
		return;
	for (int i = 0; i < l->count; i++)
		free(l->entries[i].path);
	free(l->entries);
	free(l);
}

int model_list_count(const struct model_list *l)
{
	return l->count;
}

static int wrap(const struct model_list *l, int index)
{
	return ((index % l->count) + l->count) % l->count;
}

const char *model_list_path(const struct model_list *l, int index)
{
	return l->entries[wrap(l, index)].path;
}

int model_list_find(const struct model_list *l, const char *path)
{
	for (int i = 0; path && i < l->count; i++)
		if (strcmp(l->entries[i].path, path) == 0)
			return i;
	return -1;
}

static bool same_file(const struct model_entry *a, const struct model_entry *b)
{
	return a->size == b->size && a->mtime.tv_sec == b->mtime.tv_sec &&
	       a->mtime.tv_nsec == b->mtime.tv_nsec;
}

/* Entries that were not there before and did not arrive whole are still
 * being written: left out until they do. */
static void drop_entry(struct model_list *l, int i)
{
	free(l->entries[i].path);
	memmove(&l->entries[i], &l->entries[i + 1],
		sizeof(*l->entries) * (size_t)(l->count - i - 1));
	l->count--;
}

struct model_list *model_list_rescan(const struct model_list *old, const char *spec,
				     bool (*arrived)(void *ctx, const char *path), void *ctx,
				     int *fresh)
{
	struct model_list *l = model_list_new(spec);

	*fresh = -1;
	for (int i = 0; l && i < l->count;) {
		struct model_entry *e = &l->entries[i];
		int was = model_list_find(old, e->path);
		bool whole = arrived && arrived(ctx, e->path);

		if (was < 0 && !whole) {
			drop_entry(l, i);
			continue;
		}
		if (was >= 0 && same_file(e, &old->entries[was]))
			e->bad = old->entries[was].bad;
		else if (whole)
			*fresh = i;
		i++;
	}
	if (l && l->count == 0) {
		model_list_free(l);
		l = NULL;
	}
	return l;
}

int model_list_pick(struct model_list *l, int from, int step, int shown, model_try_fn try_load,
		    void *ctx)
{
	step = step < 0 ? -1 : 1;
	for (int n = 0, i = wrap(l, from); n < l->count; n++, i = wrap(l, i + step)) {
		if (i == shown)
			return i;
		if (l->entries[i].bad)
			continue;
		if (try_load(ctx, l->entries[i].path) == 0)
			return i;
		l->entries[i].bad = true;
	}
	return -1;
}

void model_list_set_bad(struct model_list *l, int index, bool bad)
{
	l->entries[wrap(l, index)].bad = bad;
}

bool model_list_bad(const struct model_list *l, int index)
{
	return l->entries[wrap(l, index)].bad;
}
