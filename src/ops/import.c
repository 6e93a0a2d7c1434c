#include "ops/import.h"
#include "ops/check.h"
#include "ops/import_ini.h"
#include "content/content.h"
#include "config/options.h"
#include "util/file.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

/* More than this is not content for a Pi: refused rather than filling
 * the card. */
#define IMPORT_MAX_TOTAL (2048ll * 1024 * 1024)
/* A settings file, not a way to fill memory. */
#define IMPORT_MAX_INI (64 * 1024)
/* Subfolders below the model's (textures/, as Blender and Sketchfab
 * write them): deeper ones are no model's layout, and are not followed. */
#define IMPORT_MAX_DEPTH 8

struct import {
	const char *from;	  /* the stick's folder */
	int from_fd;		  /* it, opened once (not through a link) */
	char content[PATH_MAX];	  /* where the kiosk reads it */
	char staging[PATH_MAX];	  /* the copy, until it is checked */
	char model[NAME_MAX + 1]; /* the first .gltf/.glb by name; "" none */
	char *ini;		  /* the stick's kiosk.ini, read once; NULL none */
	size_t ini_size;
	bool sets_model, sets_matcap; /* the stick's kiosk.ini names its own */
	long long total, budget;      /* bytes copied, and the most allowed */
	int files, matcaps;
};

static const char *const model_exts[] = {"gltf", "glb", NULL};
static const char *const content_exts[] = {"gltf", "glb", "bin", "png", "jpg", "jpeg", NULL};
static const char *const image_exts[] = {"png", "jpg", "jpeg", NULL};
static const char *const ini_exts[] = {"ini", NULL}; /* a model's NAME.ini */
/* In a subfolder: what a model names by URI, never a model itself. */
static const char *const asset_exts[] = {"bin", "png", "jpg", "jpeg", NULL};

/* A name goes into the generated kiosk.ini (model = .../NAME): one that
 * INI syntax would read otherwise (a comment, a key, a section, blanks
 * trimmed), or a control character, is passed over. */
static bool name_usable(const struct import *im, const char *name)
{
	size_t n = strlen(name);
	bool ok = n && name[0] != ' ' && name[n - 1] != ' ';
	char shown[NAME_MAX + 1];

	for (const unsigned char *p = (const unsigned char *)name; ok && *p; p++)
		ok = *p >= 0x20 && *p != 0x7f && !strchr(";#=[]", *p);
	if (ok)
		return true;
	/* Said with its control characters as '?', so the journal line is
	 * one line. */
	snprintf(shown, sizeof(shown), "%s", name);
	for (char *c = shown; *c; c++)
		*c = (unsigned char)*c < 0x20 || *c == 0x7f ? '?' : *c;
	log_warn("%s/%s: a name with a control character, one of ;#=[] or a blank at an end "
		 "cannot go into kiosk.ini: skipped",
		 im->from, shown);
	return false;
}

static int write_all(int fd, const char *buf, size_t n)
{
	while (n) {
		ssize_t w = write(fd, buf, n);

		if (w < 0 && errno == EINTR)
			continue;
		if (w <= 0)
			return w < 0 ? -errno : -EIO;
		buf += w;
		n -= (size_t)w;
	}
	return 0;
}

/* size bytes, the size the file had when it was counted: one that grows
 * or shrinks meanwhile is refused (-ESTALE). */
static int copy_fd(int in, int out, off_t size)
{
	char buf[65536];
	ssize_t n = 1;
	int ret = 0;

	while (!ret && size > 0 && n > 0) {
		n = read(in, buf, size < (off_t)sizeof(buf) ? (size_t)size : sizeof(buf));
		if (n < 0)
			ret = errno == EINTR ? 0 : -errno;
		else if (n > 0)
			ret = write_all(out, buf, (size_t)n);
		size -= n > 0 ? n : 0;
	}
	if (!ret && (size > 0 || read(in, buf, 1) != 0))
		ret = -ESTALE;
	return ret;
}

