#include "app/kiosk.h"
#include "util/clock.h"
#include "util/log.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/signalfd.h>
#include <time.h>
#include <unistd.h>

#define MAX_EVENTS 32

/* Matcaps being copied into the folder: act once the copy has been quiet
 * this long, so a burst of files is one rescan. */
#define MATCAP_SETTLE_NS 500000000ull

enum { FD_SIGNAL, FD_DISPLAY, FD_WATCH, FD_CAMERA, FD_INPUTS };

int kiosk_add_input(struct kiosk *k, struct input_source *s)
{
	if (k->input_count == KIOSK_MAX_INPUTS) {
		log_warn("%s: too many input sources, ignored", s->name);
		s->destroy(s);
		return -ENOSPC;
	}
	k->inputs[k->input_count++] = s;
	return 0;
}

static void drop_input(struct kiosk *k, int i)
{
	log_warn("%s: input lost, running on without it", k->inputs[i]->name);
	k->inputs[i]->destroy(k->inputs[i]);
	memmove(&k->inputs[i], &k->inputs[i + 1],
		sizeof(k->inputs[0]) * (size_t)(k->input_count - i - 1));
	k->input_count--;
}

/* Decoding a matcap is done here, when it is shown, so a folder of many
 * large images costs one image of memory. A file that fails keeps the
 * previous texture and says so. */
static void sync_matcap(struct kiosk *k)
{
	struct image img;
	int want = k->app.matcap;

	if (want == k->shown_matcap || !k->scene->set)
		return;
	if (image_load(matcap_set_path(k->scene->set, want), &img) == 0) {
		renderer_set_matcap(k->renderer, &img);
		image_release(&img);
		log_info("matcap %s", matcap_set_path(k->scene->set, want));
	}
	k->shown_matcap = want;
}

static int draw(struct kiosk *k, uint64_t now)
{
	int ret;

	if (k->app.mode != k->shown_mode || k->view.ortho != k->shown_ortho) {
		if (renderer_set_mode(k->renderer, k->app.mode, k->view.ortho) == 0)
			log_info("mode %s", shading_mode_name(k->app.mode));
		k->shown_mode = k->app.mode;
		k->shown_ortho = k->view.ortho;
	}
	sync_matcap(k);
	k->view.orientation = k->app.orientation;
	/* Not connected, or waiting for the display: stay dirty, the display
	 * asks for a redraw through dispatch() when it is back. */
	k->display_absent = true;
	if (k->display->begin_frame(k->display))
		return 0;
	if (k->camera)
		renderer_use_matcap_texture(k->renderer, camera_feed_draw(k->camera, &k->app));
	renderer_draw(k->renderer, &k->view, k->display->width, k->display->height);
	ret = k->display->present(k->display);
	if (ret == -EAGAIN)
		return 0;
	k->display_absent = false;
	k->waiting_since = now;
	if (ret) {
		log_err("%s: cannot show the frame: %s", k->display->name, strerror(-ret));
		return ret;
	}
	k->frames_drawn++;
	k->app.dirty = false;
	/* The input-to-frame latency, for the bench (input events carry the
	 * kernel's timestamps). */
	if (k->app.last_input_ns > k->input_drawn_ns) {
		k->input_drawn_ns = k->app.last_input_ns;
		log_debug("frame %ld presented %.1f ms after the input", k->frames_drawn,
			  (double)(monotonic_ns() - k->input_drawn_ns) / 1e6);
	}
	return 0;
}

static void loop_signals(sigset_t *set)
{
	sigemptyset(set);
	sigaddset(set, SIGTERM);
	sigaddset(set, SIGINT);
	sigaddset(set, SIGHUP);
}

int kiosk_block_signals(void)
{
	sigset_t set;

	loop_signals(&set);
	return sigprocmask(SIG_BLOCK, &set, NULL) ? -errno : 0;
}

