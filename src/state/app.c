#include "state/app.h"
#include "state/app_priv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* While something moves, redraw at about the display's rate. */
#define FRAME_NS 16666667ull

static uint64_t advance(struct app *a, uint64_t now_ns);

static void init(struct app *a, const struct app_config *cfg, int matcap_count, uint64_t now_ns)
{
	memset(a, 0, sizeof(*a));
	a->cfg = *cfg;
	app_frame_normalise(&a->cfg.frame);
	a->matcap_count = matcap_count;
	app_home(a);
	a->state.mode = cfg->mode;
	a->state.last_input_ns = cfg->shared_clock ? 0 : now_ns;
	a->state.dirty = true;
	a->state.model_step = 1;
	a->model_count = 1;
	a->now_ns = now_ns;
	/* The first time a camera is found, it is shown. */
	a->camera_resume = true;
}

struct app *app_new(const struct app_config *cfg, int matcap_count, uint64_t now_ns)
{
	struct app *a = malloc(sizeof(*a));

	if (a)
		init(a, cfg, matcap_count, now_ns + (uint64_t)cfg->clock_offset_ns);
	return a;
}

void app_free(struct app *a)
{
	free(a);
}

const struct app_state *app_state(const struct app *a)
{
	return &a->state;
}

/* A turntable: left is left on the screen, down tilts the top towards
 * the viewer, each within [frame]'s limits. */
static void turn(struct app *a, double yaw, double pitch)
{
	a->easing = false;
	app_pose(a, a->state.yaw + yaw, a->state.pitch + pitch, a->state.zoom);
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

static bool turning(const struct app *a)
{
	for (int i = 0; i < 4; i++)
		if (a->turns[i].held || a->turns[i].until_ns > a->now_ns)
			return true;
	return false;
}

bool app_attracting(const struct app *a)
{
	return a->attract;
}

bool app_moving(const struct app *a)
{
	return a->attract || a->easing || turning(a);
}

static uint64_t attract_at(const struct app *a)
{
	if (!(a->cfg.attract_after_s > 0))
		return CLOCK_NEVER;
	return a->state.last_input_ns + (uint64_t)(a->cfg.attract_after_s * 1e9);
}

static int entries(const struct app *a)
{
	return a->matcap_count > 0 ? a->matcap_count : 1;
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
	struct app_state *st = &a->state;
	int n = entries(a), slots = n + (a->camera_available ? 1 : 0);
	int pos = st->camera_on ? n : st->matcap;

	pos = ((pos + step) % slots + slots) % slots;
	st->camera_on = pos == n;
	if (!st->camera_on)
		st->matcap = pos;
	st->dirty = true;
}

static void step_model(struct app *a, int step)
{
	int n = a->model_count;

	if (n < 2)
		return;
	a->state.model = ((a->state.model + step) % n + n) % n;
	a->state.model_step = step;
}

static void step_stop(struct app *a, int step, uint64_t t)
{
	int n = a->cfg.frame.stop_count, k = a->state.stop;

	if (n < 1)
		return;
	k = k < 0 || k >= n ? (step > 0 ? 0 : n - 1) : ((k + step) % n + n) % n;
	app_to_stop(a, k, t, a->cfg.turn_speed);
}

/* The next hotspot's view (stops[FRAME_STOPS + i]); select's: else the next stop. */
static void step_hotspot(struct app *a, bool select, uint64_t t)
{
	int k = app_frame_hotspot_step(&a->cfg.frame, a->state.stop, select);

	if (k >= 0)
		app_to_stop(a, k, t, a->cfg.turn_speed);
}

/* Attract mode from t: the stops in turn, or home (no snap) and then the
 * turn or swing, which the glide meets at its speed. */
static void attract_begin(struct app *a, uint64_t t)
{
	const struct app_frame *f = &a->cfg.frame;
	double to[3] = {f->yaw0, f->pitch0, f->zoom0}, v;

	a->attract_ns = t;
	a->attract_from = t;
	a->touring = f->stop_count > 0 && f->stop_seconds > 0;
	if (a->touring) {
		app_to_stop(a,
			    a->state.stop < 0 || a->state.stop >= f->stop_count
				? 0
				: (a->state.stop + 1) % f->stop_count,
			    t, app_ease_speed(a));
		a->stop_at = t + (uint64_t)(f->stop_seconds * 1e9);
		return;
	}
	app_set_stop(a, -1);
	if (!f->yaw_limited)
		to[0] = a->state.yaw + remainder(to[0] - a->state.yaw, 2 * M_PI);
	attract_path_make(&a->path, f, to[0], a->cfg.attract_speed);
	attract_path_at(&a->path, 0, &v);
	app_ease_to(a, t, to, v, app_ease_speed(a));
}

static void press(struct app *a, enum app_action action, uint64_t t)
{
	struct app_state *st = &a->state;

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
		if (st->camera_on || a->camera_available) {
			st->camera_on = !st->camera_on;
			st->dirty = true;
		}
		break;
	case ACTION_NEXT_MODE:
		st->mode = (enum shading_mode)((st->mode + 1) % SHADING_MODE_COUNT);
		st->dirty = true;
		break;
	case ACTION_NEXT_MODEL:
	case ACTION_PREV_MODEL:
		step_model(a, action == ACTION_NEXT_MODEL ? 1 : -1);
		break;
	case ACTION_NEXT_STOP:
	case ACTION_PREV_STOP:
		step_stop(a, action == ACTION_PREV_STOP ? -1 : 1, t);
		break;
	case ACTION_SELECT: /* the knob's press: the hotspots where there are any */
	case ACTION_NEXT_HOTSPOT:
		step_hotspot(a, action == ACTION_SELECT, t);
		break;
	case ACTION_PLAY_PAUSE:
		st->anim_paused = !st->anim_paused;
		break;
	case ACTION_NEXT_ANIMATION:
		st->anim_step++;
		break;
	case ACTION_NEXT_VARIANT:
		st->variant_step++;
		break;
	case ACTION_NEXT_LANGUAGE:
		st->lang_step++;
		st->dirty = true;
		break;
	case ACTION_RESET:
		app_home(a);
		st->mode = a->cfg.mode;
		for (int i = 0; i < 4; i++)
			a->turns[i].until_ns = 0; /* a tap's remainder would undo it */
		st->dirty = true;
		break;
	default:
		break;
	}
}

