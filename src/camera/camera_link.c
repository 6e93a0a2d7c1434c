/* The kiosk's side of the camera (src/camera/camera.h): starts the helper
 * process, keeps the newest frame, hands the others back, and treats a
 * helper that dies or stops sending frames as a camera that went away.
 * camera_fd() is an epoll descriptor holding the helper's socket and a
 * timer (the stall deadline, the next helper start), so the main loop
 * polls one descriptor and nothing here blocks. */
#include "camera/camera.h"
#include "util/clock.h"
#include "camera/camera_proto.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/dma-buf.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/timerfd.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

/* Opening a camera may take a while (an ISP, its tuning): the first
 * frame gets this much longer than the stall timeout. */
#define OPEN_GRACE_NS 5000000000ull
/* A helper that ended or was stopped is started again after a while,
 * longer each time it ends without a frame in between. */
#define RETRY_MIN_NS 2000000000ull
#define RETRY_MAX_NS 60000000000ull
#define NEVER	     UINT64_MAX

struct slot {
	struct camera_frame frame;
	int fds[CAMERA_MAX_PLANES];
	void *map[CAMERA_MAX_PLANES];
	size_t map_len[CAMERA_MAX_PLANES];
	int nfds;
	bool ready;
};

struct camera {
	struct camera_config cfg;
	char id[CAMERA_NAME_MAX];
	int epoll_fd, timer_fd;
	int sock;  /* -1: no helper */
	pid_t pid; /* 0: none to wait for */
	bool want, told_want;
	bool present;
	char name[CAMERA_NAME_MAX];
	/* The streaming session: its buffers, mapped here. */
	bool session;
	unsigned generation; /* the helper's, in its messages */
	unsigned sessions;   /* ours, in the frames: unique across helpers */
	int buffers, buffers_ready;
	struct slot slots[CAMERA_MAX_BUFFERS];
	int latest, held;
	struct camera_frame taken;
	uint64_t expect_by; /* a frame by then, or the helper is stopped */
	uint64_t start_at;  /* the next helper, NEVER while one runs */
	uint64_t retry_ns;
	unsigned stalls; /* in a row, with no frame in between */
	bool stopped_it; /* we killed the helper: its end is no news */
};

static int send_msg(struct camera *c, const struct camera_msg *m)
{
	int ret = c->sock >= 0 ? camera_msg_send(c->sock, m, NULL, 0) : -EPIPE;

	if (ret && ret != -EPIPE)
		log_debug("camera: cannot tell the helper: %s", strerror(-ret));
	return ret;
}

static void release_buffer(struct camera *c, int buffer)
{
	struct camera_msg m = {.type = CAMERA_MSG_RELEASE};

	m.u.release.generation = c->generation;
	m.u.release.buffer = buffer;
	send_msg(c, &m);
}

static void drop_slot(struct slot *s)
{
	for (int i = 0; i < CAMERA_MAX_PLANES; i++)
		if (s->map[i])
			munmap(s->map[i], s->map_len[i]);
	for (int i = 0; i < s->nfds; i++)
		close(s->fds[i]);
	memset(s, 0, sizeof(*s));
}

static void end_session(struct camera *c)
{
	for (int i = 0; i < CAMERA_MAX_BUFFERS; i++)
		drop_slot(&c->slots[i]);
	c->session = false;
	c->buffers = c->buffers_ready = 0;
	c->latest = c->held = -1;
}

static uint64_t backoff(struct camera *c)
{
	uint64_t d = c->retry_ns;

	c->retry_ns = d * 2 < RETRY_MAX_NS ? d * 2 : RETRY_MAX_NS;
	return d;
}

static void reap(struct camera *c)
{
	int status;

	if (!c->pid || waitpid(c->pid, &status, WNOHANG) != c->pid)
		return;
	if (!c->stopped_it && WIFSIGNALED(status))
		log_warn("camera: the libcamera helper ended by signal %d (%s)", WTERMSIG(status),
			 strsignal(WTERMSIG(status)));
	else if (!c->stopped_it && WIFEXITED(status) && WEXITSTATUS(status))
		log_debug("camera: the libcamera helper ended with status %d", WEXITSTATUS(status));
	c->pid = 0;
}

/* The helper is gone, or going: back to the image matcaps, and a new one
 * after a while. */
