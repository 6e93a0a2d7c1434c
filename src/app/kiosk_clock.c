/* The clock what moves by itself follows ([kiosk] clock): the loop runs
 * on CLOCK_MONOTONIC, which never steps; on a shared clock the app state
 * adds the wall clock's offset from it, read again on every pass, so the
 * state follows chrony's slews at once and its steps as they come. */
#include "app/kiosk_state.h"
#include "util/clock.h"
#include "util/log.h"

#include <time.h>

/* A frame reaches the screen some time after the state it shows: the
 * time to draw it, then the wait for the next vblank. On a screen the
 * state runs that much ahead, so each moment lands on the vblank closest
 * to it: half a refresh until flips are timed, then the average time from
 * a present to its flip (an eighth of each new one: a slow frame moves it
 * little). Offscreen a frame is shown when it is presented. */
#define LEAD_MAX_NS 1000000000ll

int64_t kiosk_clock_offset(const struct kiosk *k)
{
	uint64_t mono, real;
	int64_t lead = k->clock_lead ? k->clock_lead : (int64_t)k->display->refresh_ns / 2;

	if (!k->applied.app.shared_clock)
		return 0;
	/* Read in that order the offset errs by one read's time, < 1 us. */
	mono = clock_ns(CLOCK_MONOTONIC);
	real = clock_ns(CLOCK_REALTIME);
	return (int64_t)(real - mono) + lead;
}

void kiosk_follow_clock(struct kiosk *k)
{
	int64_t step;

	k->clock_taken_ns = clock_ns(CLOCK_MONOTONIC);
	k->clock_offset = kiosk_clock_offset(k);
	step = app_set_clock(k->app, k->clock_offset);
	if (step)
		log_warn("clock: the wall clock stepped by %+.3f s: attract mode starts afresh on "
			 "it, in step with the other kiosks ([kiosk] clock = shared)",
			 (double)step / 1e9);
}

static void log_frame(struct kiosk *k, double presented_s)
{
	log_debug("clock: frame %ld shows %.3f s, yaw %.6f, stop %d, presented at %.6f s",
		  k->clock_frame.frame, (double)k->clock_frame.pose_ns / 1e9, k->clock_frame.yaw,
		  k->clock_frame.stop, presented_s);
	k->clock_frame.pending = false;
}

/* For the wall's measurements (tests/e2e/in-step.sh): which moment of the
 * shared clock the frame shows, and when it reached the screen (on KMS
 * its flip's vblank, kiosk_clock_flipped). */
void kiosk_clock_presented(struct kiosk *k)
{
	const struct app_state *st = app_state(k->app);

	if (!k->applied.app.shared_clock || !st->pose_ns)
		return;
	k->clock_frame.pending = true;
	k->clock_frame.frame = k->frames_drawn;
	k->clock_frame.pose_ns = st->pose_ns;
	k->clock_frame.yaw = st->yaw;
	k->clock_frame.stop = st->stop;
	k->clock_frame.drawn_ns = k->clock_taken_ns;
	if (!k->display->refresh_ns)
		log_frame(k, (double)clock_ns(CLOCK_REALTIME) / 1e9);
}

void kiosk_clock_flipped(struct kiosk *k)
{
	struct display *d = k->display;
	double wall_less_mono;
	int64_t took;

	if (!k->clock_frame.pending || d->waiting || !(d->flipped_s > 0))
		return;
	took = (int64_t)(d->flipped_s * 1e9) - (int64_t)k->clock_frame.drawn_ns;
	if (took > 0 && took < LEAD_MAX_NS)
		k->clock_lead = k->clock_lead ? k->clock_lead + (took - k->clock_lead) / 8 : took;
	wall_less_mono =
	    ((double)clock_ns(CLOCK_REALTIME) - (double)clock_ns(CLOCK_MONOTONIC)) / 1e9;
	log_frame(k, d->flipped_s + wall_less_mono);
}