/* Any input, at its time (or the state's, if it came late): the clock
 * runs to it, and attract mode stops where it is. Returns that time. */
static uint64_t input_at(struct app *a, uint64_t time_ns)
{
	uint64_t t = app_clock(a, time_ns);

	t = t > a->now_ns ? t : a->now_ns;
	advance(a, t);
	if (t > a->state.last_input_ns)
		a->state.last_input_ns = t;
	if (a->attract)
		a->easing = false; /* attract's glide stops where it is */
	a->attract = false;
	a->state.pose_ns = 0;
	return t;
}

/* A knob's detent: that far at once, with nothing held (no release comes). */
static void turn_by(struct app *a, enum app_action action, double angle)
{
	double by = action == ACTION_TURN_LEFT || action == ACTION_TURN_UP ? -angle : angle;
	bool yaw = action == ACTION_TURN_LEFT || action == ACTION_TURN_RIGHT;

	turn(a, yaw ? by : 0, yaw ? 0 : by);
}

static void input(struct app *a, const struct app_event *ev)
{
	uint64_t t = input_at(a, ev->time_ns);

	if (ev->action <= ACTION_NONE || ev->action >= ACTION_COUNT)
		return;
	if (ev->pressed && app_action_is_turn(ev->action) && ev->angle > 0)
		turn_by(a, ev->action, ev->angle);
	else if (ev->pressed)
		press(a, ev->action, t);
	else if (app_action_is_turn(ev->action) && a->turns[ev->action - ACTION_TURN_LEFT].held)
		a->turns[ev->action - ACTION_TURN_LEFT].held--;
}