/* A link, a device or a pipe on the stick is not a file to copy: 1
 * (skipped, and said); else 0 with the file open in *fd, or -errno. */
static int open_plain(const char *shown, int dir, const char *name, int *fd, struct stat *st)
{
	*fd = openat(dir, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
	if (*fd < 0 && errno != ELOOP && errno != ENXIO && errno != ENODEV)
		return -errno;
	if (*fd >= 0 && !fstat(*fd, st) && S_ISREG(st->st_mode))
		return 0;
	if (*fd >= 0)
		close(*fd);
	*fd = -1;
	log_warn("%s/%s: not a plain file: skipped", shown, name);
	return 1;
}

/* Counted against the budget first; then replaced whole and synced
 * (util/file.h). */
static int copy_file(struct import *im, const char *shown, int from_dir, const char *name,
		     const char *to_dir)
{
	char dst[PATH_MAX];
	struct file_atomic a;
	struct stat st;
	int in, ret = open_plain(shown, from_dir, name, &in, &st);

	if (ret < 0)
		log_err("%s/%s: cannot open: %s", shown, name, strerror(-ret));
	if (ret)
		return ret;
	snprintf(dst, sizeof(dst), "%s/%s", to_dir, name);
	im->total += st.st_size;
	if (im->total > im->budget) {
		log_err("%s: the files come to more than %lld MiB, the most an import may take "
			"(2 GiB, and 90 %% of the free space)",
			im->from, im->budget >> 20);
		ret = -EFBIG;
		goto out;
	}
	ret = file_atomic_begin(&a, dst, 0644);
	if (!ret)
		ret = file_atomic_end(&a, copy_fd(in, a.fd, st.st_size), true);
	if (ret) {
		log_err("%s/%s: cannot copy into %s: %s", shown, name, to_dir,
			ret == -ESTALE ? "it changed while it was copied" : strerror(-ret));
	}
out:
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

static int names_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The names in an open folder, sorted; hidden ones (a Mac's ._name)
 * passed over. */
static int list_folder(int fd, char ***names, size_t *n)
{
	int dup_fd = fcntl(fd, F_DUPFD_CLOEXEC, 0), ret = 0;
	DIR *d = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
	struct dirent *e;
	char **grown;

	if (!d) {
		ret = -errno;
		if (dup_fd >= 0)
			close(dup_fd);
		return ret;
	}
	rewinddir(d);
	while (!ret && (e = readdir(d))) {
		if (e->d_name[0] == '.')
			continue;
		if (!(grown = realloc(*names, (*n + 1) * sizeof(**names))))
			ret = -ENOMEM;
		else if (!(grown[*n] = strdup(e->d_name)))
			ret = -ENOMEM;
		*names = grown ? grown : *names;
		*n += !ret;
	}
	closedir(d);
	if (*names)
		qsort(*names, *n, sizeof(**names), names_cmp);
	return ret;
}

static int copy_folder(struct import *im, int fd, const char *shown, const char *to,
		       const char *const *exts, int depth, int *count);

/* A subfolder of the model's folder, by the same rules: not a link, no
 * hidden name, files by asset_exts, under the same budget. 0 when it is
 * passed over (said), else copy_folder's result. */
static int copy_subfolder(struct import *im, int fd, const char *shown, const char *name,
			  const char *to, int depth, int *count)
{
	char sub_shown[PATH_MAX], sub_to[PATH_MAX];
	int sub = openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC), ret;

	if (sub < 0 && (errno == ELOOP || errno == ENOTDIR)) {
		log_warn("%s/%s: a link, not a folder: skipped", shown, name);
		return 0;
	}
	if (sub < 0) {
		ret = -errno;
		log_err("%s/%s: cannot open: %s", shown, name, strerror(-ret));
		return ret;
	}
	if (snprintf(sub_shown, sizeof(sub_shown), "%s/%s", shown, name) >=
		(int)sizeof(sub_shown) ||
	    snprintf(sub_to, sizeof(sub_to), "%s/%s", to, name) >= (int)sizeof(sub_to)) {
		log_warn("%s/%s: the path is too long: skipped", shown, name);
		close(sub);
		return 0;
	}
	if (depth >= IMPORT_MAX_DEPTH) {
		log_warn("%s: more than %d folders deep: skipped", sub_shown, IMPORT_MAX_DEPTH);
		close(sub);
		return 0;
	}
	ret = copy_folder(im, sub, sub_shown, sub_to, asset_exts, depth + 1, count);
	close(sub);
	return ret;
}

/* A folder, or a link to one (which copy_subfolder names and passes over). */
static bool is_folder(int fd, const char *name)
{
	struct stat st;

	return !fstatat(fd, name, &st, 0) && S_ISDIR(st.st_mode);
}

/* The files of one folder of the stick that exts allows, copied into to;
 * *count: how many. The model's folder (depth 0) brings its subfolders but
 * matcaps/ (copied on its own), and only its top-level files are models. */
static int copy_folder(struct import *im, int fd, const char *shown, const char *to,
		       const char *const *exts, int depth, int *count)
{
	char **names = NULL;
	size_t n = 0;
	int ret = list_folder(fd, &names, &n), r;
	bool model_folder = exts == content_exts;

	if (!ret && mkdir(to, 0755))
		ret = -errno;
	for (size_t i = 0; i < n; i++) {
		const char *name = names[i];

		if (!ret && exts != image_exts && is_folder(fd, name)) {
			if (!model_folder || strcmp(name, "matcaps"))
				ret = copy_subfolder(im, fd, shown, name, to, depth, count);
		} else if (!ret &&
			   (file_name_has_ext(name, exts) ||
			    (model_folder && file_name_has_ext(name, ini_exts) &&
			     strcmp(name, "kiosk.ini"))) &&
			   (!model_folder || name_usable(im, name))) {
			r = copy_file(im, shown, fd, name, to);
			ret = r < 0 ? r : 0;
			*count += !r;
			if (!r && model_folder && !im->model[0] &&
			    file_name_has_ext(name, model_exts))
				snprintf(im->model, sizeof(im->model), "%s", name);
		}
		free(names[i]);
	}
	free(names);
	return ret ? ret : sync_dir(to);
}

/* The stick's matcaps/ folder, not a link to one. */
static int copy_matcaps(struct import *im)
{
	char to[PATH_MAX + 16];
	int fd = openat(im->from_fd, "matcaps", O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC),
	    ret;

	if (fd < 0 && errno == ENOENT)
		return 0;
	if (fd < 0 && (errno == ELOOP || errno == ENOTDIR)) {
		log_warn("%s/matcaps: not a folder (a link?): skipped", im->from);
		return 0;
	}
	if (fd < 0)
		return -errno;
	snprintf(to, sizeof(to), "%s/matcaps", im->staging);
	ret = copy_folder(im, fd, im->from, to, image_exts, 0, &im->matcaps);
	close(fd);
	return ret;
}

/* kiosk.ini, read once into memory: what is checked is what is copied. A
 * link, a pipe or a large file is refused (-EINVAL, a bad stick's
 * settings). */
static int read_stick_ini(struct import *im)
{
	int fd = openat(im->from_fd, "kiosk.ini", O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC),
	    ret = 0;
	struct stat st;
	ssize_t n = 1;

	if (fd < 0 && errno == ENOENT)
		return 0;
	if (fd < 0 || fstat(fd, &st) || !S_ISREG(st.st_mode) || st.st_size > IMPORT_MAX_INI) {
		log_err("%s/kiosk.ini: not a plain file of %d KiB at most", im->from,
			IMPORT_MAX_INI / 1024);
		ret = -EINVAL;
		goto out;
	}
	if (!(im->ini = malloc(IMPORT_MAX_INI + 1))) {
		ret = -ENOMEM;
		goto out;
	}
	while (n > 0 && im->ini_size <= IMPORT_MAX_INI) {
		n = read(fd, im->ini + im->ini_size, IMPORT_MAX_INI + 1 - im->ini_size);
		im->ini_size += n > 0 ? (size_t)n : 0;
	}
	/* Notepad's byte order mark: inih drops it at the start of a file
	 * only, and the copy follows lines of ours. */
	if (n >= 0 && im->ini_size >= 3 && !memcmp(im->ini, "\xef\xbb\xbf", 3)) {
		im->ini_size -= 3;
		memmove(im->ini, im->ini + 3, im->ini_size);
	}
	if (n < 0 || im->ini_size > IMPORT_MAX_INI) {
		log_err("%s/kiosk.ini: %s", im->from,
			n < 0 ? strerror(errno) : "it grew past 64 KiB while it was read");
		ret = -EINVAL;
	}
out:
	if (fd >= 0)
		close(fd);
	return ret;
}

/* Whether the stick's own settings t set [scene] key. */
static bool stick_sets(const struct options *t, const char *key)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].section == OPTIONS_SCENE && !strcmp(option_defs[i].key, key))
			return options_origin(t, &option_defs[i]).file != NULL;
	return false;
}

