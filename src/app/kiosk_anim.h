/* The live loop's animation player: the clip of the content on screen
 * played by the wall clock, posed on the CPU (scene/anim_play.h) into the
 * renderer's live arrays at most [scene] animation_fps times a second,
 * and not at all while it does not run (paused by play-pause, by
 * animation_pause_after of no input, or the screen asleep): then the
 * clock holds, and it goes on where it stopped. next-animation crossfades
 * to the next clip; a reload of the same model goes on with its clock,
 * or crossfades where its clip changed. "all" plays every clip together. A content without playback
 * costs nothing here. */
#ifndef MK_KIOSK_ANIM_H
#define MK_KIOSK_ANIM_H

#include "content/content.h"
#include "render/render.h"

#include <stdbool.h>
#include <stdint.h>

/* How long a clip change blends the pose shown into the new clip's. */
#define KIOSK_ANIM_FADE_NS 250000000ull

struct kiosk_anim;

/* What the loop tells the player each step. */
struct kiosk_anim_input {
	bool running;  /* awake, and input within animation_pause_after */
	bool paused;   /* play-pause (the app state's anim_paused) */
	int clip_step; /* next-animation presses (the app state's anim_step) */
	/* The guided stop's clip (the app state's stop_animation): played,
	 * crossfaded, from when the stop is reached; NULL: none. */
	const char *stop_clip;
	const struct content_config *config; /* the content's settings */
	/* [kiosk] clock = shared: the state's clock now (CLOCK_REALTIME,
	 * ns), where a looping clip's phase is taken from; 0: its own. */
	uint64_t shared_ns;
};

struct kiosk_anim *kiosk_anim_new(void);
void kiosk_anim_free(struct kiosk_anim *a);
/* At now: a new content's clip is set up (a content without playback:
 * nothing), the clock advanced where it runs and a frame is due, and the
 * pose written into c's mesh and r's live arrays. true when the pose
 * changed (draw a frame); *next: when the next frame is due (CLOCK_NEVER:
 * none until something changes). */
bool kiosk_anim_step(struct kiosk_anim *a, struct content *c, struct renderer *r,
		     const struct kiosk_anim_input *in, uint64_t now, uint64_t *next);
/* The clip time shown, seconds (for tests and the journal; "all": the
 * first clip's); -1: none. */
double kiosk_anim_time(const struct kiosk_anim *a);

#endif