static void zoom(struct app *a, double scale)
{
	const struct app_frame *f = &a->cfg.frame;
	double z = app_clampd(a->state.zoom * scale, f->zoom_min, f->zoom_max);

	/* At a bound a pinch changes nothing, and nothing is drawn. */
	if (!(scale > 0) || z == a->state.zoom)
		return;
	a->easing = false;
	app_pose(a, a->state.yaw, a->state.pitch, z);
}

/* A drag turns about the viewer's axes as the arrows do: right is right
 * and down is down on the screen, whatever the model's orientation. */
static void touch(struct app *a, const struct gesture *g)
{
	uint64_t t = input_at(a, g->time_ns);
	enum app_action act = a->cfg.long_press;

	switch (g->kind) {
	case GESTURE_DRAG:
		if (g->dx != 0.0 || g->dy != 0.0)
			turn(a, g->dx * a->cfg.drag_speed, g->dy * a->cfg.drag_speed);
		break;
	case GESTURE_PINCH:
		zoom(a, g->scale);
		break;
	case GESTURE_TAP: /* on a badge: that hotspot's view */
		if (g->badge > 0 && g->badge <= a->cfg.frame.hotspot_count)
			app_to_stop(a, FRAME_STOPS + g->badge - 1, t, a->cfg.turn_speed);
		break;
	case GESTURE_DOUBLE_TAP:
		press(a, ACTION_RESET, t);
		break;
	case GESTURE_LONG_PRESS:
		if (act <= ACTION_NONE || act >= ACTION_COUNT)
			break;
		/* A turn is a tap of it: turn_step. */
		press(a, act, t);
		if (app_action_is_turn(act))
			a->turns[act - ACTION_TURN_LEFT].held--;
		break;
	default:
		break;
	}
}

/* Attract mode alone draws at attract_fps; a held turn at the display's
 * rate. */
static uint64_t attract_period(const struct app *a)
{
	return a->cfg.attract_fps > 0 ? (uint64_t)(1e9 / a->cfg.attract_fps) : 0;
}

static uint64_t next_change(const struct app *a)
{
	uint64_t period = attract_period(a), at;

	if (turning(a) || (a->attract && !period) || (a->easing && !a->attract))
		return a->now_ns + FRAME_NS;
	if (!a->attract)
		return attract_at(a);
	at = a->attract_ns + period;
	if (a->touring && a->stop_at < at)
		at = a->stop_at;
	if (a->cfg.attract_model_s > 0 && a->model_count > 1 && a->model_at < at)
		at = a->model_at;
	return at > a->now_ns ? at : a->now_ns;
}

/* On a shared clock, the stops due by now counted on their grid: the one
 * before the last reached (a glide is shorter than a stop), the last
 * glided to from there, from its time. */
static void tour_due(struct app *a, uint64_t now_ns, uint64_t every)
{
	int count = a->cfg.frame.stop_count;
	uint64_t n = steps_due(&a->stop_at, now_ns, every);
	int last = (int)(((uint64_t)a->state.stop + n) % (uint64_t)count);
	const struct frame_stop *s = &a->cfg.frame.stops[(last + count - 1) % count];

	if (n == 1)
		app_glide(a, a->stop_at - every);
	else
		app_pose(a, s->yaw, s->pitch, s->zoom);
	app_to_stop(a, last, a->stop_at - every, app_ease_speed(a));
}

/* The same on a shared clock: the pose is that of the last frame of its
 * grid, so it is the same whenever a kiosk looks. */
static void attract_move_shared(struct app *a, uint64_t now_ns, uint64_t every)
{
	uint64_t at = steps_floor(now_ns, attract_period(a));
	bool stepped = a->touring && now_ns >= a->stop_at;

	if (stepped)
		tour_due(a, now_ns, every);
	if (at <= a->attract_ns && !stepped)
		return;
	app_glide(a, at);
	a->state.pose_ns = at;
	a->attract_ns = at > a->attract_ns ? at : a->attract_ns;
}

/* Attract mode's pose, at most attract_fps times a second: the
 * display's every vblank would cost a kiosk nobody watches its CPU for
 * nothing. The pose is a function of the time, so the rate changes no
 * angle. The stops come in turn, one each stop_seconds. */
