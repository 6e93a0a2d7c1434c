/* Whole files into memory. */
#ifndef MK_FILE_H
#define MK_FILE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A regular file's bytes into *data (malloc'd, one NUL past the end;
 * the caller frees it), at most max bytes. Read, not mapped: a file cut
 * short while it is read ends short instead of raising SIGBUS, which
 * would take the kiosk down. Returns 0, -EFBIG past max, -EINVAL for a
 * file that is not regular, or another negative errno code. */
int file_read_all(const char *path, size_t max, unsigned char **data, size_t *size);

#ifdef __cplusplus
}
#endif

#endif
