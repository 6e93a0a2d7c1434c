/* Texture work on the CPU, at load time: sampling a height map where the
 * vertices are, and bringing material maps to one size (GLES2 repeats and
 * mipmaps only power-of-two textures). Images are 8-bit RGBA (image.h). */
#ifndef MK_TEXTURE_H
#define MK_TEXTURE_H

#include "util/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bilinear sample at (u, v), wrapping (glTF's default REPEAT), with v = 0
 * the image's top row, as glTF and the renderer's upload have it. Each
 * channel is returned in [0, 1]. A non-finite coordinate reads texel 0. */
void texture_sample(const struct image *img, double u, double v, double out[4]);

/* Height as the luma of the map: 0.30 R + 0.59 G + 0.11 B, in [0, 1]. */
double texture_height(const struct image *img, double u, double v);

/* Resample src into a new w x h image (bilinear at texel centres,
 * wrapping). Returns 0 or -ENOMEM / -EINVAL. */
int texture_resample(const struct image *src, int w, int h, struct image *out);

/* [scene] texture_memory = auto: a quarter of ram bytes (on a 1 GB board
 * 256 MiB, on 512 MB 128), within [16 MiB, 256 MiB]: the textures share
 * it, and the board keeps the rest for the kernel, GPU and frames. */
size_t texture_memory_auto(uint64_t ram);
/* [scene] texture_memory in bytes: mib when > 0, else auto from the
 * board's RAM (sysinfo). */
size_t texture_memory_budget(double mib);

/* The power of two nearest to n (ties up), within [1, max]. */
int texture_pot(int n, int max);

#ifdef __cplusplus
}
#endif

#endif
