/* The second half of a coarse picture (content_coarse.c) as a job of the
 * content worker (content/worker.h): the whole mesh's level of detail and
 * packing, while the loop draws the coarse one. Started by the loop when
 * the worker is idle and the content shown has a refine to do, before
 * any other job; the worker's one-job rule then keeps a model switch or a
 * reload from starting until it is done, and the loop decides at ready()
 * whether the result is still wanted. */
#ifndef MK_REFINE_JOB_H
#define MK_REFINE_JOB_H

#include "content/worker.h"

#include <stdbool.h>

struct refine_job {
	struct worker_job job; /* first: the worker hands it back */
	void (*ready)(void *ctx);
	void *ctx;
	bool busy;
	struct content_refine *refine; /* the worker's while busy */
};

void refine_job_init(struct refine_job *j, void (*ready)(void *ctx), void *ctx);
/* What it holds; the worker must be idle or freed. */
void refine_job_release(struct refine_job *j);
/* shown's refine (content_refine_take) prepared on w. 0, or a negative
 * errno (worker busy, no thread: then the refine is freed, and the coarse
 * picture stays, said in the journal). */
int refine_job_start(struct refine_job *j, struct worker *w, struct content *shown);
/* From ready(): the prepared refine, the caller's now. */
struct content_refine *refine_job_take(struct refine_job *j);

#endif
