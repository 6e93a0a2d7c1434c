/* How large the model is drawn: [scene] fit, the share of the frame its
 * silhouette fills. The renderer's camera frames the unit sphere the mesh
 * is scaled into (util/math3d.h, sphere_fit); a long or flat model fills
 * much less than that sphere does. The picture is scaled (struct view's
 * zoom) so that, at zoom 1:
 *
 * - at the start view, the silhouette's widest reach from the frame's
 *   centre, horizontally or vertically, is fit of the half-frame (for a
 *   model centred on the frame, that is: it fills fit of the frame's
 *   width or height, whichever it meets first);
 * - and over a full turn about the vertical axis (what attract mode and
 *   the left and right buttons do), no vertex leaves FRAMING_INSIDE of the
 *   half-frame: each vertex sweeps a circle about that axis, and its reach
 *   on screen over the circle is known in closed form (the tangent from the
 *   eye for the width, the circle's nearest point for the height).
 *
 * The smaller of the two scales is taken. Pinching scales from there
 * (the app's zoom is relative to it).
 *
 * framing_place does the same in the room the caption leaves, and centres
 * the outline (not the model's box or sphere: a lopsided model, a plane
 * with its tail fin, sat off-centre) at the start view in that room. */
#ifndef MK_FRAMING_H
#define MK_FRAMING_H

#include "render/render.h"

#include <stdbool.h>

/* The most of the half-frame a vertex may reach as the model turns. */
#define FRAMING_INSIDE 0.98

struct framing {
	/* The camera, from view and frame size. */
	struct quat orientation;
	bool ortho;
	double distance, sx, sy; /* eye to centre; NDC per unit of x/z and y/z */
	/* The largest |x| and |y| in normalised device coordinates at zoom 1,
	 * at the start view and over a full turn; 0 before any point. */
	double start_x, start_y, turn_x, turn_y;
	/* The outline at the start view, signed (lo x, lo y, hi x, hi y), and
	 * the lowest and highest y over a turn, in NDC at zoom 1. */
	double outline[4], turn_lo_y, turn_hi_y;
};

/* Where the model goes: the frame less the caption's box, in NDC of the
 * viewer's frame (centre and half sizes; the whole frame: 0, 0, 1, 1). */
struct framing_room {
	double cx, cy, hx, hy;
};

/* The camera of v (its orientation is the start view; its zoom is not
 * read) in a width x height frame, before any point. */
void framing_begin(struct framing *f, const struct view *v, int width, int height);
/* One vertex of the mesh, in model units (inside the unit sphere). */
void framing_add(struct framing *f, const double p[3]);
/* The zoom that fills fit (0 to 1) of the frame and keeps the turn inside;
 * 1 when no point was added. */
double framing_zoom(const struct framing *f, double fit);
/* The same in room: the zoom at which the outline at the start view fills
 * fit of the room's width or height, and over a turn stays inside
 * FRAMING_INSIDE of it, the outline's centre put at the room's (the
 * renderer shifts the picture, struct view's outline and room). outline:
 * the outline's centre in NDC at zoom 1. 1 and the centre 0 when no point
 * was added. */
double framing_place(const struct framing *f, double fit, const struct framing_room *room,
		     double outline[2]);

#endif
