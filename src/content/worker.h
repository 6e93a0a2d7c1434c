/* The content worker: every slow step between a file on disk and a draw
 * (parse, decode, simplify, prepare, the cache write and its fsync) runs
 * here, so the loop thread only uploads a finished result, draws and
 * flips. A reload, a model switch, a model that arrived in the watched
 * folder and a matcap change are all jobs of this worker: one load path.
 *
 * What it is, exactly: one job at a time, each on a thread of its own.
 * worker_start creates a thread (pthread_create, WORKER_STACK_SIZE) that
 * releases what was retired, runs the job and writes the eventfd the live
 * loop polls; worker_finish joins it (everything the job wrote is then the
 * loop's: the join orders it, with no lock) and calls the job's done() on
 * the loop thread. There is no queue and no long-lived thread: a job that
 * cannot start (-EBUSY) is asked again by its owner on a later pass. Nor
 * is there a priority here: the order is the live loop's calls
 * (src/app/kiosk.c, loop_once). After poll() a job done is finished, then
 * a model switch or arrival starts at once if the worker is idle
 * (kiosk_models_service, after the inputs); before the next sleep, if it
 * is still idle, a reload, else the matcap asked for, else an empty job
 * that only releases what was retired (kiosk_content_start_jobs). So a
 * model asked for while a job runs goes before a reload or a matcap asked
 * meanwhile. The thread makes no GL call. */
#ifndef MK_WORKER_H
#define MK_WORKER_H

#include "content/content.h"

#include <stdbool.h>

/* The worker thread's stack, set rather than left to RLIMIT_STACK (see
 * worker.c): Debian's default size, made sure of. A job's deepest
 * recursion is the JSON parse of a model, about 440 bytes a level of
 * nesting (30,000 levels overflowed 8 MiB), bounded by GLTF_JSON_MAX_DEPTH
 * (64): a parse at the bound measured 44 KiB in a release build, a Draco
 * model's whole load 20 KiB (tests/unit/test_gltf_depth.c prints them,
 * and fails past a quarter of this). Only the pages a job touches become
 * memory. */
#define WORKER_STACK_SIZE (8u << 20)

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
