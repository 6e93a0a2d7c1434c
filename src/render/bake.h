/* The matcap baker: analytic materials rendered onto a sphere, so the kiosk
 * always has a matcap (even with an empty matcaps/ folder) and the shipped
 * PNGs can be rebuilt byte for byte from the recipe in matcaps/README.md.
 *
 * Conventions: pixel (px, py) of a size x size image maps to
 * x = (px + 0.5) / size * 2 - 1 and y = 1 - (py + 0.5) / size * 2 (y up);
 * the view-space normal is (x, y, sqrt(1 - x*x - y*y)) and the viewer looks
 * along -z. Outside the unit disk the rim colour is extended outward, so
 * bilinear filtering at the disk edge never pulls in a foreign colour.
 * Alpha is 255 everywhere. */
#ifndef MK_BAKE_H
#define MK_BAKE_H

#include "util/image.h"

enum bake_material {
	BAKE_CLAY_RED,
	BAKE_BLACK_SHINY,
	BAKE_SKIN,
	BAKE_GOLD,
	BAKE_CHROME_STUDIO,
	BAKE_PEARL,
	BAKE_COUNT
};

/* The file name stem ("clay-red", ...), or NULL when m is not a material. */
const char *bake_name(enum bake_material m);

/* Render material m into out (allocated here with image_alloc; release it
 * with image_release). Returns 0, or a negative errno code after logging one
 * line; out is then empty. Allocates nothing but the image and keeps no
 * state, so it is safe as the kiosk's fallback and from several threads. */
int bake_matcap(enum bake_material m, int size, struct image *out);

#endif
