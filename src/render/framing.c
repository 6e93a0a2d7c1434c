#include "render/framing.h"
#include "util/math3d.h"

#include <math.h>

void framing_begin(struct framing *f, const struct view *v, int width, int height)
{
	bool quarter = v->rotation == 90 || v->rotation == 270;
	struct sphere_fit fit;
	double t;

	/* The same camera as render_matrices: the panel's quarter turn swaps
	 * the axes after projection, which the largest of x and y ignores. */
	sphere_fit_init(&fit, quarter ? (double)height / width : (double)width / height);
	*f = (struct framing){
	    .orientation = v->orientation, .ortho = v->ortho, .distance = fit.distance};
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
		return;
	}
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
