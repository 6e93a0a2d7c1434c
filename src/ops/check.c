/* --check-config: what the settings name, loaded as the kiosk loads it.
 * A problem is one line: where the setting came from (file:line), the
 * setting, its value and the loader's own reason. */
#include "ops/check.h"
#include "config/model_settings.h"
#include "content/content.h"
#include "content/model_list.h"
#include "content/matcap_set.h"
#include "render/background.h"
#include "scene/caption.h"
#include "util/image.h"
#include "util/log.h"

#include <errno.h>
#include <limits.h>
#include <string.h>
#include <unistd.h>

struct check {
	const struct options *o;
	FILE *out;
	int bad_files;
	int bad_settings; /* models' own NAME.ini files with errors */
};

int check_model_settings(const struct content_config *cfg, FILE *out)
{
	struct model_list *l = cfg->model && *cfg->model ? model_list_new(cfg->model) : NULL;
	int bad = 0;

	for (int i = 0; l && i < model_list_count(l); i++) {
		const char *path = model_list_path(l, i);
		struct content_config own;
		char ini[PATH_MAX];

		if (!model_settings_path(path, ini, sizeof(ini)) || access(ini, F_OK))
			continue;
		if (content_config_copy(&own, cfg))
			return bad + 1;
		if (model_settings_read(&own, path) != OPTIONS_OK)
			bad++;
		else if (out)
			fprintf(out, "  read %s (the settings of %s)\n", ini, path);
		content_config_release(&own);
	}
	model_list_free(l);
	return bad;
}

static const struct option_def *def_of(const char *section, const char *key)
{
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];

		if (d->section != OPTION_CLI &&
		    !strcmp(options_sections[d->section].name, section) && !strcmp(d->key, key))
			return d;
	}
	return NULL;
}

static void where(const struct options *o, const struct option_def *d, char *buf, size_t n)
{
	struct options_origin at = options_origin(o, d);

	if (at.file && at.line)
		snprintf(buf, n, "%s:%d", at.file, at.line);
	else
		snprintf(buf, n, "%s", at.file ? at.file : "the default");
}

/* ret: what the load returned; the cause is the last error it logged. */
static void found(struct check *c, const char *section, const char *key, const char *value, int ret)
{
	const struct option_def *d = def_of(section, key);
	char at[512], cause[768];

	where(c->o, d, at, sizeof(at));
	if (!ret) {
		fprintf(c->out, "  [%s] %s = %s (%s): loads\n", section, key, value, at);
		return;
	}
	log_last_error(cause, sizeof(cause));
	if (!cause[0])
		snprintf(cause, sizeof(cause), "%s", strerror(ret < 0 ? -ret : ret));
	log_err("%s: [%s] %s = '%s': %s", at, section, key, value, cause);
	c->bad_files++;
}

static int load_image(const char *path)
{
	struct image img = {0};
	int ret;

	log_clear_last_error();
	ret = image_load(path, &img);
	image_release(&img);
	return ret;
}

static void check_image(struct check *c, const char *section, const char *key, const char *path)
{
	if (path && *path)
		found(c, section, key, path, load_image(path));
}

/* A model's own matcaps and background (its NAME.ini) that the loader
 * replaced by the defaults: they do not load. */
static void check_own_look(struct check *c, const struct content *s)
{
	const struct content_config *own = s->own;
	char ini[PATH_MAX];

	if (!own || !s->own_look || !model_settings_path(s->model_path, ini, sizeof(ini)))
		return;
	if ((s->own_look & CONTENT_OWN_MATCAP) && own->matcap && !s->matcap_path) {
		log_err("%s: [scene] matcap = '%s': does not load (above)", ini, own->matcap);
		c->bad_files++;
	}
	if ((s->own_look & CONTENT_OWN_BACKGROUND) && own->background &&
	    background_names_image(own->background) && s->background.kind != BACKGROUND_IMAGE) {
		log_err("%s: [display] background = '%s': does not load (above)", ini,
			own->background);
		c->bad_files++;
	}
}

/* A folder's or list's models each (the kiosk passes over one that fails,
 * with a line in the journal, but it was named to be shown). */
