/* The caption's pictures of a content: the [caption] one, and one for the
 * text of each of [frame] stops in the caption's style, in each language
 * of [caption] languages (config/lang_text.h), all drawn on the worker
 * when the model loads. The loop thread only picks the one of the stop
 * and the language shown: no text is drawn on the frame thread. */
#include "content/content.h"
#include "render/render.h"
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

/* The languages of c ([caption] languages), at least one (NULL: none
 * named); the count. A list that does not parse was refused with its
 * file and line when it was read. */
int content_languages(const struct content_config *c, char codes[LANG_MAX][LANG_CODE_MAX])
{
	char err[128];
	int n = lang_list_parse(c->caption.languages, codes, err, sizeof(err));

	return n > 0 ? n : 0;
}

/* Language l's [caption] (its text in l, else the first's). */
static struct caption_config caption_in(const struct content_config *o,
					char codes[LANG_MAX][LANG_CODE_MAX], int n, int l)
{
	struct caption_config c = o->caption;
	const char *t = n ? lang_text_get(&o->texts, "caption", "text", codes[l], codes[0]) : NULL;

	c.text = t ? (char *)t : c.text;
	c.lang = n ? codes[l] : NULL;
	return c;
}

/* Stop index's text in lang (else first) when the stop names a hotspot
 * and has no text of its own: its hotspot's, malloc'd; else NULL. */
static char *hotspot_stop_text(const struct content_config *o, int index, const char *lang,
			       const char *first)
{
	struct frame_stop stops[FRAME_STOPS];
	char err[200];
	int n = frame_stops_parse(o->frame.stops, stops, FRAME_STOPS, err, sizeof(err)), at = -1;
	const char *t = "";

	if (index >= 0 && index < n && !stops[index].text[0] && stops[index].hotspot[0])
		at = hotspot_find(&o->hotspots, stops[index].hotspot);
	if (at >= 0)
		t = hotspot_text(&o->hotspots.items[at], lang, first);
	return *t ? strdup(t) : NULL;
}

/* Stop i's text in l: the translated [frame] stops[l]'s i-th, else the
 * first language's, else its hotspot's in l (a stop at a hotspot without
 * a text of its own), else the stop's own. Malloc'd or NULL (the own). */
static char *stop_text_in(const struct content_config *o, char codes[LANG_MAX][LANG_CODE_MAX],
			  int n, int l, int i)
{
	const char *t = n ? lang_text_get(&o->texts, "frame", "stops", codes[l], NULL) : NULL;
	char *own = t ? lang_stop_text(t, i) : NULL;

	if (!own && n && (t = lang_text_get(&o->texts, "frame", "stops", codes[0], NULL)))
		own = lang_stop_text(t, i);
	if (!own && n)
		own = hotspot_stop_text(o, i, codes[l], codes[0]);
	return own;
}

/* The slots of language l's pictures. */
static struct image *caption_slot(struct content *s, int l)
{
	return l == s->lang_shown ? &s->caption : &s->lang_spare[l].caption;
}

struct image *content_stop_slots(struct content *s, int l)
{
	return l == s->lang_shown ? s->stop_caption : s->lang_spare[l].stop;
}

/* The caption's picture, drawn here on the worker (FreeType and HarfBuzz
 * are no work for the loop thread): once per content, so per model. A
 * caption that fails is left out (the journal says why), unless strict. */
static int load_caption(struct content *s, const struct content_config *o,
			const struct caption_config *c, struct image *out, bool strict)
{
	char *name =
	    c->text && !strcmp(c->text, "auto") ? model_name(s->model_path, o->model_scene) : NULL;
	int ret;

	/* The frame is not known yet: content_fit_captions says what is cut. */
	struct caption_fit fit = {.quiet = true};

	ret = caption_wanted(c) ? caption_render_fit(c, name, &fit, out, NULL) : -ENOENT;
	free(name);
	if (ret == -ENOENT || (ret && !strict))
		return 0;
	return ret;
}

/* Each stop's text as the caption would show it: its font, size, colour,
 * box, position and logo, the stop's text for [caption] text (shown
 * whether or not [caption] has one: the stop's text is what the stop is
 * for). The text is taken as it is: a stop named "auto" says "auto". */
