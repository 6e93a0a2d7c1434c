/* [output.NAME] sections (config/output_settings.h). */
#include "config/output_settings.h"
#include "render/background.h"
#include "render/wall.h"
#include "util/log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PREFIX "output."

bool output_settings_section(const char *section)
{
	return !strncmp(section, PREFIX, strlen(PREFIX));
}

/* A connector's name as DRM gives it: HDMI-A-1, DSI-1, Virtual-2. */
static bool good_name(const char *name)
{
	size_t n = strlen(name);

	return n && n < sizeof(((struct output_view *)0)->name) &&
	       strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") ==
		   n;
}

/* The output called name, added when new; NULL (said) when the name is
 * bad or there are too many. */
static struct output_view *output_of(struct output_views *set, const char *path, int line,
				     const char *name)
{
	struct output_view *o = (struct output_view *)output_view_find(set, name);

	if (o)
		return o;
	if (!good_name(name)) {
		log_err("%s:%d: [output.%s]: expected a connector's name, e.g. [output.HDMI-A-2]",
			path, line, name);
		return NULL;
	}
	if (set->count == OUTPUT_VIEWS_MAX) {
		log_err("%s:%d: [output.%s]: at most %d outputs; this section is ignored", path,
			line, name, OUTPUT_VIEWS_MAX);
		return NULL;
	}
	o = &set->items[set->count++];
	output_view_defaults(o, name);
	return o;
}

static bool read_double(const char *value, double lo, double hi, double *out)
{
	char *end;
	double d = strtod(value, &end);

	if (end == value || *end || !(d >= lo && d <= hi))
		return false;
	*out = d;
	return true;
}

static bool read_look(struct output_view *o, const char *value)
{
	for (int i = 0; output_look_names[i]; i++)
		if (!strcmp(value, output_look_names[i])) {
			o->look = (enum output_look)i;
			return true;
		}
	return false;
}

static bool read_position(struct output_view *o, const char *value)
{
	int c, r, used = 0;

	if (sscanf(value, "%d ,%d%n", &c, &r, &used) != 2 || value[used] || c < 1 || c > WALL_MAX ||
	    r < 1 || r > WALL_MAX)
		return false;
	o->column = c;
	o->row = r;
	return true;
}

static bool read_flag(const char *value, bool *out)
{
	if (!strcmp(value, "yes") || !strcmp(value, "true") || !strcmp(value, "on"))
		*out = true;
	else if (!strcmp(value, "no") || !strcmp(value, "false") || !strcmp(value, "off"))
		*out = false;
	else
		return false;
	return true;
}

static bool read_background(struct output_view *o, const char *value)
{
	struct background_spec bg;
	char err[160];

	if (value[0] != '#' || strchr(value, ',') || background_parse(value, &bg, err, sizeof(err)))
		return false;
	memcpy(o->background, bg.top, sizeof(o->background));
	o->has_background = true;
	return true;
}

/* What key takes, for the error; NULL: the value was taken. */
static const char *set_value(struct output_view *o, const char *key, const char *value)
{
	double d;

	if (!strcmp(key, "view"))
		return read_look(o, value) ? NULL : "same, mirror, yaw or slice";
	if (!strcmp(key, "yaw")) {
		if (!read_double(value, -360, 360, &o->yaw))
			return "degrees from -360 to 360";
		return NULL;
	}
	if (!strcmp(key, "position"))
		return read_position(o, value) ? NULL : "COLUMN,ROW of [wall], from 1,1";
	if (!strcmp(key, "rotation")) {
		if (!read_double(value, 0, 270, &d) || (int)d % 90 || d != (int)d)
			return "0, 90, 180 or 270";
		o->rotation = (int)d;
		return NULL;
	}
	if (!strcmp(key, "caption"))
		return read_flag(value, &o->caption) ? NULL : "yes or no";
	if (!strcmp(key, "background"))
		return read_background(o, value) ? NULL : "a colour #rrggbb";
	return "";
}

bool output_settings_key(struct output_views *set, const char *path, int line, const char *section,
			 const char *key, const char *value)
{
	struct output_view *o = output_of(set, path, line, section + strlen(PREFIX));
	const char *expected;

	if (!o)
		return false;
	expected = set_value(o, key, value);
	if (expected && !expected[0])
		log_err("%s:%d: [%s] has no key '%s'; it takes view, yaw, position, rotation, "
			"caption and background",
			path, line, section, key);
	else if (expected)
		log_err("%s:%d: [%s] %s = '%s': expected %s; it keeps its default", path, line,
			section, key, value, expected);
	return !expected;
}
