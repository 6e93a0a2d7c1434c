/* What the visitor counters (state/visits.h) are told is shown: the
 * app's stop, the hotspot whose text a visitor reads (next-hotspot's view,
 * or a stop turned to it), the language on screen, attract mode. The
 * names are read from the settings once a model is uploaded: the loop
 * only indexes them. */
#include "app/kiosk_state.h"
#include "config/lang_text.h"

#include <stdio.h>
#include <string.h>

/* The hotspot each stop shows: a [frame] stop's hotspot=NAME when the
 * model has it (else none: nothing was drawn), hotspot i's view its NAME. */
static void read_hotspots(struct kiosk_seen *s, const struct content_config *cfg)
{
	struct app_frame f;
	struct quat rest;

	content_app_frame(cfg, &f, &rest);
	for (int i = 0; i < f.stop_count && i < FRAME_STOPS; i++)
		if (hotspot_find(&cfg->hotspots, f.stops[i].hotspot) >= 0)
			snprintf(s->hotspot[i], sizeof(s->hotspot[i]), "%s", f.stops[i].hotspot);
	for (int i = 0; i < cfg->hotspots.count && i < HOTSPOTS; i++)
		snprintf(s->hotspot[FRAME_STOPS + i], sizeof(s->hotspot[0]), "%s",
			 cfg->hotspots.items[i].name);
}

static void read_names(struct kiosk *k, struct kiosk_seen *s)
{
	const struct content_config *cfg = content_settings(k->content, &k->applied.content);
	char err[128];

	memset(s, 0, sizeof(*s));
	s->serial = renderer_mesh_serial(k->renderer);
	read_hotspots(s, cfg);
	/* A list that does not parse was refused with its file and line when
	 * read; the content then shows no languages either. */
	if (lang_list_parse(cfg->caption.languages, s->lang, err, sizeof(err)) < 0)
		memset(s->lang, 0, sizeof(s->lang));
}

void kiosk_observe_visits(struct kiosk *k, uint64_t now)
{
	struct kiosk_seen *s = &k->seen;
	const struct app_state *st = app_state(k->app);
	int l = k->content->lang_shown;
	struct visit_view w = {.stop = st->stop, .attract = app_attracting(k->app)};

	if (s->serial != renderer_mesh_serial(k->renderer))
		read_names(k, s);
	if (st->stop >= 0 && st->stop < FRAME_STOPS + HOTSPOTS)
		w.hotspot = s->hotspot[st->stop];
	if (k->content->lang_count > 0 && l >= 0 && l < LANG_MAX)
		w.lang = s->lang[l];
	visits_observe(&k->visits, now, &w);
}
