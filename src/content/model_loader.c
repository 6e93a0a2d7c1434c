#include "content/model_loader.h"
#include "config/settings.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

struct model_loader {
	struct worker_job job; /* first: the worker hands it back */
	struct worker *worker;
	void (*ready)(void *ctx);
	void *ctx;
	bool busy, done;
	/* The job: read by the worker alone while busy. */
	struct model_list *list;
	struct content_config config;
	struct content_look shown_look; /* what the model on screen is shown with */
	int from, step, shown, width, height;
	/* Its result. */
	struct content result;
	int picked;
};

static int try_load(void *ctx, const char *path)
{
	struct model_loader *l = ctx;

	return content_load_model(&l->result, &l->config, path, &l->shown_look, l->width,
				  l->height);
}

static void run(struct worker_job *j)
{
	struct model_loader *l = (struct model_loader *)j;

	if (l->step)
		l->picked = model_list_pick(l->list, l->from, l->step, l->shown, try_load, l);
	else if (try_load(l, model_list_path(l->list, l->from)) == 0)
		l->picked = l->from;
	else
		model_list_set_bad(l->list, l->from, true);
}

static void done(struct worker_job *j)
{
	struct model_loader *l = (struct model_loader *)j;

	l->done = true;
	l->ready(l->ctx);
}

struct model_loader *model_loader_new(struct worker *w, void (*ready)(void *ctx), void *ctx)
{
	struct model_loader *l = w ? calloc(1, sizeof(*l)) : NULL;

	if (!l)
		return NULL;
	l->job = (struct worker_job){run, done};
	l->worker = w;
	l->ready = ready;
	l->ctx = ctx;
	return l;
}

void model_loader_free(struct model_loader *l)
{
	if (!l)
		return;
	content_config_release(&l->config);
	content_look_release(&l->shown_look);
	content_release(&l->result);
	free(l);
}

bool model_loader_busy(const struct model_loader *l)
{
	return l->busy;
}

int model_loader_start(struct model_loader *l, struct model_list *list,
		       const struct content_config *c, const struct content_look *look, int from,
		       int step, int shown, int width, int height)
{
	int ret;

	if (l->busy || worker_busy(l->worker))
		return -EBUSY;
	if (content_look_copy(&l->shown_look, look))
		return -ENOMEM;
	if (content_config_copy(&l->config, c))
		return -ENOMEM;
	content_release(&l->result);
	l->list = list;
	l->from = from;
	l->step = step;
	l->shown = shown;
	l->width = width;
	l->height = height;
	l->picked = -1;
	l->done = false;
	ret = worker_start(l->worker, &l->job);
	if (ret) {
		content_config_release(&l->config);
		return ret;
	}
	l->busy = true;
	return 0;
}

int model_loader_finish(struct model_loader *l, struct content *out, int *picked)
{
	if (!l->busy || !l->done)
		return -EAGAIN;
	content_config_release(&l->config);
	l->busy = false;
	*picked = l->picked;
	*out = l->result;
	memset(&l->result, 0, sizeof(l->result));
	return 0;
}
