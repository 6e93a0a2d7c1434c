#include "ops/status.h"
#include "util/clock.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/un.h>
#include <unistd.h>

#define STATUS_SOCKET "status.sock"
#define STATUS_FRAME  "frame.png"
#define STATUS_STATE  "state.json"
#define STATUS_MAX    4096 /* the JSON, with paths and an error line */

/* A frame is read back and encoded at most this often: a client asking in
 * a loop gets the last one again instead of stalling the animation. */
#define FRAME_EVERY_NS 1000000000ull

/* An answer being written: the PNG encoding, the files and the socket
 * are a thread's, so the loop only reads the frame back. Owned by the
 * thread from pthread_create until pthread_join. */
struct status_answer {
	char dir[96];
	int client_fd;
	struct image frame; /* none when width is 0 */
	char *json;
	char frame_path[160], state_path[160];
};

struct status_server {
	char dir[96];
	int listen_fd;
	int client_fd;		/* taken, not answered yet; -1: none */
	uint64_t frame_ns;	/* when frame.png was last written; 0: never */
	uint64_t deaf_until_ns; /* accept failed (no fd left): not polled till then */
	bool writing;		/* the writer thread runs (or ran, not joined yet) */
	pthread_t writer;
	struct status_answer answer;
};

/* systemd's RuntimeDirectory= with several folders lists them with ':';
 * the first is ours. */
static void runtime_dir(char *buf, size_t n)
{
	const char *env = getenv("RUNTIME_DIRECTORY");
	size_t len;

	if (!env || !*env)
		env = "/run/matcap-kiosk";
	len = strcspn(env, ":");
	snprintf(buf, n, "%.*s", (int)len, env);
}

static int socket_address(struct sockaddr_un *a, const char *dir)
{
	*a = (struct sockaddr_un){.sun_family = AF_UNIX};
	if ((size_t)snprintf(a->sun_path, sizeof(a->sun_path), "%s/%s", dir, STATUS_SOCKET) >=
	    sizeof(a->sun_path))
		return -ENAMETOOLONG;
	return 0;
}

static int connect_to(const struct sockaddr_un *a)
{
	int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);

	if (fd < 0)
		return -errno;
	if (connect(fd, (const struct sockaddr *)a, sizeof(*a)) == 0)
		return fd;
	close(fd);
	return -errno;
}

/* A socket left by a kiosk that died is removed; one that answers
 * belongs to a kiosk that runs, and is left alone. */
static int listen_at(const struct sockaddr_un *a)
{
	int fd = connect_to(a);

	if (fd >= 0) {
		close(fd);
		return -EADDRINUSE;
	}
	unlink(a->sun_path);
	fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
	if (fd < 0)
		return -errno;
	/* The service user's alone (root reaches it too): the state and the
	 * frame show what is on a shop's screen. */
	if (bind(fd, (const struct sockaddr *)a, sizeof(*a)) || chmod(a->sun_path, 0600) ||
	    listen(fd, 4)) {
		int err = -errno;

		close(fd);
		return err;
	}
	return fd;
}

struct status_server *status_server_new(void)
{
	struct status_server *s = calloc(1, sizeof(*s));
	struct sockaddr_un a;
	int ret;

	if (!s)
		return NULL;
	runtime_dir(s->dir, sizeof(s->dir));
	s->client_fd = -1;
	ret = socket_address(&a, s->dir);
	s->listen_fd = ret ? ret : listen_at(&a);
	if (s->listen_fd >= 0) {
		log_info("status: matcap-kiosk --status answers at %s", a.sun_path);
		return s;
	}
	/* A kiosk run by hand has no runtime folder: not an error. */
	log_info("status: no socket at %s/%s (%s): --status will not reach this kiosk", s->dir,
		 STATUS_SOCKET, strerror(-s->listen_fd));
	free(s);
	return NULL;
}

/* The answer before is written: its thread joined. A client that comes
 * within one PNG encoding of the one before waits for it here (at most
 * once a second a frame is encoded at all). */
static void join_writer(struct status_server *s)
{
	if (!s->writing)
		return;
	pthread_join(s->writer, NULL);
	s->writing = false;
}

void status_server_free(struct status_server *s)
{
	struct sockaddr_un a;

	if (!s)
		return;
	join_writer(s);
	if (s->client_fd >= 0)
		close(s->client_fd);
	close(s->listen_fd);
	if (socket_address(&a, s->dir) == 0)
		unlink(a.sun_path);
	free(s);
}

