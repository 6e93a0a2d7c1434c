#include "app/kiosk.h"
#include "app/kiosk_anim.h"
#include "app/kiosk_report.h"
#include "app/kiosk_state.h"
#include "app/signals.h"
#include "state/app.h"
#include "app/kiosk_models.h"
#include "app/reload.h"
#include "ops/screen.h"
#include "ops/service.h"
#include "ops/status.h"
#include "camera/camera_feed.h"
#include "input/gpio.h"
#include "input/keyboard.h"
#include "input/knob_device.h"
#include "input/touch.h"
#include "util/clock.h"
#include "util/folder_watch.h"
#include "util/log.h"

#include <errno.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static bool awake(const struct kiosk *k)
{
	return !k->screen || screen_on(k->screen);
}

/* The screen's power decided again; a screen that just woke is drawn
 * whole, with the view as it is now. */
static void service_screen(struct kiosk *k, uint64_t now)
{
	if (k->screen && screen_update(k->screen, now))
		kiosk_tell_app(k, APP_DISPLAY_BACK);
}

static void start_screen(struct kiosk *k, uint64_t now)
{
	screen_free(k->screen);
	k->screen = screen_new(&k->applied.power, k->display, now);
	if (!k->screen)
		log_err("screen: its power cannot be managed; it stays on");
}

static int add_input(struct kiosk *k, struct input_source *s, enum input_origin origin)
{
	if (k->input_count == KIOSK_MAX_INPUTS) {
		log_warn("%s: too many input sources, ignored", s->name);
		s->destroy(s);
		return -ENOSPC;
	}
	k->origins[k->input_count] = origin;
	k->inputs[k->input_count++] = s;
	return 0;
}

int kiosk_add_input(struct kiosk *k, struct input_source *s)
{
	return add_input(k, s, INPUT_CALLER);
}

static void remove_input(struct kiosk *k, int i)
{
	size_t after = (size_t)(k->input_count - i - 1);

	k->inputs[i]->destroy(k->inputs[i]);
	memmove(&k->inputs[i], &k->inputs[i + 1], sizeof(k->inputs[0]) * after);
	memmove(&k->origins[i], &k->origins[i + 1], sizeof(k->origins[0]) * after);
	k->input_count--;
}

static void drop_input(struct kiosk *k, int i)
{
	log_warn("%s: input lost, running on without it", k->inputs[i]->name);
	remove_input(k, i);
}

static void close_inputs(struct kiosk *k, enum input_origin origin)
{
	for (int i = k->input_count - 1; i >= 0; i--)
		if (k->origins[i] == origin)
			remove_input(k, i);
}

/* Two buttons on one line is a config error: -EEXIST. */
static int open_buttons(struct kiosk *k)
{
	struct input_source *in[KIOSK_MAX_INPUTS];
	int n = gpio_open_buttons(&k->applied.buttons, in, KIOSK_MAX_INPUTS - k->input_count);

	for (int i = 0; i < n; i++)
		add_input(k, in[i], INPUT_BUTTON);
	return n < 0 ? n : 0;
}

/* The keyboards and the knobs: evdev devices both, opened again together. */
static void open_keyboards(struct kiosk *k)
{
	struct input_source *in[KIOSK_MAX_INPUTS];
	int n = keyboard_open(&k->applied.keyboard, in, KIOSK_MAX_INPUTS - k->input_count);

	n += knob_open(&k->applied.knob, in + n, KIOSK_MAX_INPUTS - k->input_count - n);
	for (int i = 0; i < n; i++)
		add_input(k, in[i], INPUT_KEYBOARD);
}

static void open_touch(struct kiosk *k)
{
	touch_free(k->touch);
	k->touch = touch_new(&k->applied.touch, k->applied.content.rotation);
}

static void start_camera(struct kiosk *k)
{
	camera_feed_free(k->camera);
	k->camera = camera_feed_new(&k->applied.camera, &k->display->gl, k->applied.shader_dir,
				    k->camera_possible);
}

int kiosk_open_devices(struct kiosk *k)
{
	int ret = open_buttons(k);

	if (ret)
		return ret;
	open_keyboards(k);
	open_touch(k);
	start_camera(k);
	return 0;
}

