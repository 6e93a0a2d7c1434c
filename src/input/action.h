/* What an input means to the kiosk: the actions a button, a key or a
 * touch is bound to, each with the time it happened. Inputs produce
 * these; the app state (src/state/app.h) consumes them. */
#ifndef MK_ACTION_H
#define MK_ACTION_H

#include <stdbool.h>
#include <stdint.h>

/* The order is that of app_action_names (the config file's words). */
enum app_action {
	ACTION_NONE,
	ACTION_TURN_LEFT, /* held: turns continuously */
	ACTION_TURN_RIGHT,
	ACTION_TURN_UP,
	ACTION_TURN_DOWN,
	ACTION_NEXT_MATCAP,
	ACTION_PREV_MATCAP,
	ACTION_TOGGLE_CAMERA,
	ACTION_NEXT_MODE,
	ACTION_RESET,	   /* back to the resting orientation and the configured mode */
	ACTION_NEXT_MODEL, /* the next model of a folder or list */
	ACTION_PREV_MODEL,
	ACTION_NEXT_STOP, /* glide to the next of [frame] stops */
	ACTION_PREV_STOP,
	ACTION_PLAY_PAUSE,     /* the model's animation stops where it is, or goes on */
	ACTION_NEXT_ANIMATION, /* its next clip, crossfaded */
	ACTION_NEXT_VARIANT,   /* its next KHR_materials_variants variant (then its default) */
	ACTION_NEXT_HOTSPOT,   /* glide to face the model's next hotspot, its text shown */
	ACTION_COUNT
};

/* "none", "turn-left", ... "next-variant", then NULL: the config file's names. */
extern const char *const app_action_names[ACTION_COUNT + 1];

struct app_event {
	uint64_t time_ns; /* CLOCK_MONOTONIC, or the kernel's event timestamp */
	enum app_action action;
	bool pressed; /* false: released (ends a held turn) */
};

static inline bool app_action_is_turn(enum app_action a)
{
	return a >= ACTION_TURN_LEFT && a <= ACTION_TURN_DOWN;
}

#endif