static void lose_helper(struct camera *c, uint64_t now, bool kill_it)
{
	if (kill_it && c->pid)
		kill(c->pid, SIGKILL);
	c->stopped_it = kill_it;
	if (c->sock >= 0) {
		epoll_ctl(c->epoll_fd, EPOLL_CTL_DEL, c->sock, NULL);
		close(c->sock);
		c->sock = -1;
	}
	end_session(c);
	reap(c);
	c->present = false;
	c->told_want = false;
	c->expect_by = NEVER;
	c->start_at = now + backoff(c);
}

static void spawn_attrs(posix_spawnattr_t *attr)
{
	sigset_t none, all;

	/* The kiosk blocks the signals its loop reads from a signalfd; the
	 * helper gets the defaults. */
	sigemptyset(&none);
	sigfillset(&all);
	posix_spawnattr_init(attr);
	posix_spawnattr_setsigmask(attr, &none);
	posix_spawnattr_setsigdefault(attr, &all);
	posix_spawnattr_setflags(attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
}

/* The same binary again, under the helper's name, with its end of the
 * socket as CAMERA_HELPER_FD. */
static int start_helper(struct camera *c)
{
	char *argv[] = {(char *)CAMERA_HELPER_NAME, NULL};
	struct epoll_event ev = {.events = EPOLLIN};
	posix_spawn_file_actions_t fa;
	posix_spawnattr_t attr;
	struct camera_msg m = {.type = CAMERA_MSG_CONFIG};
	int sv[2], theirs, ret;

	if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC | SOCK_NONBLOCK, 0, sv))
		return -errno;
	/* dup2 onto itself would keep close-on-exec set. */
	theirs = sv[1] == CAMERA_HELPER_FD ? fcntl(sv[1], F_DUPFD_CLOEXEC, 10) : sv[1];
	posix_spawn_file_actions_init(&fa);
	posix_spawn_file_actions_adddup2(&fa, theirs, CAMERA_HELPER_FD);
	spawn_attrs(&attr);
	ret =
	    theirs < 0 ? errno : posix_spawn(&c->pid, "/proc/self/exe", &fa, &attr, argv, environ);
	posix_spawn_file_actions_destroy(&fa);
	posix_spawnattr_destroy(&attr);
	if (theirs != sv[1] && theirs >= 0)
		close(theirs);
	close(sv[1]);
	if (ret) {
		log_err("camera: cannot start the libcamera helper: %s", strerror(ret));
		c->pid = 0;
		close(sv[0]);
		return -ret;
	}
	c->sock = sv[0];
	ev.data.fd = c->sock;
	epoll_ctl(c->epoll_fd, EPOLL_CTL_ADD, c->sock, &ev);
	snprintf(m.u.config.id, sizeof(m.u.config.id), "%s", c->id);
	m.u.config.width = c->cfg.width;
	m.u.config.height = c->cfg.height;
	m.u.config.log_level = c->cfg.log_level;
	send_msg(c, &m);
	c->start_at = NEVER;
	c->stopped_it = false;
	return 0;
}

static void on_session(struct camera *c, const struct camera_msg *m)
{
	end_session(c);
	if (m->u.session.buffers < 1 || m->u.session.buffers > CAMERA_MAX_BUFFERS)
		return;
	c->session = true;
	c->generation = m->u.session.generation;
	c->sessions++;
	c->buffers = m->u.session.buffers;
	for (int i = 0; i < c->buffers; i++) {
		struct camera_frame *f = &c->slots[i].frame;

		f->layout = m->u.session.layout;
		f->encoding = (enum camera_encoding)m->u.session.encoding;
		f->range = (enum camera_range)m->u.session.range;
		f->colour_space_known = m->u.session.colour_space_known;
		f->generation = c->sessions;
		f->buffer = i;
	}
}

/* Map each dmabuf once and check every plane lies inside its buffer, so
 * that a wrong stride cannot make the upload read past it. */
static int map_buffer(struct slot *s, const struct camera_msg *m)
{
	const struct camera_layout *l = &s->frame.layout;

	for (int i = 0; i < s->nfds; i++) {
		off_t size = lseek(s->fds[i], 0, SEEK_END);
		void *addr = size > 0
				 ? mmap(NULL, (size_t)size, PROT_READ, MAP_SHARED, s->fds[i], 0)
				 : MAP_FAILED;

		s->map_len[i] = size > 0 ? (size_t)size : 0;
		s->map[i] = addr == MAP_FAILED ? NULL : addr;
	}
	for (int p = 0; p < l->planes; p++) {
		int k = m->u.buffer.fd_index[p];
		size_t end = (size_t)m->u.buffer.offset[p] + camera_plane_span(&l->plane[p]);

		if (k < 0 || k >= s->nfds || !s->map_len[k] || end > s->map_len[k]) {
			log_err("camera: buffer %d plane %d is not inside its dmabuf",
				m->u.buffer.buffer, p);
			return -EINVAL;
		}
		s->frame.plane[p].fd = s->fds[k];
		s->frame.plane[p].offset = m->u.buffer.offset[p];
		s->frame.plane[p].data =
		    s->map[k] ? (const uint8_t *)s->map[k] + m->u.buffer.offset[p] : NULL;
	}
	return 0;
}

