/* Which language the texts are shown in (state/lang.h): the visitor's
 * next-language presses, attract mode's tour of them, the first after
 * idle_seconds. The pictures of every language were drawn on the
 * worker; a change here swaps and uploads them (content_show_language). */
#include "app/kiosk_state.h"
#include "util/log.h"

#include <math.h>

/* One round of attract mode's tour, in seconds: its stops each
 * stop_seconds, else one full turn. */
static double tour_round(struct kiosk *k)
{
	const struct content_config *cfg = content_settings(k->content, &k->applied.content);
	struct app_frame f;
	struct quat rest;

	content_app_frame(cfg, &f, &rest);
	if (f.stop_count > 0 && f.stop_seconds > 0)
		return f.stop_count * f.stop_seconds;
	return k->applied.app.attract_speed > 0 ? 2 * M_PI / k->applied.app.attract_speed : 0;
}

/* A model (or settings) uploaded: its languages; the visitor's choice
 * stays where the new one has it. */
static void set_up(struct kiosk *k, struct kiosk_lang *kl, const struct app_state *st)
{
	int chosen = kl->pick.chosen;

	kl->serial = renderer_mesh_serial(k->renderer);
	kl->step = st->lang_step;
	kl->round = tour_round(k);
	lang_pick_init(&kl->pick, k->content->lang_count);
	kl->pick.chosen = k->content->lang_shown;
	if (chosen < kl->pick.count && kl->pick.count > 1 && kl->picked)
		kl->pick.chosen = chosen;
}

void kiosk_show_language(struct kiosk *k, uint64_t now)
{
	struct kiosk_lang *kl = &k->lang;
	const struct app_state *st = app_state(k->app);
	uint64_t t = app_clock(k->app, now); /* the state's clock: a shared one's tour */
	double idle = t > st->last_input_ns ? (double)(t - st->last_input_ns) / 1e9 : 0;
	int shown;

	if (kl->serial != renderer_mesh_serial(k->renderer))
		set_up(k, kl, st);
	if (kl->pick.count < 2)
		return;
	if (st->lang_step != kl->step) {
		lang_pick_next(&kl->pick, st->lang_step - kl->step);
		kl->step = st->lang_step;
		kl->picked = true;
	}
	shown = lang_pick_shown(&kl->pick, idle, k->applied.app.attract_after_s, kl->round);
	if (shown == k->content->lang_shown)
		return;
	if (!content_show_language(k->content, k->renderer, shown)) {
		char codes[LANG_MAX][LANG_CODE_MAX];

		if (shown < content_languages(content_settings(k->content, &k->applied.content), codes))
			log_info("language: %s shown", codes[shown]);
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	}
}
