/* The hotspot placement tests' shared reading of a frame (test_hotspot_place.c,
 * test_hotspot_node.c): where the green dot was drawn. */
#ifndef HOTSPOT_FIXTURE_H
#define HOTSPOT_FIXTURE_H

#include "util/image.h"

#include <stddef.h>
#include <stdint.h>

/* The centre of the green dot's pixels (its ring and edge left out by
 * the colour), and how many there are. */
static inline int dot_centre(const struct image *f, double out[2])
{
	double sx = 0, sy = 0;
	int n = 0;

	for (int y = 0; y < f->height; y++)
		for (int x = 0; x < f->width; x++) {
			const uint8_t *p = f->rgba + ((size_t)y * (size_t)f->width + (size_t)x) * 4;

			if (p[1] > 200 && p[0] < 60 && p[2] < 60) {
				sx += x + 0.5, sy += y + 0.5;
				n++;
			}
		}
	if (n) {
		out[0] = sx / n;
		out[1] = sy / n;
	}
	return n;
}

#endif
