/* The live loop: sleep in poll() on every descriptor (display, inputs,
 * signals), advance the app state, and draw only when it changed. */
#ifndef MK_KIOSK_H
#define MK_KIOSK_H

#include "app/app.h"
#include "camera/camera_feed.h"
#include "display/display.h"
#include "util/folder_watch.h"
#include "input/input.h"
#include "app/options.h"
#include "render/render.h"
#include "app/content.h"
#include "app/service.h"

#include <stdbool.h>

#define KIOSK_MAX_INPUTS 16

struct kiosk {
	struct display *display;
	struct renderer *renderer;
	struct content *scene; /* on screen; a reload swaps what it holds */
	/* The start's settings and command line: a reload parses the same
	 * command line again over the config file, so options still win. */
	const struct options *opts;
	int argc;
	char **argv;
	struct app app;
	struct view view;
	struct input_source *inputs[KIOSK_MAX_INPUTS];
	int input_count;
	/* What the renderer holds now; set by the caller before kiosk_run. */
	int shown_matcap; /* the image in the texture, -1 for none */
	bool shown_ortho;
	enum shading_mode shown_mode;
	long frames_drawn;
	uint64_t input_drawn_ns; /* the last input a drawn frame shows */
	/* Kept by the loop and the reload. */
	struct folder_watch *watch; /* the matcap folder, NULL when not watched */
	uint64_t rescan_at;	    /* act on matcap changes then; CLOCK_NEVER: none */
	uint64_t waiting_since;	    /* when the pending page flip was queued */
	bool display_absent;	    /* the last draw found no display to show it on */
	struct service service;
	struct camera_feed *camera; /* the live camera; NULL: none */
};

/* Block the signals the loop reads through a signalfd. Call it before any
 * thread starts (the GL driver's), so that no thread takes them with the
 * default action. */
int kiosk_block_signals(void);
int kiosk_unblock_signals(void);
int kiosk_add_input(struct kiosk *k, struct input_source *s);
/* Set the app state, the view and the matcap watch from the settings and
 * k->scene (at the start, and after a reload). */
void kiosk_configure(struct kiosk *k, const struct options *o, uint64_t now_ns);
/* SIGHUP: the settings, model and matcaps again, swapped in only when all
 * of it loaded; on failure the scene on screen stays and the log says why. */
int kiosk_reload(struct kiosk *k, uint64_t now_ns);
/* The matcap folder changed: its images again, staying on the one shown. */
void kiosk_rescan_matcaps(struct kiosk *k);
/* Frees the inputs and the watch (not the display, renderer or scene). */
void kiosk_release(struct kiosk *k);
/* Runs until SIGTERM or SIGINT; returns 0, or a negative errno when the
 * display fails for good. Call kiosk_configure first. */
int kiosk_run(struct kiosk *k);

#endif
