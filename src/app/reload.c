/* Changing what the kiosk shows while it runs, without a black screen:
 * the new scene is built completely beside the one on screen (which stays
 * scanned out meanwhile), and swapped in only when every part of it
 * loaded and reached the GPU. */
#include "app/kiosk.h"
#include "util/log.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void watch_matcaps(struct kiosk *k)
{
	folder_watch_free(k->watch);
	k->watch = k->scene->matcap_path ? folder_watch_new(k->scene->matcap_path) : NULL;
	k->rescan_at = CLOCK_NEVER;
}

void kiosk_configure(struct kiosk *k, const struct options *o, uint64_t now_ns)
{
	static const enum log_level levels[] = {LOG_ERR, LOG_WARN, LOG_INFO, LOG_DEBUG};
	struct app_config cfg = {
	    .turn_speed = o->turn_speed * M_PI / 180,
	    .turn_step = o->turn_step * M_PI / 180,
	    .attract_after_s = o->attract_after,
	    .attract_speed = o->attract_speed * M_PI / 180,
	    .mode = (enum shading_mode)o->mode,
	    .matcap_count = k->scene->set ? matcap_set_count(k->scene->set) : 1,
	    /* Found by the camera code, not by the settings. */
	    .camera_available = k->app.cfg.camera_available,
	};

	log_set_level(levels[o->log_level]);
	k->view = content_view(o);
	cfg.rest = k->view.orientation;
	app_init(&k->app, &cfg, now_ns);
	/* content_upload gave the renderer the set's first image. */
	k->shown_matcap = 0;
	watch_matcaps(k);
}

static bool same_string(const char *a, const char *b)
{
	return a == b || (a && b && strcmp(a, b) == 0);
}

/* The display is opened once; these wait for the next start. */
static void warn_restart_only(const struct options *was, const struct options *now)
{
	if (was->backend != now->backend || was->size[0] != now->size[0] ||
	    was->size[1] != now->size[1] || was->on_busy != now->on_busy ||
	    !same_string(was->device, now->device) ||
	    !same_string(was->connector, now->connector) ||
	    !same_string(was->display_mode, now->display_mode))
		log_warn("reload: [display] settings other than rotation take effect at the next "
			 "start (systemctl restart matcap-kiosk)");
}

int kiosk_reload(struct kiosk *k, uint64_t now_ns)
{
	struct options o;
	struct content fresh;
	int ret;

	service_reloading(false);
	log_info("reload: reading the settings, the model and the matcaps again");
	ret = options_parse(&o, k->argc, k->argv);
	if (ret) {
		log_err("reload: the settings have errors (above); keeping the scene on screen");
		goto out;
	}
	ret = content_load(&fresh, &o, true);
	if (!ret && (ret = content_prepare(&fresh, &o, k->display->width, k->display->height)))
		content_release(&fresh);
	if (ret) {
		log_err("reload: keeping the scene on screen");
		goto out;
	}
	ret = content_upload(&fresh, k->renderer);
	if (ret) {
		log_err("reload: the new scene does not fit on the GPU; keeping the one on screen");
		content_release(&fresh);
		if (content_upload(k->scene, k->renderer))
			log_err("reload: the scene on screen could not be restored either");
		goto out;
	}
	content_release(k->scene);
	*k->scene = fresh;
	warn_restart_only(k->opts, &o);
	kiosk_configure(k, &o, now_ns);
	log_info("reload: done");
out:
	options_release(&o);
	service_reloading(true);
	return ret;
}

void kiosk_rescan_matcaps(struct kiosk *k)
{
	char *shown;

	k->rescan_at = CLOCK_NEVER;
	if (!k->scene->set)
		return;
	shown = strdup(matcap_set_path(k->scene->set, k->app.matcap));
	if (shown && content_rescan_matcaps(k->scene) == 0) {
		int count = matcap_set_count(k->scene->set);

		app_set_matcap_count(&k->app, count);
		/* Stay on the picture shown when it is still there. */
		for (int i = 0; i < count; i++)
			if (strcmp(matcap_set_path(k->scene->set, i), shown) == 0)
				k->app.matcap = i;
		/* It may be the very file that was rewritten: decode it again. */
		k->shown_matcap = -1;
		k->app.dirty = true;
	}
	free(shown);
}

void kiosk_release(struct kiosk *k)
{
	for (int i = 0; i < k->input_count; i++)
		k->inputs[i]->destroy(k->inputs[i]);
	k->input_count = 0;
	folder_watch_free(k->watch);
	k->watch = NULL;
}
