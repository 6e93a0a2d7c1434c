#include "content/worker.h"
#include "util/log.h"

#include <errno.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>

/* Models swapped out faster than the worker frees them: the loop waits
 * for the worker to be idle before starting a switch, so two or three is
 * what a busy kiosk ever holds; past this the loop releases in place. */
#define MAX_RETIRED 8

struct worker {
	int fd;
	bool busy;
	pthread_t thread;
	/* The thread's while busy, the loop's otherwise (pthread_create and
	 * pthread_join order every access). */
	struct worker_job *job;
	struct content *releasing[MAX_RETIRED];
	int releasing_count;
	/* The loop's alone: moved to releasing when a job starts. */
	struct content *retired[MAX_RETIRED];
	int retired_count;
};

struct worker *worker_new(void)
{
	struct worker *w = calloc(1, sizeof(*w));

	if (!w)
		return NULL;
	w->fd = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
	if (w->fd < 0) {
		log_err("worker: no eventfd (%s); content is not loaded while running",
			strerror(errno));
		free(w);
		return NULL;
	}
	return w;
}

static void release_all(struct content **c, int *count)
{
	for (int i = 0; i < *count; i++) {
		content_release(c[i]);
		free(c[i]);
	}
	*count = 0;
}

static void join(struct worker *w)
{
	uint64_t n;
	int err;

	pthread_join(w->thread, NULL);
	if (read(w->fd, &n, sizeof(n)) < 0 && (err = errno) != EAGAIN)
		log_debug("worker: eventfd: %s", strerror(err));
	w->busy = false;
}

void worker_free(struct worker *w)
{
	if (!w)
		return;
	if (w->busy)
		join(w);
	release_all(w->retired, &w->retired_count);
	close(w->fd);
	free(w);
}

int worker_fd(const struct worker *w)
{
	return w ? w->fd : -1;
}

bool worker_busy(const struct worker *w)
{
	return w->busy;
}

static void *run(void *arg)
{
	struct worker *w = arg;
	uint64_t one = 1;
	int err;

	release_all(w->releasing, &w->releasing_count);
	if (w->job)
		w->job->run(w->job);
	if (write(w->fd, &one, sizeof(one)) != sizeof(one)) {
		err = errno;
		log_err("worker: cannot tell the loop a job is done: %s", strerror(err));
	}
	return NULL;
}

/* An explicit stack, not the default RLIMIT_STACK gives (ulimit -s or
 * systemd's LimitSTACK=: 8 MiB on Debian, but "unlimited" means glibc's
 * built-in size and another C library's may be 128 KiB): a job parses a
 * model, and the JSON parsers recurse once per level of nesting that
 * scene/gltf_json_depth.h lets through (worker.h says how much that is). */
static int start_thread(struct worker *w)
{
	pthread_attr_t attr;
	int ret = pthread_attr_init(&attr);

	if (ret)
		return ret;
	ret = pthread_attr_setstacksize(&attr, WORKER_STACK_SIZE);
	if (!ret)
		ret = pthread_create(&w->thread, &attr, run, w);
	pthread_attr_destroy(&attr);
	return ret;
}

int worker_start(struct worker *w, struct worker_job *j)
{
	int ret;

	if (w->busy)
		return -EBUSY;
	w->job = j;
	memcpy(w->releasing, w->retired, sizeof(w->retired));
	w->releasing_count = w->retired_count;
	w->retired_count = 0;
	ret = -start_thread(w);
	if (ret) {
		log_err("worker: no thread to load content: %s", strerror(-ret));
		memcpy(w->retired, w->releasing, sizeof(w->retired));
		w->retired_count = w->releasing_count;
		w->releasing_count = 0;
		return ret;
	}
	w->busy = true;
	return 0;
}

int worker_finish(struct worker *w)
{
	uint64_t n;
	struct worker_job *j;

	if (!w->busy || read(w->fd, &n, sizeof(n)) != sizeof(n))
		return -EAGAIN;
	pthread_join(w->thread, NULL);
	w->busy = false;
	j = w->job;
	w->job = NULL;
	if (j)
		j->done(j);
	return 0;
}

int worker_retire(struct worker *w, struct content *c)
{
	struct content *kept = w->retired_count < MAX_RETIRED ? malloc(sizeof(*kept)) : NULL;

	if (!kept) {
		/* Rare: the loop waits for this one's cache write itself. */
		content_release(c);
		return -ENOMEM;
	}
	*kept = *c;
	memset(c, 0, sizeof(*c));
	w->retired[w->retired_count++] = kept;
	return 0;
}

bool worker_has_retired(const struct worker *w)
{
	return w && w->retired_count > 0;
}
