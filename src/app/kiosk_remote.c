/* The loop's side of remote control ([mqtt], src/ops/mqtt.c): commands
 * taken from the client's queue (already checked on its thread) become
 * the actions a button would give, the screen's power or a reload; the
 * state shown goes back out when it changed. */
#include "app/kiosk_state.h"
#include "ops/mqtt.h"
#include "ops/screen.h"
#include "util/clock.h"
#include "util/log.h"

#include <strings.h>
#include <time.h>

/* A leader's clock further ahead than this is not waited for: shown at
 * once, and said (the clocks are not in step: chrony). */
#define SYNC_WAIT_MAX_MS 10000ull

/* A press and its release of action at now: what a button gives. */
static void press(struct kiosk *k, enum app_action action, uint64_t now)
{
	struct app_msg m = {.kind = APP_INPUT, .input = {now, action, true}};

	app_apply(k->app, &m);
	m.input.pressed = false;
	app_apply(k->app, &m);
}

/* index (1-based) of count reached from shown (-1: none) by next presses. */
static int presses_to(int index, int shown, int count)
{
	return shown < 0 ? index : ((index - 1 - shown) % count + count) % count;
}

/* By step, a press; by number, as many next presses as reach it. */
static void step_or_go(struct kiosk *k, const struct remote_cmd *c, enum app_action next,
		       enum app_action prev, int shown, int count, uint64_t now)
{
	if (c->step) {
		press(k, c->step > 0 ? next : prev, now);
		return;
	}
	if (c->index > count) {
		log_warn("mqtt: '%s %d': there are %d; ignored",
			 c->verb == REMOTE_STOP ? "stop" : "matcap", c->index, count);
		return;
	}
	for (int i = presses_to(c->index, shown, count); i > 0; i--)
		press(k, next, now);
}

static int stop_count(const struct kiosk *k)
{
	struct app_frame f;
	struct quat rest;

	content_app_frame(content_settings(k->content, &k->applied.content), &f, &rest);
	return f.stop_count;
}

static void screen(struct kiosk *k, bool on, uint64_t now)
{
	if (!k->screen) {
		log_warn("mqtt: 'screen %s': the screen's power cannot be managed here; ignored",
			 on ? "on" : "off");
		return;
	}
	if (screen_remote(k->screen, on, now))
		kiosk_tell_app(k, APP_DISPLAY_BACK);
}

/* language TAG: as many next-language presses as reach it among the
 * model's [caption] languages (tags compared as BCP 47 does, whatever
 * the case). */
static void language(struct kiosk *k, const char *tag, uint64_t now)
{
	char codes[LANG_MAX][LANG_CODE_MAX];
	int n = content_languages(content_settings(k->content, &k->applied.content), codes), i = 0;

	while (i < n && strcasecmp(codes[i], tag))
		i++;
	if (i == n) {
		log_warn("mqtt: 'language %s': not one of this model's [caption] languages (%d "
			 "named); ignored",
			 tag, n);
		return;
	}
	for (int p = presses_to(i + 1, k->lang.pick.chosen, n); p > 0; p--)
		press(k, ACTION_NEXT_LANGUAGE, now);
}

static void apply(struct kiosk *k, const struct remote_cmd *c, uint64_t now)
{
	const struct app_state *st = app_state(k->app);
	int matcaps = k->content->set ? matcap_set_count(k->content->set) : 1;

	switch (c->verb) {
	case REMOTE_MODEL:
		press(k, c->step > 0 ? ACTION_NEXT_MODEL : ACTION_PREV_MODEL, now);
		break;
	case REMOTE_MATCAP:
		step_or_go(k, c, ACTION_NEXT_MATCAP, ACTION_PREV_MATCAP, st->matcap, matcaps, now);
		break;
	case REMOTE_STOP:
		step_or_go(k, c, ACTION_NEXT_STOP, ACTION_PREV_STOP, st->stop, stop_count(k), now);
		break;
	case REMOTE_VARIANT:
		press(k, ACTION_NEXT_VARIANT, now);
		break;
	case REMOTE_LANGUAGE:
		language(k, c->language, now);
		break;
	case REMOTE_SCREEN:
		screen(k, c->on, now);
		break;
	case REMOTE_RELOAD:
		kiosk_content_reload(k);
		break;
	}
}

void kiosk_remote_start(struct kiosk *k)
{
	k->remote.link = mqtt_link_new(&k->started.mqtt);
}

void kiosk_remote_stop(struct kiosk *k)
{
	mqtt_link_free(k->remote.link);
	k->remote.link = NULL;
}

int kiosk_remote_fd(const struct kiosk *k)
{
	return mqtt_link_fd(k->remote.link);
}

static unsigned long long wall_ms(void)
{
	return clock_ns(CLOCK_REALTIME) / 1000000ull;
}

