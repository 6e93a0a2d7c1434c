/* --check-config: what the settings name, loaded as the kiosk loads it.
 * A problem is one line: where the setting came from (file:line), the
 * setting, its value and the loader's own reason. */
#include "ops/check.h"
#include "ops/check_text.h"
#include "config/model_settings.h"
#include "content/content.h"
#include "content/model_list.h"
#include "content/matcap_set.h"
#include "render/background.h"
#include "scene/anim/anim.h"
#include "scene/text/caption.h"
#include "state/remote.h"
#include "state/view.h"
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
	int bad_clips;	  /* animations named that a model lacks */
	int bad_variants; /* material variants named that a model lacks */
	int bad_mqtt;	  /* [mqtt] broker or topic the client would refuse */
	int bad_texts;	  /* texts with characters no installed font has */
};

int check_model_settings(const struct content_config *cfg, FILE *out, bool stick)
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
		if (out)
			fprintf(out, "  read %s (the settings of %s)\n", ini, path);
		/* -v: each of its values, and whether the command line's is
		 * in effect over it. */
		if (model_settings_read_listed(&own, path, stick,
					       log_get_level() >= LOG_DEBUG ? out : NULL) !=
			OPTIONS_OK ||
		    own.hotspots.dropped > cfg->hotspots.dropped)
			bad++;
		/* Its hotspots' texts against the fonts (--check-config's; an
		 * import from a stick takes texts as they are). */
		else if (!stick && check_hotspot_texts(&own, &cfg->hotspots, ini))
			bad++;
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

/* [mqtt] as the client reads it at the start (it would run without
 * remote control), here with the file and line. */
