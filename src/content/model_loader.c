#include "content/model_loader.h"
#include "config/settings.h"
#include "util/log.h"

#include <errno.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>

struct model_loader {
	int fd;
	bool busy;
	pthread_t thread;
	/* The job: read by the thread alone while busy. */
	struct model_list *list;
	struct content_config config;
	int from, step, shown, width, height;
	/* Its result. */
	struct content result;
	int picked;
};

struct model_loader *model_loader_new(void)
{
	struct model_loader *l = calloc(1, sizeof(*l));

	if (!l)
		return NULL;
	l->fd = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
	if (l->fd < 0) {
		log_err("models: no eventfd (%s); models are not switched", strerror(errno));
		free(l);
		return NULL;
	}
	return l;
}

static void join(struct model_loader *l)
{
	uint64_t n;

	if (!l->busy)
		return;
	pthread_join(l->thread, NULL);
	if (read(l->fd, &n, sizeof(n)) < 0 && errno != EAGAIN)
		log_debug("models: eventfd: %s", strerror(errno));
	content_config_release(&l->config);
	l->busy = false;
}

void model_loader_free(struct model_loader *l)
{
	if (!l)
		return;
	join(l);
	content_release(&l->result);
	close(l->fd);
	free(l);
}

int model_loader_fd(const struct model_loader *l)
{
	return l->fd;
}

bool model_loader_busy(const struct model_loader *l)
{
	return l->busy;
}

static int try_load(void *ctx, const char *path)
{
	struct model_loader *l = ctx;

	return content_load_model(&l->result, &l->config, path, l->width, l->height);
}

static void *run(void *arg)
{
	struct model_loader *l = arg;
	uint64_t one = 1;

	if (l->step)
		l->picked = model_list_pick(l->list, l->from, l->step, l->shown, try_load, l);
	else if (try_load(l, model_list_path(l->list, l->from)) == 0)
		l->picked = l->from;
	else
		model_list_set_bad(l->list, l->from, true);
	if (write(l->fd, &one, sizeof(one)) != sizeof(one))
		log_err("models: cannot tell the loop a model is ready: %s", strerror(errno));
	return NULL;
}

int model_loader_start(struct model_loader *l, struct model_list *list,
		       const struct content_config *c, int from, int step, int shown, int width,
		       int height)
{
	int ret;

	if (l->busy)
		return -EBUSY;
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
	ret = -pthread_create(&l->thread, NULL, run, l);
	if (ret) {
		log_err("models: no thread to load the next one: %s", strerror(-ret));
		content_config_release(&l->config);
		return ret;
	}
	l->busy = true;
	return 0;
}

int model_loader_finish(struct model_loader *l, struct content *out, int *picked)
{
	uint64_t n;

	if (!l->busy || read(l->fd, &n, sizeof(n)) != sizeof(n))
		return -EAGAIN;
	pthread_join(l->thread, NULL);
	content_config_release(&l->config);
	l->busy = false;
	*picked = l->picked;
	*out = l->result;
	memset(&l->result, 0, sizeof(l->result));
	return 0;
}
