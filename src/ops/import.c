#include "ops/import.h"
#include "ops/check.h"
#include "ops/import_copy.h"
#include "ops/import_ini.h"
#include "content/content.h"
#include "content/model_list.h"
#include "config/options.h"
#include "util/file.h"
#include "util/log.h"

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

struct import {
	const char *from;	  /* the stick's folder */
	int from_fd;		  /* it, opened once (not through a link) */
	char content[PATH_MAX];	  /* where the kiosk reads it */
	char staging[PATH_MAX];	  /* the copy, until it is checked */
	char model[NAME_MAX + 1]; /* files.model: the first .gltf/.glb by name */
	char *ini;		  /* the stick's kiosk.ini, read once; NULL none */
	size_t ini_size;
	bool sets_model, sets_matcap; /* the stick's kiosk.ini names its own */
	int matcaps;		      /* how many were copied (files.matcaps) */
	struct import_files files;    /* the stick's files (ops/import_copy.h) */
};

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
	/* Notepad's byte order mark: the reader drops it at the start of a
	 * file only, and the written copy has lines of ours before it. */
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
	ret = file_write_all(fd, head, n);
	if (!ret && im->ini) {
		char *rebased = NULL;
		size_t size = 0;

		ret = import_ini_rebase(im->ini, im->ini_size, &rebased, &size);
		if (!ret)
			ret = file_write_all(fd, rebased, size);
		free(rebased);
	}
	if (!ret && fsync(fd))
		ret = -errno;
	if (close(fd) && !ret)
		ret = -errno;
	return ret;
}

/* A file of the staging copy's model/ as the stick's own, which the user
 * can look at: the same name. */
static const char *on_stick(const struct import *im, const char *path, char *buf, size_t n)
{
	size_t len = strlen(im->staging);
	const char *rest = path + len + 7;

	if (strncmp(path, im->staging, len) || strncmp(path + len, "/model/", 7))
		return path;
	rest += 2 * !strncmp(rest, "./", 2); /* model = . (the folder) */
	snprintf(buf, n, "%s/%s", im->from, rest);
	return buf;
}

/* Each model the settings name loaded strictly, as the kiosk loads it
 * with its matcaps, background and captions: each of a list, each of a
 * folder (content/model_list.h). The kiosk takes turns through them all,
 * and content_load stops at the first of a list that loads, so each is
 * named alone. -EIO after naming each that does not load. */
static int check_models(const struct import *im, const struct content_config *c)
{
	struct content_config one = *c;
	struct model_list *l = NULL;
	char shown[PATH_MAX];
	int n = 1, bad = 0;
	struct content s;

	if (model_spec_is_many(c->model) && !(l = model_list_new(c->model)))
		return -EIO; /* said: no model there */
	n = l ? model_list_count(l) : 1;
	for (int i = 0; i < n; i++) {
		/* one is c but for the model: c's own text, not freed */
		one.model = l ? (char *)model_list_path(l, i) : c->model;
		if (content_load(&s, &one, true)) {
			log_err("%s: the model does not load (above): the stick is refused",
				on_stick(im, one.model, shown, sizeof(shown)));
			bad++;
		} else {
			content_release(&s);
		}
	}
	model_list_free(l);
	return bad ? -EIO : 0;
}

/* What the kiosk would do with it: the settings over the installed ones
 * (kiosk.ini and kiosk.ini.d/; options on the command line are not the
 * service's), then the model and the matcaps loaded, strictly (no
 * built-in stand-in). */
static int check(const struct import *im, const struct options *o)
{
	char ini[PATH_MAX + 16];
	struct options t;
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
	ret = check_models(im, &t.content);
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

/* What an import cut short (stopped, or the power gone) left: removed,
 * and said. The caller holds the lock. */
static void remove_stale(const char *staging)
{
	struct stat st;

	if (lstat(staging, &st))
		return;
	remove_tree(staging);
	log_info("%s: removed what an import cut short left there", staging);
}

/* One import at a time (two partitions, two sticks): the staging folder
 * and the swap are shared. The lock is on the state folder itself, so a
 * refused stick leaves not even a lock file; it goes with the process.
 * how: LOCK_EX, or with LOCK_NB (-EWOULDBLOCK while an import holds it). */
static int lock_state(const char *state, int how)
{
	int fd = open(state, O_RDONLY | O_DIRECTORY | O_CLOEXEC), err = errno;

	if (fd < 0) {
		log_err("%s: cannot open: %s", state, strerror(err));
		return -err;
	}
	err = 0;
	while (flock(fd, how) && (err = errno) == EINTR)
		;
	if (err == EWOULDBLOCK && (how & LOCK_NB)) {
		close(fd);
		return -EWOULDBLOCK;
	}
	return fd;
}

void import_clean_stale(void)
{
	char state[PATH_MAX - 64], staging[PATH_MAX];
	struct stat st;
	int lock;

	file_state_dir(state, sizeof(state));
	snprintf(staging, sizeof(staging), "%s/.content.new", state);
	if (lstat(staging, &st))
		return; /* the usual case: no import was cut short */
	lock = lock_state(state, LOCK_EX | LOCK_NB);
	if (lock < 0)
		return; /* an import runs: the folder is its own */
	remove_stale(staging);
	close(lock);
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

/* The stick's settings read, its files sized (a stick over the budget
 * is refused before a byte is written), then copied into the staging
 * folder. */
static int stage(struct import *im)
{
	int ret = read_stick_ini(im);

	if (!ret)
		ret = scan_stick_ini(im);
	if (!ret)
		ret = import_files_size(&im->files);
	if (!ret)
		ret = mkdir(im->staging, 0755) ? -errno : 0;
	if (!ret)
		ret = import_files_copy(&im->files);
	snprintf(im->model, sizeof(im->model), "%s", im->files.model);
	im->matcaps = im->files.matcaps;
	if (!ret)
		ret = write_ini(im);
	if (!ret && !im->model[0] && !im->matcaps && !im->ini) {
		log_err("%s: no model (.gltf, .glb), matcaps/ or kiosk.ini to import", im->from);
		ret = -ENOENT;
	}
	return ret ? ret : import_sync_dir(im->staging);
}

/* Staged, checked and swapped in under the lock. */
static int import_locked(struct import *im, const struct options *o, const char *state)
{
	int lock = lock_state(state, LOCK_EX), ret;

	if (lock < 0)
		return lock;
	im->files.budget = budget(state);
	remove_stale(im->staging);
	ret = stage(im);
	if (!ret)
		ret = check(im, o);
	if (!ret)
		ret = swap_in(im);
	if (!ret)
		ret = import_sync_dir(state);
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
	file_state_dir(state, sizeof(state));
	snprintf(im.content, sizeof(im.content), "%s/content", state);
	snprintf(im.staging, sizeof(im.staging), "%s/.content.new", state);
	im.files = (struct import_files){.from = im.from, .from_fd = im.from_fd, .to = im.staging};
	ret = import_locked(&im, o, state);
	if (ret)
		log_err("%s: not imported (see above); the content in %s stays as it was", im.from,
			im.content);
	else
		log_info("imported %d files and %d matcaps from %s into %s%s", im.files.files,
			 im.matcaps, im.from, im.content, im.ini ? " with its kiosk.ini" : "");
	close(im.from_fd);
	free(im.ini);
	return ret;
}
