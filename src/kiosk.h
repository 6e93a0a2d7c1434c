/* The live loop: sleep in poll() on every descriptor (display, inputs,
 * signals), advance the app state, and draw only when it changed. */
#ifndef MK_KIOSK_H
#define MK_KIOSK_H

#include "app.h"
#include "display.h"
#include "input.h"
#include "matcap_set.h"
#include "render.h"

#include <stdbool.h>

#define KIOSK_MAX_INPUTS 16

struct kiosk {
	struct display *display;
	struct renderer *renderer;
	struct matcap_set *matcaps;
	struct app app;
	struct view view;
	struct input_source *inputs[KIOSK_MAX_INPUTS];
	int input_count;
	/* What the renderer holds now; set by the caller before kiosk_run. */
	int shown_matcap; /* the image in the texture, -1 for none */
	bool shown_ortho;
	enum shading_mode shown_mode;
	long frames_drawn;
};

/* Block the signals the loop reads through a signalfd. Call it before any
 * thread starts (the GL driver's), so that no thread takes them with the
 * default action. */
int kiosk_block_signals(void);
int kiosk_add_input(struct kiosk *k, struct input_source *s);
/* Runs until SIGTERM or SIGINT; returns 0, or a negative errno when the
 * display fails for good. */
int kiosk_run(struct kiosk *k);

#endif
