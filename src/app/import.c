#include "app/import.h"
#include "app/content.h"
#include "app/options.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A larger file is not a model for a Pi: refused rather than filling the
 * card. */
#define IMPORT_MAX_FILE (1024ll * 1024 * 1024)

struct import {
	const char *from;	  /* the stick's folder */
	char content[PATH_MAX];	  /* where the kiosk reads it */
	char staging[PATH_MAX];	  /* the copy, until it is checked */
	char model[NAME_MAX + 1]; /* the first .gltf/.glb by name; "" none */
	int files, matcaps;
	bool ini;
};

static bool has_ext(const char *name, const char *const *exts)
{
	const char *dot = strrchr(name, '.');

	for (; dot && *exts; exts++)
		if (!strcasecmp(dot + 1, *exts))
			return true;
	return false;
}

static const char *const model_exts[] = {"gltf", "glb", NULL};
static const char *const content_exts[] = {"gltf", "glb", "bin", "png", "jpg", "jpeg", NULL};
static const char *const image_exts[] = {"png", "jpg", "jpeg", NULL};

static int copy_fd(int in, int out)
{
	char buf[65536];
	ssize_t n;

	while ((n = read(in, buf, sizeof(buf))) > 0)
		if (write(out, buf, (size_t)n) != n)
			return -EIO;
	return n < 0 ? -errno : 0;
}

/* A link on the stick is not followed, nor anything but a plain file
 * copied: 1 (skipped, and said). */
static int plain_file(int from_dir, const char *name)
{
	struct stat st;

	if (fstatat(from_dir, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode))
		return 0;
	log_warn("%s: not a plain file: skipped", name);
	return 1;
}

/* One file, under a temporary name, synced, then renamed. */
static int copy_file(int from_dir, const char *name, const char *to_dir)
{
	char tmp[PATH_MAX], dst[PATH_MAX];
	struct stat st;
	int in = openat(from_dir, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC), out = -1, ret = 0;

	snprintf(dst, sizeof(dst), "%s/%s", to_dir, name);
	snprintf(tmp, sizeof(tmp), "%s/.%s.part", to_dir, name);
	if (in < 0 || fstat(in, &st))
		ret = -errno;
	else if (!S_ISREG(st.st_mode) || st.st_size > IMPORT_MAX_FILE)
		ret = -EFBIG;
	if (!ret && (out = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)) < 0)
		ret = -errno;
	if (!ret)
		ret = copy_fd(in, out);
	if (!ret && fsync(out))
		ret = -errno;
	if (out >= 0 && close(out) && !ret)
		ret = -errno;
	if (!ret && rename(tmp, dst))
		ret = -errno;
	if (ret) {
		unlink(tmp);
		log_err("%s: cannot copy into %s: %s", name, to_dir, strerror(-ret));
	}
	if (in >= 0)
		close(in);
	return ret;
}

static int sync_dir(const char *path)
{
	int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC), ret = 0;

	if (fd < 0 || fsync(fd))
		ret = -errno;
	if (fd >= 0)
		close(fd);
	return ret;
}

static int names_cmp(const struct dirent **a, const struct dirent **b)
{
	return strcmp((*a)->d_name, (*b)->d_name);
}

/* The files of one folder of the stick that exts allows, copied into to;
 * *count: how many. Hidden files (a Mac's ._name) are passed over. */
static int copy_folder(struct import *im, const char *from, const char *to, const char *const *exts,
		       int *count)
{
	struct dirent **names = NULL;
	int n = scandir(from, &names, NULL, names_cmp), fd = -1, ret = 0;

	if (n < 0)
		return errno == ENOENT ? 0 : -errno;
	if ((fd = open(from, O_RDONLY | O_DIRECTORY | O_CLOEXEC)) < 0 || mkdir(to, 0755))
		ret = -errno;
	for (int i = 0; i < n; i++) {
		const char *name = names[i]->d_name;

		if (!ret && name[0] != '.' && has_ext(name, exts) && !plain_file(fd, name)) {
			ret = copy_file(fd, name, to);
			*count += !ret;
			if (!ret && exts == content_exts && !im->model[0] &&
			    has_ext(name, model_exts))
				snprintf(im->model, sizeof(im->model), "%s", name);
		}
		free(names[i]);
	}
	free(names);
	if (fd >= 0)
		close(fd);
	return ret ? ret : sync_dir(to);
}

/* kiosk.ini in the content folder: the model and matcaps copied, then the
 * stick's own settings over them. */
static int write_ini(struct import *im)
{
	char path[PATH_MAX + 16], stick[PATH_MAX + 16];
	FILE *f, *in;
	int c, ret = 0;

	snprintf(path, sizeof(path), "%s/kiosk.ini", im->staging);
	snprintf(stick, sizeof(stick), "%s/kiosk.ini", im->from);
	if (!(f = fopen(path, "we")))
		return -errno;
	fprintf(f, "# Written by matcap-kiosk --import from %s.\n[scene]\n", im->from);
	if (im->model[0])
		fprintf(f, "model = %s/model/%s\n", im->content, im->model);
	if (im->matcaps)
		fprintf(f, "matcap = %s/matcaps\n", im->content);
	in = fopen(stick, "re");
	im->ini = in != NULL;
	if (in) {
		fprintf(f, "# The stick's kiosk.ini:\n");
		while ((c = fgetc(in)) != EOF)
			fputc(c, f);
		fclose(in);
	}
	if (fflush(f) || fsync(fileno(f)))
		ret = -errno;
	if (fclose(f) && !ret)
		ret = -errno;
	return ret;
}

