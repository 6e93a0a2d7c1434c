/* Whole files into memory. */
#ifndef MK_FILE_H
#define MK_FILE_H

#include <limits.h>
#include <stdbool.h>
#include <stddef.h>
#include <sys/stat.h>
#include <sys/types.h>

#ifdef __cplusplus
extern "C" {
#endif

/* file_open_read's flags. */
enum {
	FILE_NOFOLLOW = 1, /* a symbolic link is refused (-ELOOP) */
};

/* Opens path to read as content (a model, a picture, a font, a cache
 * entry): the one way the kiosk opens such a file, since a stranger may
 * leave anything where one is expected. A FIFO would block the open and
 * then the read until a writer came (the kiosk hangs), and opening a
 * device node can have effects: so the path is stat'ed and anything but a
 * regular file refused before it is opened; then it is opened O_RDONLY |
 * O_NONBLOCK | O_CLOEXEC (| O_NOFOLLOW with FILE_NOFOLLOW) and fstat'ed
 * again before any read, for one swapped in between. Returns the fd (*st
 * filled when st is not NULL) or a negative errno code: -EISDIR, -ESPIPE
 * (a FIFO), -ENXIO (a socket), -ENODEV (a device node), -ELOOP (a link,
 * with FILE_NOFOLLOW) for what is not a regular file (file_refusal says
 * which), or the open's or stat's own. */
int file_open_read(const char *path, unsigned flags, struct stat *st);

/* Why file_open_read refused a path for its type, to follow "path: " in a
 * message ("is a FIFO, not a file"); NULL for any other code. */
const char *file_refusal(int ret);

/* A regular file's bytes into *data (malloc'd, one NUL past the end;
 * the caller frees it), at most max bytes, opened by file_open_read.
 * Read, not mapped: a file cut short while it is read ends short instead
 * of raising SIGBUS, which would take the kiosk down. Returns 0, -EFBIG
 * past max, file_open_read's refusals, or another negative errno code. */
int file_read_all(const char *path, size_t max, unsigned char **data, size_t *size);

/* count bytes of fd at off (pread, again after a signal), fewer only at
 * the end of the file. Returns the count read, or a negative errno code. */
ssize_t file_read_at(int fd, void *buf, size_t count, off_t off);

/* Whether name ends in "." and one of exts ("png", ..., NULL), in any case. */
bool file_name_has_ext(const char *name, const char *const *exts);

/* A name that a sync tool writes a file under until it is whole, then
 * renames it into place: rsync's ".NAME.XXXXXX", Syncthing's
 * ".syncthing.NAME.tmp" (hidden names, both) and "~syncthing~NAME.tmp"
 * (where hidden names are not hidden). */
bool file_name_is_partial(const char *name);

/* The files of folder dir whose names have one of exts, hidden ones (a
 * leading dot) and partial ones (file_name_is_partial) left out, and
 * those that are not regular files (a FIFO named x.glb would hang the
 * reader) passed over with a warning that says why, as
 * "dir/name" in name order: *paths (count *n), each and the array
 * malloc'd (file_list_free). Returns 0 or a negative errno code (nothing
 * to free). */
int file_list_folder(const char *dir, const char *const *exts, char ***paths, int *n);
void file_list_free(char **paths, int n);

/* A file replaced whole or not at all: written under a temporary name
 * beside it (fd, or the name tmp for a writer that takes a path), then
 * renamed over it, so that a reader (or a power cut) never finds half a
 * file. */
struct file_atomic {
	char tmp[PATH_MAX];
	char path[PATH_MAX];
	int fd;
};

/* Creates the temporary file, with mode. Returns 0 or a negative errno
 * code (nothing is left behind). */
int file_atomic_begin(struct file_atomic *a, const char *path, mode_t mode);
/* ret 0: fsync first when sync (data that must survive a power cut),
 * close, rename over path; otherwise, or when one of those fails, the
 * temporary file is removed. Returns ret, or the first failure. */
int file_atomic_end(struct file_atomic *a, int ret, bool sync);

/* All of data written to fd, again after a signal or a short write: 0,
 * or a negative errno code (-EIO for a write of nothing). */
int file_write_all(int fd, const void *data, size_t size);

/* The kiosk's state folder: $STATE_DIRECTORY (systemd's StateDirectory=,
 * the first where it lists several), else /var/lib/matcap-kiosk. */
void file_state_dir(char *buf, size_t n);
/* path lies in its content/ folder, where --import puts a USB stick's
 * files: a stranger's, held to a stick's rules wherever they are read. */
bool file_in_content(const char *path);

#ifdef __cplusplus
}
#endif

#endif
