/* A matcap of the set decoded as a job of the content worker
 * (content/worker.h): a button press that asks for the next one never
 * decodes a PNG on the loop thread; the loop uploads the image when the
 * job is done and draws the previous matcap meanwhile. */
#ifndef MK_MATCAP_JOB_H
#define MK_MATCAP_JOB_H

#include "content/worker.h"
#include "util/image.h"

#include <stdbool.h>

struct matcap_job {
	struct worker_job job; /* first: the worker hands it back */
	void (*ready)(void *ctx);
	void *ctx;
	bool busy;
	int index;	    /* the set's image asked for */
	unsigned set_id;    /* the set it was asked of: a rescan makes it stale */
	char *path;	    /* the worker's while busy */
	struct image image; /* the result, once ready() was called */
	int ret;
};

void matcap_job_init(struct matcap_job *j, void (*ready)(void *ctx), void *ctx);
/* What it holds; the worker must be idle or freed. */
void matcap_job_release(struct matcap_job *j);
/* Decode path (copied) on w. 0, or a negative errno (worker busy, no
 * memory, no thread). */
int matcap_job_start(struct matcap_job *j, struct worker *w, const char *path, int index,
		     unsigned set_id);

#endif