static void on_buffer(struct camera *c, const struct camera_msg *m, const int *fds, int nfds)
{
	int b = m->u.buffer.buffer;
	struct slot *s;

	if (!c->session || m->u.buffer.generation != c->generation || b < 0 || b >= c->buffers ||
	    c->slots[b].ready) {
		for (int i = 0; i < nfds; i++)
			close(fds[i]);
		return;
	}
	s = &c->slots[b];
	memcpy(s->fds, fds, sizeof(int) * (size_t)nfds);
	s->nfds = nfds;
	if (map_buffer(s, m)) {
		struct camera_frame f = s->frame;

		drop_slot(s);
		s->frame = f;
		return;
	}
	s->ready = true;
	c->buffers_ready++;
}

/* The newest frame waits in `latest`; the one it replaces goes back. */
static void on_frame(struct camera *c, const struct camera_msg *m, uint64_t now)
{
	int b = m->u.frame.buffer;

	if (!c->session || m->u.frame.generation != c->generation || b < 0 || b >= c->buffers)
		return;
	if (!c->slots[b].ready || !c->want) {
		release_buffer(c, b);
		return;
	}
	c->slots[b].frame.sequence = m->u.frame.sequence;
	c->slots[b].frame.completed_ns = m->u.frame.completed_ns;
	if (c->latest >= 0)
		release_buffer(c, c->latest);
	c->latest = b;
	c->expect_by = now + (uint64_t)(c->cfg.stall_s * 1e9);
	c->stalls = 0;
	c->retry_ns = RETRY_MIN_NS;
}

static void read_helper(struct camera *c, uint64_t now)
{
	struct camera_msg m;
	int fds[CAMERA_MAX_PLANES], nfds, ret;

	while (c->sock >= 0 && (ret = camera_msg_recv(c->sock, &m, fds, &nfds)) != -EAGAIN) {
		if (ret == -EPROTO)
			continue;
		if (ret) {
			lose_helper(c, now, false);
			return;
		}
		if (m.type == CAMERA_MSG_BUFFER) {
			on_buffer(c, &m, fds, nfds);
			continue;
		}
		for (int i = 0; i < nfds; i++)
			close(fds[i]);
		if (m.type == CAMERA_MSG_PRESENT) {
			m.u.present.name[CAMERA_NAME_MAX - 1] = '\0';
			c->present = m.u.present.name[0] != '\0';
			snprintf(c->name, sizeof(c->name), "%s", m.u.present.name);
		} else if (m.type == CAMERA_MSG_SESSION) {
			on_session(c, &m);
		} else if (m.type == CAMERA_MSG_FRAME) {
			on_frame(c, &m, now);
		}
	}
}

static void check_stall(struct camera *c, uint64_t now)
{
	if (c->sock < 0 || !c->present || !c->told_want || now < c->expect_by)
		return;
	log_msg(c->stalls ? LOG_DEBUG : LOG_WARN,
		"camera: %s sent no frame for %.1f s; back to the image matcaps",
		c->name[0] ? c->name : "the camera", c->cfg.stall_s);
	if (!c->stalls)
		c->retry_ns = RETRY_MIN_NS;
	c->stalls++;
	lose_helper(c, now, true);
}

static void arm_timer(struct camera *c)
{
	/* The stall deadline counts only while a frame is awaited (as in
	 * check_stall): a past one would fire again at once. */
	uint64_t stall = c->sock >= 0 && c->present && c->told_want ? c->expect_by : NEVER;
	uint64_t at = stall < c->start_at ? stall : c->start_at;
	struct itimerspec its = {{0, 0}, {0, 0}};

	/* A helper killed but not yet reaped: look again soon. */
	if (c->pid && c->sock < 0 && at == NEVER)
		at = monotonic_ns() + 100000000ull;
	if (at != NEVER) {
		its.it_value.tv_sec = (time_t)(at / 1000000000ull);
		its.it_value.tv_nsec = (long)(at % 1000000000ull);
		if (!its.it_value.tv_sec && !its.it_value.tv_nsec)
			its.it_value.tv_nsec = 1;
	}
	timerfd_settime(c->timer_fd, TFD_TIMER_ABSTIME, &its, NULL);
}

