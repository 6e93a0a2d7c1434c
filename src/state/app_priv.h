/* The app state's insides, for state/app.c and state/app_pose.c only:
 * everyone else reads struct app_state (state/app.h). */
#ifndef MK_APP_PRIV_H
#define MK_APP_PRIV_H

#include "state/app_types.h"

/* One direction of turning. A press turns from its time on; the turn
 * lasts while any source holds it, and at least until until_ns, so a tap
 * shorter than a frame still turns turn_step, smoothly. */
struct app_turn {
	int held;	   /* sources holding it (a key and a button may both) */
	uint64_t until_ns; /* the tap's minimum end */
};

struct app {
	struct app_state state;
	struct app_config cfg;
	int matcap_count;	  /* image matcaps that next/prev cycle through */
	bool camera_available;	  /* found by the camera feed, not by the settings */
	bool camera_resume;	  /* show the camera when it is (back) there */
	bool attract;		  /* turning by itself */
	uint64_t attract_ns;	  /* its turn is drawn up to then */
	uint64_t model_at;	  /* attract mode steps to the next model then */
	int model_count;	  /* models that next/prev-model cycle through */
	uint64_t now_ns;	  /* the last time the state was advanced to */
	struct app_turn turns[4]; /* left, right, up, down */
	/* A glide to a view (home before attract's turn, a stop): yaw,
	 * pitch, zoom from (from, v0) to (to, v1) over ease_s from ease_ns;
	 * then attract mode's path, when it is attract's. */
	bool easing;
	uint64_t ease_ns;
	double ease_s, from[3], v0[3], to[3], v1[3];
	struct attract_path path;
	bool touring;	       /* attract mode plays the stops */
	uint64_t stop_at;      /* attract mode's next stop then */
	uint64_t attract_from; /* attract mode began then */
};

static inline double app_clampd(double x, double lo, double hi)
{
	return x < lo ? lo : x > hi ? hi : x;
}

/* state/app_pose.c */
void app_frame_normalise(struct app_frame *f);
void app_pose(struct app *a, double yaw, double pitch, double zoom);
void app_set_stop(struct app *a, int stop);
void app_home(struct app *a);
void app_ease_to(struct app *a, uint64_t t, const double to[3], double v1, double speed);
double app_ease_speed(const struct app *a);
void app_to_stop(struct app *a, int k, uint64_t t, double speed);
void app_glide(struct app *a, uint64_t now);

#endif