static void check_mqtt(struct check *c, const struct mqtt_config *m)
{
	char host[REMOTE_HOST_MAX + 1], why[200], at[512];
	int port;

	if (!m->broker || !m->broker[0])
		return;
	if (remote_broker_parse(m->broker, host, sizeof(host), &port, 1883, why, sizeof(why))) {
		where(c->o, def_of("mqtt", "broker"), at, sizeof(at));
		log_err("%s: [mqtt] broker = %s", at, why);
		c->bad_mqtt++;
	}
	if (m->topic && m->topic[0] && remote_topic_check(m->topic, why, sizeof(why))) {
		where(c->o, def_of("mqtt", "topic"), at, sizeof(at));
		log_err("%s: [mqtt] topic = %s", at, why);
		c->bad_mqtt++;
	}
	if (m->sync && m->group && m->group[0] && remote_topic_check(m->group, why, sizeof(why))) {
		where(c->o, def_of("mqtt", "group"), at, sizeof(at));
		log_err("%s: [mqtt] group = %s", at, why);
		c->bad_mqtt++;
	}
	if (m->tls && m->ca_file && m->ca_file[0])
		found(c, "mqtt", "ca_file", m->ca_file, access(m->ca_file, R_OK) ? -errno : 0);
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

/* Where a model's setting came from: its NAME.ini where that changed it,
 * else the kiosk's file and line. */
static void where_own(const struct check *c, const struct content *s, const char *mine,
		      const char *kiosks, const char *section, const char *key, char *buf, size_t n)
{
	if (s->own && mine != kiosks && (!mine || !kiosks || strcmp(mine, kiosks)) &&
	    model_settings_path(s->model_path, buf, n))
		return;
	where(c->o, def_of(section, key), buf, n);
}

/* One animation named that the model lacks, with the names it has. */
static void no_clip(struct check *c, const char *at, const char *setting, const char *want,
		    const struct content *s)
{
	const struct mesh_anim *a = s->play->anim;
	char names[512] = "";
	size_t len = 0;

	for (size_t i = 0; i < a->clip_count && len < sizeof(names); i++)
		if (a->clips[i].name)
			len += (size_t)snprintf(names + len, sizeof(names) - len, "%s\"%s\"",
						len ? ", " : ": ", a->clips[i].name);
	log_err("%s: %s = '%s': %s has no such animation, expected auto, off, all, an index "
		"below %zu or an animation's name%s",
		at, setting, want, s->model_path, a->clip_count, names);
	c->bad_clips++;
}

/* The animations the settings name, against the clips of a model that
 * plays: the kiosk shows it still for a [scene] animation it lacks, and
 * goes on with the clip playing at a stop whose animation= it lacks. */
static void check_clips(struct check *c, const struct content_config *cfg, const struct content *s,
			const char *strict)
{
	const struct content_config *use = s->own ? s->own : cfg;
	struct frame_stop stops[FRAME_STOPS];
	char at[PATH_MAX + 16], err[256];
	int n;

	if (*strict) { /* the load's own words, with the names the file has */
		where_own(c, s, use->animation, cfg->animation, "scene", "animation", at,
			  sizeof(at));
		log_err("%s: [scene] animation = '%s': %s", at,
			use->animation ? use->animation : "auto", strict);
		c->bad_clips++;
	}
	if (!s->play)
		return; /* a still model: nothing named plays */
	n = use->frame.stops
		? frame_stops_parse(use->frame.stops, stops, FRAME_STOPS, err, sizeof(err))
		: 0;
	for (int i = 0; i < n; i++) {
		char setting[64];

		if (!stops[i].animation[0] ||
		    anim_clip_find(s->play->anim, stops[i].animation) != -2) /* all: -1 */
			continue;
		where_own(c, s, use->frame.stops, cfg->frame.stops, "frame", "stops", at,
			  sizeof(at));
		snprintf(setting, sizeof(setting), "[frame] stops (stop %d) animation", i + 1);
		no_clip(c, at, setting, stops[i].animation, s);
	}
}

/* One variant named that the model lacks, with the names it has. */
static void no_variant(struct check *c, const char *at, const char *setting, const char *want,
		       const struct content *s)
{
	char names[512];

	content_variant_names(&s->mesh, names, sizeof(names));
	log_err("%s: %s = '%s': %s has no such variant, expected one of its KHR_materials_variants "
		"(%s)",
		at, setting, want, s->model_path, names);
	c->bad_variants++;
}

/* [scene] variant and the stops' variant= against the model's variants:
 * the kiosk would show its default materials, or at a stop keep the one
 * shown. */
static void check_variants(struct check *c, const struct content_config *cfg,
			   const struct content *s)
{
	const struct content_config *use = s->own ? s->own : cfg;
	struct frame_stop stops[FRAME_STOPS];
	char at[PATH_MAX + 16], err[256], setting[64];
	int n;

	if (use->variant && content_variant_find(s, use->variant) < 0) {
		where_own(c, s, use->variant, cfg->variant, "scene", "variant", at, sizeof(at));
		no_variant(c, at, "[scene] variant", use->variant, s);
	}
	n = use->frame.stops
		? frame_stops_parse(use->frame.stops, stops, FRAME_STOPS, err, sizeof(err))
		: 0;
	for (int i = 0; i < n; i++) {
		if (!stops[i].variant[0] || content_variant_find(s, stops[i].variant) >= 0)
			continue;
		where_own(c, s, use->frame.stops, cfg->frame.stops, "frame", "stops", at,
			  sizeof(at));
		snprintf(setting, sizeof(setting), "[frame] stops (stop %d) variant", i + 1);
		no_variant(c, at, setting, stops[i].variant, s);
	}
}

/* The model loaded as the live kiosk loads it, but for a clip the
 * settings name that it lacks: the kiosk shows it still, and the check
 * says so. A load that fails for that alone is done again without the
 * clips (strict: its cause); one that fails again is the file's. */
static int load(const struct check *c, const struct content_config *cfg, const char *path,
		const struct content_look *look, struct content *s, char *strict, size_t n)
{
	struct content_config again = *cfg;
	int w = c->o->display.width, h = c->o->display.height;
	int ret = content_load_model(s, cfg, path, look, w, h);

	if (!ret)
		return 0;
	log_last_error(strict, n);
	again.anim_strict = false;
	log_clear_last_error();
	ret = content_load_model(s, &again, path, look, w, h);
	if (ret)
		strict[0] = '\0';
	return ret;
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
	c->bad_settings = check_model_settings(cfg, c->out, false);
	log_clear_last_error();
	l = model_list_new(spec);
	if (!l) {
		found(c, "scene", "model", spec, -ENOENT);
		return;
	}
	for (int i = 0; i < model_list_count(l); i++) {
		const char *path = model_list_path(l, i);
		char strict[768] = "";
		int ret;

		log_clear_last_error();
		/* A model's own matcaps and background (its NAME.ini) are
		 * opened too: those that differ from the kiosk's. */
		ret = content_look_set(&look, cfg);
		if (!ret)
			ret = load(c, cfg, path, &look, &s, strict, sizeof(strict));
		if (!ret) {
			check_own_look(c, &s);
			check_clips(c, cfg, &s, strict);
			check_variants(c, cfg, &s);
			content_release(&s);
		}
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

/* The caption laid out as the kiosk lays it out in the configured frame:
 * a warning (the file and line) says what would be cut. */
static void check_caption_fits(struct check *c, const struct caption_config *cap)
{
	const struct display_config *d = &c->o->display;
	bool turned = c->o->content.rotation % 180 != 0;
	char at[512], what[600];
	struct caption_fit fit = {turned ? d->height : d->width, turned ? d->width : d->height,
				  what, false};
	struct image img;

	if (!cap->text || !strcmp(cap->text, "auto"))
		return; /* the model's name: said as each model loads */
	where(c->o, def_of("caption", "text"), at, sizeof(at));
	snprintf(what, sizeof(what), "%s: [caption] text", at);
	if (!caption_render_fit(cap, NULL, &fit, &img, NULL))
		image_release(&img);
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
	if (!ret)
		check_caption_fits(c, cap);
}

/* -v: every value in effect with where it came from: a file and line,
 * the command line or the default (the README's promise). */
static void list_values(const struct check *c)
{
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];
		char value[256], at[PATH_MAX + 16];

		if (d->section == OPTION_CLI)
			continue;
		option_value_text(c->o, d, value, sizeof(value));
		where(c->o, d, at, sizeof(at));
		fprintf(c->out, "  [%s] %s = %s (%s)\n", options_sections[d->section].name, d->key,
			value, at);
	}
}

static int check_texts_at(struct check *c)
{
	char caption_at[512], stops_at[512];

	where(c->o, def_of("caption", "text"), caption_at, sizeof(caption_at));
	where(c->o, def_of("frame", "stops"), stops_at, sizeof(stops_at));
	return check_texts(c->o, caption_at, stops_at);
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

	/* Loaded as the live kiosk loads them: with what playback needs. */
	cfg.anim_live = cfg.anim_time < 0;
	cfg.anim_strict = true;

	list_files(&c);
	if (log_get_level() >= LOG_DEBUG)
		list_values(&c);
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
	check_mqtt(&c, &o->mqtt);
	if (c.bad_mqtt) {
		log_err("%s: [mqtt] has %d error%s (above): the kiosk would run without remote "
			"control",
			name, c.bad_mqtt, c.bad_mqtt == 1 ? "" : "s");
		return CHECK_BAD_SETTINGS;
	}
	c.bad_texts = check_texts_at(&c);
	if (o->wall_refused) {
		log_err("%s: [wall] has %d error%s (above): this screen would show the whole "
			"picture",
			name, o->wall_refused, o->wall_refused == 1 ? "" : "s");
		return CHECK_BAD_SETTINGS;
	}
	if (o->content.hotspots.dropped) {
		log_err("%s: %d hotspot%s left out for the errors above", name,
			o->content.hotspots.dropped, o->content.hotspots.dropped == 1 ? "" : "s");
		return CHECK_BAD_SETTINGS;
	}
	if (c.bad_settings) {
		log_err("%s: %d model%s own settings file%s errors (above)", name, c.bad_settings,
			c.bad_settings == 1 ? "'s" : "s'", c.bad_settings == 1 ? " has" : "s have");
		return CHECK_BAD_SETTINGS;
	}
	if (c.bad_clips) {
		log_err("%s: %d animation%s named %s not in the model%s (above): the kiosk would "
			"show it still, or at a stop go on with the one playing",
			name, c.bad_clips, c.bad_clips == 1 ? "" : "s",
			c.bad_clips == 1 ? "is" : "are", c.bad_clips == 1 ? "" : "s");
		return CHECK_BAD_SETTINGS;
	}
	if (c.bad_variants) {
		log_err("%s: %d material variant%s named %s not in the model%s (above): the kiosk "
			"would show its default materials, or at a stop keep the ones shown",
			name, c.bad_variants, c.bad_variants == 1 ? "" : "s",
			c.bad_variants == 1 ? "is" : "are", c.bad_variants == 1 ? "" : "s");
		return CHECK_BAD_SETTINGS;
	}
	if (c.bad_texts) {
		log_err("%s: %d text%s would show empty boxes (above)", name, c.bad_texts,
			c.bad_texts == 1 ? "" : "s");
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
