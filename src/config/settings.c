/* What is done with one setting (parse, copy, compare, release), by the
 * table in settings_table.c. */
#include "config/settings.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double radians(double degrees)
{
	return degrees * M_PI / 180;
}

void option_defaults(struct options *o)
{
	static const struct gpio_button buttons[GPIO_BUTTONS] = {
	    {NULL, ACTION_TURN_LEFT, ACTION_NONE},
	    {NULL, ACTION_TURN_RIGHT, ACTION_NONE},
	    {NULL, ACTION_NEXT_MATCAP, ACTION_TOGGLE_CAMERA},
	};

	memset(o, 0, sizeof(*o));
	o->display.width = 1280;
	o->display.height = 720;
	o->display.render_scale = 1;
	o->content.mode = SHADING_VIEW;
	o->content.pitch = 20.0;
	o->content.yaw = -30.0;
	o->content.lod_pixels = 4.0;
	/* auto: one thread a core (issue 34). A large model is simplified in
	 * clusters on any count (scene/mesh/lod.h), so more threads cost a
	 * cluster's memory each (some 9 MB), not a model's. */
	o->content.prepare_threads = 0;
	o->content.coarse_above = 200000;
	o->content.fit = CONTENT_FIT_DEFAULT;
	o->content.caption.size = CAPTION_SIZE_DEFAULT;
	o->content.caption.padding = 12;
	o->content.caption.drift = true;
	o->content.anim_speed = 1.0;
	o->content.wall = (struct wall_layout){.columns = 1, .rows = 1, .column = 1, .row = 1};
	o->content.anim_time = -1.0; /* no --time: the rest pose */
	o->content.anim_fps = 30;
	material_config_defaults(&o->content.material);
	frame_config_defaults(&o->content.frame);
	o->log_level = LOG_INFO;
	o->app.attract_after_s = 60;
	o->app.attract_speed = radians(15);
	o->app.attract_fps = 30;
	o->app.turn_speed = radians(90);
	o->app.turn_step = radians(5);
	o->app.drag_speed = radians(180);
	o->app.long_press = ACTION_NEXT_MATCAP;
	o->buttons.debounce_ms = 10;
	o->buttons.long_press_ms = 800;
	o->knob.step = radians(15);
	o->knob.press = ACTION_SELECT;
	o->knob.long_press = ACTION_NEXT_LANGUAGE;
	memcpy(o->buttons.buttons, buttons, sizeof(buttons));
	o->camera.use = CAMERA_FEED_ON;
	o->camera.width = o->camera.height = 512;
	o->camera.view = (struct camera_view){0.5, 0.5, 0.5, false};
	o->camera.stall_s = 3;
	o->frames = 1;
	o->preview_at = -1; /* no --at: not a moment of the tour */
}

/* Strings are kept as char * or const char * (the module configs hold
 * them const); both have the same representation, and memcpy says so. */
static char *get_string(const void *field)
{
	char *s;

	memcpy(&s, field, sizeof(s));
	return s;
}

static void put_string(void *field, char *s)
{
	memcpy(field, &s, sizeof(s));
}

static void *field_of(struct options *o, const struct option_def *d)
{
	return (char *)o + d->offset;
}

static const void *const_field_of(const struct options *o, const struct option_def *d)
{
	return (const char *)o + d->offset;
}

void options_release(struct options *o)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].kind == K_STRING) {
			free(get_string(field_of(o, &option_defs[i])));
			put_string(field_of(o, &option_defs[i]), NULL);
		}
	lang_texts_release(&o->content.texts);
	options_origins_free(o);
}

int options_copy(struct options *dst, const struct options *src)
{
	int ret = 0;

	*dst = *src;
	dst->origins = NULL;
	dst->content.texts.count = 0; /* still src's: copied below */
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].kind == K_STRING)
			put_string(field_of(dst, &option_defs[i]), NULL);
	for (size_t i = 0; i < OPTION_DEFS && !ret; i++) {
		char *s;

		if (option_defs[i].kind != K_STRING)
			continue;
		s = get_string(const_field_of(src, &option_defs[i]));
		if (!s)
			continue;
		s = strdup(s);
		put_string(field_of(dst, &option_defs[i]), s);
		ret = s ? 0 : -ENOMEM;
	}
	if (!ret)
		ret = lang_texts_copy(&dst->content.texts, &src->content.texts);
	if (ret)
		options_release(dst);
	return ret;
}

