/* Changing what the kiosk shows while it runs, without a black screen and
 * without stopping the loop: the settings are read on the loop thread (a
 * small file), the new content is loaded and prepared as a job of the
 * content worker (content/worker.h) beside the one on screen, which stays
 * drawn, turned and flipped meanwhile; it is swapped in only when every
 * part of it loaded and reached the GPU. */
#ifndef MK_RELOAD_H
#define MK_RELOAD_H

#include "content/content.h"
#include "content/worker.h"
#include "config/options.h"
#include "render/render.h"

/* Logs that the reload failed: what, and the cause, the last error logged
 * since the reload began (the file, line and reason), so that --status,
 * which shows the last error, names it. */
void reload_failed(const char *what);
#include <stdbool.h>

struct reload_job {
	struct worker_job job; /* first: the worker hands it back */
	void (*ready)(void *ctx);
	void *ctx;
	/* The loop's while the job is idle, the worker's while it runs. */
	struct options fresh;	/* the settings read again */
	struct content content; /* loaded and prepared for them */
	int width, height;
	int ret;
	bool busy;
};

/* An idle job whose ready(ctx) is called on the loop thread when its
 * content is loaded (or failed). */
void reload_job_init(struct reload_job *j, void (*ready)(void *ctx), void *ctx);
/* What the job holds; the worker must be idle or freed. */
void reload_job_release(struct reload_job *j);
/* The settings of argv again and their content loaded on w for a width x
 * height display. 0, or a negative errno after logging (bad settings:
 * -EINVAL; the job is then idle again). */
int reload_start(struct reload_job *j, struct worker *w, int argc, char **argv, int width,
		 int height);
/* From ready(): the content loaded into shown and the renderer, and what
 * shown held into old (released by the caller, on the worker). Returns 0,
 * or a negative errno after logging, and then shown is what it was. */
int reload_finish(struct reload_job *j, struct content *shown, struct renderer *r,
		  struct content *old);
/* What a reload must do about the settings it read (fresh), against those
 * the kiosk started with and those it applied last: a bit
 * (1u << enum options_section) for each section whose devices must be
 * opened again. Says in the journal which settings wait for a restart. */
unsigned reload_reopen(const struct options *started, const struct options *applied,
		       const struct options *fresh);

#endif
