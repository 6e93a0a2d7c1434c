#include "app/app.h"

#include <math.h>
#include <string.h>

/* While something moves, redraw at about the display's rate. */
#define FRAME_NS 16666667ull

void app_init(struct app *a, const struct app_config *cfg, uint64_t now_ns)
{
	memset(a, 0, sizeof(*a));
	a->cfg = *cfg;
	a->orientation = quat_normalize(cfg->rest);
	a->mode = cfg->mode;
	a->now_ns = now_ns;
	a->last_input_ns = now_ns;
	a->dirty = true;
}

static void turn(struct app *a, double yaw, double pitch)
{
	struct quat q = a->orientation;

	/* Turns about the viewer's axes, applied on the left, so "left" is
	 * left on the screen whatever the model's orientation (and no gimbal
	 * lock). Normalising after each step keeps a million small turns a
	 * rotation. */
	if (yaw != 0.0)
		q = quat_multiply(quat_from_axis_angle(0, 1, 0, yaw), q);
	if (pitch != 0.0)
		q = quat_multiply(quat_from_axis_angle(1, 0, 0, pitch), q);
	a->orientation = quat_normalize(q);
	a->dirty = true;
}

/* Seconds that one direction turned within [from, to]. */
static double turn_seconds(const struct app_turn *t, uint64_t from, uint64_t to)
{
	uint64_t end = t->held || t->until_ns > to ? to : t->until_ns;

	return end > from ? (double)(end - from) * 1e-9 : 0.0;
}

static bool any_held(const struct app *a)
{
	for (int i = 0; i < 4; i++)
		if (a->turns[i].held)
			return true;
	return false;
}

bool app_moving(const struct app *a)
{
	if (a->attract)
		return true;
	for (int i = 0; i < 4; i++)
		if (a->turns[i].held || a->turns[i].until_ns > a->now_ns)
			return true;
	return false;
}

static uint64_t attract_at(const struct app *a)
{
	if (!(a->cfg.attract_after_s > 0))
		return CLOCK_NEVER;
	return a->last_input_ns + (uint64_t)(a->cfg.attract_after_s * 1e9);
}

static int entries(const struct app *a)
{
	return a->cfg.matcap_count > 0 ? a->cfg.matcap_count : 1;
}

static void press_turn(struct app *a, enum app_action action, uint64_t t)
{
	struct app_turn *turn_state = &a->turns[action - ACTION_TURN_LEFT];
	uint64_t until = t;

	/* A turn too slow to reach the step in a day is no step at all. */
	if (a->cfg.turn_speed > 0 && a->cfg.turn_step / a->cfg.turn_speed < 86400.0)
		until = t + (uint64_t)(a->cfg.turn_step / a->cfg.turn_speed * 1e9);
	turn_state->held++;
	if (until > turn_state->until_ns)
		turn_state->until_ns = until;
}

/* The cycle is every image matcap in name order, then the live camera
 * when there is one: a kiosk with three buttons reaches all of them. */
static void cycle(struct app *a, int step)
{
	int n = entries(a), slots = n + (a->cfg.camera_available ? 1 : 0);
	int pos = a->camera_on ? n : a->matcap;

	pos = ((pos + step) % slots + slots) % slots;
	a->camera_on = pos == n;
	if (!a->camera_on)
		a->matcap = pos;
	a->dirty = true;
}

static void press(struct app *a, enum app_action action, uint64_t t)
{
	if (app_action_is_turn(action)) {
		press_turn(a, action, t);
		return;
	}
	switch (action) {
	case ACTION_NEXT_MATCAP:
	case ACTION_PREV_MATCAP:
		cycle(a, action == ACTION_NEXT_MATCAP ? 1 : -1);
		break;
	case ACTION_TOGGLE_CAMERA:
		if (a->camera_on || a->cfg.camera_available) {
			a->camera_on = !a->camera_on;
			a->dirty = true;
		}
		break;
	case ACTION_NEXT_MODE:
		a->mode = (enum shading_mode)((a->mode + 1) % SHADING_MODE_COUNT);
		a->dirty = true;
		break;
	case ACTION_RESET:
		a->orientation = quat_normalize(a->cfg.rest);
		a->mode = a->cfg.mode;
		for (int i = 0; i < 4; i++)
			a->turns[i].until_ns = 0; /* a tap's remainder would undo it */
		a->dirty = true;
		break;
	default:
		break;
	}
}

void app_handle(struct app *a, const struct app_event *ev)
{
	uint64_t t = ev->time_ns > a->now_ns ? ev->time_ns : a->now_ns;

	app_advance(a, t);
	if (t > a->last_input_ns)
		a->last_input_ns = t;
	a->attract = false; /* any press or release stops it, where it is */
	if (ev->action <= ACTION_NONE || ev->action >= ACTION_COUNT)
		return;
	if (ev->pressed)
		press(a, ev->action, t);
	else if (app_action_is_turn(ev->action) && a->turns[ev->action - ACTION_TURN_LEFT].held)
		a->turns[ev->action - ACTION_TURN_LEFT].held--;
}

static uint64_t next_change(const struct app *a)
{
	if (app_moving(a))
		return a->now_ns + FRAME_NS;
	return attract_at(a);
}

uint64_t app_advance(struct app *a, uint64_t now_ns)
{
	uint64_t prev = a->now_ns, from = prev, at;
	const struct app_turn *t = a->turns;
	double yaw, pitch, speed = a->cfg.turn_speed;

	if (now_ns <= prev)
		return next_change(a);
	yaw = speed * (turn_seconds(&t[1], prev, now_ns) - turn_seconds(&t[0], prev, now_ns));
	pitch = speed * (turn_seconds(&t[3], prev, now_ns) - turn_seconds(&t[2], prev, now_ns));
	a->now_ns = now_ns;
	at = attract_at(a);
	if (!a->attract && !any_held(a) && at <= now_ns) {
		a->attract = true;
		from = at > prev ? at : prev;
	}
	if (a->attract)
		yaw += a->cfg.attract_speed * (double)(now_ns - from) * 1e-9;
	if (yaw != 0.0 || pitch != 0.0)
		turn(a, yaw, pitch);
	return next_change(a);
}

void app_set_camera_available(struct app *a, bool available)
{
	a->cfg.camera_available = available;
	if (!available && a->camera_on) {
		a->camera_on = false; /* back to the last image matcap */
		a->dirty = true;
	}
}

void app_set_matcap_count(struct app *a, int count)
{
	if (count == a->cfg.matcap_count)
		return;
	a->cfg.matcap_count = count;
	if (a->matcap >= entries(a))
		a->matcap = 0;
	a->dirty = true;
}
