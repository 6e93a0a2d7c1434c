/* The live loop's state, shared by the files that make up the loop:
 * src/app/kiosk.c (the loop, the devices, a reload applied),
 * src/app/kiosk_content.c (the content worker's jobs) and
 * src/app/kiosk_report.c (what --status and the metrics say),
 * src/app/kiosk_anim.c (the animation's frames) and src/app/kiosk_remote.c
 * (remote control over MQTT). Nothing
 * else includes it: the rest of the program sees struct kiosk as opaque
 * (src/app/kiosk.h). */
#ifndef MK_KIOSK_STATE_H
#define MK_KIOSK_STATE_H

#include "state/app.h"
#include "state/visits.h"
#include "state/remote.h"
#include "state/lang.h"
#include "content/content.h"
#include "app/kiosk_models.h"
#include "app/reload.h"
#include "content/matcap_job.h"
#include "content/refine_job.h"
#include "content/worker.h"
#include "ops/metrics.h"
#include "ops/service.h"
#include "config/settings.h"
#include "ops/status.h"
#include "camera/camera_feed.h"
#include "display/display.h"
#include "input/input.h"
#include "input/touch.h"
#include "render/render.h"
#include "render/render_scale.h"
#include "util/folder_watch.h"

#include <poll.h>
#include <stdbool.h>
#include <stdint.h>

struct kiosk_anim; /* app/kiosk_anim.h */
struct mqtt_link;  /* ops/mqtt.h */

/* The language shown (src/app/kiosk_lang.c): what was last seen of the
 * app state and the content. */
struct kiosk_lang {
	unsigned serial;       /* renderer_mesh_serial when set up */
	int step;	       /* app_state lang_step seen */
	double round;	       /* attract mode's tour, seconds a language */
	bool picked;	       /* a visitor chose one (kept across models) */
	struct lang_pick pick; /* state/lang.h */
};

/* The names the visitor counters give what is shown (kiosk_visits.c),
 * read once a model (or settings) is uploaded, not every turn of the loop. */
struct kiosk_seen {
	unsigned serial;				    /* renderer_mesh_serial when read */
	char hotspot[FRAME_STOPS + HOTSPOTS][HOTSPOT_NAME]; /* each stop's; "": none */
	char lang[LANG_MAX][LANG_CODE_MAX];		    /* [caption] languages' codes */
};

/* The material variant shown (src/app/kiosk_variant.c): what was last
 * applied, to act on changes alone. */
struct kiosk_variant {
	unsigned serial;	    /* the renderer's mesh it was set up for */
	int step;		    /* app_state variant_step seen */
	char stop[FRAME_STOP_CLIP]; /* the stop's variant seen; "": none */
	int shown;		    /* -1: the file's default materials */
	unsigned warned;	    /* the stops whose missing variant was said (bits) */
};

/* Input sources at most (kiosk_add_input). */
#define KIOSK_MAX_INPUTS 16
#define MAX_EVENTS	 32

/* Matcaps being copied into the folder: act once the copy has been quiet
 * this long, so a burst of files is one rescan. */
#define MATCAP_SETTLE_NS 500000000ull

/* The loop's descriptors, in poll()'s array. */
enum {
	FD_SIGNAL,
	FD_DISPLAY,
	FD_WATCH,
	FD_CAMERA,
	FD_STATUS,
	FD_TOUCH,
	FD_WORKER,
	FD_MODEL_WATCH,
	FD_MQTT,
	FD_INPUTS
};

/* Where an input source came from: a reload opens the buttons or the
 * keyboards again, and leaves the others alone. */
enum input_origin { INPUT_CALLER, INPUT_BUTTON, INPUT_KEYBOARD };

