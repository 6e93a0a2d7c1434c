/* Loading and preparing the next model on a thread of its own, so the
 * kiosk keeps drawing the one on screen meanwhile: one job at a time (one
 * model shown, one being prepared: memory stays bounded). The thread
 * makes no GL call; it says it is done through an eventfd that the live
 * loop polls, and the loop uploads what it prepared. */
#ifndef MK_MODEL_LOADER_H
#define MK_MODEL_LOADER_H

#include "config/content_config.h"
#include "content/content.h"
#include "content/model_list.h"

#include <stdbool.h>

struct model_loader;

/* NULL after logging. */
struct model_loader *model_loader_new(void);
/* Waits for a job under way. */
void model_loader_free(struct model_loader *l);
/* Readable once a job is done. */
int model_loader_fd(const struct model_loader *l);
bool model_loader_busy(const struct model_loader *l);
/* Pick, load and prepare the first model that loads from index from in
 * steps of step (model_list_pick), for a width x height display; step 0:
 * that one model alone (a file that changed). The list
 * is the job's until model_loader_finish; c (the content settings, how to
 * load and prepare a model) is copied. 0, or a negative errno (busy, no
 * memory, or no thread). */
int model_loader_start(struct model_loader *l, struct model_list *list,
		       const struct content_config *c, int from, int step, int shown, int width,
		       int height);
/* Once model_loader_fd is readable: the index picked (-1: none loaded;
 * shown: every other one failed) and, for another index, its model in
 * out. Returns -EAGAIN while the job runs. */
int model_loader_finish(struct model_loader *l, struct content *out, int *picked);

#endif
