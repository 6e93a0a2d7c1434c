/* The screen's power in the live loop: src/state/power.c decides from the
 * schedule, blank_after and the inputs; this puts the decision on the
 * display (KMS sleep), the panel's backlight and, with cec = on, the TV.
 * It reads the wall clock (local time, and whether the kernel says it is
 * synchronised) each time it decides. */
#ifndef MK_SCREEN_H
#define MK_SCREEN_H

#include "config/screen_config.h"
#include "display/display.h"

#include <stdbool.h>
#include <stdint.h>

struct screen;

/* NULL when out of memory or when the schedule does not parse (the
 * settings checked it already: logged). The display is not owned. */
struct screen *screen_new(const struct screen_config *cfg, struct display *d, uint64_t now_ns);
void screen_free(struct screen *s);
/* An input (button, key, touch) at now_ns: it wakes a sleeping screen.
 * Returns true when it did: everything must be drawn again. */
bool screen_input(struct screen *s, uint64_t now_ns);
/* Remote control's "screen on" (as an input) or "screen off" (until an
 * input). Returns true when the screen just woke. */
bool screen_remote(struct screen *s, bool on, uint64_t now_ns);
/* Decide again at now_ns and apply a change. Returns true when the screen
 * just woke: everything must be drawn again. */
bool screen_update(struct screen *s, uint64_t now_ns);
bool screen_on(const struct screen *s);
/* When to decide again (CLOCK_MONOTONIC), or CLOCK_NEVER. */
uint64_t screen_deadline(const struct screen *s, uint64_t now_ns);

#endif
