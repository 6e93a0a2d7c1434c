/* Where the model points: a pose within the frame's limits, a glide to a
 * view (home, a stop, attract mode's path), the stop shown. The app
 * state's (state/app.c) own helpers, on its insides (state/app_priv.h). */
#include "state/app_priv.h"

#include <math.h>
#include <string.h>

/* A frame left zero (a test's config) limits nothing. */
void app_frame_normalise(struct app_frame *f)
{
	if (!(f->zoom0 > 0))
		f->zoom0 = 1.0;
	if (!(f->zoom_min > 0))
		f->zoom_min = APP_ZOOM_MIN;
	if (!(f->zoom_max > 0))
		f->zoom_max = APP_ZOOM_MAX;
	if (f->direction == 0)
		f->direction = 1.0;
	if (!f->yaw_limited)
		f->yaw_min = -INFINITY, f->yaw_max = INFINITY;
	if (!f->pitch_limited)
		f->pitch_min = -INFINITY, f->pitch_max = INFINITY;
}

/* The orientation of yaw and pitch: yaw about the model's vertical, then
 * the tilt towards the viewer, after the model's own turn. An angle with
 * no limits is kept within one turn, so a million turns lose no
 * precision. */
void app_pose(struct app *a, double yaw, double pitch, double zoom)
{
	const struct app_frame *f = &a->cfg.frame;

	if (!f->yaw_limited)
		yaw = remainder(yaw, 2 * M_PI);
	if (!f->pitch_limited)
		pitch = remainder(pitch, 2 * M_PI);
	a->state.yaw = app_clampd(yaw, f->yaw_min, f->yaw_max);
	a->state.pitch = app_clampd(pitch, f->pitch_min, f->pitch_max);
	a->state.zoom = app_clampd(zoom, f->zoom_min, f->zoom_max);
	a->state.orientation = quat_normalize(
	    quat_multiply(quat_from_axis_angle(1, 0, 0, a->state.pitch),
			  quat_multiply(quat_from_axis_angle(0, 1, 0, a->state.yaw), a->cfg.rest)));
	a->state.dirty = true;
}

void app_set_stop(struct app *a, int stop)
{
	a->state.stop = stop;
	a->state.stop_text =
	    stop >= 0 && a->cfg.frame.stops[stop].text[0] ? a->cfg.frame.stops[stop].text : NULL;
	a->state.stop_animation = stop >= 0 && a->cfg.frame.stops[stop].animation[0]
				      ? a->cfg.frame.stops[stop].animation
				      : NULL;
	a->state.stop_variant = stop >= 0 && a->cfg.frame.stops[stop].variant[0]
				    ? a->cfg.frame.stops[stop].variant
				    : NULL;
}

void app_home(struct app *a)
{
	const struct app_frame *f = &a->cfg.frame;

	a->easing = false;
	app_set_stop(a, -1);
	app_pose(a, f->yaw0, f->pitch0, f->zoom0);
}

/* Glide from the pose now to (yaw, pitch, zoom), from rest, arriving at
 * yaw speed v1: the longer the way at speed, the longer the glide. An
 * unlimited yaw takes the short way round. */
void app_ease_to(struct app *a, uint64_t t, const double to[3], double v1, double speed)
{
	const struct app_state *st = &a->state;
	double d;

	memcpy(a->to, to, sizeof(a->to));
	if (!a->cfg.frame.yaw_limited)
		a->to[0] = st->yaw + remainder(to[0] - st->yaw, 2 * M_PI);
	a->from[0] = st->yaw;
	a->from[1] = st->pitch;
	a->from[2] = st->zoom;
	memset(a->v0, 0, sizeof(a->v0));
	memset(a->v1, 0, sizeof(a->v1));
	a->v1[0] = v1;
	d = fmax(fmax(fabs(a->to[0] - a->from[0]), fabs(a->to[1] - a->from[1])),
		 fabs(log(a->to[2] / a->from[2])));
	a->ease_s = d > 1e-9 ? app_clampd(2 * d / (speed > 0 ? speed : M_PI / 4), 0.5, 4) : 0;
	a->ease_ns = t;
	a->easing = true;
}

double app_ease_speed(const struct app *a)
{
	return a->cfg.attract_speed > 0 ? a->cfg.attract_speed : a->cfg.turn_speed;
}

void app_to_stop(struct app *a, int k, uint64_t t, double speed)
{
	const struct frame_stop *s = &a->cfg.frame.stops[k];
	double to[3] = {s->yaw, s->pitch, s->zoom};

	app_set_stop(a, k);
	app_ease_to(a, t, to, 0, speed);
	a->state.dirty = true;
}

/* The pose at now: on the glide, then (attract mode's) on the path. */
void app_glide(struct app *a, uint64_t now)
{
	double t = now > a->ease_ns ? (double)(now - a->ease_ns) * 1e-9 : 0, v, p[3];

	if (t < a->ease_s) {
		for (int i = 0; i < 3; i++)
			p[i] = ease_at(a->from[i], a->v0[i], a->to[i], a->v1[i], a->ease_s, t, &v);
		app_pose(a, p[0], p[1], p[2]);
		return;
	}
	if (a->attract && !a->touring) {
		app_pose(a, attract_path_at(&a->path, t - a->ease_s, &v), a->to[1], a->to[2]);
		return;
	}
	if (a->easing)
		app_pose(a, a->to[0], a->to[1], a->to[2]);
	a->easing = false;
}
