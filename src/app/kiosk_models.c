#include "app/kiosk_models.h"
#include "config/model_settings.h"
#include "content/model_list.h"
#include "content/model_loader.h"
#include "util/clock.h"
#include "util/folder_watch.h"
#include "util/log.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* A model copied in: act once the copy has been quiet this long. */
#define MODEL_SETTLE_NS 500000000ull
/* Files that arrived whole since the last rescan, at most. */
#define MAX_ARRIVED 16
/* The job under way loads a file that arrived, not a model asked for. */
#define REQUESTED_ARRIVED -2

struct kiosk_models {
	struct kiosk_models_parts p;
	struct model_list *list;
	struct model_loader *loader;
	struct folder_watch *watch; /* NULL: not watched */
	int shown;		    /* the list's model on screen; -1: none of them */
	int asked;		    /* the wanted model last acted on */
	int requested;		    /* the one the job under way was asked for */
	int reload;		    /* load this one alone next (it changed); -1: none */
	uint64_t rescan_at;
	uint64_t asked_ns; /* when the job under way was started, for the bench */
	char *arrived[MAX_ARRIVED];
	int arrived_count;
	bool syncing;		/* a sync tool is writing into the folder: said once */
	char *settings_changed; /* the model whose NAME.ini was written; NULL: none */
};

static void finish(void *ctx);

static void tell_app(struct kiosk_models *m, int shown)
{
	struct app_msg msg = {.kind = APP_MODELS, .models = {model_list_count(m->list), shown}};

	app_apply(m->p.app, &msg);
}

/* The model shown has its own [frame] and mode (its NAME.ini). */
static void tell_frame(struct kiosk_models *m)
{
	const struct content_config *c = content_settings(m->p.content, m->p.config);
	struct app_frame f;
	struct app_msg msg = {.kind = APP_FRAME};

	content_app_frame_at(m->p.content, c, &f, &msg.frame.rest);
	msg.frame.frame = &f;
	msg.frame.mode = c->mode;
	msg.frame.now_ns = monotonic_ns();
	app_apply(m->p.app, &msg);
}

/* The file name of model's NAME.ini; "" when it has none. */
static const char *ini_name(const char *model, char *buf, size_t n)
{
	const char *slash;

	if (!model_settings_path(model, buf, n))
		return "";
	slash = strrchr(buf, '/');
	return slash ? slash + 1 : buf;
}

static void watch_models(struct kiosk_models *m)
{
	const char *spec = m->p.config->model;

	char ini[PATH_MAX];

	/* A list names several places: each of them is read at a reload. */
	if (!strchr(spec, ','))
		m->watch = folder_watch_new(spec);
	/* One file: its folder is watched for its name, and its NAME.ini's. */
	if (m->watch && !model_spec_is_many(spec) && *ini_name(spec, ini, sizeof(ini)) &&
	    folder_watch_also(m->watch, ini_name(spec, ini, sizeof(ini))))
		log_warn("%s: its settings file is not watched (no memory)", spec);
}

struct kiosk_models *kiosk_models_new(const struct kiosk_models_parts *parts, uint64_t now_ns)
{
	struct kiosk_models *m;

	(void)now_ns;
	/* The built-in knot shown because the model failed: the list is
	 * still watched, so the file fixed or copied in is shown. */
	if (!parts->config->model)
		return NULL;
	m = calloc(1, sizeof(*m));
	if (!m)
		return NULL;
	m->p = *parts;
	m->list = model_list_new(parts->config->model);
	m->loader = m->list ? model_loader_new(parts->worker, finish, m) : NULL;
	if (!m->loader) {
		kiosk_models_free(m);
		return NULL;
	}
	m->shown = model_list_find(m->list, parts->content->model_path);
	m->reload = -1;
	m->rescan_at = CLOCK_NEVER;
	watch_models(m);
	tell_app(m, m->shown);
	m->asked = app_state(m->p.app)->model;
	log_info("models: %d, showing %s", model_list_count(m->list),
		 parts->content->model_path ? parts->content->model_path : "the built-in knot");
	return m;
}

