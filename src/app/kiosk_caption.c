/* The caption's side of the loop: its picture for the stop shown, on an
 * overlay plane where the display has one that takes it, else drawn by
 * GL over the frame; its drift against burn-in. */
#include "app/kiosk_state.h"
#include "util/clock.h"
#include "util/log.h"

#include <string.h>
#include <time.h>

/* The caption's drift goes by the wall clock: hours are the panel's. */
static double caption_clock(void)
{
	return (double)clock_ns(CLOCK_REALTIME) / 1e9;
}

/* The overlay plane is upright and in the mode's pixels: a turned panel,
 * or a primary plane that scales a smaller frame up (render_scale), keeps
 * the caption on GL (there drawn at the frame's size, scaled with it). */
static bool plane_possible(const struct kiosk *k)
{
	return k->display->overlay && !k->view.rotation && !k->display->plane_scaled;
}

/* The caption's picture of the stop the app shows ([frame] stops), the
 * one the renderer then draws: both were drawn on the worker. */
static const struct image *caption_picture(struct kiosk *k)
{
	int stop = app_state(k->app)->stop;

	renderer_show_stop(k->renderer, stop);
	return content_caption(k->content, stop);
}

/* The caption on an overlay plane where the display has one that takes it
 * (tested once per picture, after a first frame set the mode): true, and
 * GL draws none. */
static bool caption_on_plane(struct kiosk *k)
{
	struct display *d = k->display;
	const struct image *img = caption_picture(k);
	unsigned serial = renderer_caption_serial(k->renderer);

	if (!d->overlay)
		return false;
	if (!serial || !plane_possible(k) || !k->frames_drawn || serial == k->caption_refused) {
		if (k->caption_plane)
			d->overlay(d->overlay_ctx, NULL, 0, 0, 0);
		k->caption_plane = 0;
		return false;
	}
	if (d->overlay(d->overlay_ctx, img, serial, k->caption_at[0], k->caption_at[1])) {
		k->caption_refused = serial;
		k->caption_plane = 0;
		return false;
	}
	k->caption_plane = serial;
	return true;
}

/* The caption drifts against burn-in, a pixel every few minutes, and is
 * looked at every 10 s (nothing to a CPU; a clock set forward is seen
 * soon): on a plane, the plane alone moves; else a
 * frame is drawn. A picture not yet tested on a plane asks for a frame. */
uint64_t kiosk_caption_deadline(struct kiosk *k, uint64_t now)
{
	struct display *d = k->display;
	const struct image *img = caption_picture(k);
	unsigned serial = renderer_caption_serial(k->renderer);
	int at[2];

	if (!renderer_caption_at(k->renderer, &k->view, caption_clock(), d->width, d->height, at))
		return CLOCK_NEVER;
	if (d->overlay && plane_possible(k) && k->frames_drawn && serial != k->caption_plane &&
	    serial != k->caption_refused)
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	/* Another picture than the plane's (a stop's text, or back from
	 * one): the next frame puts it on the plane or draws it with GL. */
	if (k->caption_plane && serial != k->caption_plane) {
		kiosk_tell_app(k, APP_DISPLAY_BACK);
		return now + 10000000000ull;
	}
	if (at[0] == k->caption_at[0] && at[1] == k->caption_at[1])
		return now + 10000000000ull;
	if (k->caption_plane && !d->overlay(d->overlay_ctx, img, serial, at[0], at[1])) {
		log_debug("caption: its plane moved to %d,%d", at[0], at[1]);
		memcpy(k->caption_at, at, sizeof(at));
	} else {
		k->caption_refused = k->caption_plane ? k->caption_plane : k->caption_refused;
		k->caption_plane = 0;
		kiosk_tell_app(k, APP_DISPLAY_BACK);
	}
	return now + 10000000000ull;
}

void kiosk_caption_draw(struct kiosk *k, const struct view *v)
{
	struct display *d = k->display;

	caption_picture(k);
	renderer_caption_at(k->renderer, v, caption_clock(), d->width, d->height, k->caption_at);
	if (!caption_on_plane(k))
		renderer_draw_caption(k->renderer, v, caption_clock(), d->width, d->height);
}
