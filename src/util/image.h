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

/* Decode a PNG, JPEG or WebP file (found by its signature, not its name;
 * a KTX2 one is refused by name: Debian 12 and 13 ship no transcoder).
 * Returns 0, or a negative errno code after logging one line that names
 * the file and what is wrong. */
int image_load(const char *path, struct image *out);
/* The same from memory; name is used in error messages only. */
int image_decode(const char *name, const uint8_t *data, size_t size, struct image *out);

/* How large a decoded image may be: it is made smaller while it is read
 * (a box filter over the rows as they come, so the full size is never
 * held), an axis at a time by halves. */
struct image_fit {
	/* Halve an axis while its half is still at least this many pixels
	 * (the side the image is used at: what a later resample to it would
	 * keep is kept). 0: no limit. */
	int side;
	/* Then halve both while the image takes more bytes than this. 0: no
	 * limit. */
	size_t bytes;
};

/* The halvings (shifts) image_decode_fit makes of a w x h image, and the
 * size it gives (*ow x *oh, any may be NULL). */
void image_fit_shifts(int w, int h, const struct image_fit *fit, int *sx, int *sy, int *ow,
		      int *oh);
/* image_decode, made to fit (fit NULL: as image_decode; no halving:
 * the same pixels). *full_w x *full_h (may be NULL) is the file's size. */
int image_decode_fit(const char *name, const uint8_t *data, size_t size,
		     const struct image_fit *fit, struct image *out, int *full_w, int *full_h);
/* image_load, made to fit (image_decode_fit). */
int image_load_fit(const char *path, const struct image_fit *fit, struct image *out);
int image_write_png(const char *path, const struct image *img);
int image_alloc(struct image *img, int width, int height);
void image_release(struct image *img);

#endif
