/* The live loop's state, shared by the files that make up the loop:
 * src/app/kiosk.c (the loop, the devices, reloads) and
 * src/app/kiosk_report.c (what --status and the metrics say). Nothing
 * else includes it: the rest of the program sees struct kiosk as opaque
 * (src/app/kiosk.h). */
#ifndef MK_KIOSK_STATE_H
#define MK_KIOSK_STATE_H

#include "state/app.h"
#include "content/content.h"
#include "app/kiosk_models.h"
#include "ops/metrics.h"
#include "ops/service.h"
#include "config/settings.h"
#include "ops/status.h"
#include "camera/camera_feed.h"
#include "display/display.h"
#include "input/input.h"
#include "input/touch.h"
#include "render/render.h"
#include "util/folder_watch.h"

#include <stdbool.h>
#include <stdint.h>

/* Input sources at most (kiosk_add_input). */
#define KIOSK_MAX_INPUTS 16

/* Where an input source came from: a reload opens the buttons or the
 * keyboards again, and leaves the others alone. */
enum input_origin { INPUT_CALLER, INPUT_BUTTON, INPUT_KEYBOARD };

struct kiosk {
	struct display *display;
	struct renderer *renderer;
	struct content *content; /* on screen; a reload swaps what it holds */
	char **argv;
	int argc;
	bool camera_possible;
	struct options started; /* [display] stays as it was at the start */
	struct options applied; /* the settings in use, from the last reload */
	struct app *app;	/* the one owner of the state; changed by messages */
	struct view view;
	struct input_source *inputs[KIOSK_MAX_INPUTS];
	enum input_origin origins[KIOSK_MAX_INPUTS];
	int input_count;
	/* What the renderer holds now. */
	int shown_matcap; /* the image in the texture, -1 for none */
	bool shown_ortho;
	enum shading_mode shown_mode;
	long frames_drawn;
	uint64_t input_drawn_ns;    /* the last input a drawn frame shows */
	struct folder_watch *watch; /* the matcap folder, NULL when not watched */
	uint64_t rescan_at;	    /* act on matcap changes then; CLOCK_NEVER: none */
	uint64_t waiting_since;	    /* when the pending page flip was queued */
	bool display_absent;	    /* the last draw found no display to show it on */
	struct service service;
	struct camera_feed *camera;   /* the live camera; NULL: none */
	struct screen *screen;	      /* its power; NULL: always on */
	struct status_server *status; /* --status; NULL: not reachable */
	struct metrics *metrics;      /* [status] metrics; NULL: none */
	struct status_counts counts;
	uint64_t started_ns;
	double started_at;	     /* the wall clock's seconds then, for the metrics */
	struct touch *touch;	     /* the touchscreens; NULL: off */
	struct kiosk_models *models; /* a folder or list of models; NULL: one, unwatched */
};

#endif
