/* The kiosk's state, and nothing of GL, DRM, GPIO or files: timestamped
 * messages in (a button or key, the camera, the matcap folder, a reload,
 * the display), new state out. state/app.c (with its pose helpers,
 * state/app_pose.c) is the one place the state changes; everyone else
 * reads it through app_state(). That is what makes it testable without
 * hardware. Buttons and keys are turned into actions
 * elsewhere (src/input/). */
#ifndef MK_APP_H
#define MK_APP_H

#include "state/app_types.h"
#include "state/steps.h"
#include "util/clock.h"

#include <stdbool.h>
#include <stdint.h>

struct app;

/* matcap_count: the image matcaps (at least one is assumed). NULL when out
 * of memory. */
struct app *app_new(const struct app_config *cfg, int matcap_count, uint64_t now_ns);
void app_free(struct app *a);
const struct app_state *app_state(const struct app *a);
/* Apply one message. Inputs may come a little late (a deadline serviced
 * after the loop advanced); one older than the state counts at the
 * state's time. A reload starts the state afresh, but a live camera
 * stays on. */
void app_apply(struct app *a, const struct app_msg *m);
/* Advance the clock: held turns and attract mode move the model. Returns
 * the time at which the state next changes by itself, or CLOCK_NEVER. */
uint64_t app_advance(struct app *a, uint64_t now_ns);
/* The offset of the state's clock from the caller's (CLOCK_REALTIME less
 * CLOCK_MONOTONIC for a shared clock), given again on every pass: it
 * follows a clock that chrony slews. A shared clock that stepped (by more
 * than APP_CLOCK_STEP_NS) starts attract mode's schedule afresh, as at
 * the start; returns the step then, else 0. */
#define APP_CLOCK_STEP_NS 1000000000ll
int64_t app_set_clock(struct app *a, int64_t offset_ns);
/* On a shared clock, a state change another kiosk made at time_ns (the
 * caller's clock), maybe before this state's now: the state as it was
 * then, with an input then (attract mode stops then, as it did there), to
 * be advanced to now again. What moves by itself being a function of the
 * clock and the last change, the two kiosks are then in step. Nothing on
 * a kiosk's own clock, or for a time not before now. */
void app_rewind(struct app *a, uint64_t time_ns);
/* A time of the caller's clock on the state's (last_input_ns's). */
uint64_t app_clock(const struct app *a, uint64_t now_ns);
/* True in attract mode (what the visitors' counters call idle). */
bool app_attracting(const struct app *a);
/* True while the model moves by itself or by a held turn. */
bool app_moving(const struct app *a);

#endif
