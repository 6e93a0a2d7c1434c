/* What the settings make of the view (background colour, orientation) and
 * of the app state's frame (the stops, the rest pose): plain translations
 * of a content_config, no file read. The loader (content.c), the caption
 * (content_caption.c) and the loop (app/) read them; they call nothing
 * back. */
#include "content/content.h"
#include "render/framing.h"

#include <stdio.h>

struct view content_view(const struct content_config *o)
{
	struct view v = {.ortho = o->ortho, .rotation = o->rotation, .wall = o->wall};
	struct app_frame f;
	struct quat rest;
	struct background_spec bg;
	char err[200];

	if (background_parse(o->background, &bg, err, sizeof(err)))
		background_spec_default(&bg);
	background_clear_color(&bg, v.background);

	content_app_frame(o, &f, &rest);
	v.orientation = quat_multiply(quat_from_axis_angle(1, 0, 0, f.pitch0),
				      quat_multiply(quat_from_axis_angle(0, 1, 0, f.yaw0), rest));
	return v;
}

void content_app_frame(const struct content_config *c, struct app_frame *f, struct quat *rest)
{
	char err[200];

	if (frame_to_app(&c->frame, c->yaw, c->pitch, f, err, sizeof(err))) {
		struct frame_config none;

		frame_config_defaults(&none);
		frame_to_app(&none, c->yaw, c->pitch, f, err, sizeof(err));
	}
	if (frame_base(&c->frame, rest, err, sizeof(err)))
		*rest = (struct quat){1, 0, 0, 0};
	/* A stop at a hotspot without a text of its own shows the hotspot's. */
	for (int i = 0; i < f->stop_count; i++) {
		int at =
		    f->stops[i].hotspot[0] ? hotspot_find(&c->hotspots, f->stops[i].hotspot) : -1;

		if (at >= 0 && !f->stops[i].text[0])
			snprintf(f->stops[i].text, sizeof(f->stops[i].text), "%s",
				 hotspot_text(&c->hotspots.items[at], NULL, NULL));
	}
}
