/* What visitors did (issue 33), counted on the kiosk as a pure state
 * machine: inputs and what is shown, with their timestamps, in; counts
 * and seconds out. Nothing here leaves the kiosk but through what an
 * operator asks of it: the metrics file ([status] metrics) and --status.
 * Nothing is counted from the camera: its frames are a matcap, never
 * looked at (and never written to disk).
 *
 * Counted: presses per action and source (button, key, touch, knob);
 * visits (an input after the kiosk was idle: in attract mode, or no input
 * for idle_s); and seconds per (kind, name) slot: each stop a visitor is
 * at ("stop", "1" for the first), each hotspot a visitor stepped to or a
 * stop turned to ("hotspot", its NAME), the language shown to a visitor
 * ("language", its code), attract mode ("attract", ""; its tour of stops
 * and languages is attract mode's time), and what other parts feed
 * through visit_time_add. A zeroed struct visits is an empty one. */
#ifndef MK_VISITS_H
#define MK_VISITS_H

#include "input/gesture.h"
#include "input/input.h"

#include <stdbool.h>
#include <stdint.h>

/* Touch gestures that are no action, counted beside the actions. */
enum { VISITS_DRAG = ACTION_COUNT, VISITS_PINCH, VISITS_TAP, VISITS_ACTIONS };

#define VISITS_SLOTS 64 /* (kind, name) slots; time for more is dropped, and counted */
#define VISITS_KIND  16
#define VISITS_NAME  64
/* Idle after this long without input when attract mode is off. */
#define VISITS_IDLE_S 60.0

struct visit_slot {
	char kind[VISITS_KIND]; /* "stop", "attract", "hotspot", "language" ... */
	char name[VISITS_NAME]; /* which one: "2", "de", a hotspot's name; "" */
	double seconds;
};

/* What the kiosk shows, for visits_observe. */
struct visit_view {
	/* The app's stop (-1: none); FRAME_STOPS + i is hotspot i's view
	 * (next-hotspot, a tap on a badge): its hotspot's time, no stop's. */
	int stop;
	bool attract;
	const char *hotspot; /* the hotspot whose text is shown; NULL or "": none */
	const char *lang;    /* the language's code shown; NULL or "": none named */
};

struct visits {
	long presses[INPUT_KINDS][VISITS_ACTIONS];
	long count; /* visits */
	bool any_input;
	uint64_t last_input_ns;
	/* What was shown since observed_ns (0: nothing observed yet). */
	uint64_t observed_ns;
	int stop; /* observed + 1: 0 none, so that zeroed is "none" */
	bool attract;
	char hotspot[VISITS_NAME]; /* observed; "": none */
	char lang[VISITS_NAME];	   /* observed; "": none */
	bool touch_moving;	   /* a drag or pinch counted, not yet ended */
	struct visit_slot slots[VISITS_SLOTS];
	int slot_count;
	double dropped_s; /* seconds of slots that did not fit */
};

/* "none" ... "next-language", then "drag", "pinch", "tap". */
const char *visits_action_name(int action);
/* A button, key or knob event from a source of that kind; a release is
 * an input but no press. idle_s: [kiosk] attract_after (0: VISITS_IDLE_S). */
void visits_press(struct visits *v, enum input_kind kind, const struct app_event *ev,
		  double idle_s);
/* A touch gesture: a drag or pinch counts once until its end, a double
 * tap is reset, a long press long_press. */
void visits_touch(struct visits *v, const struct gesture *g, enum app_action long_press,
		  double idle_s);
/* What the kiosk shows at now_ns. The time since the last call goes to
 * what was shown then. */
void visits_observe(struct visits *v, uint64_t now_ns, const struct visit_view *w);
/* seconds more at (kind, name): for hotspots, languages and the like.
 * 0, or -1 when there is no room (the time is in dropped_s). */
int visit_time_add(struct visits *v, const char *kind, const char *name, double seconds);
/* The seconds at (kind, name); 0 when never there. */
double visits_seconds(const struct visits *v, const char *kind, const char *name);

#endif
