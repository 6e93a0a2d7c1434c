/* [frame]: how a model is framed and toured (per model from NAME.ini, or
 * for all from kiosk.ini): its orientation before the fit, the start view,
 * the limits every input obeys, how attract mode moves it, and the guided
 * stops. Plain data and pure functions of time, so the app state
 * (state/app.c) and the tests sample the same curves. */
#ifndef MK_VIEW_H
#define MK_VIEW_H

#include "state/hotspot.h"
#include "util/math3d.h"

#include <stdbool.h>
#include <stddef.h>

/* [frame] up: which of the model's axes is drawn upwards. */
enum frame_up {
	FRAME_UP_Y,
	FRAME_UP_NEG_Y,
	FRAME_UP_Z,
	FRAME_UP_NEG_Z,
	FRAME_UP_X,
	FRAME_UP_NEG_X
};

/* Stops at most, and a stop's text at most (bytes, with the NUL). */
#define FRAME_STOPS	8
#define FRAME_STOP_TEXT 128
#define FRAME_STOP_CLIP 64

/* As the settings keep it: degrees; NAN: not set. */
struct frame_config {
	enum frame_up up;
	char *orientation; /* "ROLL PITCH YAW" in degrees; NULL: up alone */
	double yaw, pitch; /* the start view; NAN: [scene]'s */
	double zoom;	   /* the start zoom, 1: the fit's */
	double yaw_min, yaw_max, pitch_min, pitch_max; /* NAN: no limit */
	double zoom_min, zoom_max;		       /* 0: APP_ZOOM_MIN/MAX */
	int attract_direction;			       /* 0: right, 1: left */
	double attract_sway;			       /* degrees each way; 0: full turns */
	char *stops;				       /* 'yaw pitch zoom "text"; ...' */
	double stop_seconds;			       /* attract mode's time at a stop; 0: none */
};

struct frame_stop {
	double yaw, pitch, zoom; /* radians, radians, the app's zoom */
	char text[FRAME_STOP_TEXT];
	/* The animation played there ([scene] animation's words: a name, an
	 * index, all); "": the one playing goes on. */
	char animation[FRAME_STOP_CLIP];
	/* The KHR_materials_variants variant shown there (its name); "": the
	 * one shown stays. */
	char variant[FRAME_STOP_CLIP];
	/* The hotspot turned to the visitor there ([hotspot.NAME]'s NAME):
	 * its facing view replaces the stop's yaw and pitch, its text an
	 * empty stop text (content_frame); "": none. */
	char hotspot[FRAME_STOP_CLIP];
};

/* In radians, as the app state uses it. */
struct app_frame {
	double yaw0, pitch0, zoom0; /* the start view */
	bool yaw_limited, pitch_limited;
	double yaw_min, yaw_max, pitch_min, pitch_max, zoom_min, zoom_max;
	double direction; /* +1: right, -1: left */
	double sway;	  /* radians each way; 0: full turns */
	int stop_count;
	/* stops[0 .. stop_count): [frame] stops; stops[FRAME_STOPS + i]: the
	 * view that faces hotspot i (next-hotspot), hotspot_count of them,
	 * filled by the content (content_app_frame_at). */
	struct frame_stop stops[FRAME_STOPS + HOTSPOTS];
	int hotspot_count;
	double stop_seconds;
};

/* The view next-hotspot (select: the select action, the knob's press)
 * glides to from the one shown (app_state.stop: a stop, FRAME_STOPS + i
 * hotspot i's view, -1 none), as an index of f->stops: the next
 * hotspot's view when the model has hotspots, else for select the next
 * of its stops, as next-stop does; -1: none. */
int app_frame_hotspot_step(const struct app_frame *f, int shown, bool select);

void frame_config_defaults(struct frame_config *f);
/* The model's turn before everything (up, then orientation). 0, or -1
 * with err naming what is wrong. */
int frame_base(const struct frame_config *f, struct quat *out, char *err, size_t n);
/* Parse 'yaw pitch zoom "text" animation=CLIP variant=NAME hotspot=NAME;
 * ...' (degrees; the text and the last three optional, those in any
 * order). The count, or -1 with err. */
int frame_stops_parse(const char *text, struct frame_stop *out, int max, char *err, size_t n);
/* f in radians for the app, with the start yaw and pitch (degrees) that
 * apply when f sets none. -1 with err when its stops do not parse or a
 * limit's minimum is above its maximum. */
int frame_to_app(const struct frame_config *f, double yaw_deg, double pitch_deg,
		 struct app_frame *out, char *err, size_t n);
/* The start view, in degrees: f's, else the fallback's. */
double frame_start_yaw(const struct frame_config *f, double fallback);
double frame_start_pitch(const struct frame_config *f, double fallback);

/* One coordinate's ease from (p0, v0) to (p1, v1) over d seconds: the cubic
 * whose position and speed match at both ends. Position and speed at t. */
double ease_at(double p0, double v0, double p1, double v1, double d, double t, double *speed);

/* Attract mode's swing or turn from home at time t after it started:
 * full turns at speed (direction's sign), or a sine about a centre whose
 * peak speed is speed. */
struct attract_path {
	double home, centre, amplitude, phase, omega, velocity; /* velocity: full turns */
};
void attract_path_make(struct attract_path *p, const struct app_frame *f, double home,
		       double speed);
double attract_path_at(const struct attract_path *p, double t, double *speed);

#endif