int kiosk_unblock_signals(void)
{
	sigset_t set;

	loop_signals(&set);
	return sigprocmask(SIG_UNBLOCK, &set, NULL) ? -errno : 0;
}

static int open_signals(void)
{
	sigset_t set;

	int fd;

	loop_signals(&set);
	fd = signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK);
	return fd < 0 ? -errno : fd;
}

/* True when the loop should stop. SIGHUPs queued together are one reload. */
static bool read_signals(struct kiosk *k, int fd)
{
	struct signalfd_siginfo si;
	bool quit = false, reload = false;

	while (read(fd, &si, sizeof(si)) == sizeof(si)) {
		if (si.ssi_signo == SIGHUP) {
			reload = true;
			continue;
		}
		log_info("%s: shutting down", strsignal((int)si.ssi_signo));
		quit = true;
	}
	if (reload && !quit) {
		bool camera_on = k->app.camera_on;

		/* A large model may take a while: the watchdog must not
		 * run out meanwhile. */
		service_keepalive(&k->service, monotonic_ns());
		kiosk_reload(k, monotonic_ns());
		/* The app state starts afresh; a live camera stays on. */
		k->app.camera_on = camera_on && k->app.cfg.camera_available;
	}
	return quit;
}

static void read_input(struct kiosk *k, int i, uint64_t now)
{
	struct app_event ev[MAX_EVENTS];
	int n = k->inputs[i]->read(k->inputs[i], now, ev, MAX_EVENTS);

	if (n < 0) {
		drop_input(k, i);
		return;
	}
	for (int e = 0; e < n; e++)
		app_handle(&k->app, &ev[e]);
}

static int poll_timeout_ms(struct kiosk *k, uint64_t deadline, uint64_t now)
{
	for (int i = 0; i < k->input_count; i++) {
		uint64_t d = k->inputs[i]->deadline(k->inputs[i]);

		deadline = d < deadline ? d : deadline;
	}
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

static void service_matcaps(struct kiosk *k, const struct pollfd *fds, uint64_t now)
{
	if ((fds[FD_WATCH].revents & POLLIN) && k->watch && folder_watch_read(k->watch))
		k->rescan_at = now + MATCAP_SETTLE_NS;
	if (now >= k->rescan_at)
		kiosk_rescan_matcaps(k);
}

int kiosk_run(struct kiosk *k)
{
	struct pollfd fds[FD_INPUTS + KIOSK_MAX_INPUTS];
	int sig_fd = open_signals();
	int ret = 0;

	if (sig_fd < 0) {
		log_err("cannot watch signals: %s", strerror(-sig_fd));
		return sig_fd;
	}
	service_init(&k->service, monotonic_ns());
	for (;;) {
		uint64_t now = monotonic_ns();
		uint64_t next = app_advance(&k->app, now);
		int n;

		if (k->app.dirty && !k->display->waiting && (ret = draw(k, now)))
			break;
		camera_feed_service(k->camera, &k->app, 0, k->display->waiting, monotonic_ns());
		tell_service(k, now);
		next = earliest(next, k->rescan_at, service_deadline(&k->service));
		n = fill_fds(k, fds, sig_fd);
		if (poll(fds, (nfds_t)n, poll_timeout_ms(k, next, now)) < 0 && errno != EINTR) {
			ret = -errno;
			break;
		}
		if ((fds[FD_SIGNAL].revents & POLLIN) && read_signals(k, sig_fd))
			break;
		if (fds[FD_DISPLAY].revents & POLLIN) {
			ret = k->display->dispatch(k->display);
			if (ret < 0) {
				log_err("%s: display failed", k->display->name);
				break;
			}
			k->app.dirty |= ret > 0;
			ret = 0;
		}
		camera_feed_service(k->camera, &k->app, fds[FD_CAMERA].revents, k->display->waiting,
				    monotonic_ns());
		service_matcaps(k, fds, monotonic_ns());
		service_inputs(k, fds, monotonic_ns());
	}
	service_stopping();
	close(sig_fd);
	return ret;
}
