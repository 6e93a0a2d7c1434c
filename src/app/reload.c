#include "app/reload.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

void reload_failed(const char *what)
{
	char cause[768];

	log_last_error(cause, sizeof(cause));
	if (cause[0])
		log_err("reload: %s; keeping the scene on screen (%s)", what, cause);
	else
		log_err("reload: %s; keeping the scene on screen", what);
}

/* Test hooks: MK_TEST_PREPARE_DELAY_MS slows each reload's preparation
 * down, so that it outlasts the watchdog (tests/e2e/live.sh);
 * MK_TEST_PREPARE_GATE holds it until a file exists. Built into
 * the sanitizer builds of the tests alone (-DMK_TEST_HOOKS). */
static void test_delay(void)
{
#ifdef MK_TEST_HOOKS
	const char *env = getenv("MK_TEST_PREPARE_DELAY_MS");
	long ms = env ? strtol(env, NULL, 10) : 0;
	struct timespec t = {ms / 1000, (ms % 1000) * 1000000};

	const char *gate = getenv("MK_TEST_PREPARE_GATE");
	struct timespec tick = {0, 10 * 1000000};

	if (ms > 0)
		nanosleep(&t, NULL);
	/* Or until a file exists (tests/unit/test_kiosk_reload.c): as long
	 * as the test needs, however slow the machine, at most a minute. */
	for (int i = 0; gate && i < 6000 && access(gate, F_OK); i++)
		nanosleep(&tick, NULL);
#endif
}

/* On the worker thread: everything but the GL upload. */
static void run(struct worker_job *job)
{
	struct reload_job *j = (struct reload_job *)job;
	const struct content_config *c = &j->fresh.content;

	j->ret = content_load(&j->content, c, true);
	if (!j->ret && (j->ret = content_prepare(&j->content, c, j->width, j->height)))
		content_release(&j->content);
	if (!j->ret)
		test_delay();
}

static void done(struct worker_job *job)
{
	struct reload_job *j = (struct reload_job *)job;

	j->ready(j->ctx);
}

void reload_job_init(struct reload_job *j, void (*ready)(void *ctx), void *ctx)
{
	memset(j, 0, sizeof(*j));
	j->job = (struct worker_job){run, done};
	j->ready = ready;
	j->ctx = ctx;
}

void reload_job_release(struct reload_job *j)
{
	options_release(&j->fresh);
	content_release(&j->content);
	j->busy = false;
}

int reload_start(struct reload_job *j, struct worker *w, int argc, char **argv, int width,
		 int height)
{
	int ret;

	reload_job_release(j);
	if (options_parse(&j->fresh, argc, argv) != OPTIONS_OK) {
		reload_failed("the settings have errors");
		options_release(&j->fresh);
		return -EINVAL;
	}
	/* A reload is the live kiosk's: its animation plays (main.c). */
	j->fresh.content.anim_live = j->fresh.content.anim_time < 0;
	j->fresh.content.crash_memory = true;
	j->fresh.content.coarse_first = true;
	j->width = width;
	j->height = height;
	j->ret = -EINPROGRESS;
	ret = worker_start(w, &j->job);
	if (ret) {
		reload_failed("the content cannot be loaded: the worker does not start");
		options_release(&j->fresh);
		return ret;
	}
	j->busy = true;
	return 0;
}

int reload_finish(struct reload_job *j, struct content *shown, struct renderer *r,
		  struct content *old)
{
	int ret = j->ret;

	j->busy = false;
	memset(old, 0, sizeof(*old));
	if (ret) {
		reload_failed("the scene does not load");
		return ret;
	}
	ret = content_upload(&j->content, r);
	if (ret) {
		log_err("reload: the new scene does not fit on the GPU; keeping the one on screen");
		content_release(&j->content);
		/* Its matcap is decoded again on the worker (its image went
		 * once on the GPU). */
		if (content_upload_model(shown, r))
			log_err("reload: the scene on screen could not be restored either");
		return ret;
	}
	*old = *shown;
	*shown = j->content;
	memset(&j->content, 0, sizeof(j->content));
	return 0;
}

unsigned reload_reopen(const struct options *started, const struct options *applied,
		       const struct options *fresh)
{
	unsigned since_start = options_changed(started, fresh);
	unsigned since_last = options_changed(applied, fresh);
	unsigned reopen = 0;

	for (int i = 0; i < OPTIONS_SECTIONS; i++) {
		const struct options_section_rule *rule = &options_sections[i];

		/* Warned at every reload until the restart: the kiosk runs on
		 * with what it started with. */
		if (rule->reload == OPTIONS_AT_START && (since_start & 1u << i))
			log_warn("reload: [%s] settings apply %s", rule->name, rule->says);
		if (rule->reload == OPTIONS_REOPEN && (since_last & 1u << i))
			reopen |= 1u << i;
	}
	return reopen;
}
