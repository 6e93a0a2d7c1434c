/* Decoded images: always 8-bit RGBA, rows top first, no padding. */
#ifndef MK_IMAGE_H
#define MK_IMAGE_H

#include <stddef.h>
#include <stdint.h>

/* Anything larger is refused before a byte is allocated: a matcap needs
 * little, and a hostile header must not make us allocate gigabytes. */
#define IMAGE_MAX_SIDE 8192

struct image {
	int width;
	int height;
	uint8_t *rgba;
};

/* Decode a PNG or JPEG file (found by its signature, not its name).
 * Returns 0, or a negative errno code after logging one line that names
 * the file and what is wrong. */
int image_load(const char *path, struct image *out);
/* The same from memory; name is used in error messages only. */
int image_decode(const char *name, const uint8_t *data, size_t size, struct image *out);
int image_write_png(const char *path, const struct image *img);
int image_alloc(struct image *img, int width, int height);
void image_release(struct image *img);

#endif