/* -EINVAL after naming each key the stick may not set and each path that
 * leaves it: its kiosk.ini alone, read with a stick's rules. What it sets
 * itself is not written for it (write_ini). */
static int scan_stick_ini(struct import *im)
{
	char name[PATH_MAX + 16];
	struct options t;
	int ret;

	if (!im->ini || !im->ini_size)
		return 0;
	option_defaults(&t);
	snprintf(name, sizeof(name), "%s/kiosk.ini", im->from);
	ret = options_read_text(&t, name, NULL, im->ini, im->ini_size, &options_rules_stick)
		  ? -EINVAL
		  : 0;
	im->sets_model = stick_sets(&t, "model");
	im->sets_matcap = stick_sets(&t, "matcap");
	options_release(&t);
	return ret;
}

/* kiosk.ini in the content folder: the model and matcaps copied, for the
 * keys the stick's own file does not set (a key may be set once), then
 * that file as it was read, its relative paths made the content folder's
 * (the files are in model/ there). */
static int write_ini(struct import *im)
{
	char path[PATH_MAX + 16], head[3 * PATH_MAX];
	int fd, ret;
	size_t n = 0;

	n += (size_t)snprintf(head, sizeof(head), "# Written by matcap-kiosk --import.\n[scene]\n");
	if (im->model[0] && !im->sets_model)
		n += (size_t)snprintf(head + n, sizeof(head) - n, "model = model/%s\n", im->model);
	if (im->matcaps && !im->sets_matcap)
		n += (size_t)snprintf(head + n, sizeof(head) - n, "matcap = matcaps\n");
	snprintf(path, sizeof(path), "%s/kiosk.ini", im->staging);
	if ((fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644)) < 0)
		return -errno;
	ret = write_all(fd, head, n);
	if (!ret && im->ini) {
		char *rebased = NULL;
		size_t size = 0;

		ret = import_ini_rebase(im->ini, im->ini_size, &rebased, &size);
		if (!ret)
			ret = write_all(fd, rebased, size);
		free(rebased);
	}
	if (!ret && fsync(fd))
		ret = -errno;
	if (close(fd) && !ret)
		ret = -errno;
	return ret;
}