static void check_models(struct check *c, const struct content_config *cfg)
{
	const char *spec = cfg->model;
	struct model_list *l;
	struct content s;
	struct content_look look = {0};

	if (!spec || !*spec)
		return; /* the built-in knot */
	c->bad_settings = check_model_settings(cfg, c->out);
	log_clear_last_error();
	l = model_list_new(spec);
	if (!l) {
		found(c, "scene", "model", spec, -ENOENT);
		return;
	}
	for (int i = 0; i < model_list_count(l); i++) {
		const char *path = model_list_path(l, i);
		int ret;

		log_clear_last_error();
		/* A model's own matcaps and background (its NAME.ini) are
		 * opened too: those that differ from the kiosk's. */
		ret = content_look_set(&look, cfg);
		if (!ret)
			ret = content_load_model(&s, cfg, path, &look, c->o->display.width,
						 c->o->display.height);
		if (!ret)
			check_own_look(c, &s);
		if (!ret)
			content_release(&s);
		found(c, "scene", "model", path, ret);
	}
	model_list_free(l);
	content_look_release(&look);
}

static void check_matcaps(struct check *c)
{
	const char *named = c->o->content.matcap, *path = named;
	struct matcap_set *set;
	int loaded = 0;

	if (!path && !(path = content_default_matcaps())) {
		log_err("[scene] matcap: none named, and no matcaps installed: the kiosk would "
			"show the built-in clay");
		c->bad_files++;
		return;
	}
	log_clear_last_error();
	set = matcap_set_open(path);
	if (!set) {
		found(c, "scene", "matcap", path, -ENOENT);
		return;
	}
	/* Every one: the kiosk cycles through them all. */
	for (int i = 0; i < matcap_set_count(set); i++) {
		const char *file = matcap_set_path(set, i);
		int ret = load_image(file);

		if (ret)
			found(c, "scene", "matcap", file, ret);
		else
			loaded++;
	}
	if (loaded == matcap_set_count(set) && loaded > 1) {
		char at[512];

		where(c->o, def_of("scene", "matcap"), at, sizeof(at));
		fprintf(c->out, "  [scene] matcap = %s (%s): its %d matcaps load\n", path, at,
			loaded);
	} else if (loaded == 1) {
		found(c, "scene", "matcap", path, 0);
	}
	matcap_set_free(set);
}

/* The caption's font, drawn once as the kiosk draws it, and its logo. */
static void check_caption(struct check *c, const struct caption_config *cap)
{
	struct caption_config font = {.text = "Ag", .size = cap->size, .font = cap->font};
	struct image img;
	int ret;

	if (!caption_wanted(cap))
		return;
	check_image(c, "caption", "logo", cap->logo);
	log_clear_last_error();
	ret = caption_render(&font, NULL, &img);
	image_release(&img);
	if (ret || cap->font)
		found(c, "caption", "font", cap->font ? cap->font : CAPTION_FONT_DEFAULT, ret);
}

static void list_files(struct check *c)
{
	const char *const *files;
	int n = options_files_read(c->o, &files);

	for (int i = 0; i < n; i++)
		fprintf(c->out, "  read %s\n", files[i]);
	if (c->o->include && *c->o->include && access(c->o->include, F_OK))
		fprintf(c->out, "  [kiosk] include = %s: none there (nothing to read over it)\n",
			c->o->include);
}

int check_config_run(const struct options *o, FILE *out)
{
	struct check c = {.o = o, .out = out};
	const char *name = o->config ? o->config : "the command line";
	struct content_config cfg = o->content;
	int maps;

	list_files(&c);
	if (o->include_ignored) {
		log_err("%s: the settings are not valid: an included file has errors (above)",
			name);
		return CHECK_BAD_SETTINGS;
	}
	check_image(&c, "material", "iridescence_ramp", cfg.material.ramp);
	check_image(&c, "material", "detail_map", cfg.material.detail_map);
	check_image(&c, "material", "displacement_map", cfg.material.height_map);
	maps = c.bad_files;
	if (maps) /* each model alone, not once more for the maps */
		cfg.material.ramp = cfg.material.detail_map = cfg.material.height_map = NULL;
	check_models(&c, &cfg);
	check_matcaps(&c);
	check_image(&c, "display", "poster", o->poster);
	if (o->content.background && background_names_image(o->content.background))
		check_image(&c, "display", "background", o->content.background);
	check_caption(&c, &o->content.caption);
	if (c.bad_settings) {
		log_err("%s: %d model%s own settings file%s errors (above)", name, c.bad_settings,
			c.bad_settings == 1 ? "'s" : "s'", c.bad_settings == 1 ? " has" : "s have");
		return CHECK_BAD_SETTINGS;
	}
	if (c.bad_files) {
		log_err("%s: the settings read, but %d file%s they name %s not load (above): the "
			"kiosk would show a stand-in (the knot, the clay matcap, the background) "
			"or, drawing offscreen, stop",
			name, c.bad_files, c.bad_files == 1 ? "" : "s",
			c.bad_files == 1 ? "does" : "do");
		return CHECK_BAD_FILE;
	}
	fprintf(out, "%s: the settings are valid, and every file they name loads\n", name);
	return 0;
}
