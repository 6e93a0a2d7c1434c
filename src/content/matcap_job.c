#include "content/matcap_job.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static void run(struct worker_job *job)
{
	struct matcap_job *j = (struct matcap_job *)job;

	j->ret = image_load(j->path, &j->image);
}

static void done(struct worker_job *job)
{
	struct matcap_job *j = (struct matcap_job *)job;

	j->busy = false;
	j->ready(j->ctx);
}

void matcap_job_init(struct matcap_job *j, void (*ready)(void *ctx), void *ctx)
{
	memset(j, 0, sizeof(*j));
	j->job = (struct worker_job){run, done};
	j->ready = ready;
	j->ctx = ctx;
	j->index = -1;
}

void matcap_job_release(struct matcap_job *j)
{
	image_release(&j->image);
	free(j->path);
	j->path = NULL;
	j->busy = false;
}

int matcap_job_start(struct matcap_job *j, struct worker *w, const char *path, int index,
		     unsigned set_id)
{
	int ret;

	if (worker_busy(w))
		return -EBUSY;
	matcap_job_release(j);
	j->path = strdup(path);
	if (!j->path)
		return -ENOMEM;
	j->index = index;
	j->set_id = set_id;
	j->ret = -EINPROGRESS;
	ret = worker_start(w, &j->job);
	if (!ret)
		j->busy = true;
	return ret;
}
