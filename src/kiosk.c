#include "kiosk.h"
#include "log.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/signalfd.h>
#include <time.h>
#include <unistd.h>

#define MAX_EVENTS 32

enum { FD_SIGNAL, FD_DISPLAY, FD_INPUTS };

static uint64_t monotonic_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

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

	if (want == k->shown_matcap || !k->matcaps)
		return;
	if (image_load(matcap_set_path(k->matcaps, want), &img) == 0) {
		renderer_set_matcap(k->renderer, &img);
		image_release(&img);
		log_info("matcap %s", matcap_set_path(k->matcaps, want));
	}
	k->shown_matcap = want;
}

static void draw(struct kiosk *k)
{
	if (k->app.mode != k->shown_mode || k->view.ortho != k->shown_ortho) {
		if (renderer_set_mode(k->renderer, k->app.mode, k->view.ortho) == 0)
			log_info("mode %s", shading_mode_name(k->app.mode));
		k->shown_mode = k->app.mode;
		k->shown_ortho = k->view.ortho;
	}
	sync_matcap(k);
	k->view.orientation = k->app.orientation;
	if (k->display->begin_frame(k->display))
		return;
	renderer_draw(k->renderer, &k->view, k->display->width, k->display->height);
	if (k->display->present(k->display) == 0)
		k->frames_drawn++;
	k->app.dirty = false;
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

static int open_signals(void)
{
	sigset_t set;

	loop_signals(&set);
	return signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK);
}

/* True when the loop should stop. */
static bool read_signals(int fd)
{
	struct signalfd_siginfo si;
	bool quit = false;

	while (read(fd, &si, sizeof(si)) == sizeof(si)) {
		if (si.ssi_signo == SIGHUP) {
			log_info("SIGHUP: reload is not supported yet, ignored");
			continue;
		}
		log_info("%s: shutting down", strsignal((int)si.ssi_signo));
		quit = true;
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
	if (deadline == APP_NEVER)
		return -1;
	return deadline <= now ? 0 : (int)((deadline - now + 999999) / 1000000);
}

static int fill_fds(struct kiosk *k, struct pollfd *fds, int sig_fd)
{
	fds[FD_SIGNAL] = (struct pollfd){.fd = sig_fd, .events = POLLIN};
	fds[FD_DISPLAY] = (struct pollfd){.fd = k->display->get_fd(k->display), .events = POLLIN};
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

int kiosk_run(struct kiosk *k)
{
	struct pollfd fds[FD_INPUTS + KIOSK_MAX_INPUTS];
	int sig_fd = open_signals();
	int ret = 0;

	if (sig_fd < 0) {
		log_err("cannot watch signals: %s", strerror(-sig_fd));
		return sig_fd;
	}
	for (;;) {
		uint64_t now = monotonic_ns();
		uint64_t next = app_advance(&k->app, now);
		int n;

		if (k->app.dirty && !k->display->waiting)
			draw(k);
		n = fill_fds(k, fds, sig_fd);
		if (poll(fds, (nfds_t)n, poll_timeout_ms(k, next, now)) < 0 && errno != EINTR) {
			ret = -errno;
			break;
		}
		if ((fds[FD_SIGNAL].revents & POLLIN) && read_signals(sig_fd))
			break;
		if ((fds[FD_DISPLAY].revents & POLLIN) && k->display->dispatch(k->display) < 0) {
			log_err("%s: display failed", k->display->name);
			ret = -EIO;
			break;
		}
		service_inputs(k, fds, monotonic_ns());
	}
	close(sig_fd);
	return ret;
}
