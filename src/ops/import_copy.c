/* The stick's files, sized then copied by one walk (ops/import_copy.h).
 * The sizing walk says what it passes over; the copying walk, which
 * takes the same files by the same rules, does not say it again. */
#include "ops/import_copy.h"
#include "util/file.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Subfolders below the model's (textures/, as Blender and Sketchfab
 * write them): deeper ones are no model's layout, and are not followed. */
#define IMPORT_MAX_DEPTH 8
#define DEPTH_TEXT	 "8" /* IMPORT_MAX_DEPTH, for the journal */

static const char *const model_exts[] = {"gltf", "glb", NULL};
static const char *const content_exts[] = {"gltf", "glb",  "bin",  "png",
					   "jpg",  "jpeg", "webp", NULL};
static const char *const image_exts[] = {"png", "jpg", "jpeg", "webp", NULL};
static const char *const ini_exts[] = {"ini", NULL}; /* a model's NAME.ini */
/* In a subfolder: what a model names by URI, never a model itself. */
static const char *const asset_exts[] = {"bin", "png", "jpg", "jpeg", "webp", NULL};

enum folder_kind {
	FOLDER_MODEL,	/* the stick's matcap-kiosk/: models, their files, NAME.ini */
	FOLDER_ASSETS,	/* a subfolder of it: what a model names by URI */
	FOLDER_MATCAPS, /* matcaps/: images, no subfolder */
};

struct walk {
	struct import_files *f;
	bool copying; /* else sizing: the walk that says what it passes over */
};

/* One folder of the stick. */
struct folder {
	int fd;
	char rel[PATH_MAX]; /* under the stick's folder ("": it), printable */
	char to[PATH_MAX];  /* its copy */
	enum folder_kind kind;
	int depth;
};

/* The length of the UTF-8 character at p (1 to 4), or 0: not UTF-8
 * (overlong, a surrogate, past U+10FFFF, cut short) or a control
 * character (C0, DEL, C1). */
static size_t printable_len(const unsigned char *p)
{
	unsigned c = p[0], cp, min;
	size_t len;

	if (c < 0x20 || c == 0x7f)
		return 0;
	if (c < 0x80)
		return 1;
	if (c >= 0xc2 && c <= 0xdf)
		len = 2, cp = c & 0x1f, min = 0x80;
	else if (c >= 0xe0 && c <= 0xef)
		len = 3, cp = c & 0x0f, min = 0x800;
	else if (c >= 0xf0 && c <= 0xf4)
		len = 4, cp = c & 0x07, min = 0x10000;
	else
		return 0;
	for (size_t i = 1; i < len; i++) {
		if ((p[i] & 0xc0) != 0x80) /* a NUL too: the name ends */
			return 0;
		cp = cp << 6 | (p[i] & 0x3f);
	}
	if (cp < min || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff) || cp <= 0x9f)
		return 0;
	return len;
}

bool import_name_printable(const char *name)
{
	const unsigned char *p = (const unsigned char *)name;
	size_t len = 1;

	while (*p && (len = printable_len(p)))
		p += len;
	return len != 0;
}

const char *import_name_escape(const char *name, char *buf, size_t size)
{
	const unsigned char *p = (const unsigned char *)name;
	size_t n = 0;

	while (*p) {
		size_t len = printable_len(p), w = len;
		char one[8];

		if (len && *p != '\\') {
			memcpy(one, p, len);
		} else if (strchr("\n\t\r\\", *p)) {
			w = (size_t)snprintf(one, sizeof(one), "\\%c",
					     *p == '\n'	  ? 'n'
					     : *p == '\t' ? 't'
					     : *p == '\r' ? 'r'
							  : '\\');
			len = 1;
		} else {
			w = (size_t)snprintf(one, sizeof(one), "\\x%02x", *p);
			len = 1;
		}
		if (n + w >= size)
			break;
		memcpy(buf + n, one, w);
		n += w;
		p += len;
	}
	buf[n] = '\0';
	return buf;
}