static int load_stops(struct content *s, const struct content_config *o,
		      char codes[LANG_MAX][LANG_CODE_MAX], int n, int l, bool strict)
{
	struct caption_config c = caption_in(o, codes, n, l);
	struct app_frame f;
	struct quat rest;

	content_app_frame(o, &f, &rest);
	for (int i = 0; i < f.stop_count && i < CAPTION_STOPS; i++) {
		char *own = stop_text_in(o, codes, n, l, i);
		int ret;

		c.text = own ? own : f.stops[i].text;
		ret = c.text[0]
			  ? caption_render_fit(&c, c.text, &(struct caption_fit){.quiet = true},
					       &content_stop_slots(s, l)[i], NULL)
			  : 0;
		free(own);
		if (ret && ret != -ENOENT && strict)
			return ret;
		if (ret && ret != -ENOENT)
			log_warn("[frame] stops: stop %d's text is not shown", i + 1);
	}
	return 0;
}

/* Which language is shown first: --lang's, else the first. */
static int first_shown(const struct content_config *o, char codes[LANG_MAX][LANG_CODE_MAX], int n)
{
	for (int l = 0; o->lang && l < n; l++)
		if (!strcasecmp(codes[l], o->lang))
			return l;
	if (o->lang)
		log_warn("--lang %s: not one of [caption] languages = %s; the first is shown",
			 o->lang, o->caption.languages ? o->caption.languages : "(none)");
	return 0;
}

/* All of a content's caption pictures together, at most: each language's
 * caption and stops (a model's NAME.ini may set six languages of nine
 * full-frame pictures each: 450 MiB at 1920x1080). */
#define CAPTION_PICTURES_MAX (64 << 20)

static size_t pictures_bytes(const struct content *s)
{
	size_t n = (size_t)s->caption.width * s->caption.height;

	for (int i = 0; i < CAPTION_STOPS; i++)
		n += (size_t)s->stop_caption[i].width * s->stop_caption[i].height;
	for (int l = 0; l < LANG_MAX; l++) {
		n += (size_t)s->lang_spare[l].caption.width * s->lang_spare[l].caption.height;
		for (int i = 0; i < CAPTION_STOPS; i++)
			n += (size_t)s->lang_spare[l].stop[i].width *
			     s->lang_spare[l].stop[i].height;
	}
	return n * 4;
}

/* Language l's pictures into the shown slots, the shown ones into the
 * old language's spare slot: a swap, nothing drawn. */
static void swap_in(struct content *s, int l)
{
	struct content_lang *old = &s->lang_spare[s->lang_shown], *now = &s->lang_spare[l];

	old->caption = s->caption;
	memcpy(old->stop, s->stop_caption, sizeof(old->stop));
	s->caption = now->caption;
	memcpy(s->stop_caption, now->stop, sizeof(s->stop_caption));
	memset(now, 0, sizeof(*now));
	s->lang_shown = l;
}

/* The languages past the budget (of the count drawn) left out, the last
 * first, never the first: next-language passes them by. Said once. */
static void within_budget(struct content *s, int drawn)
{
	int had = drawn;

	while (drawn > 1 && pictures_bytes(s) > CAPTION_PICTURES_MAX) {
		int l = --drawn;

		if (l == s->lang_shown)
			swap_in(s, 0);
		image_release(&s->lang_spare[l].caption);
		for (int i = 0; i < CAPTION_STOPS; i++)
			image_release(&s->lang_spare[l].stop[i]);
	}
	if (drawn == had)
		return;
	s->lang_count = drawn;
	log_warn("%s: [caption] languages: only the first %d are shown; with the next, the "
		 "captions' pictures would take more than %d MiB",
		 s->model_path ? s->model_path : "the model", drawn, CAPTION_PICTURES_MAX >> 20);
}

int content_load_captions(struct content *s, const struct content_config *o, bool strict)
{
	char codes[LANG_MAX][LANG_CODE_MAX];
	int n = content_languages(o, codes), ret = 0;

	s->caption_place = (struct caption_config){.padding = o->caption.padding,
						   .position = o->caption.position,
						   .drift = o->caption.drift};
	s->lang_count = n;
	s->lang_shown = first_shown(o, codes, n);
	s->caption_frame[0] = s->caption_frame[1] = 0; /* not laid out for a frame yet */
	for (int l = 0; l < (n ? n : 1) && !ret && s->lang_count >= l; l++) {
		struct caption_config c = caption_in(o, codes, n, l);

		ret = load_caption(s, o, &c, caption_slot(s, l), strict);
		if (!ret)
			ret = load_stops(s, o, codes, n, l, strict);
		if (!ret && n)
			within_budget(s, l + 1);
	}
	return ret;
}

