/* The kiosk's state, and nothing of GL, DRM, GPIO or files: timestamped
 * actions in, new state out. That is what makes it testable without
 * hardware. Buttons and keys are turned into actions elsewhere
 * (src/button.c, src/gpio.c, src/keyboard.c). */
#ifndef MK_APP_H
#define MK_APP_H

#include "math3d.h"
#include "shading.h"

#include <stdbool.h>
#include <stdint.h>

#define APP_NEVER UINT64_MAX

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
	ACTION_RESET, /* back to the resting orientation and the configured mode */
	ACTION_COUNT
};

/* "none", "turn-left", ... "reset", then NULL: the config file's names. */
extern const char *const app_action_names[ACTION_COUNT + 1];

struct app_event {
	uint64_t time_ns; /* CLOCK_MONOTONIC, or the kernel's event timestamp */
	enum app_action action;
	bool pressed; /* false: released (ends a held turn) */
};

struct app_config {
	double turn_speed;	/* radians per second while a turn is held */
	double turn_step;	/* radians a tap turns, however short the tap */
	double attract_after_s; /* idle time before turning by itself; 0: never */
	double attract_speed;	/* radians per second in attract mode */
	struct quat rest;	/* orientation at start and after a reset */
	enum shading_mode mode;
	int matcap_count; /* image matcaps that next/prev cycle through */
	bool camera_available;
};

/* One direction of turning. A press turns from its time on; the turn
 * lasts while any source holds it, and at least until until_ns, so a tap
 * shorter than a frame still turns turn_step, smoothly. */
struct app_turn {
	int held;	   /* sources holding it (a key and a button may both) */
	uint64_t until_ns; /* the tap's minimum end */
};

struct app {
	struct app_config cfg;
	struct quat orientation;
	int matcap;	/* index into the image matcaps */
	bool camera_on; /* the live camera frame is the matcap */
	enum shading_mode mode;
	bool dirty;	 /* something changed since the last frame drawn */
	bool attract;	 /* turning by itself */
	uint64_t now_ns; /* the last time the state was advanced to */
	uint64_t last_input_ns;
	uint64_t attract_since_ns;
	struct app_turn turns[4]; /* left, right, up, down */
};

static inline bool app_action_is_turn(enum app_action a)
{
	return a >= ACTION_TURN_LEFT && a <= ACTION_TURN_DOWN;
}

void app_init(struct app *a, const struct app_config *cfg, uint64_t now_ns);
/* Events may come a little late (a deadline serviced after the loop
 * advanced); an event older than the state counts at the state's time. */
void app_handle(struct app *a, const struct app_event *ev);
/* Advance the clock: held turns and attract mode move the model. Returns
 * the time at which the state next changes by itself, or APP_NEVER. */
uint64_t app_advance(struct app *a, uint64_t now_ns);
/* True while the model moves by itself or by a held turn. */
bool app_moving(const struct app *a);
/* The camera appeared or went away (unplugged, stalled). */
void app_set_camera_available(struct app *a, bool available);
void app_set_matcap_count(struct app *a, int count);

#endif
