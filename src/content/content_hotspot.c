/* A content's hotspots: its settings' [hotspot.NAME] sections made the
 * renderer's (render/hotspot_gl.h) on the worker, their points moved
 * into the mesh's unit sphere by the loader's own fit, and handed to the
 * renderer with the model. */
#include "content/content.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The loader's centring and scale (mesh.fit); a mesh without one (the
 * built-in models, already in the unit sphere) is taken as it is. */
static void fit_of(const struct mesh *m, double centre[3], double *scale)
{
	bool known = m->fit[3] > 0 && isfinite(m->fit[3]);

	for (int k = 0; k < 3; k++)
		centre[k] = known ? m->fit[k] : 0;
	*scale = known ? m->fit[3] : 1;
}

/* Which drawn hotspot each stop's picture labels; a stop naming a
 * hotspot the model lacks is said once a load (it keeps its own view). */
static void label_stops(struct content *s, const struct content_config *o)
{
	struct frame_stop stops[FRAME_STOPS];
	char err[200];
	int n = frame_stops_parse(o->frame.stops, stops, FRAME_STOPS, err, sizeof(err));

	for (int i = 0; i < CAPTION_STOPS; i++)
		s->stop_hotspot[i] = -1;
	for (int i = 0; i < n; i++) {
		int at = stops[i].hotspot[0] ? hotspot_find(&o->hotspots, stops[i].hotspot) : -1;

		if (stops[i].hotspot[0] && at < 0)
			log_err("[frame] stops: stop %d's hotspot=%s: expected the NAME of one of "
				"the model's [hotspot.NAME] sections; the stop keeps its own view",
				i + 1, stops[i].hotspot);
		s->stop_hotspot[i] = at < 0 ? -1 : content_hotspot_drawn(s, at);
	}
	for (int i = 0; i < HOTSPOTS; i++)
		s->stop_hotspot[CONTENT_HOTSPOT_CAPTION + i] = content_hotspot_drawn(s, i);
}

/* Where hotspot h is in the file's coordinates: its point, or its node's
 * origin at the pose the mesh was baked at (*node: the node's index, else
 * -1); false (said: the file, the line, the name) when the model has no
 * node of that name, and the hotspot is not drawn. */
static bool where_of(const struct content *s, const struct hotspot *h, double at[3], int *node)
{
	const struct mesh_node *n = h->has_point ? NULL : mesh_node_find(&s->mesh, h->node);

	*node = n ? (int)n->index : -1;
	if (!h->has_point && !n) {
		log_err("%s:%d: [hotspot.%s] node = %s: the model %s has no node of that name "
			"(expected the name of one of its %u named nodes); this hotspot is not "
			"shown",
			h->file, h->line, h->name, h->node, s->model_path ? s->model_path : "",
			s->mesh.node_count);
		return false;
	}
	for (int k = 0; k < 3; k++)
		at[k] = n ? n->origin[k] : h->point[k];
	return true;
}

void content_load_hotspots(struct content *s, const struct content_config *o)
{
	double centre[3], scale, at[3];
	int n = 0;

	fit_of(&s->mesh, centre, &scale);
	for (int i = 0; i < o->hotspots.count && n < CONTENT_HOTSPOTS; i++) {
		const struct hotspot *h = &o->hotspots.items[i];
		struct render_hotspot *out = &s->hotspots[n];

		if (!where_of(s, h, at, &s->hotspot_node[n]))
			continue;
		memset(out, 0, sizeof(*out));
		for (int k = 0; k < 3; k++) {
			out->point[k] = (float)((at[k] - centre[k]) * scale);
			out->normal[k] = (float)h->normal[k];
		}
		out->has_normal = h->has_normal;
		out->badge = h->look == HOTSPOT_BADGE;
		out->number = i + 1;
		memcpy(out->color, h->color, sizeof(out->color));
		s->hotspot_source[n++] = i;
	}
	s->hotspot_count = n;
	label_stops(s, o);
}

void content_hotspots_follow(struct content *s, struct renderer *r)
{
	const struct anim_play *p = s->play;
	bool moved = false;

	for (int k = 0; p && p->worlds && k < s->hotspot_count; k++) {
		int node = s->hotspot_node[k];

		if (node < 0 || (size_t)node >= p->anim->node_count)
			continue;
		/* The play's worlds are the file's; its fit is the drawn mesh's. */
		for (int c = 0; c < 3; c++)
			s->hotspots[k].point[c] =
			    (float)((p->worlds[node][12 + c] - p->center[c]) * p->scale);
		moved = true;
	}
	if (moved)
		renderer_set_hotspots(r, s->hotspots, s->hotspot_count, s->stop_hotspot);
}

/* The direction that faces the visitor at hotspot h: its normal,
 * else from the model's centre to it; after the model's base turn. */
static void facing_dir(const struct render_hotspot *h, struct quat rest, double out[3])
{
	const float *d = h->has_normal ? h->normal : h->point;
	float m[16];

	mat4_from_quat(m, rest);
	for (int r = 0; r < 3; r++)
		out[r] = m[r] * d[0] + m[4 + r] * d[1] + m[8 + r] * d[2];
}