static void attract_move(struct app *a, uint64_t now_ns)
{
	uint64_t every = (uint64_t)(a->cfg.frame.stop_seconds * 1e9);

	if (a->cfg.shared_clock) {
		attract_move_shared(a, now_ns, every);
		return;
	}
	if (a->touring && now_ns >= a->stop_at) {
		app_glide(a, a->stop_at); /* the stop reached, then on from there */
		app_to_stop(a, (a->state.stop + 1) % a->cfg.frame.stop_count, a->stop_at,
			    app_ease_speed(a));
		a->stop_at += every;
		if (a->stop_at <= now_ns)
			a->stop_at = now_ns + every;
	}
	if (now_ns < a->attract_ns + attract_period(a))
		return;
	app_glide(a, now_ns);
	a->attract_ns = now_ns;
}

/* Attract mode shows every model in turn, one each attract_model_s. */
static void attract_models(struct app *a, uint64_t now_ns)
{
	uint64_t every = (uint64_t)(a->cfg.attract_model_s * 1e9);

	if (!every || a->model_count < 2 || now_ns < a->model_at)
		return;
	if (a->cfg.shared_clock) { /* every step counted, as on every kiosk */
		step_model(
		    a, (int)(steps_due(&a->model_at, now_ns, every) % (uint64_t)a->model_count));
		a->state.model_step = 1;
		return;
	}
	step_model(a, 1);
	a->model_at += every;
	if (a->model_at <= now_ns) /* asleep meanwhile: no catching up */
		a->model_at = now_ns + every;
}

static uint64_t advance(struct app *a, uint64_t now_ns)
{
	uint64_t prev = a->now_ns, at;
	const struct app_turn *t = a->turns;
	double yaw, pitch, speed = a->cfg.turn_speed;

	if (now_ns <= prev)
		return next_change(a);
	yaw = speed * (turn_seconds(&t[1], prev, now_ns) - turn_seconds(&t[0], prev, now_ns));
	pitch = speed * (turn_seconds(&t[3], prev, now_ns) - turn_seconds(&t[2], prev, now_ns));
	a->now_ns = now_ns;
	at = attract_at(a);
	if (yaw != 0.0 || pitch != 0.0)
		turn(a, yaw, pitch);
	if (!a->attract && !any_held(a) && at <= now_ns) {
		a->attract = true;
		/* A shared clock's schedule starts when it is due, not when
		 * this kiosk looked. */
		attract_begin(a, at > prev || a->cfg.shared_clock ? at : prev);
		a->model_at = a->attract_ns + (uint64_t)(a->cfg.attract_model_s * 1e9);
	}
	if (a->attract) {
		attract_move(a, now_ns);
		attract_models(a, now_ns);
	} else if (a->easing) {
		app_glide(a, now_ns);
	}
	return next_change(a);
}

uint64_t app_clock(const struct app *a, uint64_t now_ns)
{
	return now_ns + (uint64_t)a->cfg.clock_offset_ns;
}

uint64_t app_advance(struct app *a, uint64_t now_ns)
{
	uint64_t next = advance(a, app_clock(a, now_ns));

	return next == CLOCK_NEVER ? next : next - (uint64_t)a->cfg.clock_offset_ns;
}

static void set_camera_available(struct app *a, bool available)
{
	a->camera_available = available;
	if (!available && a->state.camera_on) {
		a->state.camera_on = false; /* back to the last image matcap */
		a->state.dirty = true;
	}
}

/* Lost while shown: back to it when it returns. A new frame is drawn
 * only while the camera is shown. */
static void camera(struct app *a, bool available, bool frame)
{
	if (available != a->camera_available) {
		if (!available && a->state.camera_on)
			a->camera_resume = true;
		set_camera_available(a, available);
		if (available && a->camera_resume) {
			a->state.camera_on = true;
			a->state.dirty = true;
			a->camera_resume = false;
		}
	}
	if (frame && a->state.camera_on)
		a->state.dirty = true;
}

/* Staying on the picture shown when it is still there. */
static void matcaps(struct app *a, int count, int shown)
{
	a->matcap_count = count;
	if (shown >= 0 && shown < entries(a))
		a->state.matcap = shown;
	else if (a->state.matcap >= entries(a))
		a->state.matcap = 0;
	a->state.dirty = true; /* it may be the very file that was rewritten */
}