/* What the kiosk would do with it: the settings over the installed ones
 * (kiosk.ini and kiosk.ini.d/; options on the command line are not the
 * service's), then the model and the matcaps loaded, strictly (no
 * built-in stand-in). */
static int check(const struct import *im, const struct options *o)
{
	char ini[PATH_MAX + 16];
	struct options t;
	struct content s;
	int ret = 0;

	/* The installed files alone: o holds what the content folder's
	 * kiosk.ini (the include) set, and that is what is replaced. */
	option_defaults(&t);
	if (o->config && options_read_installed(&t, o->config) != OPTIONS_OK) {
		ret = -EINVAL;
		goto out;
	}
	free(t.include);
	t.include = NULL; /* the installed fragment is replaced, not read */
	/* The stick's file alone was read with its lines in scan_stick_ini.
	 * Now the bytes that will be installed, as the kiosk will read them:
	 * with a stick's rules (options_read_file reads the include so), the
	 * paths relative to the content folder. */
	snprintf(ini, sizeof(ini), "%s/kiosk.ini", im->staging);
	if (options_read_one(&t, ini, &options_rules_stick) != OPTIONS_OK) {
		ret = -EINVAL;
		goto out;
	}
	/* Each model's own settings file, refused as kiosk.ini is. */
	if (check_model_settings(&t.content, NULL, true)) {
		ret = -EINVAL;
		goto out;
	}
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

/* One import at a time (two partitions, two sticks): the staging folder
 * and the swap are shared. The lock is on the state folder itself, so a
 * refused stick leaves not even a lock file; it goes with the process. */
static int lock_state(const char *state)
{
	int fd = open(state, O_RDONLY | O_DIRECTORY | O_CLOEXEC), err = errno;

	if (fd < 0) {
		log_err("%s: cannot open: %s", state, strerror(err));
		return -err;
	}
	while (flock(fd, LOCK_EX) && errno == EINTR)
		;
	return fd;
}

/* 2 GiB, or 90 % of what the content's file system has free. */
static long long budget(const char *state)
{
	struct statvfs fs;
	long long free_bytes;

	if (statvfs(state, &fs))
		return IMPORT_MAX_TOTAL;
	free_bytes = (long long)fs.f_bavail * (long long)fs.f_frsize;
	free_bytes -= free_bytes / 10;
	return free_bytes < IMPORT_MAX_TOTAL ? free_bytes : IMPORT_MAX_TOTAL;
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
	char to[PATH_MAX + 16];
	int ret = read_stick_ini(im);

	if (!ret)
		ret = scan_stick_ini(im);
	snprintf(to, sizeof(to), "%s/model", im->staging);
	if (!ret)
		ret = copy_folder(im, im->from_fd, im->from, to, content_exts, 0, &im->files);
	if (!ret)
		ret = copy_matcaps(im);
	if (!ret)
		ret = write_ini(im);
	if (!ret && !im->model[0] && !im->matcaps && !im->ini) {
		log_err("%s: no model (.gltf, .glb), matcaps/ or kiosk.ini to import", im->from);
		ret = -ENOENT;
	}
	return ret ? ret : sync_dir(im->staging);
}

/* Staged, checked and swapped in under the lock. */
static int import_locked(struct import *im, const struct options *o, const char *state)
{
	int lock = lock_state(state), ret;

	if (lock < 0)
		return lock;
	im->budget = budget(state);
	remove_tree(im->staging); /* what an import cut short left */
	ret = mkdir(im->staging, 0755) ? -errno : stage(im);
	if (!ret)
		ret = check(im, o);
	if (!ret)
		ret = swap_in(im);
	if (!ret)
		ret = sync_dir(state);
	remove_tree(im->staging);
	close(lock);
	return ret;
}

int import_run(const struct options *o)
{
	struct import im = {.from = o->import};
	char state[PATH_MAX - 64];
	int ret;

	im.from_fd = open(im.from, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	if (im.from_fd < 0 && errno == ENOENT) {
		log_info("%s: no such folder: nothing to import", im.from);
		return 0;
	}
	if (im.from_fd < 0) {
		ret = -errno;
		log_err("%s: not a folder to import (a link?): %s", im.from, strerror(-ret));
		return ret;
	}
	state_dir(state, sizeof(state));
	snprintf(im.content, sizeof(im.content), "%s/content", state);
	snprintf(im.staging, sizeof(im.staging), "%s/.content.new", state);
	ret = import_locked(&im, o, state);
	if (ret)
		log_err("%s: not imported (see above); the content in %s stays as it was", im.from,
			im.content);
	else
		log_info("imported %d files and %d matcaps from %s into %s%s", im.files, im.matcaps,
			 im.from, im.content, im.ini ? " with its kiosk.ini" : "");
	close(im.from_fd);
	free(im.ini);
	return ret;
}
