/* Which variant is shown: [scene] variant when a model is uploaded (none:
 * the file's default materials), a stop's variant= when the stop is
 * reached (the attract tour steps through them by its stops),
 * next-variant on from the one shown. Names the model lacks were said at
 * load ([scene] variant) or are said once here (a stop's); the model
 * shows what it showed. */
#include "app/kiosk_state.h"
#include "util/log.h"

#include <string.h>

/* A stop's variant, said once for each stop (the tour comes back). */
static int find(struct kiosk *k, struct kiosk_variant *kv, int stop, const char *name)
{
	int v = content_variant_find(k->content, name);
	unsigned bit = stop >= 0 && stop < 32 ? 1u << stop : 0;

	if (v < 0 && !(kv->warned & bit))
		log_warn("%s: [frame] stops (stop %d) variant=%s: the model has no such variant; "
			 "the one shown stays",
			 k->content->model_path ? k->content->model_path : "the model", stop + 1,
			 name);
	kv->warned |= bit;
	return v;
}

static void set_up(struct kiosk *k, struct kiosk_variant *kv, const struct app_state *st)
{
	const struct content_config *cfg = content_settings(k->content, &k->applied.content);

	kv->serial = renderer_mesh_serial(k->renderer);
	kv->step = st->variant_step;
	kv->stop[0] = '\0';
	kv->warned = 0;
	/* Its absence was said at load. */
	kv->shown = cfg->variant ? content_variant_find(k->content, cfg->variant) : -1;
}

void kiosk_show_variant(struct kiosk *k)
{
	struct kiosk_variant *kv = &k->variant;
	const struct app_state *st = app_state(k->app);
	const char *stop = st->stop_variant ? st->stop_variant : "";
	int count = renderer_variant_count(k->renderer);
	bool named;

	if (kv->serial != renderer_mesh_serial(k->renderer))
		set_up(k, kv, st);
	if (strcmp(stop, kv->stop)) {
		int v = stop[0] && count ? find(k, kv, st->stop, stop) : -1;

		if (v >= 0)
			kv->shown = v;
		snprintf(kv->stop, sizeof(kv->stop), "%s", stop);
	}
	if (st->variant_step != kv->step) {
		kv->shown = app_variant_step(kv->shown, count, st->variant_step - kv->step);
		kv->step = st->variant_step;
	}
	if (!renderer_show_variant(k->renderer, kv->shown))
		return;
	named = kv->shown >= 0 && (uint32_t)kv->shown < k->content->mesh.variant_count;
	log_debug("%s: showing %s%s", k->content->model_path ? k->content->model_path : "the model",
		  named ? "variant " : "its own materials",
		  named ? k->content->mesh.variant_names[kv->shown] : "");
	kiosk_tell_app(k, APP_DISPLAY_BACK);
}