/* A picture drawn again within the frame (less the margin round it):
 * wrapped to its width, cut to its height. */
static void fit_picture(const struct caption_config *c, const char *name, const char *what,
			const int frame[2], struct image *img)
{
	struct caption_fit fit = {frame[0], frame[1], what, false};
	struct image again;

	if (!img->rgba)
		return;
	if (caption_render_fit(c, name, &fit, &again, NULL))
		return;
	image_release(img);
	*img = again;
}

/* Language l's pictures fitted to frame. */
static void fit_language(struct content *s, const struct content_config *o,
			 char codes[LANG_MAX][LANG_CODE_MAX], int n, int l, const int frame[2])
{
	struct caption_config c = caption_in(o, codes, n, l);
	char what[512];
	struct app_frame f;
	struct quat rest;

	snprintf(what, sizeof(what), "%s%s[caption] text%s%s%s", s->model_path ? s->model_path : "",
		 s->model_path ? ": " : "", n ? "[" : "", n ? codes[l] : "", n ? "]" : "");
	if (caption_slot(s, l)->rgba) {
		char *name = c.text && !strcmp(c.text, "auto")
				 ? model_name(s->model_path, o->model_scene)
				 : NULL;

		fit_picture(&c, name, what, frame, caption_slot(s, l));
		free(name);
	}
	content_app_frame(o, &f, &rest);
	for (int i = 0; i < f.stop_count && i < CAPTION_STOPS; i++) {
		char *own = stop_text_in(o, codes, n, l, i);

		c.text = own ? own : f.stops[i].text;
		snprintf(what, sizeof(what), "[frame] stops: stop %d's text", i + 1);
		fit_picture(&c, c.text, what, frame, &content_stop_slots(s, l)[i]);
		free(own);
	}
}

void content_fit_captions(struct content *s, const struct content_config *o, int width, int height)
{
	int frame[2] = {o->rotation % 180 ? height : width, o->rotation % 180 ? width : height};
	char codes[LANG_MAX][LANG_CODE_MAX];
	int n = content_languages(o, codes);

	/* Drawn for this frame already: a caption is laid out once a frame. */
	if (width <= 0 || height <= 0 ||
	    (s->caption_frame[0] == frame[0] && s->caption_frame[1] == frame[1]))
		return;
	for (int l = 0; l < (s->lang_count ? s->lang_count : 1); l++)
		fit_language(s, o, codes, n, l, frame);
	if (s->lang_count)
		within_budget(s, s->lang_count);
	/* The model is fitted into the frame less the caption's box, now
	 * that the pictures' sizes in every language are known. */
	content_frame(s, o, width, height);
	s->caption_frame[0] = frame[0];
	s->caption_frame[1] = frame[1];
}

void content_release_captions(struct content *s)
{
	image_release(&s->caption);
	for (int i = 0; i < CAPTION_STOPS; i++)
		image_release(&s->stop_caption[i]);
	for (int l = 0; l < LANG_MAX; l++) {
		image_release(&s->lang_spare[l].caption);
		for (int i = 0; i < CAPTION_STOPS; i++)
			image_release(&s->lang_spare[l].stop[i]);
	}
}

int content_show_language(struct content *s, struct renderer *r, int lang)
{
	int ret;

	lang = lang >= 0 && lang < s->lang_count ? lang : 0;
	if (lang == s->lang_shown)
		return 0;
	swap_in(s, lang);
	ret = renderer_set_caption(r, &s->caption, &s->caption_place);
	if (!ret)
		ret = renderer_set_stop_captions(r, s->stop_caption, CAPTION_STOPS,
						 &s->caption_place);
	if (ret)
		log_err("[caption] languages: cannot show language %d's texts: %s", lang + 1,
			strerror(-ret));
	return ret;
}

const struct image *content_caption(const struct content *s, int stop)
{
	if (stop >= 0 && stop < CAPTION_STOPS && s->stop_caption[stop].rgba)
		return &s->stop_caption[stop];
	return &s->caption;
}