/* What is passed over is said once, by the sizing walk, escaped. */
static void passed_over(struct walk *w, const struct folder *d, const char *name, const char *why)
{
	char shown[4 * NAME_MAX + 1];

	if (w->copying)
		return;
	w->f->skipped++;
	log_warn("%s/%s%s%s: %s: skipped", w->f->from, d->rel, *d->rel ? "/" : "",
		 import_name_escape(name, shown, sizeof(shown)), why);
}

/* size bytes, the size the file had when it was opened: one that grows
 * or shrinks meanwhile is refused (-ESTALE), so no more than was counted
 * against the budget is ever written. */
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
			ret = file_write_all(out, buf, (size_t)n);
		size -= n > 0 ? n : 0;
	}
	if (!ret && (size > 0 || read(in, buf, 1) != 0))
		ret = -ESTALE;
	return ret;
}

int import_sync_dir(const char *path)
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

static bool takes_file(enum folder_kind kind, const char *name)
{
	if (kind == FOLDER_MODEL)
		return file_name_has_ext(name, content_exts) ||
		       (file_name_has_ext(name, ini_exts) && strcmp(name, "kiosk.ini"));
	return file_name_has_ext(name, kind == FOLDER_ASSETS ? asset_exts : image_exts);
}

/* matcaps/ is walked on its own (walk_matcaps), and has no subfolders. */
static bool takes_folder(enum folder_kind kind, const char *name)
{
	return kind == FOLDER_ASSETS || (kind == FOLDER_MODEL && strcmp(name, "matcaps"));
}

/* A name of the model's folder goes into the generated kiosk.ini (model
 * = .../NAME): one that INI syntax would read otherwise (a comment, a
 * key, a section, blanks trimmed) cannot. */
static bool ini_safe(const char *name)
{
	size_t n = strlen(name);

	return n && name[0] != ' ' && name[n - 1] != ' ' && !strpbrk(name, ";#=[]");
}

static const char *not_plain(mode_t mode)
{
	if (S_ISFIFO(mode))
		return "a pipe (FIFO), not a plain file";
	if (S_ISSOCK(mode))
		return "a socket, not a plain file";
	if (S_ISCHR(mode) || S_ISBLK(mode))
		return "a device node, not a plain file";
	return S_ISLNK(mode) ? "a link, not a plain file" : "not a plain file";
}

/* buf: IMPORT_SHOWN bytes, which hold any (name is at most NAME_MAX). */
static void path_of(const struct folder *d, const char *name, char *buf)
{
	snprintf(buf, IMPORT_SHOWN, "%s%s%s", d->rel, *d->rel ? "/" : "", name);
}

/* Kept in order, largest first: a refusal names them. */
static void note_size(struct import_files *f, const struct folder *d, const char *name,
		      long long size)
{
	int i = IMPORT_LARGEST;

	f->total += size;
	while (i > 0 && size > f->largest[i - 1].size)
		i--;
	if (i == IMPORT_LARGEST)
		return;
	memmove(&f->largest[i + 1], &f->largest[i],
		(IMPORT_LARGEST - 1 - (size_t)i) * sizeof(f->largest[0]));
	path_of(d, name, f->largest[i].path);
	f->largest[i].size = size;
}

/* Counted against the budget again (the file may have grown since it was
 * sized); then replaced whole and synced (util/file.h). */
