/* Loading and preparing the next model of a folder or list as a job of
 * the content worker (content/worker.h), so the kiosk keeps drawing the
 * one on screen meanwhile: one job at a time (one model shown, one being
 * prepared: memory stays bounded). The loop uploads what it prepared. */
#ifndef MK_MODEL_LOADER_H
#define MK_MODEL_LOADER_H

#include "config/content_config.h"
#include "content/content.h"
#include "content/model_list.h"
#include "content/worker.h"

#include <stdbool.h>

struct model_loader;

/* Jobs run on w; ready(ctx) is called on the loop thread (from
 * worker_finish) when one is done: then model_loader_finish. NULL after
 * logging. */
struct model_loader *model_loader_new(struct worker *w, void (*ready)(void *ctx), void *ctx);
/* The worker must be freed (or idle) first: a job under way is the
 * worker's until then. */
void model_loader_free(struct model_loader *l);
bool model_loader_busy(const struct model_loader *l);
/* Pick, load and prepare the first model that loads from index from in
 * steps of step (model_list_pick), for a width x height display; step 0:
 * that one model alone (a file that changed). The list
 * is the job's until model_loader_finish; c (the content settings, how to
 * load and prepare a model) and look (what the model on screen is shown
 * with: content_load_model) are copied. 0, or a negative errno (the worker
 * busy, no memory, or no thread). */
int model_loader_start(struct model_loader *l, struct model_list *list,
		       const struct content_config *c, const struct content_look *look, int from,
		       int step, int shown, int width, int height);
/* From ready(): the index picked (-1: none loaded; shown: every other one
 * failed) and, for another index, its model in out. Returns -EAGAIN while
 * the job runs. */
int model_loader_finish(struct model_loader *l, struct content *out, int *picked);

#endif
