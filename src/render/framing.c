#include "render/framing.h"
#include "util/math3d.h"

#include <math.h>

void framing_begin(struct framing *f, const struct view *v, int width, int height)
{
	struct wall_slice slice;
	struct sphere_fit fit;
	double t;

	/* The same camera as render_matrices: the panel's quarter turn swaps
	 * the axes after projection, which the largest of x and y ignores;
	 * a wall's screen is framed as the whole wall, the model fitted to it. */
	wall_slice_turned(&v->wall, v->rotation, width, height, &slice);
	sphere_fit_init(&fit, slice.aspect);
	*f = (struct framing){.orientation = v->orientation,
			      .ortho = v->ortho,
			      .distance = fit.distance,
			      .outline = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL},
			      .turn_lo_y = HUGE_VAL,
			      .turn_hi_y = -HUGE_VAL};
	if (v->ortho) {
		f->sx = 1.0 / (fit.aspect > 1 ? fit.aspect : 1);
		f->sy = 1.0 / (fit.aspect > 1 ? 1 : 1 / fit.aspect);
	} else {
		t = tan(fit.half_fov);
		f->sx = 1.0 / (t * fit.aspect);
		f->sy = 1.0 / t;
	}
}

static void rotate(struct quat q, const double p[3], double out[3])
{
	/* out = q p q*, expanded: p + 2w (u x p) + 2 u x (u x p). */
	double u[3] = {q.x, q.y, q.z}, c[3], cc[3];

	vec3_cross(u, p, c);
	vec3_cross(u, c, cc);
	for (int i = 0; i < 3; i++)
		out[i] = p[i] + 2 * q.w * c[i] + 2 * cc[i];
}

static void grow(double *at, double v)
{
	if (v > *at)
		*at = v;
}

/* The signed reach: the start view's outline, and the turn's y. */
static void outline_add(struct framing *f, double x, double y, double turn_lo, double turn_hi)
{
	f->outline[0] = fmin(f->outline[0], x);
	f->outline[1] = fmin(f->outline[1], y);
	f->outline[2] = fmax(f->outline[2], x);
	f->outline[3] = fmax(f->outline[3], y);
	f->turn_lo_y = fmin(f->turn_lo_y, turn_lo);
	f->turn_hi_y = fmax(f->turn_hi_y, turn_hi);
}

void framing_add(struct framing *f, const double p[3])
{
	double e[3], r, d = f->distance;

	rotate(f->orientation, p, e);
	/* e is in the camera's axes: x right, y up, z towards the eye. */
	r = hypot(e[0], e[2]);
	if (f->ortho) {
		grow(&f->start_x, fabs(e[0]) * f->sx);
		grow(&f->start_y, fabs(e[1]) * f->sy);
		grow(&f->turn_x, r * f->sx);
		grow(&f->turn_y, fabs(e[1]) * f->sy);
		outline_add(f, e[0] * f->sx, e[1] * f->sy, e[1] * f->sy, e[1] * f->sy);
		return;
	}
	/* Over a turn, y is farthest from the centre where the vertex is
	 * nearest (d - r), nearest to it where farthest (d + r). */
	outline_add(f, e[0] / (d - e[2]) * f->sx, e[1] / (d - e[2]) * f->sy,
		    e[1] / (e[1] < 0 ? d - r : d + r) * f->sy,
		    e[1] / (e[1] > 0 ? d - r : d + r) * f->sy);
	grow(&f->start_x, fabs(e[0]) / (d - e[2]) * f->sx);
	grow(&f->start_y, fabs(e[1]) / (d - e[2]) * f->sy);
	/* Over a turn the vertex sweeps a circle of radius r about the
	 * vertical through the centre, at distance d from the eye (d > 1 >=
	 * r): its widest reach is along the tangent from the eye, r over
	 * sqrt(d^2 - r^2); its highest where the circle is nearest, d - r. */
	grow(&f->turn_x, r / sqrt(d * d - r * r) * f->sx);
	grow(&f->turn_y, fabs(e[1]) / (d - r) * f->sy);
}

double framing_zoom(const struct framing *f, double fit)
{
	double start = fmax(f->start_x, f->start_y), turn = fmax(f->turn_x, f->turn_y);

	if (!(start > 0) || !(turn > 0))
		return 1.0;
	return fmin(fit / start, FRAMING_INSIDE / turn);
}

/* The largest zoom z at which a reach of z * a from the room's centre
 * stays within b; a <= 0: any. */
static double within(double a, double b)
{
	return a > 0 ? b / a : HUGE_VAL;
}

double framing_place(const struct framing *f, double fit, const struct framing_room *room,
		     double outline[2])
{
	double wx = (f->outline[2] - f->outline[0]) / 2, wy = (f->outline[3] - f->outline[1]) / 2;
	double z, in_x = FRAMING_INSIDE * room->hx, in_y = FRAMING_INSIDE * room->hy;

	outline[0] = outline[1] = 0;
	if (!(wx > 0) && !(wy > 0))
		return 1.0;
	outline[0] = (f->outline[2] + f->outline[0]) / 2;
	outline[1] = (f->outline[3] + f->outline[1]) / 2;
	z = fmin(within(wx, fit * room->hx), within(wy, fit * room->hy));
	/* Over a turn x reaches turn_x either side of the model's axis,
	 * which the shift moves by -z * outline[0]; y reaches from turn_lo_y
	 * to turn_hi_y, moved by -z * outline[1]. */
	z = fmin(z, within(f->turn_x + fabs(outline[0]), in_x));
	z = fmin(z, within(f->turn_hi_y - outline[1], in_y));
	z = fmin(z, within(outline[1] - f->turn_lo_y, in_y));
	return z;
}
