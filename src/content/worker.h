/* The one content worker: every slow step between a file on disk and a
 * draw (parse, decode, simplify, prepare, the cache write and its fsync)
 * runs here, one job at a time, so the loop thread only uploads a finished
 * result, draws and flips. A reload, a model switch, a model that arrived
 * in the watched folder and a matcap change are all jobs of this worker:
 * one load path. The thread makes no GL call. It says a job is done
 * through an eventfd the live loop polls; the loop then calls
 * worker_finish, which joins the thread (everything the job wrote is then
 * the loop's) and calls the job's done() on the loop thread. */
#ifndef MK_WORKER_H
#define MK_WORKER_H

#include "content/content.h"

#include <stdbool.h>

/* Embedded first in each kind of job (reload, model, matcap). */
struct worker_job {
	void (*run)(struct worker_job *j);  /* on the worker thread */
	void (*done)(struct worker_job *j); /* on the loop thread, from worker_finish */
};

struct worker;

/* NULL after logging. */
struct worker *worker_new(void);
/* Waits for the job under way (its done() is not called) and releases
 * what was retired. */
void worker_free(struct worker *w);
/* Readable once a job is done. */
int worker_fd(const struct worker *w);
bool worker_busy(const struct worker *w);
/* Runs j on the worker thread; j is the caller's and must live until its
 * done() ran. j NULL: only what was retired is released. 0, or a
 * negative errno (-EBUSY while a job runs, or no thread). */
int worker_start(struct worker *w, struct worker_job *j);
/* Once worker_fd is readable: joins the job and calls its done().
 * Returns -EAGAIN while it runs. */
int worker_finish(struct worker *w);
/* Content the loop is done with (a model swapped out): moved into the
 * worker and released by its next job, where waiting for its cache
 * write and sync costs the loop nothing. c is left empty. */
int worker_retire(struct worker *w, struct content *c);
/* Contents retired and not released yet: the loop starts an empty job
 * for them when the worker is idle. */
bool worker_has_retired(const struct worker *w);

#endif
