/* --stop N and --at SECONDS: the offscreen still of a moment the live
 * kiosk would show, by its own app state (state/app.c) fed the same
 * inputs and the same clock, so a stop's glide, the tour's steps and
 * attract mode's path are not computed a second way here. */
#include "app/preview.h"
#include "state/app.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>

#define NS 1000000000ull
/* The live kiosk draws attract mode at [kiosk] attract_fps; a display's
 * rate, where that is 0, taken as 60. */
#define PREVIEW_FPS 60.0
/* A glide to a stop ends well before this (at turn_speed, a half turn). */
#define PREVIEW_GLIDE_S 60.0

static void press(struct app *a, enum app_action action, uint64_t t)
{
	struct app_msg m = {.kind = APP_INPUT, .input = {t, action, true}};

	app_apply(a, &m);
	m.input.pressed = false;
	app_apply(a, &m);
}

/* Frame by frame from `from` to `to`, as the loop advances the state;
 * until: stop early once the model rests (a stop's glide). */
static uint64_t run_frames(struct app *a, uint64_t from, uint64_t to, double fps, bool until_rest)
{
	uint64_t step = (uint64_t)(NS / (fps > 0 ? fps : PREVIEW_FPS)), t = from;

	while (t < to) {
		t = t + step < to ? t + step : to;
		app_advance(a, t);
		if (until_rest && !app_moving(a))
			break;
	}
	return t;
}

static int check_stop(const struct options *o, const struct app_config *cfg)
{
	if (o->preview_stop > 0 && o->preview_at >= 0) {
		log_err("--stop %d and --at %g: one moment at a time; expected one of them",
			o->preview_stop, o->preview_at);
		return -EINVAL;
	}
	if (o->preview_stop <= cfg->frame.stop_count)
		return 0;
	if (!cfg->frame.stop_count) {
		log_err("--stop %d: the model has no stops ([frame] stops); expected none, or "
			"--at for the attract mode's turn",
			o->preview_stop);
		return -EINVAL;
	}
	log_err("--stop %d: the model has %d stop%s ([frame] stops); expected 1 to %d",
		o->preview_stop, cfg->frame.stop_count, cfg->frame.stop_count == 1 ? "" : "s",
		cfg->frame.stop_count);
	return -EINVAL;
}

/* The app at the moment asked for, from its start at time 1 s (0 is no
 * input in the app's clock). */
static void run_app(const struct options *o, const struct app_config *cfg, struct app *a)
{
	const uint64_t t0 = NS;
	uint64_t t = t0;

	if (o->preview_stop > 0) {
		for (int i = 0; i < o->preview_stop; i++)
			press(a, ACTION_NEXT_STOP, t0);
		run_frames(a, t0, t0 + (uint64_t)(PREVIEW_GLIDE_S * NS), cfg->attract_fps, true);
	}
	if (o->preview_at >= 0) {
		t = t0 + (uint64_t)((cfg->attract_after_s + o->preview_at) * NS);
		run_frames(a, t0, t, cfg->attract_fps, false);
	}
}

int preview_moment(const struct options *o, const struct content *s, const struct content_config *c,
		   struct view *v, int *stop)
{
	struct app_config cfg = o->app;
	const struct app_state *st;
	struct app *a;
	int ret;

	*v = content_view(c);
	content_app_frame(c, &cfg.frame, &cfg.rest);
	cfg.mode = c->mode;
	cfg.attract_model_s = 0; /* one model: the one drawn */
	cfg.shared_clock = false; /* --at counts from the start, not the wall clock */
	/* --stop: the stop as a visitor's presses leave it, no tour after;
	 * --at: the tour, even where attract_after = 0 turns it off. */
	if (o->preview_stop > 0 || cfg.attract_after_s <= 0)
		cfg.attract_after_s = o->preview_stop > 0 ? 0 : 1e-3;
	ret = check_stop(o, &cfg);
	if (ret)
		return ret;
	a = app_new(&cfg, 1, NS);
	if (!a)
		return -ENOMEM;
	run_app(o, &cfg, a);
	st = app_state(a);
	v->orientation = st->orientation;
	v->zoom = (float)(st->zoom * (s->zoom > 0 ? s->zoom : 1.0));
	content_place_view(s, v);
	*stop = st->stop;
	log_debug("preview: stop %d, yaw %.1f, pitch %.1f, zoom %.3f", st->stop,
		  st->yaw * 180 / 3.141592653589793, st->pitch * 180 / 3.141592653589793, st->zoom);
	app_free(a);
	return ret;
}
