/* The moment an offscreen still shows (--output): the start view, one of
 * [frame] stops (--stop N), or a moment of the attract tour (--at
 * SECONDS), found by running the app state as the live kiosk runs it, a
 * frame at a time, so the still is what the screen would show then. */
#ifndef MK_PREVIEW_H
#define MK_PREVIEW_H

#include "config/settings.h"
#include "content/content.h"
#include "render/render.h"

/* v: the view of that moment (orientation, zoom, the outline placed) for
 * content s with settings c; *stop: the stop shown (-1: none), whose
 * caption picture the still draws. 0, -EINVAL after logging (a stop the
 * model lacks), or -ENOMEM. */
int preview_moment(const struct options *o, const struct content *s, const struct content_config *c,
		   struct view *v, int *stop);

#endif