/* The model on screen now (a model that failed was passed over, or the
 * list changed): the wanted one follows it. */
static void models(struct app *a, int count, int shown)
{
	a->model_count = count > 0 ? count : 1;
	if (shown >= 0 && shown < a->model_count)
		a->state.model = shown;
	else if (a->state.model >= a->model_count)
		a->state.model = 0;
	a->state.dirty = true;
}

static void reload(struct app *a, const struct app_config *cfg, int matcap_count, uint64_t now_ns)
{
	bool camera_on = a->state.camera_on, available = a->camera_available;
	bool resume = a->camera_resume;

	init(a, cfg, matcap_count, now_ns + (uint64_t)cfg->clock_offset_ns);
	a->camera_available = available;
	a->camera_resume = resume;
	a->state.camera_on = camera_on && available;
}

/* A shared clock's state from the epoch again, as at the start, at
 * time_ns (the caller's clock): the model list it was told of kept. */
static void restart(struct app *a, uint64_t time_ns)
{
	int models = a->model_count;
	struct app_config cfg = a->cfg; /* reload's init clears a->cfg first */

	reload(a, &cfg, a->matcap_count, time_ns);
	a->model_count = models;
}

void app_rewind(struct app *a, uint64_t time_ns)
{
	uint64_t t = app_clock(a, time_ns);
	struct app_event none = {.time_ns = time_ns, .action = ACTION_NONE};

	if (!a->cfg.shared_clock || t >= a->now_ns || t == 0)
		return;
	/* Advanced from just before then: the pure state then. */
	restart(a, time_ns - 1);
	advance(a, t);
	input(a, &none);
}

int64_t app_set_clock(struct app *a, int64_t offset_ns)
{
	int64_t step = offset_ns - a->cfg.clock_offset_ns;

	a->cfg.clock_offset_ns = offset_ns;
	if (!a->cfg.shared_clock || (step < APP_CLOCK_STEP_NS && step > -APP_CLOCK_STEP_NS))
		return 0;
	/* The others stepped too, or this one was wrong: from the epoch again. */
	restart(a, a->now_ns - (uint64_t)(offset_ns - step));
	return step;
}

/* Another model is shown: its own frame, from its start view. Attract
 * mode goes on from there. */
static void frame(struct app *a, const struct app_frame *f, struct quat rest,
		  enum shading_mode mode, uint64_t now_ns)
{
	a->cfg.frame = *f;
	a->cfg.rest = rest;
	a->cfg.mode = mode;
	a->state.mode = mode;
	app_frame_normalise(&a->cfg.frame);
	app_home(a);
	now_ns += (uint64_t)a->cfg.clock_offset_ns;
	/* On a shared clock the model's tour keeps attract mode's start:
	 * another kiosk loaded the model sooner or later. */
	if (a->attract && a->cfg.shared_clock)
		attract_begin(a, a->attract_from);
	else if (a->attract)
		attract_begin(a, now_ns > a->now_ns ? now_ns : a->now_ns);
}

void app_apply(struct app *a, const struct app_msg *m)
{
	switch (m->kind) {
	case APP_INPUT:
		input(a, &m->input);
		break;
	case APP_CAMERA:
		camera(a, m->camera.available, m->camera.frame);
		break;
	case APP_MATCAPS:
		matcaps(a, m->matcaps.count, m->matcaps.shown);
		break;
	case APP_RELOADED:
		reload(a, m->reload.config, m->reload.matcap_count, m->reload.now_ns);
		break;
	case APP_DISPLAY_BACK:
		a->state.dirty = true;
		break;
	case APP_FRAME_SHOWN:
		a->state.dirty = false;
		break;
	case APP_TOUCH:
		touch(a, &m->touch);
		break;
	case APP_MODELS:
		models(a, m->models.count, m->models.shown);
		break;
	case APP_FRAME:
		frame(a, m->frame.frame, m->frame.rest, m->frame.mode, m->frame.now_ns);
		break;
	}
}