/* The content part's strings: the table's string settings whose field lies
 * inside struct options' content, at their offset within it. */
static bool in_content(const struct option_def *d)
{
	size_t at = offsetof(struct options, content);

	return d->kind == K_STRING && d->offset >= at &&
	       d->offset < at + sizeof(struct content_config);
}

static size_t content_offset(const struct option_def *d)
{
	return d->offset - offsetof(struct options, content);
}

void content_config_release(struct content_config *c)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (in_content(&option_defs[i])) {
			free(get_string((char *)c + content_offset(&option_defs[i])));
			put_string((char *)c + content_offset(&option_defs[i]), NULL);
		}
	lang_texts_release(&c->texts);
}

int content_config_copy(struct content_config *dst, const struct content_config *src)
{
	int ret = 0;

	*dst = *src;
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (in_content(&option_defs[i]))
			put_string((char *)dst + content_offset(&option_defs[i]), NULL);
	for (size_t i = 0; i < OPTION_DEFS && !ret; i++) {
		char *s;

		if (!in_content(&option_defs[i]))
			continue;
		s = get_string((const char *)src + content_offset(&option_defs[i]));
		if (!s)
			continue;
		s = strdup(s);
		put_string((char *)dst + content_offset(&option_defs[i]), s);
		ret = s ? 0 : -ENOMEM;
	}
	if (!ret)
		ret = lang_texts_copy(&dst->texts, &src->texts);
	else
		dst->texts.count = 0; /* still src's: not this copy's to free */
	if (ret)
		content_config_release(dst);
	return ret;
}

static bool same_string(const char *a, const char *b)
{
	return a == b || (a && b && strcmp(a, b) == 0);
}

static bool same_value(const struct options *a, const struct options *b, const struct option_def *d)
{
	const void *x = const_field_of(a, d), *y = const_field_of(b, d);

	if (d->kind == K_STRING)
		return same_string(get_string(x), get_string(y));
	/* WxH: the height is the int after the width. */
	return memcmp(x, y, OPTION_TWO_INTS(d) ? 2 * sizeof(int) : d->size) == 0;
}

unsigned options_changed(const struct options *a, const struct options *b)
{
	unsigned changed = 0;

	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];
		const struct options_section_rule *rule;

		if (d->section == OPTION_CLI || same_value(a, b, d))
			continue;
		rule = &options_sections[d->section];
		if (rule->reload == OPTIONS_AT_START && rule->live_key &&
		    !strcmp(rule->live_key, d->key))
			continue;
		changed |= 1u << d->section;
	}
	/* A KEY[LANG] text is [caption]'s or [frame]'s: both apply at once. */
	if (!lang_texts_same(&a->content.texts, &b->content.texts))
		changed |= 1u << OPTIONS_CAPTION;
	return changed;
}

void option_accepted(const struct option_def *d, char *buf, size_t n)
{
	size_t len = 0;

	switch (d->kind) {
	case K_INT:
		if (d->step > 1)
			snprintf(buf, n, "a multiple of %g from %g to %g", d->step, d->lo, d->hi);
		else
			snprintf(buf, n, "%s%sa whole number from %g to %g",
				 d->choices ? d->choices[0] : "", d->choices ? " or " : "", d->lo,
				 d->hi);
		return;
	case K_DOUBLE:
	case K_DEGREES:
		snprintf(buf, n, "%s%sa number from %g to %g", d->choices ? d->choices[0] : "",
			 d->choices ? " or " : "", d->lo, d->hi);
		return;
	case K_SIZE:
		snprintf(buf, n, "WIDTHxHEIGHT, each from %g to %g", d->lo, d->hi);
		return;
	case K_PAIR:
		snprintf(buf, n, "%s, each a whole number from %g to %g", d->arg, d->lo, d->hi);
		return;
	case K_FLAG:
		snprintf(buf, n, "true or false");
		return;
	case K_CHOICE:
	case K_LEVEL:
		buf[0] = '\0';
		for (const char *const *c = d->choices; *c && len + 1 < n; c++)
			len += (size_t)snprintf(buf + len, n - len, "%s%s",
						c == d->choices ? "" : ", ", *c);
		return;
	default:
		snprintf(buf, n, "a path");
	}
}

