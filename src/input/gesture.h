/* Touch gestures as a pure state machine: frames of touch points (what
 * the touchscreen reports between two SYN_REPORTs) with their timestamps
 * in, gestures out, and the time at which it must be asked again without
 * a frame (for a long press). It knows no evdev, so the tests drive it with
 * made-up touches.
 *
 * One finger that moves drags; two fingers pinch; a short still touch is a
 * tap, and two taps close together a double tap; a still touch held long
 * enough is a long press. Positions are fractions of the screen (0..1, x to
 * the right, y down, after the panel's rotation: gesture_map). */
#ifndef MK_GESTURE_H
#define MK_GESTURE_H

#include "util/clock.h"

#include <stdbool.h>
#include <stdint.h>

/* Type-B multitouch devices have at most this many slots worth following. */
#define GESTURE_MAX_POINTS 10
/* The most gestures one call can produce. */
#define GESTURE_MAX_EVENTS 1

struct gesture_config {
	uint64_t tap_ns;	/* the longest touch that is still a tap */
	uint64_t double_tap_ns; /* the longest gap between the ends of two taps */
	uint64_t long_ns;	/* a still touch this long is a long press */
	double slop;		/* movement (screen fraction) under which a touch is still */
};

/* Sensible defaults: 250 ms tap, 350 ms double tap, 700 ms long press,
 * 2 % of the screen of slop. */
void gesture_config_defaults(struct gesture_config *cfg);

struct gesture_point {
	int id; /* the contact's tracking id: the same finger keeps it */
	double x, y;
};

enum gesture_kind {
	GESTURE_DRAG,	    /* dx, dy: movement since the previous frame */
	GESTURE_PINCH,	    /* scale: finger distance now over the previous frame's */
	GESTURE_TAP,	    /* a short still touch */
	GESTURE_DOUBLE_TAP, /* the second of two taps in a row (the first was a tap) */
	GESTURE_LONG_PRESS, /* a still touch held for long_ns; its release does nothing */
	GESTURE_END,	    /* every finger lifted after a drag or a pinch */
};

struct gesture {
	enum gesture_kind kind;
	uint64_t time_ns;
	double dx, dy;
	double scale;
	/* GESTURE_TAP: where, in fractions of the screen as it is seen
	 * (turned with the panel), and the hotspot badge there, 1 + its
	 * index, as the loop's hit test found it (app/kiosk.c); 0: none. */
	double x, y;
	int badge;
};

struct gesture_state {
	struct gesture_config cfg;
	struct gesture_point prev[GESTURE_MAX_POINTS];
	int prev_n;
	uint64_t start_ns; /* the first finger of this touch came down */
	double start_x, start_y;
	bool moved;	      /* beyond the slop: a drag, not a tap */
	bool multi;	      /* a second finger came: a pinch, not a tap */
	bool long_fired;      /* the long press was reported */
	uint64_t last_tap_ns; /* the end of the last tap; CLOCK_NEVER: none */
};

void gesture_init(struct gesture_state *g, const struct gesture_config *cfg);
/* The touches down now (n of them, at most GESTURE_MAX_POINTS; the rest
 * are ignored), at time_ns. Writes up to GESTURE_MAX_EVENTS into out and
 * returns the count. */
int gesture_frame(struct gesture_state *g, uint64_t time_ns, const struct gesture_point *pts, int n,
		  struct gesture *out);
/* Time passed to now_ns with no frame: the long press. */
int gesture_timeout(struct gesture_state *g, uint64_t now_ns, struct gesture *out);
/* When gesture_timeout has something to do, or CLOCK_NEVER. */
uint64_t gesture_deadline(const struct gesture_state *g);

/* A raw device position (its axis ranges min..max) to the screen fraction
 * the viewer sees, for a panel turned by rotation degrees (0, 90, 180 or
 * 270, as [display] rotation): the device is fixed to the panel, so its
 * axes turn with the picture. A degenerate range maps to the centre. */
void gesture_map(int raw_x, int raw_y, const int range_x[2], const int range_y[2], int rotation,
		 double *x, double *y);

#endif
