/* A model's own matcaps and background (content.h, content_load_look):
 * decoded on the worker with the model where they differ from what is on
 * screen, so a swap shows them with it and a step back to a model without
 * them shows kiosk.ini's again. */
#include "content/content.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static bool same(const char *a, const char *b)
{
	return a == b || (a && b && !strcmp(a, b));
}

static int dup_text(char **to, const char *from)
{
	*to = from ? strdup(from) : NULL;
	return from && !*to ? -ENOMEM : 0;
}

void content_look_release(struct content_look *l)
{
	free(l->matcap);
	free(l->matcap_first);
	free(l->background);
	memset(l, 0, sizeof(*l));
}

int content_look_copy(struct content_look *to, const struct content_look *from)
{
	struct content_look l = {0};
	int ret = dup_text(&l.matcap, from->matcap);

	if (!ret)
		ret = dup_text(&l.matcap_first, from->matcap_first);
	if (!ret)
		ret = dup_text(&l.background, from->background);
	content_look_release(to);
	if (ret)
		content_look_release(&l);
	*to = l;
	return ret;
}

int content_look_set(struct content_look *l, const struct content_config *c)
{
	struct content_look from = {c->matcap, c->matcap_first, c->background};

	return content_look_copy(l, &from);
}

int content_load_look(struct content *s, const struct content_config *c,
		      const struct content_look *shown)
{
	struct content_look want = {0};
	int ret = content_look_set(&want, c);

	if (!ret && shown &&
	    !(same(want.matcap, shown->matcap) && same(want.matcap_first, shown->matcap_first))) {
		/* Not strict: a matcap that fails is the built-in clay, said. */
		ret = content_load_matcap(c, false, s);
		s->own_look |= CONTENT_OWN_MATCAP;
		log_info("%s: shown with the matcaps %s", s->model_path,
			 s->matcap_path ? s->matcap_path : "of the built-in clay");
	}
	if (!ret && shown && !same(want.background, shown->background)) {
		const char *what = c->background ? c->background : "by default";

		ret = content_load_background(c, false, &s->background, &s->background_image);
		s->own_look |= CONTENT_OWN_BACKGROUND;
		if (c->background && background_names_image(c->background) &&
		    s->background.kind != BACKGROUND_IMAGE)
			what = "by default (its own does not load)";
		log_info("%s: shown on the background %s", s->model_path, what);
	}
	content_look_release(&s->look);
	s->look = want;
	return ret;
}

int content_upload_look(struct content *s, struct renderer *r)
{
	int ret = 0;

	if (s->own_look & CONTENT_OWN_BACKGROUND) {
		ret = renderer_set_background(r, &s->background, &s->background_image);
		image_release(&s->background_image);
	}
	if (s->own_look & CONTENT_OWN_MATCAP) {
		int m = renderer_set_matcap(r, &s->matcap);

		image_release(&s->matcap);
		ret = ret ? ret : m;
	}
	return ret;
}
