#include "util/file.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* A model of tens of MB is touched once per 4 KiB page otherwise: huge
 * pages where the kernel offers them on request (it may not: no harm). */
static void advise_huge(void *buf, size_t size)
{
	const uintptr_t huge = 2u << 20;
	uintptr_t start = ((uintptr_t)buf + huge - 1) & ~(huge - 1);
	uintptr_t end = ((uintptr_t)buf + size) & ~(huge - 1);

	if (end > start)
		madvise((void *)start, end - start, MADV_HUGEPAGE);
}

ssize_t file_read_at(int fd, void *buf, size_t count, off_t off)
{
	size_t got = 0;
	ssize_t n = 1;

	while (got < count && n > 0) {
		n = pread(fd, (unsigned char *)buf + got, count - got, off + (off_t)got);
		if (n < 0 && errno == EINTR)
			n = 1;
		else if (n > 0)
			got += (size_t)n;
	}
	return n < 0 ? -errno : (ssize_t)got;
}

/* Not calloc: the bytes are about to be overwritten, and zeroing a 30 MB
 * model first costs as much as reading it from the page cache. */
static int read_fd(int fd, size_t want, unsigned char **data, size_t *size)
{
	unsigned char *buf = malloc(want + 1);
	ssize_t n;

	*data = NULL;
	*size = 0;
	if (!buf)
		return -ENOMEM;
	advise_huge(buf, want);
	n = file_read_at(fd, buf, want, 0);
	if (n < 0) {
		free(buf);
		return (int)n;
	}
	buf[n] = 0;
	*data = buf;
	*size = (size_t)n;
	return 0;
}

/* 0 for a regular file, or the code file_open_read refuses its type with. */
static int kind_code(mode_t mode)
{
	if (S_ISREG(mode))
		return 0;
	if (S_ISDIR(mode))
		return -EISDIR;
	if (S_ISFIFO(mode))
		return -ESPIPE;
	if (S_ISSOCK(mode))
		return -ENXIO;
	if (S_ISCHR(mode) || S_ISBLK(mode))
		return -ENODEV;
	return S_ISLNK(mode) ? -ELOOP : -EINVAL;
}

const char *file_refusal(int ret)
{
	switch (ret) {
	case -EISDIR:
		return "is a folder, not a file";
	case -ESPIPE:
		return "is a FIFO, not a file";
	case -ENXIO:
		return "is a socket, not a file";
	case -ENODEV:
		return "is a device node, not a file";
	case -ELOOP:
		return "is a symbolic link, which is not followed here";
	default:
		return NULL;
	}
}

int file_open_read(const char *path, unsigned flags, struct stat *st)
{
	int oflags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | (flags & FILE_NOFOLLOW ? O_NOFOLLOW : 0);
	struct stat own, *s = st ? st : &own;
	int fd, ret;

	/* Before the open: that of a FIFO blocks, that of a device acts. */
	if ((flags & FILE_NOFOLLOW ? lstat(path, s) : stat(path, s)))
		return -errno;
	ret = kind_code(s->st_mode);
	if (ret)
		return ret;
	fd = open(path, oflags);
	if (fd < 0)
		return -errno;
	/* Again on what was opened: the path may name another by now. */
	ret = fstat(fd, s) ? -errno : kind_code(s->st_mode);
	if (ret) {
		close(fd);
		return ret;
	}
	return fd;
}

int file_read_all(const char *path, size_t max, unsigned char **data, size_t *size)
{
	struct stat st;
	int fd = file_open_read(path, 0, &st), ret;

	*data = NULL;
	*size = 0;
	if (fd < 0)
		return fd;
	if ((unsigned long long)st.st_size > max)
		ret = -EFBIG;
	else
		ret = read_fd(fd, (size_t)st.st_size, data, size);
	close(fd);
	return ret;
}

