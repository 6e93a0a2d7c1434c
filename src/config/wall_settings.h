/* [wall] as a whole: a position outside the wall, or a bezel without the
 * screen's size, is said with the file and line that set it, and the
 * kiosk falls back (the whole picture; no bezel) instead of refusing to
 * start: a screen of a wall that stays dark is worse than one showing the
 * whole model. Each key alone is checked by the table (settings.c). */
#ifndef MK_WALL_SETTINGS_H
#define MK_WALL_SETTINGS_H

#include "config/settings.h"

/* Logs each [wall] setting of o that does not hold with the others and
 * puts o's wall back to what can be shown. Returns how many were said. */
int wall_settings_check(struct options *o);

#endif