static bool parse_number(const char *s, double lo, double hi, double step, double *out)
{
	char *end;

	errno = 0;
	*out = strtod(s, &end);
	if (errno || end == s || *end || !(*out >= lo && *out <= hi))
		return false;
	return step == 0 || (*out == (double)(long)*out && (long)*out % (long)step == 0);
}

/* WxH (or A,B: sep) into two ints side by side (the static asserts
 * above). */
static bool parse_size(const char *s, const struct option_def *d, char *field, char sep)
{
	char w[16], h[16];
	double a, b;
	int wh[2];
	const char *x = strchr(s, sep);

	if (!x || x == s || (size_t)(x - s) >= sizeof(w) || strlen(x + 1) >= sizeof(h))
		return false;
	memcpy(w, s, (size_t)(x - s));
	w[x - s] = '\0';
	strcpy(h, x + 1);
	if (!parse_number(w, d->lo, d->hi, 1, &a) || !parse_number(h, d->lo, d->hi, 1, &b))
		return false;
	wh[0] = (int)a;
	wh[1] = (int)b;
	memcpy(field, &wh[0], sizeof(int));
	memcpy(field + sizeof(int), &wh[1], sizeof(int));
	return true;
}

static bool parse_flag(const char *s, bool *out)
{
	static const char *const yes[] = {"true", "yes", "on", "1"}, *const no[] = {"false", "no",
										    "off", "0"};

	for (int i = 0; i < 4; i++) {
		if (strcmp(s, yes[i]) == 0 || strcmp(s, no[i]) == 0) {
			*out = strcmp(s, yes[i]) == 0;
			return true;
		}
	}
	return false;
}

static bool set_number(void *p, const struct option_def *d, const char *value)
{
	double v;

	if (d->choices && strcmp(value, d->choices[0]) == 0) {
		if (d->kind == K_INT)
			*(int *)p = 0;
		else
			*(double *)p = 0;
		return true;
	}
	if (!parse_number(value, d->lo, d->hi, d->kind == K_INT ? (d->step ? d->step : 1) : 0, &v))
		return false;
	if (d->kind == K_INT)
		*(int *)p = (int)v;
	else
		*(double *)p = d->kind == K_DEGREES ? radians(v) : v;
	return true;
}

/* A choice of two may be kept as a bool (on_busy: exit_when_busy). */
static bool set_choice(void *p, const struct option_def *d, const char *value)
{
	int i = 0;

	while (d->choices[i] && strcmp(value, d->choices[i]) != 0)
		i++;
	if (!d->choices[i])
		return false;
	if (d->kind == K_LEVEL)
		*(enum log_level *)p = log_levels[i];
	else if (d->size == sizeof(bool))
		*(bool *)p = i != 0;
	else
		*(int *)p = i;
	return true;
}

bool option_set_value(struct options *o, const struct option_def *d, const char *value)
{
	void *p = field_of(o, d);
	char *copy;

	switch (d->kind) {
	case K_FLAG:
		return parse_flag(value, p);
	case K_STRING:
		copy = strdup(value);
		free(get_string(p));
		put_string(p, copy);
		return copy != NULL;
	case K_SIZE:
		return parse_size(value, d, p, 'x');
	case K_PAIR:
		return parse_size(value, d, p, ',');
	case K_CHOICE:
	case K_LEVEL:
		return set_choice(p, d, value);
	default:
		return set_number(p, d, value);
	}
}
