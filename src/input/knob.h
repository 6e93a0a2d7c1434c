/* A rotary knob as a pure decoder: the evdev events of a relative axis
 * (REL_DIAL, REL_WHEEL or REL_X: what the kernel's rotary-encoder driver
 * sends with rotary-encoder,relative-axis) and of its key, with their
 * timestamps, in; app events out. It knows no device, so the tests drive
 * it with recorded event sequences; src/input/knob_device.c reads the
 * devices udev finds.
 *
 * Counts add up to detents (per_detent counts each; a turn back drops
 * what was counted the other way, so a wobble on a detent is nothing),
 * taken at each SYN_REPORT. A detent clockwise (a positive count) turns
 * the model right by step, or goes to the next stop. The key is a button
 * (src/input/button.h): a press does press, one held does long_press. */
#ifndef MK_KNOB_H
#define MK_KNOB_H

#include "input/button.h"

#include <stdbool.h>
#include <stdint.h>

/* The most events one call gives: the detents of one report are capped
 * at this (more in 10 ms is a spin, not a visitor counting stops). */
#define KNOB_MAX_EVENTS BUTTON_MAX_EVENTS

/* How long the knob's key is held for its long press. */
#define KNOB_LONG_NS 800000000ull

/* What a detent does; the order is that of knob_turns_names. A new use
 * (hotspots) is one more value and its row in knob.c's turn table. */
enum knob_turns { KNOB_TURNS_MODEL, KNOB_TURNS_STOPS, KNOB_TURNS_COUNT };

/* "model", "stops", then NULL: the config file's words. */
extern const char *const knob_turns_names[KNOB_TURNS_COUNT + 1];

/* [knob] in kiosk.ini. */
struct knob_config {
	/* NULL or "auto": every knob udev finds; "none": none; else the one
	 * device named (/dev/input/eventN or a link to it). */
	char *device;
	double step; /* radians a detent turns the model */
	enum knob_turns turns;
	enum app_action press;	    /* its key pressed */
	enum app_action long_press; /* its key held KNOB_LONG_NS; ACTION_NONE: none */
};

struct knob_decoder {
	enum knob_turns turns;
	double step;
	unsigned axis;	/* the REL_ code counted; the device's others are not */
	int per_detent; /* counts a detent: 1 for the rotary-encoder driver */
	int counts;	/* since the last detent, all one way */
	struct button key;
};

/* The axis a knob turns: REL_DIAL, else REL_WHEEL, else REL_X, of those
 * has[] says the device has (indexed by the REL_ code); -1: none. */
int knob_axis(const bool *has, int count);
void knob_decoder_init(struct knob_decoder *d, const struct knob_config *c, unsigned axis,
		       int per_detent);
/* One evdev event at time_ns: up to KNOB_MAX_EVENTS into out; the count. */
int knob_decoder_event(struct knob_decoder *d, uint64_t time_ns, unsigned type, unsigned code,
		       int value, struct app_event *out);
/* The key's long press, due at knob_decoder_deadline. */
int knob_decoder_timeout(struct knob_decoder *d, uint64_t now_ns, struct app_event *out);
uint64_t knob_decoder_deadline(const struct knob_decoder *d);
/* The device went away: the key released, nothing held. */
int knob_decoder_lost(struct knob_decoder *d, uint64_t now_ns, struct app_event *out);

#endif
