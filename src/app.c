#include "app.h"

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
	 * left on the screen whatever the model's orientation. Normalising
	 * after each step keeps a million small turns a rotation. */
	if (yaw != 0.0)
		q = quat_multiply(quat_from_axis_angle(0, 1, 0, yaw), q);
	if (pitch != 0.0)
		q = quat_multiply(quat_from_axis_angle(1, 0, 0, pitch), q);
	a->orientation = quat_normalize(q);
	a->dirty = true;
}

static void held_direction(const struct app *a, double *yaw, double *pitch)
{
	*yaw = ((a->held >> ACTION_TURN_RIGHT) & 1) - (double)((a->held >> ACTION_TURN_LEFT) & 1);
	*pitch = ((a->held >> ACTION_TURN_DOWN) & 1) - (double)((a->held >> ACTION_TURN_UP) & 1);
}

static int entries(const struct app *a)
{
	return a->cfg.matcap_count > 0 ? a->cfg.matcap_count : 1;
}

static void press(struct app *a, enum app_action action)
{
	switch (action) {
	case ACTION_TURN_LEFT:
	case ACTION_TURN_RIGHT:
	case ACTION_TURN_UP:
	case ACTION_TURN_DOWN: {
		double s = a->cfg.turn_step;

		a->held |= 1u << action;
		turn(a,
		     action == ACTION_TURN_RIGHT  ? s
		     : action == ACTION_TURN_LEFT ? -s
						  : 0,
		     action == ACTION_TURN_DOWN ? s
		     : action == ACTION_TURN_UP ? -s
						: 0);
		break;
	}
	case ACTION_NEXT_MATCAP:
	case ACTION_PREV_MATCAP:
		/* Leaving the camera entry returns to the image matcaps. */
		if (a->camera_on)
			a->camera_on = false;
		else
			a->matcap =
			    (a->matcap + (action == ACTION_NEXT_MATCAP ? 1 : -1) + entries(a)) %
			    entries(a);
		a->dirty = true;
		break;
	case ACTION_TOGGLE_CAMERA:
		a->camera_on = !a->camera_on && a->cfg.camera_available;
		a->dirty = true;
		break;
	case ACTION_NEXT_MODE:
		a->mode = (enum shading_mode)((a->mode + 1) % SHADING_MODE_COUNT);
		a->dirty = true;
		break;
	case ACTION_RESET:
		a->orientation = quat_normalize(a->cfg.rest);
		a->dirty = true;
		break;
	default:
		break;
	}
}

void app_handle(struct app *a, const struct app_event *ev)
{
	if (ev->time_ns > a->now_ns)
		app_advance(a, ev->time_ns);
	a->last_input_ns = ev->time_ns;
	if (a->attract) {
		a->attract = false; /* any press or release stops it */
		a->dirty = true;
	}
	if (ev->pressed)
		press(a, ev->action);
	else if (ev->action > ACTION_NONE && ev->action < ACTION_COUNT)
		a->held &= ~(1u << ev->action);
}

uint64_t app_advance(struct app *a, uint64_t now_ns)
{
	double dt, yaw, pitch;
	uint64_t attract_at;

	if (now_ns <= a->now_ns)
		return a->held || a->attract ? a->now_ns + FRAME_NS : APP_NEVER;
	dt = (double)(now_ns - a->now_ns) * 1e-9;
	a->now_ns = now_ns;
	held_direction(a, &yaw, &pitch);
	if (yaw != 0.0 || pitch != 0.0)
		turn(a, yaw * a->cfg.turn_speed * dt, pitch * a->cfg.turn_speed * dt);
	attract_at = a->cfg.attract_after_s > 0
			 ? a->last_input_ns + (uint64_t)(a->cfg.attract_after_s * 1e9)
			 : APP_NEVER;
	if (!a->held && attract_at != APP_NEVER && now_ns >= attract_at) {
		if (a->attract)
			turn(a, a->cfg.attract_speed * dt, 0.0);
		a->attract = true;
	}
	if (a->held || a->attract)
		return now_ns + FRAME_NS;
	return attract_at;
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
	a->cfg.matcap_count = count;
	if (a->matcap >= entries(a))
		a->matcap = 0;
	a->dirty = true;
}