struct camera *camera_new(const struct camera_config *cfg)
{
	struct camera *c = calloc(1, sizeof(*c));
	struct epoll_event ev = {.events = EPOLLIN};

	if (!c)
		return NULL;
	c->cfg = *cfg;
	snprintf(c->id, sizeof(c->id), "%s", cfg->id ? cfg->id : "");
	c->cfg.id = c->id;
	c->sock = -1;
	c->latest = c->held = -1;
	c->expect_by = NEVER;
	c->retry_ns = RETRY_MIN_NS;
	c->epoll_fd = epoll_create1(EPOLL_CLOEXEC);
	c->timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC | TFD_NONBLOCK);
	ev.data.fd = c->timer_fd;
	if (c->epoll_fd < 0 || c->timer_fd < 0 ||
	    epoll_ctl(c->epoll_fd, EPOLL_CTL_ADD, c->timer_fd, &ev)) {
		log_err("camera: no epoll or timer descriptor: %s", strerror(errno));
		camera_free(c);
		return NULL;
	}
	if (start_helper(c))
		c->start_at = monotonic_ns() + backoff(c);
	arm_timer(c);
	return c;
}

void camera_free(struct camera *c)
{
	if (!c)
		return;
	/* Closing the socket tells the helper to stop the camera and end;
	 * one that does not within a second is killed. */
	if (c->sock >= 0)
		close(c->sock);
	c->sock = -1;
	for (int i = 0; i < 100 && c->pid && waitpid(c->pid, NULL, WNOHANG) == 0; i++)
		usleep(10000);
	if (c->pid && waitpid(c->pid, NULL, WNOHANG) == 0) {
		kill(c->pid, SIGKILL);
		waitpid(c->pid, NULL, 0);
	}
	end_session(c);
	if (c->timer_fd >= 0)
		close(c->timer_fd);
	if (c->epoll_fd >= 0)
		close(c->epoll_fd);
	free(c);
}

int camera_fd(const struct camera *c)
{
	return c->epoll_fd;
}

void camera_dispatch(struct camera *c, struct camera_state *out)
{
	uint64_t now = monotonic_ns(), ticks;

	while (read(c->timer_fd, &ticks, sizeof(ticks)) == sizeof(ticks))
		;
	read_helper(c, now);
	check_stall(c, now);
	reap(c);
	if (c->sock < 0 && !c->pid && now >= c->start_at && start_helper(c))
		c->start_at = now + backoff(c);
	arm_timer(c);
	out->present = c->present;
	out->streaming = c->session && c->buffers_ready == c->buffers;
	out->frame = out->streaming && c->latest >= 0;
	out->name = c->name[0] ? c->name : NULL;
}

void camera_set_streaming(struct camera *c, bool on)
{
	struct camera_msg m = {.type = CAMERA_MSG_WANT};

	c->want = on;
	if (c->sock < 0 || c->told_want == on)
		return;
	m.u.want.on = on;
	if (send_msg(c, &m))
		return;
	c->told_want = on;
	/* Stopped: the helper frees its buffers; so do we. */
	if (!on)
		end_session(c);
	c->expect_by =
	    on ? monotonic_ns() + (uint64_t)(c->cfg.stall_s * 1e9) + OPEN_GRACE_NS : NEVER;
	arm_timer(c);
}

const struct camera_frame *camera_take(struct camera *c)
{
	if (!c->session || c->latest < 0)
		return NULL;
	if (c->held >= 0)
		release_buffer(c, c->held);
	c->held = c->latest;
	c->latest = -1;
	c->taken = c->slots[c->held].frame;
	return &c->taken;
}

void camera_frame_cpu_access(const struct camera_frame *f, bool begin)
{
	struct dma_buf_sync sync = {.flags = DMA_BUF_SYNC_READ |
					     (begin ? DMA_BUF_SYNC_START : DMA_BUF_SYNC_END)};

	for (int p = 0; p < f->layout.planes; p++) {
		if (!f->plane[p].data || f->plane[p].fd < 0 ||
		    (p > 0 && f->plane[p].fd == f->plane[p - 1].fd))
			continue;
		/* Not every exporter implements it; the read is still right
		 * on a coherent machine. */
		ioctl(f->plane[p].fd, DMA_BUF_IOCTL_SYNC, &sync);
	}
}
