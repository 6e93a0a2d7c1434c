/* The kiosk's state, and nothing of GL, DRM, GPIO or files: timestamped
 * messages in (a button or key, the camera, the matcap folder, a reload,
 * the display), new state out. This file is the one place the state
 * changes; everyone else reads it through app_state(). That is what makes
 * it testable without hardware. Buttons and keys are turned into actions
 * elsewhere (src/input/). */
#ifndef MK_APP_H
#define MK_APP_H

#include "input/action.h"
#include "input/gesture.h"
#include "util/clock.h"
#include "util/math3d.h"
#include "render/shading.h"
#include "state/view.h"

#include <stdbool.h>
#include <stdint.h>

/* [kiosk] in kiosk.ini (turn_* and attract_*), and the resting pose the
 * kiosk takes from [scene]. */
struct app_config {
	double turn_speed;	/* radians per second while a turn is held */
	double turn_step;	/* radians a tap turns, however short the tap */
	double attract_after_s; /* idle time before turning by itself; 0: never */
	double attract_speed;	/* radians per second in attract mode */
	double attract_fps;	/* frames per second at most in attract mode; 0: the display's */
	double attract_model_s; /* the next model this often in attract mode; 0: never */
	struct quat rest;	/* the model's own turn ([frame] up, orientation) */
	struct app_frame frame; /* start view, limits, attract's shape, stops */
	enum shading_mode mode;
	double drag_speed;	    /* radians a drag across the whole screen turns */
	enum app_action long_press; /* what a long touch does */
};

/* A pinch zooms within these: the model stays whole and big enough to see. */
#define APP_ZOOM_MIN 0.5
#define APP_ZOOM_MAX 4.0

/* What a frame shows: read-only outside src/state/app.c. */
struct app_state {
	struct quat orientation;
	int matcap;	/* index into the image matcaps */
	bool camera_on; /* the live camera frame is the matcap */
	enum shading_mode mode;
	double zoom; /* the picture's scale about its centre: 1 at rest */
	bool dirty;  /* something changed since the last frame drawn */
	uint64_t last_input_ns;
	int model;	   /* the model wanted, an index into the model list */
	int model_step;	   /* +1 or -1: the way the last step went, for passing over */
	double yaw, pitch; /* radians: orientation is pitch x yaw x rest */
	int stop;	   /* the guided stop shown or eased to; -1: none */
	/* That stop's text (for a caption), or NULL; owned by the app, valid
	 * until the next message. */
	const char *stop_text;
	/* The clip that stop plays ([frame] stops' animation=), or NULL. */
	const char *stop_animation;
	bool anim_paused; /* play-pause: the animation is held */
	int anim_step;	  /* next-animation: how many clips on from the one set */
	/* next-variant: how many variants on from the one shown (the kiosk
	 * steps by the difference: app_variant_step); the variant the stop
	 * shows ([frame] stops' variant=), or NULL. */
	int variant_step;
	const char *stop_variant;
	/* next-language: presses so far (the kiosk steps by the
	 * difference, state/lang.h). */
	int lang_step;
};

enum app_msg_kind {
	APP_INPUT,	  /* .input: a button or a key */
	APP_CAMERA,	  /* .camera: what the camera feed found */
	APP_MATCAPS,	  /* .matcaps: the matcap folder was read again */
	APP_RELOADED,	  /* .reload: the settings were read again */
	APP_DISPLAY_BACK, /* a display came (back): everything is drawn again */
	APP_FRAME_SHOWN,  /* the state was drawn and handed to the display */
	APP_TOUCH,	  /* .touch: a touchscreen gesture */
	APP_MODELS,	  /* .models: a model was shown, or the list read again */
	APP_FRAME,	  /* .frame: the model shown has this [frame] (its NAME.ini) */
};

struct app_msg {
	enum app_msg_kind kind;
	union {
		struct app_event input;
		struct gesture touch;
		struct {
			bool available; /* a camera is there and can be drawn */
			bool frame;	/* it sent a new frame */
		} camera;
		struct {
			int count; /* image matcaps that next/prev cycle through */
			int shown; /* where the image shown before is now; -1: gone */
		} matcaps;
		struct {
			int count; /* models that next/prev-model cycle through */
			int shown; /* the one on screen now; -1: none of them */
		} models;
		struct {
			const struct app_frame *frame;
			struct quat rest;
			enum shading_mode mode;
			uint64_t now_ns;
		} frame;
		struct {
			const struct app_config *config;
			int matcap_count;
			uint64_t now_ns;
		} reload;
	};
};

struct app;

/* matcap_count: the image matcaps (at least one is assumed). NULL when out
 * of memory. */
struct app *app_new(const struct app_config *cfg, int matcap_count, uint64_t now_ns);
void app_free(struct app *a);
const struct app_state *app_state(const struct app *a);
/* Apply one message. Inputs may come a little late (a deadline serviced
 * after the loop advanced); one older than the state counts at the
 * state's time. A reload starts the state afresh, but a live camera
 * stays on. */
void app_apply(struct app *a, const struct app_msg *m);
/* Advance the clock: held turns and attract mode move the model. Returns
 * the time at which the state next changes by itself, or CLOCK_NEVER. */
uint64_t app_advance(struct app *a, uint64_t now_ns);
/* True in attract mode (what the visitors' counters call idle). */
bool app_attracting(const struct app *a);
/* True while the model moves by itself or by a held turn. */
bool app_moving(const struct app *a);

/* The variant shown after `steps` next-variant presses from `shown`, of
 * a model of `count` variants: each in turn, then the file's default
 * materials (-1), then the first again. -1 for a model without any. */
int app_variant_step(int shown, int count, int steps);

#endif