static void sync_mode(struct kiosk *k, enum shading_mode mode)
{
	if (mode == k->shown_mode && k->view.ortho == k->shown_ortho)
		return;
	if (renderer_set_mode(k->renderer, mode, k->view.ortho) == 0)
		log_info("mode %s", shading_mode_name(mode));
	k->shown_mode = mode;
	k->shown_ortho = k->view.ortho;
}

/* The input-to-frame latency, for the bench (input events carry the
 * kernel's timestamps). */
static void log_latency(struct kiosk *k, uint64_t last_input_ns)
{
	if (last_input_ns <= k->input_drawn_ns)
		return;
	k->input_drawn_ns = last_input_ns;
	log_debug("frame %ld presented %.1f ms after the input", k->frames_drawn,
		  (double)(app_clock(k->app, monotonic_ns()) - k->input_drawn_ns) / 1e6);
}

/* One output's picture of the frame (the only one where there is one):
 * the view as [output.NAME] turns it, the caption where it has one.
 * -EAGAIN: that output shows nothing now. */
static int draw_output(struct kiosk *k, const struct output_view *o)
{
	const struct app_state *st = app_state(k->app);
	struct display *d = k->display;
	struct view v = k->view;
	int w, h;

	output_view_apply(o, &v);
	if (d->begin_frame(d))
		return -EAGAIN;
	if (k->camera)
		renderer_use_matcap_texture(k->renderer,
					    camera_feed_draw(k->camera, st->camera_on));
	render_scale_begin(k->scale, d->plane_scaled, d->width, d->height, &w, &h);
	renderer_draw(k->renderer, &v, w, h);
	render_scale_end(k->scale);
	/* The frame is full size again: full-resolution overlays (the
	 * caption, the logo) draw here, at d->width x d->height, before the
	 * present. */
	if (!o || o->caption)
		kiosk_caption_draw(k, &v);
	return d->present(d);
}

/* Every output's picture ([display] outputs; one elsewhere). -EAGAIN when
 * none showed it. */
static int draw_outputs(struct kiosk *k)
{
	struct display *d = k->display;
	int n = d->select_output ? d->outputs : 1, shown = 0;

	for (int i = 0; i < n; i++) {
		int ret;

		if (d->select_output && d->select_output(d, i))
			continue;
		ret = draw_output(k, output_view_find(&k->applied.outputs, d->output_name));
		if (ret && ret != -EAGAIN && n == 1)
			return ret;
		/* One of several that fails leaves the others running: said
		 * when it starts failing and when it shows again. */
		if (n > 1 && ret != -EAGAIN && !!ret != !!(k->outputs_failed & (1u << i))) {
			k->outputs_failed ^= 1u << i;
			if (ret)
				log_err(
				    "kms: %s: cannot show the frame: %s; the other outputs go on",
				    d->output_name, strerror(-ret));
			else
				log_info("kms: %s shows frames again", d->output_name);
		}
		shown += !ret;
	}
	/* The first output is the one read back (--status's frame) and
	 * measured between frames. */
	if (n > 1)
		d->select_output(d, 0);
	return shown ? 0 : -EAGAIN;
}

static int draw(struct kiosk *k, uint64_t now)
{
	const struct app_state *st = app_state(k->app);
	struct display *d = k->display;
	int ret;

	sync_mode(k, st->mode);
	k->view.orientation = st->orientation;
	/* Pinching scales the fitted picture ([scene] fit). */
	k->view.zoom = (float)(st->zoom * (k->content->zoom > 0 ? k->content->zoom : 1.0));
	content_place_view(k->content, &k->view);
	/* Not connected, or waiting for the display: stay dirty, the display
	 * asks for a redraw through dispatch() when it is back. */
	k->display_absent = true;
	ret = draw_outputs(k);
	if (ret == -EAGAIN)
		return 0;
	k->display_absent = false;
	k->waiting_since = now;
	if (ret) {
		log_err("%s: cannot show the frame: %s", d->name, strerror(-ret));
		return ret;
	}
	k->frames_drawn++;
	kiosk_clock_presented(k);
	kiosk_tell_app(k, APP_FRAME_SHOWN);
	log_latency(k, st->last_input_ns);
	return 0;
}

