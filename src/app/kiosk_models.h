/* The live loop's side of several models: the list [scene] model names,
 * the worker that prepares the next one (model_loader.h), and the watch on
 * the model's file or folder. The app state says which model is wanted
 * (next/prev-model, attract mode); this swaps it in once it is ready, on
 * the loop's thread, where GL is. */
#ifndef MK_KIOSK_MODELS_H
#define MK_KIOSK_MODELS_H

#include "state/app.h"
#include "content/content.h"
#include "content/worker.h"
#include "config/content_config.h"
#include "ops/status.h"
#include "display/display.h"
#include "render/render.h"

#include <poll.h>
#include <stdint.h>

/* What it works on; none of it is freed here, and each outlives it. */
struct kiosk_models_parts {
	struct app *app;
	struct content *content; /* on screen: its model is swapped */
	struct renderer *renderer;
	struct display *display;
	const struct content_config *config; /* [scene] model and how to prepare one */
	struct worker *worker;		     /* the content worker, shared with the loop */
	struct status_counts *counts;	     /* model loads counted here */
	/* A model swapped in with its own matcaps or background (or back
	 * to kiosk.ini's): what (CONTENT_OWN_*) is on the GPU now. */
	void (*look_changed)(void *ctx, unsigned what);
	void *ctx;
};

struct kiosk_models;

/* NULL when there is no model file to switch or watch (the built-in knot),
 * or after logging. Tells the app how many models there are. */
struct kiosk_models *kiosk_models_new(const struct kiosk_models_parts *parts, uint64_t now_ns);
/* The worker must be idle (or freed): a model being prepared is its job. */
void kiosk_models_free(struct kiosk_models *m);
/* The watch's descriptor for poll (-1 where there is none); a model
 * prepared is told through the worker's. */
void kiosk_models_fill_fds(const struct kiosk_models *m, struct pollfd fds[1]);
/* When it must be serviced with nothing to read; CLOCK_NEVER: not. */
/* Another model was asked for (a step, a file that arrived or changed)
 * and is not started yet: a coarse picture's full level of detail is
 * then not worth its upload. */
bool kiosk_models_switching(const struct kiosk_models *m);
uint64_t kiosk_models_deadline(const struct kiosk_models *m);
/* The models next/prev-model step through; 0 for NULL. */
int kiosk_models_count(const struct kiosk_models *m);
/* A file changed, or another model wanted: a job started when the worker
 * is idle (a model prepared is swapped in from the worker's done()). */
void kiosk_models_service(struct kiosk_models *m, const struct pollfd fds[1], uint64_t now_ns);

#endif