int status_server_fd(const struct status_server *s)
{
	return s && monotonic_ns() >= s->deaf_until_ns ? s->listen_fd : -1;
}

/* Out of descriptors, the waiting client stays in the queue and the fd
 * stays readable: poll would spin, so the socket is left alone a second. */
bool status_server_accept(struct status_server *s)
{
	if (!s)
		return false;
	if (s->client_fd < 0)
		s->client_fd = accept4(s->listen_fd, NULL, NULL, SOCK_CLOEXEC);
	if (s->client_fd < 0 && errno != EAGAIN && errno != EINTR) {
		log_warn("status: cannot take a client: %s; trying again in a second",
			 strerror(errno));
		s->deaf_until_ns = monotonic_ns() + 1000000000ull;
	}
	return s->client_fd >= 0;
}

bool status_server_wants_frame(const struct status_server *s)
{
	return s && (!s->frame_ns || monotonic_ns() - s->frame_ns >= FRAME_EVERY_NS);
}

/* A JSON string: quotes, backslashes and control characters escaped. */
static void json_string(FILE *f, const char *s)
{
	if (!s) {
		fputs("null", f);
		return;
	}
	fputc('"', f);
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;

		if (c == '"' || c == '\\')
			fprintf(f, "\\%c", c);
		else if (c < 0x20)
			fprintf(f, "\\u%04x", c);
		else
			fputc(c, f);
	}
	fputc('"', f);
}

/* What visitors did, as the metrics say it (presses, visits, seconds). */
static void write_visits(FILE *f, const struct visits *v)
{
	const char *sep = "";

	fprintf(f, ",\n  \"visits\": {\"count\": %ld, \"presses\": [", v->count);
	for (int s = 0; s < INPUT_KINDS; s++)
		for (int a = 1; a < VISITS_ACTIONS; a++)
			if (v->presses[s][a]) {
				fprintf(
				    f, "%s{\"source\": \"%s\", \"action\": \"%s\", \"count\": %ld}",
				    sep, input_kind_names[s], visits_action_name(a),
				    v->presses[s][a]);
				sep = ", ";
			}
	fputs("], \"seconds\": [", f);
	for (int i = 0; i < v->slot_count; i++) {
		fprintf(f, "%s{\"kind\": ", i ? ", " : "");
		json_string(f, v->slots[i].kind);
		fputs(", \"name\": ", f);
		json_string(f, v->slots[i].name);
		fprintf(f, ", \"seconds\": %.3f}", v->slots[i].seconds);
	}
	fputs("]}", f);
}

static void write_json(FILE *f, const struct status_report *r, const char *frame, const char *state)
{
	fputs("{\n  \"model\": ", f);
	json_string(f, r->model);
	fputs(",\n  \"matcap\": ", f);
	json_string(f, r->matcap);
	fputs(",\n  \"mode\": ", f);
	json_string(f, r->mode);
	fprintf(f, ",\n  \"view\": [%.6f, %.6f, %.6f, %.6f]", r->view[0], r->view[1], r->view[2],
		r->view[3]);
	fprintf(f, ",\n  \"power\": \"%s\",\n  \"camera\": %s", r->screen_on ? "on" : "off",
		r->camera_on ? "true" : "false");
	fprintf(f, ",\n  \"uptime_s\": %.1f,\n  \"frames_drawn\": %ld", r->uptime_s,
		r->frames_drawn);
	fputs(",\n  \"last_error\": ", f);
	json_string(f, r->last_error);
	fputs(",\n  \"frame\": ", f);
	json_string(f, frame);
	fputs(",\n  \"state\": ", f);
	json_string(f, state);
	if (r->visits)
		write_visits(f, r->visits);
	fputs("\n}\n", f);
}

/* Each replaced whole (util/file.h), so that a reader never sees half a
 * file; not synced: the folder is in /run, gone at the next boot anyway. */
static int write_png(const char *dir, const struct image *frame, char *path, size_t n)
{
	struct file_atomic a;
	int ret;

	snprintf(path, n, "%s/%s", dir, STATUS_FRAME);
	ret = file_atomic_begin(&a, path, 0600);
	if (!ret)
		ret = file_atomic_end(&a, image_write_png(a.tmp, frame), false);
	return ret;
}

