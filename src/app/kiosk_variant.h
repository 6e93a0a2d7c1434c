/* The loop's side of KHR_materials_variants: the variant the settings,
 * the stop reached and next-variant ask for, shown by the renderer (a
 * change of the draw list's materials: no upload). */
#ifndef MK_KIOSK_VARIANT_H
#define MK_KIOSK_VARIANT_H

#include "state/view.h"

/* What was last applied, to act on changes alone. */
struct kiosk_variant {
	unsigned serial;	    /* the renderer's mesh it was set up for */
	int step;		    /* app_state variant_step seen */
	char stop[FRAME_STOP_CLIP]; /* the stop's variant seen; "": none */
	int shown;		    /* -1: the file's default materials */
};

struct kiosk;

/* Called each pass of the loop, after the app state changed: shows the
 * variant asked for, and asks for a frame when the picture changed. */
void kiosk_show_variant(struct kiosk *k);

#endif
