/* The look: the matcaps (the set, the one it starts at) and the
 * background, kiosk.ini's and a model's own. A model's own (content.h,
 * content_load_look) are decoded on the worker with the model where they
 * differ from what is on screen, so a swap shows them with it and a step
 * back to a model without them shows kiosk.ini's again. content.c loads
 * the model and calls these; nothing here calls content.c. */
#include "content/content.h"
#include "render/bake.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef MK_MATCAP_DIR
#define MK_MATCAP_DIR "/usr/local/share/matcap-kiosk/matcaps"
#endif

const char *content_default_matcaps(void)
{
	/* Installed data first; the source tree's folder when run from it. */
	if (access(MK_MATCAP_DIR, R_OK) == 0)
		return MK_MATCAP_DIR;
	return access("matcaps", R_OK) == 0 ? "matcaps" : NULL;
}

/* The shipped folder starts with a bright matcap that reads on the
 * default background (README.md, "The first picture"); another folder in
 * name order, unless [scene] matcap_first names where. */
#define MATCAP_FIRST_SHIPPED "gold"
/* A coloured model's start under [scene] matcap_first = auto, where the
 * folder has it: the shipped neutral one. */
#define MATCAP_FIRST_NEUTRAL "pearl"

/* [scene] matcap_first = auto, the default (unset too). */
static bool first_is_auto(const struct content_config *o)
{
	return !o->matcap_first || !*o->matcap_first || !strcmp(o->matcap_first, "auto");
}

/* Whether the model is drawn in colours of its own (base colour factors,
 * a base colour texture or COLOR_0, as the loader kept them): a matcap
 * multiplies them, and gold's would turn a blue box olive. */
static bool model_coloured(const struct content_config *o, const struct mesh *m)
{
	return o->material.base_color != MATERIAL_OFF && (m->colors || m->has_colors);
}

/* Where [scene] matcap_first = auto starts the set of path, into buf (""
 * for the folder's first), said in the journal: a coloured model on a
 * neutral matcap (pearl, else the folder's least tinted, each file
 * decoded small: this runs where the model loads, off the loop thread),
 * another on gold (the shipped folder's) or the folder's first. */
static void auto_first(const struct content_config *o, const struct mesh *m,
		       const struct matcap_set *set, const char *path, char *buf, size_t n)
{
	bool coloured = model_coloured(o, m);
	int i;

	buf[0] = '\0';
	if (matcap_set_count(set) < 2)
		return;
	if (!coloured && !o->matcap)
		snprintf(buf, n, "%s", MATCAP_FIRST_SHIPPED);
	else if (coloured && matcap_set_has(set, MATCAP_FIRST_NEUTRAL))
		snprintf(buf, n, "%s", MATCAP_FIRST_NEUTRAL);
	else if (coloured && (i = matcap_set_most_neutral(set)) >= 0)
		snprintf(buf, n, "%s", strrchr(matcap_set_path(set, i), '/') + 1);
	log_info("[scene] matcap_first = auto: %s starts on %s: %s", path,
		 buf[0] ? buf : matcap_set_path(set, 0),
		 coloured ? "the model has colours of its own, and a neutral matcap keeps them"
			  : "the model has no colour of its own");
}

/* The matcap the set starts at, into buf; NULL: the folder's first. */
static const char *first_matcap(const struct content_config *o, const struct mesh *m,
				const struct matcap_set *set, const char *path, char *buf, size_t n)
{
	if (!first_is_auto(o))
		return o->matcap_first;
	if (set)
		auto_first(o, m, set, path, buf, n);
	return buf[0] ? buf : NULL;
}

static struct matcap_set *open_matcaps(const struct content_config *o, const struct mesh *m,
				       const char *path, char *first, size_t n)
{
	struct matcap_set *set = matcap_set_open(path);
	const char *name;

	first[0] = '\0';
	name = first_matcap(o, m, set, path, first, n);
	if (name != first)
		snprintf(first, n, "%s", name ? name : "");
	if (set && first[0] && matcap_set_start_at(set, first) && !first_is_auto(o))
		log_warn("[scene] matcap_first = %s: no such matcap in %s; expected one of its "
			 "file names, with or without the extension; starting at %s",
			 first, path, matcap_set_path(set, 0));
	return set;
}

int content_load_matcap(const struct content_config *o, bool strict, struct content *s)
{
	const char *path = o->matcap ? o->matcap : content_default_matcaps();
	char first[256] = "";
	int ret = -ENOENT;

	s->set = path ? open_matcaps(o, &s->mesh, path, first, sizeof(first)) : NULL;
	if (s->set)
		ret = image_load(matcap_set_path(s->set, 0), &s->matcap);
	if (ret && strict && o->matcap)
		return ret;
	if (ret) {
		log_warn("using the built-in clay matcap");
		matcap_set_free(s->set);
		s->set = NULL;
		return bake_matcap(BAKE_CLAY_RED, 256, &s->matcap);
	}
	s->matcap_path = strdup(path);
	if (first[0] && !(s->matcap_first = strdup(first)))
		return -ENOMEM;
	return s->matcap_path ? 0 : -ENOMEM;
}

int content_rescan_matcaps(struct content *s)
{
	struct matcap_set *set;

	if (!s->matcap_path)
		return -ENOENT;
	set = matcap_set_open(s->matcap_path);
	if (!set) {
		log_warn("%s: keeping the %d matcaps known before", s->matcap_path,
			 matcap_set_count(s->set));
		return -ENOENT;
	}
	/* The cycle starts where the settings said ([scene] matcap_first),
	 * while that one is there. */
	if (s->matcap_first)
		matcap_set_start_at(set, s->matcap_first);
	matcap_set_free(s->set);
	s->set = set;
	log_info("%s: %d matcaps", s->matcap_path, matcap_set_count(set));
	return 0;
}

int content_load_background(const struct content_config *o, bool strict,
			    struct background_spec *spec, struct image *img)
{
	char err[200];
	int ret = background_parse(o->background, spec, err, sizeof(err));

	memset(img, 0, sizeof(*img));
	if (ret) /* the settings checked it: a caller that did not */
		log_err("[display] background = '%s' is not valid: %s; expected %s", o->background,
			err, BACKGROUND_EXPECTED);
	if (!ret && spec->kind == BACKGROUND_IMAGE)
		ret = image_load(spec->path, img);
	spec->path = NULL; /* it pointed into o's text */
	if (!ret || strict)
		return ret;
	log_warn("[display] background: the default instead");
	background_spec_default(spec);
	return 0;
}

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
