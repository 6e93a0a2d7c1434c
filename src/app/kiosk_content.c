/* The live loop's side of the content worker (content/worker.h): what is
 * asked (a reload, the matcap the app state wants, a matcap folder that
 * changed) becomes a job when the worker is idle, and a job done is
 * uploaded here, on the loop thread, where GL is. Model switches are the
 * worker's jobs too (kiosk_models.c, started after the inputs). One job
 * at a time: here, before the loop sleeps, a coarse picture's full level
 * of detail first, then a reload, then a matcap,
 * then the release of what was swapped out (content/worker.h). */
#include "app/kiosk_state.h"
#include "util/clock.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static void reload_ready(void *ctx)
{
	struct kiosk *k = ctx;
	struct content old;
	int ret = reload_finish(&k->reload, k->content, k->renderer, &old);

	if (ret) {
		k->counts.reload_failures++;
		/* Loaded but not uploaded: the matcap's texture may be the new
		 * one's, or none; a new set id makes the record stale, so the
		 * image asked for is decoded again. */
		if (k->reload.ret == 0)
			k->matcap_set_id++;
		reload_job_release(&k->reload);
		service_reloading(true);
	} else {
		/* The old content's cache write is waited for on the worker.
		 * Its settings are the loop's to apply (kiosk_content_service's
		 * caller), then the reload is over. */
		worker_retire(k->worker, &old);
		k->matcap_set_id++;
		k->reload_applied = true;
	}
}

/* f, prepared, in place of the coarse mesh shown; what goes is released
 * on the worker. */
static void swap_refine(struct kiosk *k, struct content_refine *f)
{
	struct content old;

	if (content_refine_swap(k->content, f, k->renderer, &old) == 0)
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	worker_retire(k->worker, &old);
}

/* A coarse picture's full level of detail, prepared: swapped in, unless
 * another model was asked for meanwhile. Then it is kept aside, prepared:
 * the switch drops it with the coarse model (it would show the old model
 * again until the new one is ready), and one that finds no other model
 * leaves it to be swapped in without a job (start_refine). */
static void refine_ready(void *ctx)
{
	struct kiosk *k = ctx;
	struct content_refine *f = refine_job_take(&k->refine);

	if (!kiosk_models_switching(k->models)) {
		swap_refine(k, f);
		return;
	}
	log_info("%s: its full level of detail waits: another model was asked for",
		 content_name(k->content));
	k->content->refine = f;
}

void kiosk_matcap_settled(struct kiosk *k, int index)
{
	k->shown_matcap.set_id = k->matcap_set_id;
	k->shown_matcap.index = index;
}

/* A file that fails keeps the previous texture and says so; the image is
 * given back once on the GPU. */
static void matcap_ready(void *ctx)
{
	struct kiosk *k = ctx;
	struct matcap_job *j = &k->matcap;

	/* The set was read again meanwhile: the index may name another file. */
	if (j->set_id != k->matcap_set_id || !k->content->set) {
		matcap_job_release(j);
		return;
	}
	if (j->ret == 0 && renderer_set_matcap(k->renderer, &j->image) == 0)
		log_info("matcap %s", j->path);
	kiosk_matcap_settled(k, j->index);
	matcap_job_release(j);
	kiosk_tell_app(k, APP_DISPLAY_BACK);
}

int kiosk_content_start(struct kiosk *k)
{
	reload_job_init(&k->reload, reload_ready, k);
	matcap_job_init(&k->matcap, matcap_ready, k);
	refine_job_init(&k->refine, refine_ready, k);
	k->coarse_frame = -1;
	k->worker = worker_new();
	return k->worker ? 0 : -ENOMEM;
}

void kiosk_content_stop(struct kiosk *k)
{
	worker_free(k->worker);
	k->worker = NULL;
	reload_job_release(&k->reload);
	matcap_job_release(&k->matcap);
	refine_job_release(&k->refine);
}

void kiosk_content_reload(struct kiosk *k)
{
	k->reload_wanted = true;
}

static void start_reload(struct kiosk *k)
{
	k->reload_wanted = false;
	service_reloading(false);
	/* --status names this reload's failure, or none after a good one. */
	log_clear_last_error();
	log_info("reload: reading the settings, the model and the matcaps again");
	k->reload_frames = k->frames_drawn;
	k->reload_longest_ns = 0;
	k->reload_timed = true;
	if (reload_start(&k->reload, k->worker, k->argc, k->argv, k->display->width,
			 k->display->height)) {
		k->counts.reload_failures++;
		service_reloading(true);
	}
}

/* Decoding a matcap is done when it is shown, so a folder of many large
 * images costs one image of memory. */
