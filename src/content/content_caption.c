/* The caption's pictures of a content: the [caption] one, and one for the
 * text of each of [frame] stops in the caption's style, all drawn on the
 * worker when the model loads. The loop thread only picks the one of the
 * stop shown: no text is drawn on the frame thread. */
#include "content/content.h"
#include "scene/gltf/gltf_name.h"
#include "scene/text/model_name.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The content's stop pictures are indexed as the app state's stops. */
_Static_assert(CAPTION_STOPS >= FRAME_STOPS, "a picture for every stop");

/* The name "auto" shows: the glTF's title or scene name, unless it is
 * one exporters give every file ("Scene": every Blender file), else the
 * model file's made readable (the built-in knot has none). Malloc'd, or
 * NULL. */
static char *model_name(const char *path, const char *scene)
{
	char *named = path ? gltf_model_name(path, scene) : NULL;

	if (named && !model_name_generic(named))
		return named;
	if (named)
		log_debug("%s: [caption] text = auto: '%s' names no model, the file's name shown",
			  path, named);
	free(named);
	return model_name_from_file(path);
}

/* The caption's picture, drawn here on the worker (FreeType and HarfBuzz
 * are no work for the loop thread): once per content, so per model. A
 * caption that fails is left out (the journal says why), unless strict. */
static int load_caption(struct content *s, const struct content_config *o, bool strict)
{
	char *name = o->caption.text && !strcmp(o->caption.text, "auto")
			 ? model_name(s->model_path, o->model_scene)
			 : NULL;
	int ret;

	/* The frame is not known yet: content_fit_captions says what is cut. */
	struct caption_fit fit = {.quiet = true};

	ret = caption_wanted(&o->caption)
		  ? caption_render_fit(&o->caption, name, &fit, &s->caption, NULL)
		  : -ENOENT;
	free(name);
	if (ret == -ENOENT || (ret && !strict))
		return 0;
	return ret;
}

/* Each stop's text as the caption would show it: its font, size, colour,
 * box, position and logo, the stop's text for [caption] text (shown
 * whether or not [caption] has one: the stop's text is what the stop is
 * for). The text is taken as it is: a stop named "auto" says "auto". */
static int load_stops(struct content *s, const struct content_config *o, bool strict)
{
	struct app_frame f;
	struct quat rest;

	content_app_frame(o, &f, &rest);
	for (int i = 0; i < f.stop_count && i < CAPTION_STOPS; i++) {
		struct caption_config c = o->caption;
		int ret;

		if (!f.stops[i].text[0])
			continue;
		c.text = f.stops[i].text;
		ret = caption_render_fit(&c, f.stops[i].text, &(struct caption_fit){.quiet = true},
					 &s->stop_caption[i], NULL);
		if (ret && ret != -ENOENT && strict)
			return ret;
		if (ret && ret != -ENOENT)
			log_warn("[frame] stops: stop %d's text is not shown", i + 1);
	}
	return 0;
}

int content_load_captions(struct content *s, const struct content_config *o, bool strict)
{
	int ret;

	s->caption_place = (struct caption_config){.padding = o->caption.padding,
						   .position = o->caption.position,
						   .drift = o->caption.drift};
	ret = load_caption(s, o, strict);
	if (!ret)
		ret = load_stops(s, o, strict);
	return ret;
}

/* A picture larger than the frame (less the margin round it) drawn again
 * within it; one that fits is kept as it is. */
static void fit_picture(const struct caption_config *c, const char *name, const char *what,
			const int frame[2], struct image *img)
{
	struct caption_fit fit = {frame[0], frame[1], what, false};
	struct image again;

	if (!img->rgba ||
	    (img->width <= frame[0] - 2 * c->padding && img->height <= frame[1] - 2 * c->padding))
		return;
	if (caption_render_fit(c, name, &fit, &again, NULL))
		return;
	image_release(img);
	*img = again;
}

void content_fit_captions(struct content *s, const struct content_config *o, int width, int height)
{
	int frame[2] = {o->rotation % 180 ? height : width, o->rotation % 180 ? width : height};
	char what[512];
	struct app_frame f;
	struct quat rest;

	if (width <= 0 || height <= 0)
		return;
	snprintf(what, sizeof(what), "%s%s[caption] text", s->model_path ? s->model_path : "",
		 s->model_path ? ": " : "");
	if (s->caption.rgba) {
		char *name = o->caption.text && !strcmp(o->caption.text, "auto")
				 ? model_name(s->model_path, o->model_scene)
				 : NULL;

		fit_picture(&o->caption, name, what, frame, &s->caption);
		free(name);
	}
	content_app_frame(o, &f, &rest);
	for (int i = 0; i < f.stop_count && i < CAPTION_STOPS; i++) {
		struct caption_config c = o->caption;

		c.text = f.stops[i].text;
		snprintf(what, sizeof(what), "[frame] stops: stop %d's text", i + 1);
		fit_picture(&c, f.stops[i].text, what, frame, &s->stop_caption[i]);
	}
	/* The model is fitted into the frame less the caption's box, now
	 * that its size is known. */
	content_frame(s, o, width, height);
}

void content_release_captions(struct content *s)
{
	image_release(&s->caption);
	for (int i = 0; i < CAPTION_STOPS; i++)
		image_release(&s->stop_caption[i]);
}

const struct image *content_caption(const struct content *s, int stop)
{
	if (stop >= 0 && stop < CAPTION_STOPS && s->stop_caption[stop].rgba)
		return &s->stop_caption[stop];
	return &s->caption;
}
