/* The arithmetic of a wall of screens: the whole wall's size in this
 * screen's pixels, and this screen's rectangle in the wall's NDC. */
#include "render/wall.h"
#include "util/math3d.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>

bool wall_active(const struct wall_layout *w)
{
	return w->columns > 1 || w->rows > 1;
}

static void slice_whole(int width, int height, struct wall_slice *out)
{
	*out = (struct wall_slice){.aspect = (double)width / height,
				   .width = width,
				   .height = height,
				   .rect = {-1, -1, 1, 1},
				   .whole = true};
}

static bool layout_valid(const struct wall_layout *w, char *why, size_t n)
{
	if (w->columns < 1 || w->columns > WALL_MAX || w->rows < 1 || w->rows > WALL_MAX) {
		snprintf(why, n, "a wall of %dx%d screens; expected 1 to %d columns and rows",
			 w->columns, w->rows, WALL_MAX);
		return false;
	}
	if (w->column < 1 || w->column > w->columns || w->row < 1 || w->row > w->rows) {
		snprintf(why, n,
			 "position %d,%d is outside the wall of %d columns and %d rows; expected "
			 "COLUMN,ROW from 1,1 (top left) to %d,%d",
			 w->column, w->row, w->columns, w->rows, w->columns, w->rows);
		return false;
	}
	if (!(w->bezel >= 0 && w->bezel <= WALL_BEZEL_MAX)) {
		snprintf(why, n, "bezel %g mm; expected 0 to %d", w->bezel, WALL_BEZEL_MAX);
		return false;
	}
	return true;
}

int wall_slice(const struct wall_layout *w, int width, int height, struct wall_slice *out,
	       char *why, size_t n)
{
	double gx = 0, gy = 0, left, top;

	if (n)
		why[0] = '\0';
	slice_whole(width, height, out);
	/* No frame yet (a display not known), a zeroed layout or 1x1: nothing
	 * to cut. */
	if (width <= 0 || height <= 0 || (!w->columns && !w->rows && !w->column && !w->row) ||
	    (w->columns == 1 && w->rows == 1 && w->column == 1 && w->row == 1))
		return 0;
	if (!layout_valid(w, why, n))
		return -EINVAL;
	/* The gap between two pictures, at each axis's own pixels per mm:
	 * a panel's pixels need not be square in millimetres. */
	if (w->bezel > 0 && w->screen_w > 0 && w->screen_h > 0) {
		gx = w->bezel * width / w->screen_w;
		gy = w->bezel * height / w->screen_h;
	}
	out->width = w->columns * (double)width + (w->columns - 1) * gx;
	out->height = w->rows * (double)height + (w->rows - 1) * gy;
	out->aspect = out->width / out->height;
	left = (w->column - 1) * (width + gx);
	top = (w->row - 1) * (height + gy); /* rows count down, NDC's y up */
	out->rect[0] = -1 + 2 * left / out->width;
	out->rect[2] = -1 + 2 * (left + width) / out->width;
	out->rect[3] = 1 - 2 * top / out->height;
	out->rect[1] = 1 - 2 * (top + height) / out->height;
	out->whole = false;
	return 0;
}

void wall_slice_turned(const struct wall_layout *w, int rotation, int width, int height,
		       struct wall_slice *out)
{
	bool quarter = rotation == 90 || rotation == 270;
	char why[200];

	wall_slice(w, quarter ? height : width, quarter ? width : height, out, why, sizeof(why));
}

void wall_pixels(const struct wall_layout *w, int rotation, int width, int height, int *ww, int *wh)
{
	bool quarter = rotation == 90 || rotation == 270;
	struct wall_slice s;

	wall_slice_turned(w, rotation, width, height, &s);
	*ww = s.whole ? width : (int)lround(quarter ? s.height : s.width);
	*wh = s.whole ? height : (int)lround(quarter ? s.width : s.height);
}

void wall_crop(const struct wall_slice *s, float m[16])
{
	double w = s->rect[2] - s->rect[0], h = s->rect[3] - s->rect[1];

	mat4_identity(m);
	m[0] = (float)(2 / w);
	m[5] = (float)(2 / h);
	m[12] = (float)(-(s->rect[0] + s->rect[2]) / w);
	m[13] = (float)(-(s->rect[1] + s->rect[3]) / h);
}
