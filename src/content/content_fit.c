/* [scene] fit: the zoom at which the model fills its share of the frame
 * less the caption's box, and where its outline goes (render/framing.h):
 * its centre at the start view at the room's centre. */
#include "content/content.h"
#include "render/framing.h"
#include "util/log.h"

#include <math.h>

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

/* The tallest of a language's pictures in the caption's band (its
 * caption, a stop's); a hotspot's text goes beside its badge, not there. */
static int pictures_height(const struct image *caption, const struct image *stops, int h)
{
	if (caption->rgba && caption->height > h)
		h = caption->height;
	for (int i = 0; i < CONTENT_HOTSPOT_CAPTION; i++)
		if (stops[i].rgba && stops[i].height > h)
			h = stops[i].height;
	return h;
}

/* The tallest caption picture the model shows, in any of its languages:
 * a switch of language never moves the model. */
static int caption_height(const struct content *s)
{
	int h = pictures_height(&s->caption, s->stop_caption, 0);

	for (int l = 0; l < s->lang_count; l++)
		if (l != s->lang_shown)
			h = pictures_height(&s->lang_spare[l].caption, s->lang_spare[l].stop, h);
	return h;
}

/* The frame less the caption's band (its box, its margin above and below
 * and its drift), in NDC of the viewer's frame; a caption over half the
 * frame leaves the model half of it. */
static struct framing_room caption_room(const struct content *s, const struct content_config *o,
					int width, int height)
{
	const struct caption_config *c = &o->caption;
	struct wall_slice slice;
	int ch = caption_height(s);
	double band, frame_h;

	/* A wall's band is the bottom (or top) row's, a share of the wall. */
	wall_slice_turned(&o->wall, o->rotation, width, height, &slice);
	frame_h = slice.height;
	bool top = c->position == CAPTION_TOP || c->position == CAPTION_TOP_LEFT ||
		   c->position == CAPTION_TOP_RIGHT;

	if (!ch || frame_h <= 0)
		return (struct framing_room){0, 0, 1, 1};
	band = 2.0 * (ch + 2 * c->padding + (c->drift ? CAPTION_DRIFT_PX : 0)) / frame_h;
	band = fmin(band, 1.0);
	return (struct framing_room){0, top ? -band / 2 : band / 2, 1, 1 - band / 2};
}

void content_frame(struct content *s, const struct content_config *o, int width, int height)
{
	struct view v = content_view(o);
	struct framing_room room;
	struct wall_slice slice;
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
	room = caption_room(s, o, width, height);
	s->zoom = framing_place(&f, o->fit > 0 ? o->fit : CONTENT_FIT_DEFAULT, &room, s->outline);
	s->room[0] = room.cx;
	s->room[1] = room.cy;
	wall_slice_turned(&v.wall, v.rotation, width, height,
			  &slice);   /* the wall's aspect, or the frame's */
	if (width > 0 && height > 0) /* in the unit render_matrices divides out */
		s->outline[0] *= sphere_fit_x_unit(v.ortho, slice.aspect);
	if (o->zoom > 0) /* --zoom: that scale, about the frame's centre as before */
		s->zoom = o->zoom, s->outline[0] = s->outline[1] = s->room[1] = 0;
	log_debug("framing: zoom %.6f, the outline's centre (%.3f, %.3f) to (%.3f, %.3f) (over a "
		  "turn %.2f x %.2f of the half-frame)",
		  s->zoom, s->outline[0], s->outline[1], s->room[0], s->room[1], f.turn_x,
		  f.turn_y);
}

void content_place_view(const struct content *s, struct view *v)
{
	for (int i = 0; i < 2; i++) {
		v->outline[i] = (float)s->outline[i];
		v->room[i] = (float)s->room[i];
	}
}