static void forget_arrived(struct kiosk_models *m)
{
	for (int i = 0; i < m->arrived_count; i++)
		free(m->arrived[i]);
	m->arrived_count = 0;
}

void kiosk_models_free(struct kiosk_models *m)
{
	if (!m)
		return;
	model_loader_free(m->loader);
	model_list_free(m->list);
	folder_watch_free(m->watch);
	forget_arrived(m);
	free(m->settings_changed);
	free(m);
}

void kiosk_models_fill_fds(const struct kiosk_models *m, struct pollfd fds[1])
{
	fds[0] =
	    (struct pollfd){.fd = m && m->watch ? folder_watch_fd(m->watch) : -1, .events = POLLIN};
}

bool kiosk_models_switching(const struct kiosk_models *m)
{
	return m && (m->reload >= 0 || app_state(m->p.app)->model != m->asked);
}

uint64_t kiosk_models_deadline(const struct kiosk_models *m)
{
	return m && !worker_busy(m->p.worker) ? m->rescan_at : CLOCK_NEVER;
}

int kiosk_models_count(const struct kiosk_models *m)
{
	return m && m->list ? model_list_count(m->list) : 0;
}

/* On the GPU, in place of the model on screen; on failure that one stays. */
static int show(struct kiosk_models *m, struct content *fresh, int index)
{
	struct content old;
	int ret = content_upload_model(fresh, m->p.renderer);
	unsigned own;

	if (ret) {
		m->p.counts->model_load_failures++;
		log_err("%s: does not fit on the GPU; keeping %s", fresh->model_path,
			m->p.content->model_path);
		model_list_set_bad(m->list, index, true);
		content_release(fresh);
		if (content_upload_model(m->p.content, m->p.renderer))
			log_err("models: the model on screen could not be restored either");
		return ret;
	}
	content_take_model(m->p.content, fresh, &old);
	own = m->p.content->own_look;
	m->p.content->own_look = 0;
	if (own && content_upload_look(m->p.content, m->p.renderer))
		log_err("%s: its matcap or background does not fit on the GPU",
			m->p.content->model_path);
	if (own && m->p.look_changed)
		m->p.look_changed(m->p.ctx, own);
	tell_frame(m);
	/* Its cache write and sync are waited for on the worker. */
	worker_retire(m->p.worker, &old);
	m->shown = index;
	m->p.counts->model_loads++;
	log_info("model %d of %d: %s", index + 1, model_list_count(m->list),
		 m->p.content->model_path);
	/* The frame that shows it is drawn next: what a switch costs is this
	 * and one frame (the bench adds them). */
	log_debug("models: swapped in %.1f ms after it was asked for",
		  (double)(monotonic_ns() - m->asked_ns) / 1e6);
	return 0;
}

/* The loader's ready(): on the loop thread, from the worker's done(). */
static void finish(void *ctx)
{
	struct kiosk_models *m = ctx;
	struct content fresh;
	int picked;

	if (model_loader_finish(m->loader, &fresh, &picked))
		return;
	if (picked >= 0 && fresh.model_path)
		show(m, &fresh, picked);
	else /* none loaded, or only the one on screen */
		m->p.counts->model_load_failures++;
	content_release(&fresh);
	/* The user may have stepped on meanwhile: that step stands, and is
	 * acted on next. A file that arrived is shown whatever was wanted. */
	if (m->requested != REQUESTED_ARRIVED && app_state(m->p.app)->model != m->requested) {
		tell_app(m, -1);
		return;
	}
	tell_app(m, m->shown);
	m->asked = app_state(m->p.app)->model;
}

static void start(struct kiosk_models *m, int from, int step)
{
	struct display *d = m->p.display;

	m->requested = from;
	m->asked_ns = monotonic_ns();
	if (model_loader_start(m->loader, m->list, m->p.config, &m->p.content->look, from, step,
			       m->shown, d->width, d->height)) {
		tell_app(m, m->shown);
		m->asked = app_state(m->p.app)->model;
	}
}

/* A model's NAME.ini written (config/model_settings.h): that model is
 * loaded again once the folder is quiet, when it is the one shown. */
