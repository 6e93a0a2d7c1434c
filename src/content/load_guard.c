#include "content/load_guard.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A record: "SIZE SECONDS.NANOSECONDS PATH", the path %XX-escaped where a
 * byte would end the line or forge a journal line (controls, DEL, '%'). */
#define RECORD_MAX (PATH_MAX * 3 + 64)
/* The skip list stays small: entries whose file changed or went are
 * dropped each time one is added, and past this many the oldest too. */
#define SKIP_MAX 64
#define FILE_MAX (SKIP_MAX * RECORD_MAX)
#define BOOT_ID	 "/proc/sys/kernel/random/boot_id"

int load_guard_dir(char *buf, size_t size)
{
	const char *env = getenv("STATE_DIRECTORY");

	if (!env || !*env)
		return -ENOENT;
	snprintf(buf, size, "%.*s", (int)strcspn(env, ":"), env);
	return 0;
}

static void escape(const char *s, char *out, size_t n)
{
	size_t k = 0;

	for (; *s && k + 4 < n; s++) {
		unsigned char c = (unsigned char)*s;

		if (c < 0x20 || c == 0x7f || c == '%')
			k += (size_t)snprintf(out + k, n - k, "%%%02X", c);
		else
			out[k++] = (char)c;
	}
	out[k] = '\0';
}

static void unescape(const char *s, char *out, size_t n)
{
	size_t k = 0;
	unsigned v;

	for (; *s && k + 1 < n; s++) {
		if (s[0] == '%' && s[1] && s[2] && sscanf(s + 1, "%2x", &v) == 1) {
			out[k++] = (char)v;
			s += 2;
		} else {
			out[k++] = *s;
		}
	}
	out[k] = '\0';
}

/* path as it is now; -errno when it cannot be looked at. */
static int record(const char *path, char *out, size_t n)
{
	struct stat st;
	int len;

	if (stat(path, &st))
		return -errno;
	len = snprintf(out, n, "%lld %lld.%09ld ", (long long)st.st_size,
		       (long long)st.st_mtim.tv_sec, st.st_mtim.tv_nsec);
	if (len < 0 || (size_t)len >= n)
		return -ENAMETOOLONG;
	escape(path, out + len, n - (size_t)len);
	return 0;
}

/* The record's path, as the journal may show it (escaped). */
static const char *record_path(const char *rec)
{
	const char *sp = strchr(rec, ' ');

	sp = sp ? strchr(sp + 1, ' ') : NULL;
	return sp ? sp + 1 : rec;
}

/* A record whose file is still as it was. */
static bool still_same(const char *rec)
{
	char path[PATH_MAX], now[RECORD_MAX];

	unescape(record_path(rec), path, sizeof(path));
	return record(path, now, sizeof(now)) == 0 && strcmp(now, rec) == 0;
}

static void join(char *out, size_t n, const char *dir, const char *name)
{
	snprintf(out, n, "%s/%s", dir, name);
}

/* The whole of dir/name as a string (NUL-terminated); NULL when absent. */
static char *read_text(const char *dir, const char *name)
{
	char path[PATH_MAX];
	unsigned char *data = NULL;
	size_t size = 0;
	char *text;

	join(path, sizeof(path), dir, name);
	if (file_read_all(path, FILE_MAX, &data, &size))
		return NULL;
	text = realloc(data, size + 1);
	if (!text) {
		free(data);
		return NULL;
	}
	text[size] = '\0';
	return text;
}

/* text into dir/name whole or not at all: a temporary, then renamed. */
static int write_text(const char *dir, const char *name, const char *text)
{
	char path[PATH_MAX], tmp[PATH_MAX];
	FILE *f;
	int ret = 0;

	join(path, sizeof(path), dir, name);
	snprintf(tmp, sizeof(tmp), "%s/.%s.new", dir, name);
	f = fopen(tmp, "we");
	if (!f)
		return -errno;
	if (fputs(text, f) == EOF)
		ret = -errno;
	if (fclose(f) && !ret)
		ret = -errno;
	if (!ret && rename(tmp, path))
		ret = -errno;
	if (ret)
		unlink(tmp);
	return ret;
}

/* This boot's id; "" when unreadable (then every marker counts). Read, not
 * through file_read_all: a /proc file's size says 0. */
static void boot_id(char *out, size_t n)
{
	int fd = open(BOOT_ID, O_RDONLY | O_CLOEXEC);
	ssize_t got = fd < 0 ? -1 : file_read_at(fd, out, n - 1, 0);

	if (fd >= 0)
		close(fd);
	out[got > 0 ? got : 0] = '\0';
	out[strcspn(out, "\n")] = '\0';
}