static bool start_matcap(struct kiosk *k)
{
	int want = app_state(k->app)->matcap;
	const struct matcap_set *set = k->content->set;

	if (!set || (k->shown_matcap.set_id == k->matcap_set_id && k->shown_matcap.index == want))
		return false; /* asked for and shown are one */
	if (matcap_job_start(&k->matcap, k->worker, matcap_set_path(set, want), want,
			     k->matcap_set_id) == 0)
		return true;
	kiosk_matcap_settled(k, want); /* no memory: the previous texture stays */
	return false;
}

/* A coarse picture's whole model, once a frame showed it: the first frame
 * (its programs compiled, a software rasteriser on every core) does not
 * share the CPU with the simplification. */
static bool start_refine(struct kiosk *k)
{
	struct content_refine *f = k->content->refine;

	if (!f || content_refine_prepared(f)) {
		k->coarse_frame = -1;
		k->content->refine = NULL;
		if (f) /* kept aside by refine_ready: no other model came */
			swap_refine(k, f);
		return false;
	}
	/* Another coarse model swapped in meanwhile: its own frame first. */
	if (k->coarse_frame < 0 || k->coarse_of != f) {
		k->coarse_frame = k->frames_drawn;
		k->coarse_of = f;
	}
	if (k->frames_drawn == k->coarse_frame)
		return false;
	k->coarse_frame = -1;
	return refine_job_start(&k->refine, k->worker, k->content) == 0;
}

uint64_t kiosk_content_deadline(const struct kiosk *k)
{
	const struct content_refine *f = k->content->refine;
	bool drawn = k->coarse_frame >= 0 && k->coarse_of == f && k->frames_drawn > k->coarse_frame;

	/* A prepared one (kept aside) is swapped in as soon as the worker is idle. */
	return f && (drawn || content_refine_prepared(f)) && !worker_busy(k->worker) ? 0
										     : CLOCK_NEVER;
}

/* Before the loop sleeps: the next job, when the worker is idle. */
void kiosk_content_start_jobs(struct kiosk *k)
{
	if (worker_busy(k->worker) || start_refine(k))
		return;
	if (k->reload_wanted)
		start_reload(k);
	else if (!start_matcap(k) && worker_has_retired(k->worker))
		worker_start(k->worker, NULL);
}

bool kiosk_content_service(struct kiosk *k, const struct pollfd *fds)
{
	k->reload_applied = false;
	if (fds[FD_WORKER].revents & POLLIN)
		worker_finish(k->worker);
	return k->reload_applied;
}

void kiosk_watch_matcaps(struct kiosk *k)
{
	folder_watch_free(k->watch);
	k->watch = k->content->matcap_path ? folder_watch_new(k->content->matcap_path) : NULL;
	k->rescan_at = CLOCK_NEVER;
}

/* The matcap folder changed: its images again, staying on the one shown. */
static int find_matcap(const struct matcap_set *set, const char *path)
{
	for (int i = 0; i < matcap_set_count(set); i++)
		if (strcmp(matcap_set_path(set, i), path) == 0)
			return i;
	return -1;
}

/* A folder listing (no image is decoded here: the one shown is decoded
 * again on the worker, it may be the very file that was rewritten). */
static void rescan_matcaps(struct kiosk *k)
{
	struct app_msg m = {.kind = APP_MATCAPS};
	char *shown;

	k->rescan_at = CLOCK_NEVER;
	if (!k->content->set)
		return;
	shown = strdup(matcap_set_path(k->content->set, app_state(k->app)->matcap));
	if (shown && content_rescan_matcaps(k->content) == 0) {
		m.matcaps.count = matcap_set_count(k->content->set);
		m.matcaps.shown = find_matcap(k->content->set, shown);
		app_apply(k->app, &m);
		k->matcap_set_id++;
	}
	free(shown);
}

void kiosk_service_matcaps(struct kiosk *k, const struct pollfd *fds, uint64_t now)
{
	if ((fds[FD_WATCH].revents & POLLIN) && k->watch && folder_watch_read(k->watch))
		k->rescan_at = now + MATCAP_SETTLE_NS;
	if (now >= k->rescan_at)
		rescan_matcaps(k);
}

void kiosk_look_changed(void *ctx, unsigned what)
{
	struct kiosk *k = ctx;

	if (what & CONTENT_OWN_MATCAP) {
		struct app_msg m = {.kind = APP_MATCAPS};

		/* The set's first image is on the GPU now: the cycle starts
		 * there, and the watch follows the set. */
		m.matcaps.count = k->content->set ? matcap_set_count(k->content->set) : 1;
		m.matcaps.shown = 0;
		app_apply(k->app, &m);
		k->matcap_set_id++;
		kiosk_matcap_settled(k, 0);
		kiosk_watch_matcaps(k);
	}
	if (what & CONTENT_OWN_BACKGROUND) {
		struct view v = content_view(content_settings(k->content, &k->applied.content));

		memcpy(k->view.background, v.background, sizeof(k->view.background));
	}
}
