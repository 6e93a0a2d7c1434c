/* The renderer's hotspots (render/hotspot_gl.h): the set shown, drawn
 * after the model in its own pass, and where each is for a tap or a test.
 * Split from render.c, which uploads the model. */
#include "render/render.h"
#include "render/render_priv.h"

#include <errno.h>
#include <string.h>

int renderer_set_hotspots(struct renderer *r, const struct render_hotspot *hs, int count)
{
	if (count > RENDER_HOTSPOTS)
		count = RENDER_HOTSPOTS;
	if (count > 0 && !r->hotspot_gl && !(r->hotspot_gl = hotspot_gl_new(r->gl)))
		return -EINVAL;
	if (count > 0)
		memcpy(r->hotspots, hs, (size_t)count * sizeof(*hs));
	r->hotspot_count = count > 0 ? count : 0;
	return 0;
}

void renderer_set_hotspot_points(struct renderer *r, const float *points, int count)
{
	for (int i = 0; i < count && i < r->hotspot_count; i++)
		memcpy(r->hotspots[i].point, points + 3 * i, sizeof(r->hotspots[i].point));
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