static void start_models(struct kiosk *k, uint64_t now_ns)
{
	struct kiosk_models_parts parts = {k->app,     k->content,	    k->renderer,
					   k->display, &k->applied.content, k->worker,
					   &k->counts, kiosk_look_changed,  k};

	kiosk_models_free(k->models);
	k->models = kiosk_models_new(&parts, now_ns);
}

/* The app state, the view and the matcap watch from k->applied and
 * k->content (at the start, and after a reload). */
static int configure(struct kiosk *k, uint64_t now_ns)
{
	const struct options *o = &k->applied;
	struct app_config cfg = o->app;
	int count = k->content->set ? matcap_set_count(k->content->set) : 1;
	struct app_msg m = {.kind = APP_RELOADED, .reload = {&cfg, count, now_ns}};

	log_set_level(o->log_level);
	const struct content_config *shown = content_settings(k->content, &o->content);

	k->view = content_view(shown);
	content_app_frame_at(k->content, shown, &cfg.frame, &cfg.rest);
	cfg.mode = shown->mode;
	cfg.clock_offset_ns = kiosk_clock_offset(k);
	if (k->app)
		app_apply(k->app, &m);
	else
		k->app = app_new(&cfg, count, now_ns);
	/* content_upload gave the renderer the set's first image. */
	kiosk_matcap_settled(k, 0);
	kiosk_watch_matcaps(k);
	if (!k->app)
		return -ENOMEM;
	start_models(k, now_ns);
	return 0;
}

static void reopen_devices(struct kiosk *k, unsigned sections)
{
	if (sections & 1u << OPTIONS_BUTTONS) {
		log_info("reload: [buttons] changed: opening the buttons again");
		close_inputs(k, INPUT_BUTTON);
		if (open_buttons(k))
			log_err("reload: two buttons are one line; running on without buttons");
	}
	if (sections & (1u << OPTIONS_KEYBOARD | 1u << OPTIONS_KNOB)) {
		log_info(
		    "reload: [keyboard] or [knob] changed: opening the keyboards and knobs again");
		close_inputs(k, INPUT_KEYBOARD);
		open_keyboards(k);
	}
	if (sections & 1u << OPTIONS_CAMERA) {
		log_info("reload: [camera] changed: starting the camera again");
		start_camera(k);
	}
	if (sections & 1u << OPTIONS_POWER) {
		log_info("reload: [power] changed: deciding the screen's power again");
		start_screen(k, monotonic_ns());
	}
	if (sections & 1u << OPTIONS_TOUCH) {
		log_info("reload: [touch] changed: opening the touchscreens again");
		open_touch(k);
	}
}

/* A reload's content is on the screen (kiosk_content.c): its settings
 * now, and the devices whose sections changed opened again; then the
 * reload is over for systemd. */
static void apply_reload(struct kiosk *k, uint64_t now_ns)
{
	unsigned reopen = reload_reopen(&k->started, &k->applied, &k->reload.fresh);

	metrics_follow(&k->metrics, k->reload.fresh.metrics);
	options_release(&k->applied);
	k->applied = k->reload.fresh;
	memset(&k->reload.fresh, 0, sizeof(k->reload.fresh)); /* k->applied owns it now */
	configure(k, now_ns);
	if (k->touch)
		touch_set_rotation(k->touch, k->applied.content.rotation);
	reopen_devices(k, reopen);
	log_info("reload: done (%ld frames drawn meanwhile)", k->frames_drawn - k->reload_frames);
	k->counts.reloads++;
	service_reloading(true);
}

/* SIGHUPs queued together are one reload. */
static enum signals_seen read_signals(struct kiosk *k, int fd)
{
	enum signals_seen seen = signals_read(fd);

	/* The content is loaded on the worker: the loop draws, flips and
	 * pings the watchdog meanwhile. */
	if (seen == SIGNALS_HUP)
		kiosk_content_reload(k);
	return seen;
}

static void read_input(struct kiosk *k, int i, uint64_t now)
{
	struct app_event ev[MAX_EVENTS];
	int n = k->inputs[i]->read(k->inputs[i], now, ev, MAX_EVENTS);

	if (n < 0) {
		drop_input(k, i);
		return;
	}
	for (int e = 0; e < n; e++) {
		struct app_msg m = {.kind = APP_INPUT, .input = ev[e]};

		visits_press(&k->visits, k->inputs[i]->kind, &ev[e],
			     k->applied.app.attract_after_s);
		/* Any input wakes a sleeping screen; it also does what it does. */
		if (k->screen && screen_input(k->screen, now))
			kiosk_tell_app(k, APP_DISPLAY_BACK);
		app_apply(k->app, &m);
	}
}

