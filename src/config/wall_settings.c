/* [wall]'s keys checked together, once they are all read (a drop-in may
 * set columns after kiosk.ini set position). */
#include "config/wall_settings.h"
#include "util/log.h"

#include <stdio.h>
#include <string.h>

static const struct option_def *wall_key(const char *key)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].section == OPTIONS_WALL && !strcmp(option_defs[i].key, key))
			return &option_defs[i];
	return NULL;
}

/* "FILE:LINE: [wall] KEY", "the command line: [wall] KEY" or "[wall] KEY
 * (the default)": who set it. */
static void where(const struct options *o, const char *key, char *buf, size_t n)
{
	const struct option_def *d = wall_key(key);
	struct options_origin at = d ? options_origin(o, d) : (struct options_origin){0};

	if (at.file && at.line)
		snprintf(buf, n, "%s:%d: [wall] %s", at.file, at.line, key);
	else if (at.file)
		snprintf(buf, n, "%s: [wall] %s", at.file, key);
	else if (d && content_config_from_cli(&o->content, d))
		snprintf(buf, n, "the command line: --%s", d->name);
	else
		snprintf(buf, n, "[wall] %s (the default)", key);
}

int wall_settings_check(struct options *o)
{
	struct wall_layout *w = &o->content.wall;
	int said = 0;
	char at[300];

	if (w->column > w->columns || w->row > w->rows) {
		where(o, "position", at, sizeof(at));
		log_err("%s = %d,%d is outside the wall of %d columns and %d rows; "
			"expected COLUMN,ROW from 1,1 (top left) to %d,%d: this screen shows the "
			"whole picture, no wall",
			at, w->column, w->row, w->columns, w->rows, w->columns, w->rows);
		*w = (struct wall_layout){.columns = 1, .rows = 1, .column = 1, .row = 1};
		said++;
	}
	if (w->bezel > 0 && (w->screen_w <= 0 || w->screen_h <= 0)) {
		where(o, "bezel", at, sizeof(at));
		log_err("%s = %g: a bezel needs [wall] screen_size (WIDTHxHEIGHT, millimetres of "
			"one screen's picture) to turn millimetres into pixels; the bezel is taken "
			"as 0",
			at, w->bezel);
		w->bezel = 0;
		said++;
	}
	return said;
}