static int copy_file(struct walk *w, const struct folder *d, const char *name, int in,
		     const struct stat *st)
{
	struct import_files *f = w->f;
	char dst[PATH_MAX], shown[IMPORT_SHOWN];
	struct file_atomic a;
	int ret;

	path_of(d, name, shown);
	f->total += st->st_size;
	if (f->total > f->budget) {
		log_err("%s/%s: the files came to more than %lld MiB, the most an import may take, "
			"while they were copied (one grew?)",
			f->from, shown, f->budget >> 20);
		return -EFBIG;
	}
	if (snprintf(dst, sizeof(dst), "%s/%s", d->to, name) >= (int)sizeof(dst))
		return -ENAMETOOLONG;
	ret = file_atomic_begin(&a, dst, 0644);
	if (!ret)
		ret = file_atomic_end(&a, copy_fd(in, a.fd, st->st_size), true);
	if (ret) {
		log_err("%s/%s: cannot copy into %s: %s", f->from, shown, d->to,
			ret == -ESTALE ? "it changed while it was copied" : strerror(-ret));
		return ret;
	}
	if (d->kind == FOLDER_MATCAPS)
		f->matcaps++;
	else
		f->files++;
	if (d->kind == FOLDER_MODEL && !f->model[0] && file_name_has_ext(name, model_exts))
		snprintf(f->model, sizeof(f->model), "%s", name);
	return 0;
}

/* A plain file (seen: its lstat), opened without following a link or
 * waiting, and read only once fstat says it is the file that was seen. */
static int walk_file(struct walk *w, const struct folder *d, const char *name,
		     const struct stat *seen)
{
	int fd = openat(d->fd, name, O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC), ret = 0;
	char shown[IMPORT_SHOWN];
	struct stat st;

	path_of(d, name, shown);
	if (fd < 0 || fstat(fd, &st))
		ret = -errno;
	else if (!S_ISREG(st.st_mode) || st.st_ino != seen->st_ino || st.st_dev != seen->st_dev)
		ret = -ESTALE;
	if (ret)
		log_err("%s/%s: cannot open: %s", w->f->from, shown,
			ret == -ESTALE || ret == -ELOOP ? "it was replaced while it was read"
							: strerror(-ret));
	else if (!w->copying)
		note_size(w->f, d, name, st.st_size);
	else
		ret = copy_file(w, d, name, fd, &st);
	if (fd >= 0)
		close(fd);
	return ret;
}

static int walk_folder(struct walk *w, const struct folder *d);

/* A subfolder of the model's folder, by the same rules: not a link, under
 * the same budget, IMPORT_MAX_DEPTH deep at most. */