bool load_guard_skipped(const char *dir, const char *path)
{
	char now[RECORD_MAX], *list;
	bool found = false;

	if (record(path, now, sizeof(now)) || !(list = read_text(dir, LOAD_GUARD_SKIP)))
		return false;
	for (char *save = NULL, *l = strtok_r(list, "\n", &save); l && !found;
	     l = strtok_r(NULL, "\n", &save))
		found = strcmp(l, now) == 0;
	free(list);
	return found;
}

/* The skip list with rec added, less what changed since and the oldest
 * past SKIP_MAX. */
static int skip_add(const char *dir, const char *rec)
{
	char *list = read_text(dir, LOAD_GUARD_SKIP), *lines[SKIP_MAX], *out;
	size_t n = 0, len = strlen(rec) + 2;
	int ret;

	for (char *save = NULL, *l = list ? strtok_r(list, "\n", &save) : NULL; l;
	     l = strtok_r(NULL, "\n", &save)) {
		if (strcmp(l, rec) == 0 || !still_same(l))
			continue;
		if (n == SKIP_MAX - 1)
			memmove(lines, lines + 1, sizeof(*lines) * --n);
		lines[n++] = l;
	}
	for (size_t i = 0; i < n; i++)
		len += strlen(lines[i]) + 1;
	out = malloc(len);
	ret = out ? 0 : -ENOMEM;
	if (out) {
		out[0] = '\0';
		for (size_t i = 0; i < n; i++)
			strcat(strcat(out, lines[i]), "\n");
		ret = write_text(dir, LOAD_GUARD_SKIP, strcat(strcat(out, rec), "\n"));
	}
	free(out);
	free(list);
	return ret;
}

int load_guard_recover(const char *dir)
{
	char *marker = read_text(dir, LOAD_GUARD_MARKER), *rec, boot[64], path[PATH_MAX];
	int found = 0, ret;

	if (!marker)
		return 0;
	join(path, sizeof(path), dir, LOAD_GUARD_MARKER);
	unlink(path);
	boot_id(boot, sizeof(boot));
	rec = strchr(marker, '\n');
	if (rec)
		*rec++ = '\0', rec[strcspn(rec, "\n")] = '\0';
	if (!rec || !*rec || strncmp(marker, "boot ", 5)) {
		log_warn("%s: not a marker this kiosk wrote; removed", path);
	} else if (*boot && strcmp(marker + 5, boot)) {
		log_info("%s: the machine went down while it was loading; it is tried again",
			 record_path(rec));
	} else {
		found = 1;
		log_err("%s: the last start died while loading it (the process was killed); "
			"skipped until it changes",
			record_path(rec));
		ret = skip_add(dir, rec);
		if (ret)
			log_err("%s/%s: cannot be written (%s): that model will be loaded again",
				dir, LOAD_GUARD_SKIP, strerror(-ret));
	}
	free(marker);
	return found;
}

int load_guard_enter(const char *dir, const char *path)
{
	char rec[RECORD_MAX], boot[64], *text;
	int ret;

	load_guard_recover(dir);
	if (record(path, rec, sizeof(rec)))
		return 0; /* not there: its load says so */
	if (load_guard_skipped(dir, path)) {
		log_err("%s: skipped: the kiosk died while loading it before (%s/%s); replace "
			"the file to try it again",
			record_path(rec), dir, LOAD_GUARD_SKIP);
		return -ECANCELED;
	}
	boot_id(boot, sizeof(boot));
	text = malloc(strlen(rec) + sizeof(boot) + 8);
	if (!text)
		return 0;
	sprintf(text, "boot %s\n%s\n", boot, rec);
	ret = write_text(dir, LOAD_GUARD_MARKER, text);
	if (ret)
		log_warn("%s/%s: cannot be written (%s): a model that kills the kiosk will "
			 "not be remembered",
			 dir, LOAD_GUARD_MARKER, strerror(-ret));
	free(text);
	return 0;
}

void load_guard_leave(const char *dir)
{
	char path[PATH_MAX];

	join(path, sizeof(path), dir, LOAD_GUARD_MARKER);
	if (unlink(path) && errno != ENOENT)
		log_warn("%s: cannot be removed (%s): the next start will pass over the model "
			 "just loaded",
			 path, strerror(errno));
}
