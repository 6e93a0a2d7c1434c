/* The kiosk's state, and nothing of GL, DRM, GPIO or files: timestamped
 * actions in, new state out. That is what makes it testable without
 * hardware. Buttons and keys are turned into actions elsewhere
 * (src/input/). */
#ifndef MK_APP_H
#define MK_APP_H

#include "input/action.h"
#include "util/clock.h"
#include "util/math3d.h"
#include "render/shading.h"

#include <stdbool.h>
#include <stdint.h>

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

void app_init(struct app *a, const struct app_config *cfg, uint64_t now_ns);
/* Events may come a little late (a deadline serviced after the loop
 * advanced); an event older than the state counts at the state's time. */
void app_handle(struct app *a, const struct app_event *ev);
/* Advance the clock: held turns and attract mode move the model. Returns
 * the time at which the state next changes by itself, or CLOCK_NEVER. */
uint64_t app_advance(struct app *a, uint64_t now_ns);
/* True while the model moves by itself or by a held turn. */
bool app_moving(const struct app *a);
/* The camera appeared or went away (unplugged, stalled). */
void app_set_camera_available(struct app *a, bool available);
void app_set_matcap_count(struct app *a, int count);

#endif
