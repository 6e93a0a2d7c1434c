#include "display/cec_link.h"
#include "display/cec.h"
#include "util/log.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct cec_link {
	pthread_t thread;
	pthread_mutex_t lock;
	pthread_cond_t wake;
	char path[64];
	/* Under lock. */
	bool pending, on, quit;
};

static void *run(void *arg)
{
	struct cec_link *l = arg;
	struct cec *c = cec_new(l->path);
	bool on;

	pthread_mutex_lock(&l->lock);
	for (;;) {
		while (!l->pending && !l->quit)
			pthread_cond_wait(&l->wake, &l->lock);
		if (!l->pending)
			break;
		on = l->on;
		l->pending = false;
		pthread_mutex_unlock(&l->lock);
		if (c)
			cec_power(c, on);
		pthread_mutex_lock(&l->lock);
	}
	pthread_mutex_unlock(&l->lock);
	cec_free(c);
	return NULL;
}

struct cec_link *cec_link_new(const char *path)
{
	struct cec_link *l = calloc(1, sizeof(*l));
	int ret;

	if (!l)
		return NULL;
	snprintf(l->path, sizeof(l->path), "%s", path);
	pthread_mutex_init(&l->lock, NULL);
	pthread_cond_init(&l->wake, NULL);
	ret = pthread_create(&l->thread, NULL, run, l);
	if (ret) {
		log_err("cec %s: no thread (%s); the TV's power is left alone", path,
			strerror(ret));
		pthread_cond_destroy(&l->wake);
		pthread_mutex_destroy(&l->lock);
		free(l);
		return NULL;
	}
	return l;
}

void cec_link_free(struct cec_link *l)
{
	if (!l)
		return;
	pthread_mutex_lock(&l->lock);
	l->quit = true;
	pthread_cond_signal(&l->wake);
	pthread_mutex_unlock(&l->lock);
	pthread_join(l->thread, NULL);
	pthread_cond_destroy(&l->wake);
	pthread_mutex_destroy(&l->lock);
	free(l);
}

void cec_link_power(struct cec_link *l, bool on)
{
	pthread_mutex_lock(&l->lock);
	l->on = on;
	l->pending = true;
	pthread_cond_signal(&l->wake);
	pthread_mutex_unlock(&l->lock);
}