static int write_state(const char *dir, const char *json, char *path, size_t n)
{
	size_t len = strlen(json);
	struct file_atomic a;
	int ret;

	snprintf(path, n, "%s/%s", dir, STATUS_STATE);
	ret = file_atomic_begin(&a, path, 0600);
	if (!ret)
		ret = file_atomic_end(&a, write(a.fd, json, len) == (ssize_t)len ? 0 : -EIO, false);
	return ret;
}

/* The JSON in memory: the file and the socket get the same text. */
static char *report_text(const struct status_report *r, const char *frame, const char *state)
{
	char *buf = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&buf, &size);

	if (!f)
		return NULL;
	write_json(f, r, frame, state);
	if (fclose(f)) {
		free(buf);
		return NULL;
	}
	return buf;
}

/* On the writer thread. */
static void *write_answer(void *arg)
{
	struct status_answer *w = arg;
	bool have_frame = w->frame.width > 0;
	ssize_t sent;
	int err;

	if (have_frame && write_png(w->dir, &w->frame, w->frame_path, sizeof(w->frame_path)))
		log_warn("status: cannot write %s", w->frame_path);
	if (!w->json) {
		log_err("status: no memory for the report");
	} else if ((err = write_state(w->dir, w->json, w->state_path, sizeof(w->state_path))) ==
		   0) {
		/* The client waits for it; one that left or reads nothing is
		 * not waited for (the answer fits the socket's buffer). */
		sent = send(w->client_fd, w->json, strlen(w->json), MSG_NOSIGNAL | MSG_DONTWAIT);
		if (sent != (ssize_t)strlen(w->json))
			log_debug("status: the client took %zd of %zu bytes", sent,
				  strlen(w->json));
		log_info("status: wrote %s%s%s", w->state_path, have_frame ? " and " : "",
			 have_frame ? w->frame_path : "");
	} else {
		log_err("status: cannot write %s: %s (expected a writable runtime folder)",
			w->state_path, strerror(-err));
	}
	free(w->json);
	w->json = NULL;
	image_release(&w->frame);
	close(w->client_fd);
	return NULL;
}

void status_server_answer(struct status_server *s, const struct status_report *r,
			  struct image *frame)
{
	struct status_answer *w = &s->answer;
	bool have_frame = false;
	int ret;

	join_writer(s);
	memset(w, 0, sizeof(*w));
	snprintf(w->dir, sizeof(w->dir), "%s", s->dir);
	snprintf(w->frame_path, sizeof(w->frame_path), "%s/%s", s->dir, STATUS_FRAME);
	snprintf(w->state_path, sizeof(w->state_path), "%s/%s", s->dir, STATUS_STATE);
	if (frame && frame->width) {
		w->frame = *frame; /* the thread's now */
		memset(frame, 0, sizeof(*frame));
		s->frame_ns = monotonic_ns(), have_frame = true;
	} else if (s->frame_ns) { /* asked again within a second: the last one */
		have_frame = access(w->frame_path, R_OK) == 0;
	}
	w->json = report_text(r, have_frame ? w->frame_path : NULL, w->state_path);
	w->client_fd = s->client_fd;
	s->client_fd = -1;
	ret = pthread_create(&s->writer, NULL, write_answer, w);
	if (ret) {
		log_warn("status: no thread to write the answer (%s): written here", strerror(ret));
		write_answer(w);
		return;
	}
	s->writing = true;
}

int status_client_run(FILE *out)
{
	char dir[96], buf[STATUS_MAX];
	struct sockaddr_un a;
	ssize_t n;
	int fd, ret = 1;

	runtime_dir(dir, sizeof(dir));
	fd = socket_address(&a, dir);
	if (!fd)
		fd = connect_to(&a);
	if (fd < 0) {
		fprintf(stderr,
			"matcap-kiosk: --status: no kiosk answers at %s/%s: %s (is the service "
			"running? the socket is the service user's: run it as root)\n",
			dir, STATUS_SOCKET, strerror(-fd));
		return 1;
	}
	/* A kiosk stuck in the GPU driver does not hold the caller forever. */
	setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &(struct timeval){.tv_sec = 10},
		   sizeof(struct timeval));
	while ((n = read(fd, buf, sizeof(buf))) > 0) {
		fwrite(buf, 1, (size_t)n, out);
		ret = 0;
	}
	if (ret)
		fprintf(stderr, "matcap-kiosk: --status: the kiosk at %s/%s sent no answer\n", dir,
			STATUS_SOCKET);
	close(fd);
	return ret;
}
