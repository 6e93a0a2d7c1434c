/* The matcaps a kiosk cycles through: every PNG/JPEG of a folder, in name
 * order, or one file. Decoding happens when an entry is shown. */
#ifndef MK_MATCAP_SET_H
#define MK_MATCAP_SET_H

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

#endif
