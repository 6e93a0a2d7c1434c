/* The app state's types: its settings, what a frame shows, its messages
 * (state/app.h has what acts on them). */
#ifndef MK_APP_TYPES_H
#define MK_APP_TYPES_H

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
	/* [kiosk] clock = shared: what moves by itself is a function of the
	 * shared clock (CLOCK_REALTIME, ns) and of the last state change,
	 * the start counting as one at the clock's epoch, so kiosks whose
	 * clocks chrony or PTP keep together draw the same moment. The
	 * state's times are then the shared clock's: the caller's plus
	 * clock_offset_ns (app_set_clock). */
	bool shared_clock;
	int64_t clock_offset_ns;
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
	double zoom;		/* the picture's scale about its centre: 1 at rest */
	bool dirty;		/* something changed since the last frame drawn */
	uint64_t last_input_ns; /* on the state's clock (app_clock) */
	/* On a shared clock in attract mode: the moment of its grid the pose
	 * is of (alike on every kiosk); else 0. */
	uint64_t pose_ns;
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

#endif
