/* The renderer's hotspots (render/hotspot_gl.h): the set shown, drawn
 * after the model in its own pass, and where each is for a tap or a test.
 * Split from render.c, which uploads the model. */
#include "render/render.h"
#include "render/render_priv.h"

#include <errno.h>
#include <math.h>
#include <string.h>

int renderer_set_hotspots(struct renderer *r, const struct render_hotspot *hs, int count,
			  const int *stop_hotspot)
{
	for (int i = 0; i < CAPTION_STOPS; i++)
		r->stop_hotspot[i] = stop_hotspot && stop_hotspot[i] < count ? stop_hotspot[i] : -1;
	if (count > RENDER_HOTSPOTS)
		count = RENDER_HOTSPOTS;
	if (count > 0 && !r->hotspot_gl && !(r->hotspot_gl = hotspot_gl_new(r->gl)))
		return -EINVAL;
	if (count > 0)
		memcpy(r->hotspots, hs, (size_t)count * sizeof(*hs));
	r->hotspot_count = count > 0 ? count : 0;
	return 0;
}

bool renderer_hotspot_at(const struct renderer *r, const struct view *v, int width, int height,
			 int i, struct hotspot_place *out)
{
	float mv[16], proj[16];

	if (i < 0 || i >= r->hotspot_count)
		return false;
	render_matrices(v, width, height, mv, proj);
	hotspot_project(&r->hotspots[i], mv, proj, v->ortho, width, height, out);
	return true;
}

void render_draw_hotspots(struct renderer *r, const struct view *v, int width, int height)
{
	float mv[16], proj[16];

	if (!r->hotspot_gl || !r->hotspot_count)
		return;
	render_matrices(v, width, height, mv, proj);
	hotspot_gl_draw(r->hotspot_gl, r->hotspots, r->hotspot_count, mv, proj, v->ortho,
			v->rotation, width, height);
}

/* Framebuffer pixels to the turned screen's (the caption's), undoing the
 * panel's quarter turn the projection holds. */
static void to_turned(double x, double y, int width, int height, int rotation, double out[2])
{
	static const double c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
	int k = ((rotation / 90) % 4 + 4) % 4;
	double nx = 2 * x / width - 1, ny = 1 - 2 * y / height;
	double tx = c[k] * nx + sn[k] * ny, ty = -sn[k] * nx + c[k] * ny;
	int sw = rotation % 180 ? height : width, sh = rotation % 180 ? width : height;

	out[0] = (tx + 1) * 0.5 * sw;
	out[1] = (1 - ty) * 0.5 * sh;
}

bool render_hotspot_label(const struct renderer *r, const struct view *v, int i, const int size[2],
			  int width, int height, int out[2])
{
	struct hotspot_place at;
	double t[2], radius;
	int sw = v->rotation % 180 ? height : width, sh = v->rotation % 180 ? width : height;

	if (!renderer_hotspot_at(r, v, width, height, i, &at) || !at.ahead || at.fade <= 0)
		return false;
	to_turned(at.x, at.y, width, height, v->rotation, t);
	radius = hotspot_radius(r->hotspots[i].badge, sw < sh ? sw : sh);
	/* The margin: the caption's own distance from the edge would do, a
	 * few pixels more than the badge's ring. */
	hotspot_label_place(t[0], t[1], radius, size[0], size[1], sw, sh, (int)(radius / 2) + 2,
			    out);
	return true;
}

int renderer_hotspot_hit(const struct renderer *r, const struct view *v, int width, int height,
			 double fx, double fy)
{
	int sw = v->rotation % 180 ? height : width, sh = v->rotation % 180 ? width : height;
	int best = -1;
	double best_d = 0;

	for (int i = 0; i < r->hotspot_count; i++) {
		struct hotspot_place at;
		double t[2], d, reach;

		if (!renderer_hotspot_at(r, v, width, height, i, &at) || !at.ahead || at.fade <= 0)
			continue;
		to_turned(at.x, at.y, width, height, v->rotation, t);
		/* A fingertip is larger than a badge: half as much again and
		 * a few millimetres' pixels around it. */
		reach = hotspot_radius(r->hotspots[i].badge, sw < sh ? sw : sh) * 1.5 + 12;
		d = hypot(fx * sw - t[0], fy * sh - t[1]);
		if (d <= reach && (best < 0 || d < best_d))
			best = i, best_d = d;
	}
	return best;
}
