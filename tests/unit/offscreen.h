/* The offscreen display the goldens use, for the unit tests that draw:
 * OSMesa where Mesa has it, else EGL headless. Each unit test is a program
 * of its own, so this header defines what it needs once per test.
 * The display is left open at the end: Mesa's context teardown leaks
 * inside the library, which LeakSanitizer is told here. */
#ifndef MK_TEST_OFFSCREEN_H
#define MK_TEST_OFFSCREEN_H

#include "display/display.h"

#include <stddef.h>

/* A current context drawing into a width x height frame, or NULL. */
static inline struct display *offscreen_open(int width, int height)
{
	struct display_config cfg = {.width = width, .height = height};
	struct display *d;

#ifdef MK_HAVE_OSMESA
	d = display_osmesa_new(&cfg);
#else
	d = display_egl_new(&cfg);
#endif
	if (d && d->begin_frame(d))
		return NULL;
	return d;
}

/* libfontconfig: FcInit's configuration, once a process, 288 bytes on
 * Debian 12 (a program of its own that only sorts fonts leaks as much);
 * the caption's fallback fonts ask it. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
	return "leak:libOSMesa\nleak:libLLVM\nleak:display_osmesa_new\nleak:display_egl_new\n"
	       "leak:libfontconfig\n";
}

#endif