int content_hotspot_drawn(const struct content *s, int index)
{
	for (int k = 0; k < s->hotspot_count; k++)
		if (s->hotspot_source[k] == index)
			return k;
	return -1;
}

bool content_hotspot_facing(const struct content *s, int index, struct quat rest, double *yaw,
			    double *pitch)
{
	int k = content_hotspot_drawn(s, index);
	double d[3];

	if (k < 0)
		return false;
	facing_dir(&s->hotspots[k], rest, d);
	hotspot_facing(d, yaw, pitch);
	return true;
}

/* The first of c's languages into lang, or NULL when none is named. */
static const char *first_language(const struct content_config *c, char lang[LANG_CODE_MAX])
{
	char codes[LANG_MAX][LANG_CODE_MAX];

	if (!content_languages(c, codes))
		return NULL;
	memcpy(lang, codes[0], LANG_CODE_MAX);
	return lang;
}

void content_app_frame_at(const struct content *s, const struct content_config *c,
			  struct app_frame *f, struct quat *rest)
{
	char lang[LANG_CODE_MAX];

	content_app_frame(c, f, rest);
	for (int i = 0; i < f->stop_count; i++) {
		int at =
		    f->stops[i].hotspot[0] ? hotspot_find(&c->hotspots, f->stops[i].hotspot) : -1;

		if (at >= 0)
			content_hotspot_facing(s, at, *rest, &f->stops[i].yaw, &f->stops[i].pitch);
	}
	/* next-hotspot's views: each faces its hotspot at the start zoom (one
	 * not drawn, a node the model lacks: the start view), its text the
	 * hotspot's. */
	f->hotspot_count = c->hotspots.count;
	for (int i = 0; i < c->hotspots.count && i < HOTSPOTS; i++) {
		struct frame_stop *v = &f->stops[FRAME_STOPS + i];

		memset(v, 0, sizeof(*v));
		v->yaw = f->yaw0, v->pitch = f->pitch0, v->zoom = f->zoom0;
		content_hotspot_facing(s, i, *rest, &v->yaw, &v->pitch);
		snprintf(v->text, sizeof(v->text), "%s",
			 hotspot_text(&c->hotspots.items[i], NULL, first_language(c, lang)));
	}
}

/* Hotspot i's text in language l of the n codes (none named: its own)
 * drawn into its picture's slot of l. */
static void load_text(struct content *s, const struct content_config *o,
		      char codes[LANG_MAX][LANG_CODE_MAX], int n, int l, int i)
{
	const struct hotspot *h = &o->hotspots.items[i];
	struct caption_config c = o->caption;
	char text[HOTSPOT_TEXT];
	int ret;

	snprintf(text, sizeof(text), "%s",
		 hotspot_text(h, n ? codes[l] : NULL, n ? codes[0] : NULL));
	if (!text[0])
		return;
	c.text = text;
	c.lang = n ? codes[l] : NULL;
	ret = caption_render_fit(&c, text, &(struct caption_fit){.quiet = true},
				 &content_stop_slots(s, l)[CONTENT_HOTSPOT_CAPTION + i], NULL);
	if (ret && ret != -ENOENT)
		log_warn("[hotspot.%s] text%s%s%s: not shown (the caption could not draw it)",
			 h->name, n ? "[" : "", n ? codes[l] : "", n ? "]" : "");
}

void content_load_hotspot_captions(struct content *s, const struct content_config *o)
{
	char codes[LANG_MAX][LANG_CODE_MAX];
	int n = content_languages(o, codes);

	/* lang_count: the languages drawn within the pictures' budget. */
	for (int l = 0; l < (n && s->lang_count ? s->lang_count : 1); l++)
		for (int i = 0; i < o->hotspots.count && i < HOTSPOTS; i++)
			load_text(s, o, codes, n, l, i);
}

int content_show_hotspot(const struct content *s, const struct content_config *c, int number,
			 struct renderer *r, struct view *v)
{
	struct app_frame f;
	struct quat rest;
	double yaw, pitch;

	content_app_frame(c, &f, &rest);
	if (number < 1 || number > c->hotspots.count ||
	    !content_hotspot_facing(s, number - 1, rest, &yaw, &pitch)) {
		log_err("--hotspot %d: expected the number of one of the model's %d hotspots with "
			"a point ([hotspot.NAME] sections, in the order of its files)",
			number, c->hotspots.count);
		return -EINVAL;
	}
	v->orientation = quat_multiply(quat_from_axis_angle(1, 0, 0, pitch),
				       quat_multiply(quat_from_axis_angle(0, 1, 0, yaw), rest));
	renderer_show_stop(r, CONTENT_HOTSPOT_CAPTION + number - 1);
	return 0;
}

int content_hotspot_tapped(const struct content *s, const struct renderer *r, const struct view *v,
			   int width, int height, double fx, double fy)
{
	int k = renderer_hotspot_hit(r, v, width, height, fx, fy);

	return k >= 0 && k < s->hotspot_count ? s->hotspot_source[k] + 1 : 0;
}
