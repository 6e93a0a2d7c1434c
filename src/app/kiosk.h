/* The live loop: sleep in poll() on every descriptor (display, inputs,
 * camera, matcap folder, signals), hand what happened to the app state
 * (src/state/app.h) as messages, and draw only when the state changed. */
#ifndef MK_KIOSK_H
#define MK_KIOSK_H

#include "content/content.h"
#include "config/options.h"
#include "display/display.h"
#include "input/input.h"
#include "render/render.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

/* What the kiosk runs on; none of it is freed by the kiosk. */
struct kiosk_parts {
	struct display *display;
	struct renderer *renderer; /* already holding the content, its first matcap and mode */
	struct content *content;   /* on screen; a reload swaps what it holds */
	/* The settings it starts with (copied), and the command line a
	 * reload parses again over the config file, so options still win. */
	const struct options *options;
	char **argv;	      /* NULL-terminated */
	bool camera_possible; /* the display can draw camera frames (EGL) */
};

struct kiosk;

/* The app state, the view and the matcap watch from the settings. No
 * inputs and no camera yet. NULL when out of memory. */
struct kiosk *kiosk_new(const struct kiosk_parts *parts, uint64_t now_ns);
/* Frees the inputs, the camera and the watch (not the parts). The GL
 * context must be current. */
void kiosk_free(struct kiosk *k);
/* An input source of the caller's; the kiosk destroys it when it drops it. */
int kiosk_add_input(struct kiosk *k, struct input_source *s);
/* The buttons, keyboards and touchscreens of the settings, and the
 * camera. A button or camera that cannot be had is logged and left out. Returns 0, or -EEXIST
 * when two buttons are one line (a config error). */
int kiosk_open_devices(struct kiosk *k);
/* Runs until SIGTERM or SIGINT; returns 0, or a negative errno when the
 * display fails for good. */
int kiosk_run(struct kiosk *k);
long kiosk_frames_drawn(const struct kiosk *k);
/* --stats: the camera's figures, when there is one. */
void kiosk_print_stats(const struct kiosk *k, FILE *out);

#endif
