/* A wall of screens showing one picture: [wall] columns, rows, position,
 * bezel and screen_size. Each kiosk draws its slice of one camera
 * frustum (an off-axis projection), so that the model crosses the
 * screens' borders as one object. Pure arithmetic, no GL: the renderer's
 * projection (render_matrices), the fit (render/framing.c) and the
 * content's pixel density all ask it, so they cannot disagree. */
#ifndef MK_WALL_H
#define MK_WALL_H

#include <stdbool.h>
#include <stddef.h>

#define WALL_MAX       16  /* columns or rows */
#define WALL_BEZEL_MAX 200 /* millimetres */

/* The layout as the settings give it. Zeroed, or 1x1: no wall (the whole
 * picture on this screen). */
struct wall_layout {
	int columns, rows;
	int column, row;	/* this kiosk's screen, from 1 at the top left; side by side */
	double bezel;		/* millimetres of dark frame between two pictures, both frames */
	int screen_w, screen_h; /* millimetres of one picture (the active area); 0: unset */
};

/* What this screen shows of the wall. */
struct wall_slice {
	double aspect; /* the whole wall's, width over height, gaps included */
	double width;  /* the whole wall's pixels at this screen's density */
	double height;
	double rect[4]; /* this screen's picture in the wall's NDC: x0, y0, x1, y1 */
	bool whole;	/* no wall: rect is [-1, 1]^2 and aspect this screen's */
};

/* Whether w is a wall of more than one screen. */
bool wall_active(const struct wall_layout *w);

/* The slice of w that a screen of width x height pixels (as the viewer
 * sees it, after the panel's turn) shows. A bezel needs the screen's size
 * to turn millimetres into pixels: without it the bezel counts as 0.
 * Returns 0; or -EINVAL with why filled (what was expected), and out is
 * then the whole picture on this screen, as for no wall. */
int wall_slice(const struct wall_layout *w, int width, int height, struct wall_slice *out,
	       char *why, size_t n);

/* The slice a width x height frame shows of w on a panel turned by
 * rotation degrees (struct view's): turned a quarter, it shows height x
 * width. A layout that does not hold is the whole picture (the settings
 * said why when they were read). */
void wall_slice_turned(const struct wall_layout *w, int rotation, int width, int height,
		       struct wall_slice *out);
/* The whole wall's size in pixels at this frame's density, in the
 * frame's own axes (before the panel's turn), rounded: width x height
 * with no wall. What judges how large the model is drawn (the level of
 * detail, the matcap's filter) must see the wall, not one screen. */
void wall_pixels(const struct wall_layout *w, int rotation, int width, int height, int *ww,
		 int *wh);
/* The off-axis crop: the matrix that maps the slice's rectangle onto
 * [-1, 1]^2 (x' = (2x - (x0 + x1)) / (x1 - x0), the same for y), to
 * multiply after the wall's projection. */
void wall_crop(const struct wall_slice *s, float m[16]);

#endif
