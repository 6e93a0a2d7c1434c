/* What the settings make of the view (background colour, orientation) and
 * of the app state's frame (the stops, the rest pose): plain translations
 * of a content_config, no file read. The loader (content.c), the caption
 * (content_caption.c) and the loop (app/) read them, and the fit of a
 * model (content.c, content_coarse.c); they call nothing back. */
#include "content/content.h"
#include "render/framing.h"
#include "util/log.h"

#include <math.h>

struct view content_view(const struct content_config *o)
{
	struct view v = {.ortho = o->ortho, .rotation = o->rotation};
	struct app_frame f;
	struct quat rest;
	struct background_spec bg;
	char err[200];

	if (background_parse(o->background, &bg, err, sizeof(err)))
		background_spec_default(&bg);
	background_clear_color(&bg, v.background);

	content_app_frame(o, &f, &rest);
	v.orientation = quat_multiply(quat_from_axis_angle(1, 0, 0, f.pitch0),
				      quat_multiply(quat_from_axis_angle(0, 1, 0, f.yaw0), rest));
	return v;
}

void content_app_frame(const struct content_config *c, struct app_frame *f, struct quat *rest)
{
	char err[200];

	if (frame_to_app(&c->frame, c->yaw, c->pitch, f, err, sizeof(err))) {
		struct frame_config none;

		frame_config_defaults(&none);
		frame_to_app(&none, c->yaw, c->pitch, f, err, sizeof(err));
	}
	if (frame_base(&c->frame, rest, err, sizeof(err)))
		*rest = (struct quat){1, 0, 0, 0};
}

/* Positions of the prepared mesh as the GPU gets them: the mesh's own, or
 * the packed arrays (float32, or int16 in units of position_scale). */
static void frame_packed(struct framing *f, const struct mesh_packed *m)
{
	const void *a = m->arrays[MESH_POSITIONS];
	bool int16 = mesh_array_int16(m->format, MESH_POSITIONS);

	for (uint32_t i = 0; a && i < m->vertex_count; i++) {
		double p[3];

		for (int c = 0; c < 3; c++)
			p[c] = int16 ? fmax(((const int16_t *)a)[3 * i + c] / 32767.0, -1.0) *
					   m->position_scale
				     : ((const float *)a)[3 * i + c];
		framing_add(f, p);
	}
}

void content_fit(struct content *s, const struct content_config *o, int width, int height)
{
	struct view v = content_view(o);
	struct framing f;

	framing_begin(&f, &v, width, height);
	if (s->cached)
		frame_packed(&f, mesh_cache_entry_mesh(s->cached));
	else if (s->packed.vertex_count)
		frame_packed(&f, &s->packed);
	for (uint32_t i = 0; s->mesh.positions && i < s->mesh.vertex_count; i++) {
		const float *q = s->mesh.positions + 3 * (size_t)i;
		double p[3] = {q[0], q[1], q[2]};

		framing_add(&f, p);
	}
	s->zoom =
	    o->zoom > 0 ? o->zoom : framing_zoom(&f, o->fit > 0 ? o->fit : CONTENT_FIT_DEFAULT);
	log_debug("framing: zoom %.6f (at the start %.2f x %.2f, over a turn %.2f x %.2f of the "
		  "half-frame)",
		  s->zoom, f.start_x, f.start_y, f.turn_x, f.turn_y);
}
