/* The matcaps a kiosk cycles through: every PNG/JPEG/WebP of a folder, in name
 * order, or one file. Decoding happens when an entry is shown. */
#ifndef MK_MATCAP_SET_H
#define MK_MATCAP_SET_H

#include "util/image.h"

#include <stdbool.h>

struct matcap_set;

/* Returns NULL after logging when the path holds no usable image name. */
struct matcap_set *matcap_set_open(const char *path);
void matcap_set_free(struct matcap_set *s);
int matcap_set_count(const struct matcap_set *s);
const char *matcap_set_path(const struct matcap_set *s, int index);
/* Start the cycle at the file called name (with or without its
 * extension), going on in name order and round to the ones before it.
 * Returns 0, -ENOENT when none is called that (the order stays), or
 * -ENOMEM. */
int matcap_set_start_at(struct matcap_set *s, const char *name);
/* Whether the set holds a file called name (as matcap_set_start_at). */
bool matcap_set_has(const struct matcap_set *s, const char *name);

/* How a matcap tints what it multiplies, over the disk inscribed in the
 * image (its corners are never drawn): the mean chroma (max - min of R,
 * G, B) and the mean value (max of R, G, B), 0..255. */
struct matcap_tint {
	double chroma, value;
};
void matcap_measure(const struct image *img, struct matcap_tint *out);
/* The index of the set's most neutral matcap: the least chroma among
 * those bright enough to show a colour (mean value of a quarter or more;
 * among all when none is), each decoded small; the first
 * MATCAP_MEASURED_MAX in name order are measured. -1: none decodes.
 * Reads files: never on the loop thread. */
#define MATCAP_MEASURED_MAX 64
int matcap_set_most_neutral(const struct matcap_set *s);

#endif
