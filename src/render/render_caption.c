/* The renderer's captions: the model's, and one a stop for the guided
 * stops, each a texture of its own (render/caption.c); the one shown is
 * the stop's where it has one, else the model's. Split from render.c,
 * which uploads the model. */
#include "render/render.h"
#include "render/render_priv.h"
#include "render/caption.h"

#include <errno.h>

int renderer_set_caption(struct renderer *r, const struct image *img,
			 const struct caption_config *c)
{
	struct caption_gl *cap = img && img->rgba ? caption_gl_new(r->gl, img, c) : NULL;

	if (img && img->rgba && !cap)
		return -EINVAL;
	caption_gl_free(r->caption);
	r->caption = cap;
	r->caption_serial = cap ? ++r->serials : 0;
	return 0;
}

int renderer_set_stop_captions(struct renderer *r, const struct image *imgs, int count,
			       const struct caption_config *c)
{
	struct caption_gl *caps[CAPTION_STOPS] = {0};
	int i;

	for (i = 0; i < count && i < CAPTION_STOPS; i++)
		if (imgs[i].rgba && !(caps[i] = caption_gl_new(r->gl, &imgs[i], c)))
			break;
	if (i < count && i < CAPTION_STOPS) {
		while (i--)
			caption_gl_free(caps[i]);
		return -EINVAL;
	}
	for (i = 0; i < CAPTION_STOPS; i++) {
		caption_gl_free(r->stop_caption[i]);
		r->stop_caption[i] = caps[i];
		r->stop_serial[i] = caps[i] ? ++r->serials : 0;
	}
	return 0;
}

void renderer_show_stop(struct renderer *r, int stop)
{
	r->stop = stop;
}

/* The picture shown: the stop's where it has one, else the caption. */
static const struct caption_gl *shown(const struct renderer *r, unsigned *serial)
{
	int i = r->stop;

	if (i >= 0 && i < CAPTION_STOPS && r->stop_caption[i]) {
		*serial = r->stop_serial[i];
		return r->stop_caption[i];
	}
	*serial = r->caption ? r->caption_serial : 0;
	return r->caption;
}

/* A stop at a hotspot shows its text beside the badge, kept on screen,
 * while the badge is before the eye and not edge-on (the depth that
 * hides a badge is the GPU's: a label of a badge that another part
 * hides still shows); else in the caption's place. */
static bool label_at(const struct renderer *r, const struct caption_gl *cap, const struct view *v,
		     int width, int height, int out[2])
{
	int size[2];

	if (r->stop < 0 || r->stop >= CAPTION_STOPS || r->stop_hotspot[r->stop] < 0 ||
	    cap != r->stop_caption[r->stop])
		return false;
	caption_gl_size(cap, size);
	return render_hotspot_label(r, v, r->stop_hotspot[r->stop], size, width, height, out);
}

unsigned renderer_caption_serial(const struct renderer *r)
{
	unsigned serial;

	shown(r, &serial);
	return serial;
}

bool renderer_caption_at(const struct renderer *r, const struct view *v, double seconds, int width,
			 int height, int out[2])
{
	unsigned serial;
	const struct caption_gl *cap = shown(r, &serial);

	if (!cap)
		return false;
	if (!label_at(r, cap, v, width, height, out))
		caption_gl_at(cap, seconds, width, height, v->rotation, out);
	return true;
}

void renderer_draw_caption(struct renderer *r, const struct view *v, double seconds, int width,
			   int height)
{
	unsigned serial;
	const struct caption_gl *cap = shown(r, &serial);

	int at[2];

	if (cap && label_at(r, cap, v, width, height, at))
		caption_gl_draw_at(cap, at, width, height, v->rotation);
	else if (cap)
		caption_gl_draw(cap, seconds, width, height, v->rotation);
}
