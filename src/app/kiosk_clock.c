/* The clock what moves by itself follows ([kiosk] clock): the loop runs
 * on CLOCK_MONOTONIC, which never steps; on a shared clock the app state
 * adds the wall clock's offset from it, read again on every pass, so the
 * state follows chrony's slews at once and its steps as they come. */
#include "app/kiosk_state.h"
#include "util/clock.h"
#include "util/log.h"

#include <time.h>

int64_t kiosk_clock_offset(const struct kiosk *k)
{
	uint64_t mono, real;

	if (!k->applied.app.shared_clock)
		return 0;
	/* Read in that order the offset errs by one read's time, < 1 us. */
	mono = clock_ns(CLOCK_MONOTONIC);
	real = clock_ns(CLOCK_REALTIME);
	return (int64_t)(real - mono);
}

void kiosk_follow_clock(struct kiosk *k)
{
	int64_t step;

	k->clock_offset = kiosk_clock_offset(k);
	step = app_set_clock(k->app, k->clock_offset);
	if (step)
		log_warn("clock: the wall clock stepped by %+.3f s: attract mode starts afresh on "
			 "it, in step with the other kiosks ([kiosk] clock = shared)",
			 (double)step / 1e9);
}

/* For the wall's measurements (tests/e2e/in-step.sh): which moment of the
 * shared clock the frame shows, and when it was presented. */
void kiosk_clock_presented(struct kiosk *k)
{
	const struct app_state *st = app_state(k->app);

	if (!k->applied.app.shared_clock || !st->pose_ns)
		return;
	log_debug("clock: frame %ld shows %.3f s, yaw %.6f, stop %d, presented at %.6f s",
		  k->frames_drawn, (double)st->pose_ns / 1e9, st->yaw, st->stop,
		  (double)clock_ns(CLOCK_REALTIME) / 1e9);
}
