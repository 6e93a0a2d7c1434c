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
	/* The knob's press (or a button's): what the knob points at is taken;
	 * today the next stop (hotspots, issue 33, step through theirs). */
	ACTION_SELECT,
	/* The knob's long press (or a button's, a key's): the texts in the
	 * next of [caption] languages. */
	ACTION_NEXT_LANGUAGE,
	ACTION_COUNT
};

/* "none", "turn-left", ... "next-language", then NULL: the config file's names. */
extern const char *const app_action_names[ACTION_COUNT + 1];

/* What kind of thing a source is: the visitors' presses are counted per
 * kind (src/state/visits.h); the order is that of input_kind_names. */
enum input_kind {
	INPUT_KIND_OTHER,
	INPUT_KIND_BUTTON,
	INPUT_KIND_KEY,
	INPUT_KIND_TOUCH,
	INPUT_KIND_KNOB,
	INPUT_KINDS
};

/* "other", "button", "key", "touch", "knob": the metrics' source label. */
extern const char *const input_kind_names[INPUT_KINDS];

struct app_event {
	uint64_t time_ns; /* CLOCK_MONOTONIC, or the kernel's event timestamp */
	enum app_action action;
	bool pressed; /* false: released (ends a held turn) */
	/* A turn pressed with an angle (radians, > 0): a knob's detent,
	 * turned that far at once with nothing held and no release. */
	double angle;
};

static inline bool app_action_is_turn(enum app_action a)
{
	return a >= ACTION_TURN_LEFT && a <= ACTION_TURN_DOWN;
}

#endif
