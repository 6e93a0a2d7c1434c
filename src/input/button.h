/* One push button as a pure state machine: debounced edges with their
 * timestamps in, app events out, and the time at which it must be asked
 * again without an edge (to settle a bounce, for a long press or a
 * repeat). It knows no GPIO, so the tests drive it with made-up times.
 *
 * Debouncing: the first edge after a quiet line counts at once (a press
 * feels instant); edges that follow within the window of the previous
 * edge are bounce and ignored. When a burst ends on the other level than
 * the one reported (a tap shorter than the window, or a missed edge), that
 * level is taken once the line has been quiet for the window. A press and
 * a release that bounce each give exactly one event. */
#ifndef MK_BUTTON_H
#define MK_BUTTON_H

#include "input/action.h"
#include "util/clock.h"

#include <stdbool.h>
#include <stdint.h>

/* The most events one call can produce. */
#define BUTTON_MAX_EVENTS 8

struct button_config {
	/* What a press does. A turn lasts while the button is held. */
	enum app_action press;
	/* ACTION_NONE: none. Otherwise a press held for long_ns does this
	 * instead, and a shorter one does press as a tap when released. */
	enum app_action long_press;
	uint64_t debounce_ns; /* 0: every edge counts */
	uint64_t long_ns;     /* long press; also the delay before repeats */
	/* Hold-to-repeat for actions that are not turns and have no long
	 * press: once held for long_ns, the press again every repeat_ns.
	 * 0: no repeat. */
	uint64_t repeat_ns;
};

struct button {
	struct button_config cfg;
	bool raw;  /* the level of the last edge seen */
	bool down; /* the debounced level, as reported */
	/* This press gives nothing on release: its long action fired, or it
	 * was already down at start-up. */
	bool spent;
	uint64_t edge_ns; /* the last edge seen, bounce or not */
	uint64_t hold_ns; /* next long press or repeat while down; CLOCK_NEVER */
	bool seen_edge;
};

/* down: the level the line has now (a button held at start-up is taken
 * as already down and does nothing until released and pressed again). */
void button_init(struct button *b, const struct button_config *cfg, bool down);
/* An edge at time_ns to level down (true: pressed, after any active-low
 * inversion). Writes up to BUTTON_MAX_EVENTS into out; returns the count. */
int button_edge(struct button *b, uint64_t time_ns, bool down, struct app_event *out);
/* Time passed to now_ns with no edge: settle, long press, repeat. */
int button_timeout(struct button *b, uint64_t now_ns, struct app_event *out);
/* When button_timeout has something to do, or CLOCK_NEVER. */
uint64_t button_deadline(const struct button *b);
/* The line went away: release what is held, so nothing turns forever. */
int button_lost(struct button *b, uint64_t now_ns, struct app_event *out);

#endif