static bool settings_of(struct kiosk_models *m, const char *path)
{
	char ini[PATH_MAX];

	for (int i = 0; i < model_list_count(m->list); i++)
		if (model_settings_path(model_list_path(m->list, i), ini, sizeof(ini)) &&
		    !strcmp(ini, path)) {
			free(m->settings_changed);
			m->settings_changed = strdup(model_list_path(m->list, i));
			return true;
		}
	return false;
}

static bool arrived_path(void *ctx, const char *path)
{
	struct kiosk_models *m = ctx;

	for (int i = 0; i < m->arrived_count; i++)
		if (strcmp(m->arrived[i], path) == 0)
			return true;
	return false;
}

static void note_arrived(void *ctx, const char *folder, const char *name)
{
	struct kiosk_models *m = ctx;
	const char *spec = m->p.config->model;
	char path[PATH_MAX], ini[PATH_MAX];
	bool one_file = !model_spec_is_many(spec);

	/* One file: the watch reports its name or its NAME.ini's alone. */
	if (one_file && !strcmp(name, ini_name(spec, ini, sizeof(ini)))) {
		free(m->settings_changed);
		m->settings_changed = strdup(spec);
		return;
	}
	if (one_file)
		snprintf(path, sizeof(path), "%s", spec);
	else
		snprintf(path, sizeof(path), "%s/%s", folder, name);
	if (!one_file && settings_of(m, path))
		return;
	if (m->arrived_count < MAX_ARRIVED && !arrived_path(m, path))
		m->arrived[m->arrived_count++] = strdup(path);
	if (m->arrived_count && !m->arrived[m->arrived_count - 1])
		m->arrived_count--;
}

/* The folder (or file) changed: the list again, and the model that
 * arrived or changed last is loaded and shown when ready. */
static void rescan(struct kiosk_models *m)
{
	int fresh;
	struct model_list *l =
	    model_list_rescan(m->list, m->p.config->model, arrived_path, m, &fresh);

	m->rescan_at = CLOCK_NEVER;
	m->syncing = false;
	forget_arrived(m);
	if (!l)
		return;
	model_list_free(m->list);
	m->list = l;
	m->shown = model_list_find(l, m->p.content->model_path);
	m->reload = fresh;
	if (fresh < 0 && m->settings_changed &&
	    model_list_find(l, m->settings_changed) == m->shown && m->shown >= 0) {
		log_info("models: %s: its settings changed: loading it again", m->settings_changed);
		m->reload = m->shown;
	}
	free(m->settings_changed);
	m->settings_changed = NULL;
	if (fresh >= 0)
		log_debug("models: %s arrived or changed: loading it", model_list_path(l, fresh));
	tell_app(m, m->shown);
	m->asked = app_state(m->p.app)->model;
}

void kiosk_models_service(struct kiosk_models *m, const struct pollfd fds[1], uint64_t now_ns)
{
	int want;

	if (!m)
		return;
	if ((fds[0].revents & POLLIN) && m->watch &&
	    folder_watch_read_names(m->watch, note_arrived, m))
		m->rescan_at = now_ns + MODEL_SETTLE_NS;
	/* The list is the job's while it runs; the worker does one job at
	 * a time (a reload or a matcap may hold it). */
	if (model_loader_busy(m->loader) || worker_busy(m->p.worker))
		return;
	/* rsync and Syncthing write each file under a temporary name and
	 * rename it into place; a .gltf may land before its .bin or its
	 * textures/: the folder is read once nothing is being written. */
	if (now_ns >= m->rescan_at && m->watch &&
	    folder_watch_sync_under_way(m->watch, time(NULL))) {
		if (!m->syncing)
			log_info("models: a sync is writing into %s: waiting until it is done",
				 m->p.config->model);
		m->syncing = true;
		m->rescan_at = now_ns + MODEL_SETTLE_NS;
	}
	if (now_ns >= m->rescan_at)
		rescan(m);
	want = app_state(m->p.app)->model;
	if (m->reload >= 0) {
		start(m, m->reload, 0);
		m->requested = REQUESTED_ARRIVED;
		m->reload = -1;
	} else if (want != m->asked) {
		m->asked = want;
		start(m, want, app_state(m->p.app)->model_step);
	}
}
