/* The display a C bench draws on, by the backend named on its command
 * line: osmesa (where built) or egl-headless; NULL for another name. */
#ifndef MK_BENCH_DISPLAY_H
#define MK_BENCH_DISPLAY_H

#include "display/display.h"

#include <string.h>

static inline struct display *bench_display_open(const char *name, struct display_config *cfg)
{
#ifdef MK_HAVE_OSMESA
	if (!strcmp(name, "osmesa"))
		return display_osmesa_new(cfg);
#endif
	if (!strcmp(name, "egl-headless"))
		return display_egl_new(cfg);
	return NULL;
}

#endif
