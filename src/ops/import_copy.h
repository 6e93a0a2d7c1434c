/* The files --import takes from a USB stick's matcap-kiosk/ folder
 * (ops/import.h): models, their buffers and images (subfolders too, as
 * Blender and Sketchfab lay them out) and matcaps/. The stick is walked
 * twice by the same rules: first each file is sized (fstat), and a stick
 * over the budget is refused before a byte is written; then each is
 * copied, against the budget again (a file may grow meanwhile).
 *
 * Only plain files are taken, each opened without following a link and
 * without waiting (O_NOFOLLOW | O_NONBLOCK), its type read with fstat
 * before any read. A link, a pipe, a socket or a device node is passed
 * over with a line that says so; so is a name that is not printable text
 * (a control character, or not UTF-8), named escaped (\n, \x01), so that
 * no name writes a line of its own into the journal. */
#ifndef MK_IMPORT_COPY_H
#define MK_IMPORT_COPY_H

#include <limits.h>
#include <stdbool.h>
#include <stddef.h>

/* How many of the largest files a refusal for size names. */
#define IMPORT_LARGEST 3
/* A path under the stick's folder, as the journal names it: a folder's
 * path and a name in it. */
#define IMPORT_SHOWN (PATH_MAX + NAME_MAX + 2)

struct import_large {
	char path[IMPORT_SHOWN]; /* under the stick's folder, printable */
	long long size;
};

struct import_files {
	/* Set by the caller. */
	const char *from; /* the stick's folder, as the journal names it */
	int from_fd;	  /* it, opened once (not through a link) */
	const char *to;	  /* the staging folder: model/ and matcaps/ go in it */
	long long budget; /* the most bytes an import may take */
	/* Set by the walks. */
	long long total;	  /* bytes sized, then bytes copied */
	int files;		  /* files copied into model/ */
	int matcaps;		  /* files copied into matcaps/ */
	int skipped;		  /* entries passed over (said), by the sizing walk */
	char model[NAME_MAX + 1]; /* the first .gltf/.glb by name; "" none */
	struct import_large largest[IMPORT_LARGEST]; /* by the sizing walk */
};

/* Every file the copy would take, sized: 0, -EFBIG after naming the
 * largest files when they come to more than f->budget, or -errno after
 * naming the file. Nothing is written. */
int import_files_size(struct import_files *f);
/* The same files copied into f->to (which must not exist yet), each
 * replaced whole and synced: 0 or -errno after naming the file. */
int import_files_copy(struct import_files *f);

/* fsync of a folder, for the names in it: 0 or -errno. */
int import_sync_dir(const char *path);

/* A name of printable characters only: valid UTF-8, with no control
 * character (below 0x20, 0x7f, or U+0080 to U+009F). */
bool import_name_printable(const char *name);
/* name with each control character, backslash and byte that is not UTF-8
 * escaped (\n, \t, \\, \x01), cut to fit buf (size > 0); returns buf. */
const char *import_name_escape(const char *name, char *buf, size_t size);

#endif