struct kiosk {
	struct display *display;
	struct renderer *renderer;
	struct render_scale *scale; /* [display] render_scale's GL pass */
	struct content *content;    /* on screen; a reload swaps what it holds */
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
	/* What the renderer holds now. The matcap asked for is the app
	 * state's (app_state()->matcap); the image in the texture is recorded
	 * here only by kiosk_matcap_settled, where one was uploaded (or was
	 * refused, and the previous stays: asked once, said once). A job runs
	 * while the two differ. A set read again bumps matcap_set_id: what
	 * was recorded of the old set no longer matches. */
	struct {
		unsigned set_id; /* matcap_set_id when it was recorded */
		int index;	 /* into that set */
	} shown_matcap;
	bool shown_ortho;
	enum shading_mode shown_mode;
	long frames_drawn;
	uint64_t input_drawn_ns;    /* the last input a drawn frame shows */
	struct folder_watch *watch; /* the matcap folder, NULL when not watched */
	uint64_t rescan_at;	    /* act on matcap changes then; CLOCK_NEVER: none */
	uint64_t waiting_since;	    /* when the pending page flip was queued */
	unsigned outputs_failed;    /* bit i: output i's last frame failed (several outputs) */
	bool display_absent;	    /* the last draw found no display to show it on */
	struct service service;
	struct camera_feed *camera;   /* the live camera; NULL: none */
	struct screen *screen;	      /* its power; NULL: always on */
	struct status_server *status; /* --status; NULL: not reachable */
	struct metrics *metrics;      /* [status] metrics; NULL: none */
	struct status_counts counts;
	struct visits visits; /* what visitors did, for the metrics and --status */
	uint64_t started_ns;
	double started_at;	     /* the wall clock's seconds then, for the metrics */
	struct touch *touch;	     /* the touchscreens; NULL: off */
	struct kiosk_models *models; /* a folder or list of models; NULL: one, unwatched */
	/* The content worker and its jobs other than a model switch's. */
	struct worker *worker;
	struct reload_job reload;
	bool reload_wanted;	  /* SIGHUP seen, not started yet */
	bool reload_applied;	  /* in this pass: the devices may be new */
	long reload_frames;	  /* frames_drawn when the reload started */
	struct matcap_job matcap; /* decoding the image asked for */
	unsigned matcap_set_id;	  /* bumped when the set or the texture changes under it */
	/* A coarse picture's full level of detail (content/refine_job.h),
	 * and frames_drawn when the content shown was first found with
	 * coarse_of to refine: it starts once a frame showed it (a screen
	 * asleep draws none: it waits for the wake); -1: none found yet. */
	struct refine_job refine;
	long coarse_frame;
	const struct content_refine *coarse_of;
	/* The loop thread's longest step, from a wake-up to the next sleep:
	 * what a page flip or an input may wait for (the bench reads it). */
	uint64_t woke_ns;
	int64_t clock_offset;	 /* [kiosk] clock = shared: CLOCK_REALTIME less CLOCK_MONOTONIC */
	int64_t clock_lead;	 /* ... and the time a frame takes to the screen (kiosk_clock.c) */
	uint64_t clock_taken_ns; /* CLOCK_MONOTONIC when the state was last advanced */
	struct {		 /* a frame on a shared clock, until its flip (kiosk_clock.c) */
		bool pending;
		long frame;
		uint64_t drawn_ns; /* CLOCK_MONOTONIC when its state was taken */
		uint64_t pose_ns;
		double yaw;
		int stop;
	} clock_frame;
	uint64_t longest_step_ns;
	/* The same, from a reload's start to the first step after its
	 * upload; logged then (the figure of issue 22 on the board). */
	uint64_t reload_longest_ns;
	bool reload_timed;
	int caption_at[2];	  /* where the caption is shown (it drifts) */
	unsigned caption_plane;	  /* the caption picture on an overlay plane; 0: none */
	unsigned caption_refused; /* the one no plane took (drawn with GL) */
	struct kiosk_anim *anim;  /* the animation player (kiosk_anim.h) */
	/* The material variant shown (kiosk_variant.h). */
	struct kiosk_variant variant;
	/* [mqtt] remote control (kiosk_remote.c). */
	struct {
		struct mqtt_link *link;	 /* NULL: off */
		struct remote_sync sent; /* a leader's last step */
		bool sent_any;
		uint64_t sent_input_ns; /* on a shared clock: the press it followed */
		struct remote_sync due; /* a follower's step to show at due.at_ms */
		bool due_any;
	} remote;
	/* The language the texts are shown in (kiosk_lang.c). */
	struct kiosk_lang lang;
	struct kiosk_seen seen; /* kiosk_visits.c */
};