static int walk_subfolder(struct walk *w, const struct folder *d, const char *name)
{
	struct folder *sub = malloc(sizeof(*sub));
	int ret = sub ? 0 : -ENOMEM;

	if (!ret && d->depth >= IMPORT_MAX_DEPTH) {
		passed_over(w, d, name, "more than " DEPTH_TEXT " folders deep");
		goto out;
	}
	if (!ret &&
	    (snprintf(sub->rel, sizeof(sub->rel), "%s%s%s", d->rel, *d->rel ? "/" : "", name) >=
		 (int)sizeof(sub->rel) ||
	     snprintf(sub->to, sizeof(sub->to), "%s/%s", d->to, name) >= (int)sizeof(sub->to))) {
		passed_over(w, d, name, "the path is too long");
		goto out;
	}
	if (!ret)
		sub->fd = openat(d->fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	if (!ret && sub->fd < 0) {
		ret = -errno;
		log_err("%s/%s: cannot open: %s", w->f->from, sub->rel, strerror(-ret));
		goto out;
	}
	if (!ret) {
		sub->kind = FOLDER_ASSETS;
		sub->depth = d->depth + 1;
		ret = walk_folder(w, sub);
		close(sub->fd);
	}
out:
	free(sub);
	return ret;
}

/* One entry, by its lstat: never opened unless it is a plain file. */
static int walk_entry(struct walk *w, const struct folder *d, const char *name)
{
	struct stat st, target;

	if (!import_name_printable(name)) {
		passed_over(w, d, name, "a name with a control character, or not UTF-8");
		return 0;
	}
	if (fstatat(d->fd, name, &st, AT_SYMLINK_NOFOLLOW)) {
		int ret = -errno;

		log_err("%s/%s%s%s: cannot read: %s", w->f->from, d->rel, *d->rel ? "/" : "", name,
			strerror(-ret));
		return ret;
	}
	if (S_ISDIR(st.st_mode))
		return takes_folder(d->kind, name) ? walk_subfolder(w, d, name) : 0;
	if (S_ISLNK(st.st_mode) && takes_folder(d->kind, name) &&
	    !fstatat(d->fd, name, &target, 0) && S_ISDIR(target.st_mode))
		passed_over(w, d, name, "a link, not a folder");
	else if (!takes_file(d->kind, name))
		return 0;
	else if (!S_ISREG(st.st_mode))
		passed_over(w, d, name, not_plain(st.st_mode));
	else if (d->kind == FOLDER_MODEL && !ini_safe(name))
		passed_over(
		    w, d, name,
		    "a name with one of ;#=[] or a blank at an end cannot go into kiosk.ini");
	else
		return walk_file(w, d, name, &st);
	return 0;
}

/* Its entries in name order, and its copy made and synced. */
static int walk_folder(struct walk *w, const struct folder *d)
{
	char **names = NULL;
	size_t n = 0;
	int ret = list_folder(d->fd, &names, &n);

	if (!ret && w->copying && mkdir(d->to, 0755))
		ret = -errno;
	for (size_t i = 0; i < n; i++) {
		if (!ret)
			ret = walk_entry(w, d, names[i]);
		free(names[i]);
	}
	free(names);
	return !ret && w->copying ? import_sync_dir(d->to) : ret;
}

/* The stick's matcaps/ folder, not a link to one. */
static int walk_matcaps(struct walk *w, struct folder *d)
{
	int ret = 0;

	d->fd = openat(w->f->from_fd, "matcaps", O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	if (d->fd < 0 && errno == ENOENT)
		return 0;
	if (d->fd < 0 && (errno == ELOOP || errno == ENOTDIR)) {
		if (!w->copying)
			log_warn("%s/matcaps: not a folder (a link?): skipped", w->f->from);
		return 0;
	}
	if (d->fd < 0) {
		ret = -errno;
		log_err("%s/matcaps: cannot open: %s", w->f->from, strerror(-ret));
		return ret;
	}
	snprintf(d->rel, sizeof(d->rel), "matcaps");
	snprintf(d->to, sizeof(d->to), "%s/matcaps", w->f->to);
	d->kind = FOLDER_MATCAPS;
	d->depth = 0;
	ret = walk_folder(w, d);
	close(d->fd);
	return ret;
}

static int walk_stick(struct walk *w)
{
	struct folder *d = calloc(1, sizeof(*d));
	int ret = d ? 0 : -ENOMEM;

	w->f->total = 0;
	if (!ret) {
		d->fd = w->f->from_fd;
		d->kind = FOLDER_MODEL;
		snprintf(d->to, sizeof(d->to), "%s/model", w->f->to);
		ret = walk_folder(w, d);
	}
	if (!ret)
		ret = walk_matcaps(w, d);
	free(d);
	return ret;
}

int import_files_size(struct import_files *f)
{
	struct walk w = {.f = f, .copying = false};
	char names[IMPORT_LARGEST * (IMPORT_SHOWN + 32)] = "";
	size_t n = 0;
	int ret;

	memset(f->largest, 0, sizeof(f->largest));
	f->skipped = 0;
	ret = walk_stick(&w);
	if (ret || f->total <= f->budget)
		return ret;
	for (int i = 0; i < IMPORT_LARGEST && f->largest[i].size; i++)
		n +=
		    (size_t)snprintf(names + n, sizeof(names) - n, "%s%s (%.1f MiB)", i ? ", " : "",
				     f->largest[i].path, (double)f->largest[i].size / (1 << 20));
	log_err("%s: the files come to %lld MiB, more than %lld MiB, the most an import may take "
		"(2 GiB, and 90 %% of the free space): nothing copied; the largest: %s",
		f->from, f->total >> 20, f->budget >> 20, names);
	return -EFBIG;
}

int import_files_copy(struct import_files *f)
{
	struct walk w = {.f = f, .copying = true};

	f->files = f->matcaps = 0;
	f->model[0] = '\0';
	return walk_stick(&w);
}
