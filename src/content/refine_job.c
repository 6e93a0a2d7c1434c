#include "content/refine_job.h"
#include "util/log.h"

#include <errno.h>
#include <string.h>

static void run(struct worker_job *job)
{
	struct refine_job *j = (struct refine_job *)job;

	content_refine_run(j->refine);
}

static void done(struct worker_job *job)
{
	struct refine_job *j = (struct refine_job *)job;

	j->busy = false;
	j->ready(j->ctx);
}

void refine_job_init(struct refine_job *j, void (*ready)(void *ctx), void *ctx)
{
	memset(j, 0, sizeof(*j));
	j->job = (struct worker_job){run, done};
	j->ready = ready;
	j->ctx = ctx;
}

void refine_job_release(struct refine_job *j)
{
	content_refine_free(j->refine);
	j->refine = NULL;
	j->busy = false;
}

int refine_job_start(struct refine_job *j, struct worker *w, struct content *shown)
{
	int ret;

	if (worker_busy(w))
		return -EBUSY;
	refine_job_release(j);
	j->refine = content_refine_take(shown);
	if (!j->refine)
		return -EINVAL;
	ret = worker_start(w, &j->job);
	if (ret) {
		log_err("%s: its full level of detail cannot be prepared (%s): the coarse picture "
			"stays",
			content_name(shown), strerror(-ret));
		refine_job_release(j);
		return ret;
	}
	j->busy = true;
	return 0;
}

struct content_refine *refine_job_take(struct refine_job *j)
{
	struct content_refine *f = j->refine;

	j->refine = NULL;
	return f;
}