/* A message with no payload to the app state (a frame shown, the display
 * to draw again). Inline: every file of the loop tells the app, and a
 * function of kiosk.c called from the files kiosk.c calls would make them
 * one piece again (tests/tools/layers.sh refuses circles of calls). */
static inline void kiosk_tell_app(struct kiosk *k, enum app_msg_kind kind)
{
	struct app_msg m = {.kind = kind};

	app_apply(k->app, &m);
}

/* src/app/kiosk_caption.c: the caption over the frame just drawn (before the
 * present), and when it next drifts or must be tested on a plane. */
void kiosk_caption_draw(struct kiosk *k, const struct view *v);
uint64_t kiosk_caption_deadline(struct kiosk *k, uint64_t now);
/* src/app/kiosk_clock.c: the offset of the app state's clock from the
 * loop's (CLOCK_MONOTONIC): 0 on its own clock, CLOCK_REALTIME's on a
 * shared one. Follow it on every pass (a step is said in the journal);
 * a frame presented on a shared clock is logged at debug level. */
int64_t kiosk_clock_offset(const struct kiosk *k);
void kiosk_follow_clock(struct kiosk *k);
void kiosk_clock_presented(struct kiosk *k);
void kiosk_clock_flipped(struct kiosk *k);
/* src/app/kiosk_anim.c: the animation's pose at now, a frame asked for
 * when it changed; returns when the next frame is due (CLOCK_NEVER:
 * none). */
uint64_t kiosk_play_animation(struct kiosk *k, uint64_t now, bool awake);
/* src/app/kiosk_variant.c: the variant the settings, the stop reached
 * and next-variant ask for, shown by the renderer (the draw list's
 * materials changed: no upload); a frame asked for when it changed. */
void kiosk_show_variant(struct kiosk *k);
/* src/app/kiosk_lang.c: the language next-language, attract mode and
 * idle_seconds ask for, its pictures given to the renderer; a frame
 * asked for when it changed. */
void kiosk_show_language(struct kiosk *k, uint64_t now);
/* src/app/kiosk_visits.c: what is shown at now (the stop, the hotspot,
 * the language, attract mode) to the visitor counters. */
void kiosk_observe_visits(struct kiosk *k, uint64_t now);
/* src/app/kiosk_content.c: the content worker's jobs (reload, matcap,
 * the matcap folder). */
int kiosk_content_start(struct kiosk *k);
void kiosk_content_stop(struct kiosk *k);
void kiosk_content_reload(struct kiosk *k);
/* Before the loop sleeps: the next job, when the worker is idle. */
void kiosk_content_start_jobs(struct kiosk *k);
/* When a job is due with nothing to wake the loop (a coarse picture
 * drawn: its refine); CLOCK_NEVER: none. */
uint64_t kiosk_content_deadline(const struct kiosk *k);
/* A job done is handed on. True when a reload's content was uploaded:
 * the loop then applies its settings (kiosk.c; the devices may be new)
 * and tells systemd the reload is over (service_reloading). */
bool kiosk_content_service(struct kiosk *k, const struct pollfd *fds);
void kiosk_watch_matcaps(struct kiosk *k);
/* The set's image `index` is in the texture (or refused: the previous
 * stays): the one writer of k->shown_matcap. */
void kiosk_matcap_settled(struct kiosk *k, int index);
/* kiosk_models_parts.look_changed: a model's own matcaps or background
 * (or kiosk.ini's again) are on the GPU: the cycle, the watch and the
 * clear colour follow. */
void kiosk_look_changed(void *ctx, unsigned what);
void kiosk_service_matcaps(struct kiosk *k, const struct pollfd *fds, uint64_t now);
/* src/app/kiosk_remote.c: [mqtt] remote control, started with the loop
 * (its settings are [mqtt]'s at the start); commands taken when its fd is
 * readable, the state published when it changed. */
void kiosk_remote_start(struct kiosk *k);
void kiosk_remote_stop(struct kiosk *k);
int kiosk_remote_fd(const struct kiosk *k);
void kiosk_remote_service(struct kiosk *k, short revents, uint64_t now);
void kiosk_remote_publish(struct kiosk *k);
/* A follower's step due later (CLOCK_MONOTONIC), or CLOCK_NEVER. */
uint64_t kiosk_remote_deadline(const struct kiosk *k, uint64_t now);

#endif