/* A path the settings name in the content folder is, for the check, the
 * same file in the staging copy. */
static char *staged(const struct import *im, const char *path)
{
	size_t n = strlen(im->content);
	char *s = NULL;

	if (path && !strncmp(path, im->content, n) && path[n] == '/') {
		if (asprintf(&s, "%s%s", im->staging, path + n) < 0)
			s = NULL;
		return s;
	}
	return path ? strdup(path) : NULL;
}

/* The stick's kiosk.ini as it is (read from the staged copy, which holds
 * it after two lines of ours, would shift its line numbers). It may not
 * name a file to include: the stick brings its settings, not a path into
 * the kiosk's files. */
static int check_stick_ini(const struct import *im, struct options *t)
{
	char path[PATH_MAX + 16], *text = NULL;
	size_t size = 0;
	FILE *f, *mem = open_memstream(&text, &size);
	int c, ret = mem ? 0 : -ENOMEM;

	snprintf(path, sizeof(path), "%s/kiosk.ini", im->from);
	if (!ret && !(f = fopen(path, "re")))
		ret = -errno;
	else if (!ret) {
		while ((c = fgetc(f)) != EOF)
			fputc(c, mem);
		fclose(f);
	}
	if (mem && fclose(mem) && !ret)
		ret = -ENOMEM;
	if (!ret && options_read_memory(t, path, text, size) != OPTIONS_OK)
		ret = -EINVAL;
	if (!ret && t->include) {
		log_err("%s: [kiosk] include: a stick's settings may not name another file", path);
		ret = -EINVAL;
	}
	free(text);
	return ret;
}

/* What the kiosk would do with it: the settings over its own, then the
 * model and the matcaps loaded, strictly (no built-in stand-in). */
static int check(const struct import *im, const struct options *o)
{
	char ini[PATH_MAX + 16];
	struct options t;
	struct content s;
	char *model, *matcap;
	int ret = options_copy(&t, o);

	if (ret)
		return ret;
	free(t.include);
	t.include = NULL; /* the installed fragment is replaced, not read */
	/* The stick's file first, so that a mistake is named by its line. */
	if (im->ini && (ret = check_stick_ini(im, &t)))
		goto out;
	snprintf(ini, sizeof(ini), "%s/kiosk.ini", im->staging);
	if (options_read_file(&t, ini) != OPTIONS_OK) {
		ret = -EINVAL;
		goto out;
	}
	model = staged(im, t.content.model);
	matcap = staged(im, t.content.matcap);
	free(t.content.model);
	free(t.content.matcap);
	t.content.model = model;
	t.content.matcap = matcap;
	/* A file that does not load is not a mistake in the settings. */
	ret = content_load(&s, &t.content, true) ? -EIO : 0;
	if (!ret)
		content_release(&s);
out:
	options_release(&t);
	return ret;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
	(void)st;
	(void)flag;
	(void)ftw;
	return remove(path);
}

static void remove_tree(const char *path)
{
	nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

static void state_dir(char *buf, size_t n)
{
	const char *env = getenv("STATE_DIRECTORY");

	if (!env || !*env)
		env = "/var/lib/matcap-kiosk";
	snprintf(buf, n, "%.*s", (int)strcspn(env, ":"), env);
}

/* The checked copy takes the content folder's place in one step; the old
 * one is then removed. */
static int swap_in(struct import *im)
{
	int ret = 0;

	if (renameat2(AT_FDCWD, im->staging, AT_FDCWD, im->content, RENAME_EXCHANGE) == 0)
		remove_tree(im->staging);
	else if (errno == ENOENT)
		ret = rename(im->staging, im->content) ? -errno : 0;
	else
		ret = -errno;
	return ret;
}

static int stage(struct import *im)
{
	char from[PATH_MAX + 16], to[PATH_MAX + 16];
	int ret;

	snprintf(to, sizeof(to), "%s/model", im->staging);
	ret = copy_folder(im, im->from, to, content_exts, &im->files);
	snprintf(from, sizeof(from), "%s/matcaps", im->from);
	snprintf(to, sizeof(to), "%s/matcaps", im->staging);
	if (!ret)
		ret = copy_folder(im, from, to, image_exts, &im->matcaps);
	if (!ret)
		ret = write_ini(im);
	if (!ret && !im->model[0] && !im->matcaps && !im->ini) {
		log_err("%s: no model (.gltf, .glb), matcaps/ or kiosk.ini to import", im->from);
		ret = -ENOENT;
	}
	return ret ? ret : sync_dir(im->staging);
}

int import_run(const struct options *o)
{
	struct import im = {.from = o->import};
	char state[PATH_MAX - 64];
	int ret;

	state_dir(state, sizeof(state));
	snprintf(im.content, sizeof(im.content), "%s/content", state);
	snprintf(im.staging, sizeof(im.staging), "%s/.content.new", state);
	remove_tree(im.staging); /* what an import cut short left */
	ret = mkdir(im.staging, 0755) ? -errno : stage(&im);
	if (!ret)
		ret = check(&im, o);
	if (!ret)
		ret = swap_in(&im);
	if (!ret)
		ret = sync_dir(state);
	if (ret)
		log_err("%s: not imported (see above); the content in %s stays as it was", im.from,
			im.content);
	else
		log_info("imported %d files and %d matcaps from %s into %s%s", im.files, im.matcaps,
			 im.from, im.content, im.ini ? " with its kiosk.ini" : "");
	remove_tree(im.staging);
	return ret;
}