/* Gestures are inputs: they wake a sleeping screen and do what they do. */
static void service_touch(struct kiosk *k, const struct pollfd *fds, uint64_t now)
{
	struct app_msg m = {.kind = APP_TOUCH};
	struct gesture g[MAX_EVENTS];
	int n;

	if (!k->touch || (!(fds[FD_TOUCH].revents & POLLIN) && touch_deadline(k->touch) > now))
		return;
	n = touch_dispatch(k->touch, now, g, MAX_EVENTS);
	for (int i = 0; i < n; i++) {
		if (k->screen && screen_input(k->screen, now))
			kiosk_tell_app(k, APP_DISPLAY_BACK);
		m.touch = g[i];
		visits_touch(&k->visits, &g[i], k->applied.app.long_press,
			     k->applied.app.attract_after_s);
		if (g[i].kind == GESTURE_TAP)
			m.touch.badge = content_hotspot_tapped(k->content, k->renderer, &k->view,
							       k->display->width,
							       k->display->height, g[i].x, g[i].y);
		app_apply(k->app, &m);
	}
}

static int poll_timeout_ms(struct kiosk *k, uint64_t deadline, uint64_t now)
{
	for (int i = 0; i < k->input_count; i++) {
		uint64_t d = k->inputs[i]->deadline(k->inputs[i]);

		deadline = d < deadline ? d : deadline;
	}
	if (k->touch && touch_deadline(k->touch) < deadline)
		deadline = touch_deadline(k->touch);
	if (deadline == CLOCK_NEVER)
		return -1;
	return deadline <= now ? 0 : (int)((deadline - now + 999999) / 1000000);
}

static int fill_fds(struct kiosk *k, struct pollfd *fds, int sig_fd)
{
	fds[FD_SIGNAL] = (struct pollfd){.fd = sig_fd, .events = POLLIN};
	fds[FD_DISPLAY] = (struct pollfd){.fd = k->display->get_fd(k->display), .events = POLLIN};
	fds[FD_WATCH] =
	    (struct pollfd){.fd = k->watch ? folder_watch_fd(k->watch) : -1, .events = POLLIN};
	fds[FD_CAMERA] =
	    (struct pollfd){.fd = k->camera ? camera_feed_fd(k->camera) : -1, .events = POLLIN};
	fds[FD_STATUS] = (struct pollfd){.fd = status_server_fd(k->status), .events = POLLIN};
	fds[FD_TOUCH] = (struct pollfd){.fd = k->touch ? touch_fd(k->touch) : -1, .events = POLLIN};
	fds[FD_WORKER] = (struct pollfd){.fd = worker_fd(k->worker), .events = POLLIN};
	kiosk_models_fill_fds(k->models, &fds[FD_MODEL_WATCH]);
	fds[FD_MQTT] = (struct pollfd){.fd = kiosk_remote_fd(k), .events = POLLIN};
	for (int i = 0; i < k->input_count; i++)
		fds[FD_INPUTS + i] = (struct pollfd){.fd = k->inputs[i]->fd, .events = POLLIN};
	return FD_INPUTS + k->input_count;
}

static void service_inputs(struct kiosk *k, const struct pollfd *fds, uint64_t now)
{
	/* Backwards, so a dropped source does not shift the ones to come. */
	for (int i = k->input_count - 1; i >= 0; i--)
		if ((fds[FD_INPUTS + i].revents & (POLLIN | POLLERR | POLLHUP)) ||
		    k->inputs[i]->deadline(k->inputs[i]) <= now)
			read_input(k, i, now);
}

/* READY=1 once a frame is on the screen: right after present() for a
 * backend that never waits, after the page flip for one that does. With
 * no display at all, waiting for one is the running state. The watchdog
 * is pinged only while page flips complete, so a hung driver restarts us. */