int file_atomic_begin(struct file_atomic *a, const char *path, mode_t mode)
{
	const char *slash = strrchr(path, '/');
	int dir = slash ? (int)(slash - path) : 0;
	const char *name = slash ? slash + 1 : path;

	a->fd = -1;
	if (snprintf(a->path, sizeof(a->path), "%s", path) >= (int)sizeof(a->path) ||
	    snprintf(a->tmp, sizeof(a->tmp), "%.*s%s.%s.XXXXXX", dir, path, slash ? "/" : "",
		     name) >= (int)sizeof(a->tmp))
		return -ENAMETOOLONG;
	a->fd = mkostemp(a->tmp, O_CLOEXEC);
	if (a->fd < 0)
		return -errno;
	if (fchmod(a->fd, mode)) {
		int ret = -errno;

		file_atomic_end(a, ret, false);
		return ret;
	}
	return 0;
}

int file_atomic_end(struct file_atomic *a, int ret, bool sync)
{
	if (a->fd < 0)
		return ret ? ret : -EBADF;
	if (!ret && sync && fsync(a->fd))
		ret = -errno;
	if (close(a->fd) && !ret)
		ret = -errno;
	a->fd = -1;
	if (!ret && rename(a->tmp, a->path))
		ret = -errno;
	if (ret)
		unlink(a->tmp);
	return ret;
}

bool file_name_has_ext(const char *name, const char *const *exts)
{
	const char *dot = strrchr(name, '.');

	for (; dot && *exts; exts++)
		if (!strcasecmp(dot + 1, *exts))
			return true;
	return false;
}

static int compare_paths(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static int list_add(char ***paths, int *n, const char *dir, const char *name)
{
	size_t size = strlen(dir) + strlen(name) + 2;
	char **grown = realloc(*paths, sizeof(*grown) * (size_t)(*n + 1));

	if (!grown)
		return -ENOMEM;
	*paths = grown;
	grown[*n] = malloc(size);
	if (!grown[*n])
		return -ENOMEM;
	snprintf(grown[*n], size, "%s/%s", dir, name);
	(*n)++;
	return 0;
}

bool file_name_is_partial(const char *name)
{
	return name[0] == '.' || !strncmp(name, "~syncthing~", 11);
}

/* A name the folder lists may be anything: a FIFO or a device node named
 * like a model is passed over here, saying why, rather than handed to a
 * reader (which file_open_read would refuse too, but after the list had
 * counted it). Links are followed: a folder of links to models is fine. */
static bool is_regular(DIR *d, const char *dir, const char *name)
{
	struct stat st;
	int ret = fstatat(dirfd(d), name, &st, 0) ? -errno : kind_code(st.st_mode);

	if (ret && file_refusal(ret))
		log_warn("%s/%s: %s; passed over", dir, name, file_refusal(ret));
	else if (ret)
		log_warn("%s/%s: cannot stat it: %s; passed over", dir, name, strerror(-ret));
	return !ret;
}

int file_list_folder(const char *dir, const char *const *exts, char ***paths, int *n)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	int ret = 0;

	*paths = NULL;
	*n = 0;
	if (!d)
		return -errno;
	while (!ret && (e = readdir(d)))
		if (!file_name_is_partial(e->d_name) && file_name_has_ext(e->d_name, exts) &&
		    is_regular(d, dir, e->d_name))
			ret = list_add(paths, n, dir, e->d_name);
	closedir(d);
	if (ret) {
		file_list_free(*paths, *n);
		*paths = NULL;
		*n = 0;
	} else if (*n) { /* qsort(NULL, 0) is undefined */
		qsort(*paths, (size_t)*n, sizeof(**paths), compare_paths);
	}
	return ret;
}

void file_list_free(char **paths, int n)
{
	for (int i = 0; i < n; i++)
		free(paths[i]);
	free(paths);
}

void file_state_dir(char *buf, size_t n)
{
	const char *env = getenv("STATE_DIRECTORY");

	if (!env || !*env)
		env = "/var/lib/matcap-kiosk";
	snprintf(buf, n, "%.*s", (int)strcspn(env, ":"), env);
}

bool file_in_content(const char *path)
{
	char dir[PATH_MAX];
	size_t n;

	file_state_dir(dir, sizeof(dir));
	n = strlen(dir);
	return path && !strncmp(path, dir, n) && !strncmp(path + n, "/content/", 9);
}

int file_write_all(int fd, const void *data, size_t size)
{
	const char *p = data;

	while (size) {
		ssize_t n = write(fd, p, size);

		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0)
			return n < 0 ? -errno : -EIO;
		p += n;
		size -= (size_t)n;
	}
	return 0;
}
