#include "util/file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
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

/* Not calloc: the bytes are about to be overwritten, and zeroing a 30 MB
 * model first costs as much as reading it from the page cache. */
static int read_fd(int fd, size_t want, unsigned char **data, size_t *size)
{
	unsigned char *buf = malloc(want + 1);
	size_t got = 0;
	ssize_t n = 1;
	int ret = 0;

	if (!buf)
		return -ENOMEM;
	advise_huge(buf, want);
	while (got < want && n > 0) {
		n = read(fd, buf + got, want - got);
		if (n < 0 && errno == EINTR)
			n = 1;
		else if (n > 0)
			got += (size_t)n;
	}
	if (n < 0) {
		ret = -errno;
		free(buf);
		buf = NULL;
		got = 0;
	} else {
		buf[got] = 0;
	}
	*data = buf;
	*size = got;
	return ret;
}

int file_read_all(const char *path, size_t max, unsigned char **data, size_t *size)
{
	struct stat st;
	int fd = open(path, O_RDONLY | O_CLOEXEC), ret;

	*data = NULL;
	*size = 0;
	if (fd < 0)
		return -errno;
	if (fstat(fd, &st))
		ret = -errno;
	else if (!S_ISREG(st.st_mode))
		ret = -EINVAL;
	else if ((unsigned long long)st.st_size > max)
		ret = -EFBIG;
	else
		ret = read_fd(fd, (size_t)st.st_size, data, size);
	close(fd);
	return ret;
}