static void tell_service(struct kiosk *k, uint64_t now)
{
	bool stuck = k->display->waiting && now - k->waiting_since > k->service.ping_ns;

	/* A second frame is drawn only after the first one's flip: while the
	 * model turns, a flip is pending whenever this runs. */
	if (k->frames_drawn > 1 || (k->frames_drawn > 0 && !k->display->waiting))
		service_ready(&k->service, true);
	else if (k->display_absent)
		service_ready(&k->service, false);
	service_ping(&k->service, now, !stuck);
}

static uint64_t earliest(uint64_t a, uint64_t b, uint64_t c)
{
	uint64_t ab = a < b ? a : b;

	return ab < c ? ab : c;
}

/* What the camera found goes to the app state; it streams while shown. */
static void service_camera(struct kiosk *k, short revents)
{
	struct camera_feed_report r =
	    camera_feed_service(k->camera, revents, k->display->waiting, monotonic_ns());
	struct app_msg m = {.kind = APP_CAMERA, .camera = {r.available, r.frame}};

	app_apply(k->app, &m);
	/* A sleeping screen shows no camera: it need not stream. */
	camera_feed_stream(k->camera, app_state(k->app)->camera_on && awake(k));
}

/* A page flip done or a display plugged in; < 0: the display is gone. */
static int service_display(struct kiosk *k, const struct pollfd *fds)
{
	int ret;

	if (!(fds[FD_DISPLAY].revents & POLLIN))
		return 0;
	ret = k->display->dispatch(k->display);
	if (ret < 0) {
		log_err("%s: display failed", k->display->name);
		return ret;
	}
	kiosk_clock_flipped(k);
	if (ret > 0)
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	return 0;
}

static void note_step(struct kiosk *k)
{
	uint64_t step = k->woke_ns ? monotonic_ns() - k->woke_ns : 0;

	if (step > k->longest_step_ns)
		k->longest_step_ns = step;
	if (!k->reload_timed)
		return;
	if (step > k->reload_longest_ns)
		k->reload_longest_ns = step;
	/* The pass after the upload has drawn the new content: done. */
	if (k->reload_applied) {
		log_info("reload: the loop's longest step during it took %.1f ms",
			 (double)k->reload_longest_ns / 1e6);
		k->reload_timed = false;
	}
}

/* One pass: draw when the state changed, sleep until something happens,
 * and hand it on. Returns 1 to stop, 0 to go on, or a negative errno. */
static int loop_once(struct kiosk *k, int sig_fd)
{
	struct pollfd fds[FD_INPUTS + KIOSK_MAX_INPUTS];
	uint64_t now = monotonic_ns(), next;
	enum signals_seen sig = SIGNALS_NONE;
	int n, ret;

	kiosk_follow_clock(k);
	next = earliest(app_advance(k->app, now), kiosk_caption_deadline(k, now), CLOCK_NEVER);

	service_screen(k, now);
	kiosk_content_start_jobs(k);
	next = earliest(next, kiosk_play_animation(k, now, awake(k)), CLOCK_NEVER);
	kiosk_show_variant(k);
	kiosk_show_language(k, now);
	if (app_state(k->app)->dirty && awake(k) && !k->display->waiting && (ret = draw(k, now)))
		return ret;
	service_camera(k, 0);
	kiosk_remote_publish(k);
	tell_service(k, now);
	/* Asleep, nothing is drawn: what moves by itself need not wake us. */
	if (!awake(k))
		next = CLOCK_NEVER;
	if (k->screen)
		next = earliest(next, screen_deadline(k->screen, now), CLOCK_NEVER);
	next = earliest(next, k->rescan_at, service_deadline(&k->service));
	next = earliest(next, kiosk_models_deadline(k->models), metrics_deadline(k->metrics));
	kiosk_observe_visits(k, now);
	next = earliest(next, kiosk_content_deadline(k), kiosk_remote_deadline(k, now));
	n = fill_fds(k, fds, sig_fd);
	note_step(k);
	if (poll(fds, (nfds_t)n, poll_timeout_ms(k, next, now)) < 0 && errno != EINTR)
		return -errno;
	k->woke_ns = monotonic_ns();
	if (fds[FD_SIGNAL].revents & POLLIN)
		sig = read_signals(k, sig_fd);
	if (sig == SIGNALS_QUIT)
		return 1;
	/* After a reload was applied the inputs and the camera may be new:
	 * their revents are stale, and the next poll asks again. */
	if (kiosk_content_service(k, fds)) {
		apply_reload(k, monotonic_ns());
		return 0;
	}
	if ((ret = service_display(k, fds)))
		return ret;
	service_camera(k, fds[FD_CAMERA].revents);
	if (fds[FD_STATUS].revents & POLLIN)
		kiosk_report_status(k);
	kiosk_report_metrics(k, monotonic_ns(), false);
	kiosk_service_matcaps(k, fds, monotonic_ns());
	service_inputs(k, fds, monotonic_ns());
	service_touch(k, fds, monotonic_ns());
	kiosk_remote_service(k, fds[FD_MQTT].revents, monotonic_ns());
	/* After the inputs: a step to another model starts at once. */
	kiosk_models_service(k->models, &fds[FD_MODEL_WATCH], monotonic_ns());
	return 0;
}