/* A leader's step shown: what differs, by the presses that reach it. */
static void follow(struct kiosk *k, const struct remote_sync *s, uint64_t now)
{
	const struct app_state *st = app_state(k->app);
	int matcaps = k->content->set ? matcap_set_count(k->content->set) : 1;
	int models = kiosk_models_count(k->models), stops = stop_count(k);

	log_info("mqtt: the leader's step: model %d, matcap %d, stop %d", s->model + 1,
		 s->matcap + 1, s->stop + 1);
	if (s->model >= 0 && s->model < models && s->model != st->model)
		for (int i = presses_to(s->model + 1, st->model, models); i > 0; i--)
			press(k, ACTION_NEXT_MODEL, now);
	if (s->matcap < matcaps && s->matcap != st->matcap)
		for (int i = presses_to(s->matcap + 1, st->matcap, matcaps); i > 0; i--)
			press(k, ACTION_NEXT_MATCAP, now);
	if (s->stop >= 0 && s->stop < stops && s->stop != st->stop)
		for (int i = presses_to(s->stop + 1, st->stop, stops); i > 0; i--)
			press(k, ACTION_NEXT_STOP, now);
}

/* A follower's step waits for its time on the wall clock. */
static void service_step(struct kiosk *k, uint64_t now)
{
	struct remote_sync s;
	unsigned long long wall;

	if (mqtt_link_take_sync(k->remote.link, &s)) {
		k->remote.due = s;
		k->remote.due_any = true;
	}
	if (!k->remote.due_any)
		return;
	wall = wall_ms();
	if (k->remote.due.at_ms > wall + SYNC_WAIT_MAX_MS)
		log_warn("mqtt: the leader's step is %.1f s ahead of this clock: shown now (are "
			 "both clocks synchronised? chrony)",
			 (double)(k->remote.due.at_ms - wall) / 1e3);
	else if (k->remote.due.at_ms > wall)
		return;
	k->remote.due_any = false;
	/* On a shared clock the step is taken at the leader's time, from the
	 * state as it was then, so that attract mode comes back on both
	 * together, however late the step came (a retained one after a
	 * restart). */
	if (k->applied.app.shared_clock) {
		now = k->remote.due.at_ms * 1000000ull - (uint64_t)k->clock_offset;
		app_rewind(k->app, now);
	}
	follow(k, &k->remote.due, now);
}

void kiosk_remote_service(struct kiosk *k, short revents, uint64_t now)
{
	struct remote_cmd cmds[MQTT_QUEUE];
	char said[64];
	int n;

	if (revents & POLLIN) {
		n = mqtt_link_take(k->remote.link, cmds, MQTT_QUEUE);
		for (int i = 0; i < n; i++) {
			remote_describe(&cmds[i], said, sizeof(said));
			log_info("mqtt: %s", said);
			apply(k, &cmds[i], now);
		}
	}
	if (k->remote.link && k->started.mqtt.sync == MQTT_SYNC_FOLLOWER)
		service_step(k, now);
}

uint64_t kiosk_remote_deadline(const struct kiosk *k, uint64_t now)
{
	unsigned long long wall;

	if (!k->remote.due_any)
		return CLOCK_NEVER;
	wall = wall_ms();
	return k->remote.due.at_ms > wall ? now + (k->remote.due.at_ms - wall) * 1000000ull : now;
}

/* A leader's step when what it shows changed: the wall clock it shows it
 * from, for the followers. */
static void lead(struct kiosk *k)
{
	const struct app_state *st = app_state(k->app);
	struct remote_sync s = {wall_ms(), kiosk_models_count(k->models) ? st->model : -1,
				st->matcap, st->stop};

	/* On a shared clock every kiosk follows attract mode by itself: a
	 * step is sent for a press, with the press's time. */
	if (k->applied.app.shared_clock) {
		if (st->last_input_ns == k->remote.sent_input_ns)
			return;
		k->remote.sent_input_ns = st->last_input_ns;
		s.at_ms = st->last_input_ns / 1000000ull;
	}
	if (k->remote.sent_any && s.model == k->remote.sent.model &&
	    s.matcap == k->remote.sent.matcap && s.stop == k->remote.sent.stop)
		return;
	k->remote.sent = s;
	k->remote.sent_any = true;
	mqtt_link_publish_sync(k->remote.link, &s);
}

void kiosk_remote_publish(struct kiosk *k)
{
	const struct app_state *st;
	struct remote_state r;
	char error[512];

	if (!k->remote.link)
		return;
	st = app_state(k->app);
	log_last_error(error, sizeof(error));
	r = (struct remote_state){.model = remote_basename(k->content->model_path),
				  .matcap = k->content->set ? remote_basename(matcap_set_path(
								  k->content->set, st->matcap))
							    : NULL,
				  .stop = st->stop + 1,
				  .screen_on = !k->screen || screen_on(k->screen),
				  .error = error};
	mqtt_link_publish_state(k->remote.link, &r);
	if (k->started.mqtt.sync == MQTT_SYNC_LEADER)
		lead(k);
}
