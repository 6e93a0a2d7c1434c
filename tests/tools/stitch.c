/* Puts the pictures of a wall's screens side by side, as the wall shows
 * them: COLUMNS x ROWS pictures of one size, given row by row from the top
 * left, GAP_X and GAP_Y pixels of black between two (the bezels). The
 * seam test compares it with the whole wall drawn as one picture; the
 * golden wall-2x2 is one.
 *   stitch OUT.png COLUMNS ROWS GAP_X GAP_Y IN.png... */
#include "util/image.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int number(const char *s, int lo, int hi)
{
	char *end;
	long v = strtol(s, &end, 10);

	return *s && !*end && v >= lo && v <= hi ? (int)v : -1;
}

/* Picture i at its place in the wall. */
static void place(struct image *wall, const struct image *in, int x, int y)
{
	for (int row = 0; row < in->height; row++)
		memcpy(wall->rgba + ((size_t)(y + row) * wall->width + x) * 4,
		       in->rgba + (size_t)row * in->width * 4, (size_t)in->width * 4);
}

static int stitch(const char *out, int columns, int rows, int gx, int gy, char **paths)
{
	struct image wall = {0}, in;
	int w = 0, h = 0, ret = 0;

	for (int i = 0; i < columns * rows && !ret; i++) {
		if ((ret = image_load(paths[i], &in)))
			break;
		if (!wall.rgba && (w = in.width, h = in.height,
				   (ret = image_alloc(&wall, columns * w + (columns - 1) * gx,
						      rows * h + (rows - 1) * gy))))
			break;
		if (in.width != w || in.height != h) {
			fprintf(stderr, "stitch: %s is %dx%d; expected %dx%d as the first\n",
				paths[i], in.width, in.height, w, h);
			ret = 1;
		} else {
			if (i == 0) /* black bezels, opaque */
				for (size_t p = 0; p < (size_t)wall.width * wall.height; p++)
					memcpy(wall.rgba + 4 * p, "\0\0\0\377", 4);
			place(&wall, &in, (i % columns) * (w + gx), (i / columns) * (h + gy));
		}
		image_release(&in);
	}
	if (!ret)
		ret = image_write_png(out, &wall);
	image_release(&wall);
	return ret != 0;
}

int main(int argc, char **argv)
{
	int columns = argc > 5 ? number(argv[2], 1, 16) : -1;
	int rows = argc > 5 ? number(argv[3], 1, 16) : -1;
	int gx = argc > 5 ? number(argv[4], 0, 4096) : -1;
	int gy = argc > 5 ? number(argv[5], 0, 4096) : -1;

	if (columns < 0 || rows < 0 || gx < 0 || gy < 0 || argc != 6 + columns * rows) {
		fprintf(stderr, "usage: stitch OUT.png COLUMNS ROWS GAP_X GAP_Y IN.png... "
				"(COLUMNS x ROWS pictures, row by row from the top left)\n");
		return 2;
	}
	return stitch(argv[1], columns, rows, gx, gy, argv + 6);
}