int kiosk_run(struct kiosk *k)
{
	int sig_fd = signals_open();
	int ret = 0;

	if (sig_fd < 0) {
		log_err("cannot watch signals: %s", strerror(-sig_fd));
		return sig_fd;
	}
	service_init(&k->service, monotonic_ns());
	k->status = status_server_new();
	metrics_follow(&k->metrics, k->applied.metrics);
	kiosk_remote_start(k);
	while (!(ret = loop_once(k, sig_fd)))
		;
	service_stopping();
	log_info("loop: the longest step between two sleeps took %.1f ms",
		 (double)k->longest_step_ns / 1e6);
	kiosk_report_metrics(k, monotonic_ns(), true);
	kiosk_remote_stop(k);
	status_server_free(k->status);
	k->status = NULL;
	close(sig_fd);
	return ret < 0 ? ret : 0;
}

struct kiosk *kiosk_new(const struct kiosk_parts *p, uint64_t now_ns)
{
	struct kiosk *k = calloc(1, sizeof(*k));

	if (!k)
		return NULL;
	k->display = p->display;
	k->renderer = p->renderer;
	k->content = p->content;
	k->argv = p->argv;
	while (p->argv[k->argc])
		k->argc++;
	k->camera_possible = p->camera_possible;
	k->started_ns = now_ns;
	k->started_at = (double)clock_ns(CLOCK_REALTIME) / 1e9;
	/* The renderer already holds the mode. */
	k->shown_mode = p->options->content.mode;
	k->shown_ortho = p->options->content.ortho;
	k->scale = render_scale_new(&p->display->gl, p->options->display.render_scale,
				    p->display->samples, p->options->shader_dir);
	k->anim = kiosk_anim_new();
	if (!k->scale || !k->anim || kiosk_content_start(k) ||
	    options_copy(&k->started, p->options) || options_copy(&k->applied, p->options) ||
	    configure(k, now_ns)) {
		kiosk_free(k);
		return NULL;
	}
	start_screen(k, now_ns);
	return k;
}

void kiosk_free(struct kiosk *k)
{
	if (!k)
		return;
	close_inputs(k, INPUT_CALLER);
	close_inputs(k, INPUT_BUTTON);
	close_inputs(k, INPUT_KEYBOARD);
	camera_feed_free(k->camera);
	touch_free(k->touch);
	screen_free(k->screen);
	folder_watch_free(k->watch);
	/* The worker first: a job under way is its until joined. */
	kiosk_content_stop(k);
	kiosk_models_free(k->models);
	metrics_free(k->metrics);
	app_free(k->app);
	render_scale_free(k->scale);
	kiosk_anim_free(k->anim);
	options_release(&k->started);
	options_release(&k->applied);
	free(k);
}

long kiosk_frames_drawn(const struct kiosk *k)
{
	return k->frames_drawn;
}

const struct app_state *kiosk_app_state(const struct kiosk *k)
{
	return app_state(k->app);
}

bool kiosk_reloading(const struct kiosk *k)
{
	return k->reload_wanted || k->reload.busy;
}

void kiosk_print_stats(const struct kiosk *k, FILE *out)
{
	fprintf(out, "loop longest_step_ms %.1f\n", (double)k->longest_step_ns / 1e6);
	camera_feed_print_stats(k->camera, out);
}
