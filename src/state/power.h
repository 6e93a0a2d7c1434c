/* Whether the screen should be on: `[power] schedule` by weekday and local
 * time, and `blank_after` minutes without input. Pure: the clocks in, on or
 * off out, so the tests run whole weeks and DST days in microseconds; the
 * loop makes the display sleep or wake.
 *
 * - Inside the schedule (or without one) the screen is on, and sleeps
 *   after blank_after without input (0: never).
 * - Outside the schedule it is off; an input wakes it for blank_after (a
 *   minute when that is 0), then it sleeps again.
 * - A wall clock that is not synchronised (a Raspberry Pi has no RTC and
 *   boots in the past until NTP answers) cannot say the time of day: the
 *   schedule is not used and the screen stays on, and power_update says so
 *   once. */
#ifndef MK_POWER_H
#define MK_POWER_H

#include "state/schedule.h"
#include "util/clock.h"

#include <stdbool.h>
#include <stdint.h>

struct power_config {
	struct schedule schedule; /* count 0: always inside */
	double blank_after_s;	  /* 0: never blank for idleness */
};

/* The wall clock as the loop reads it (localtime_r and timedatectl's
 * idea of synchronised), with the monotonic time it was read at. */
struct power_clock {
	uint64_t now_ns; /* CLOCK_MONOTONIC */
	int wday;	 /* 0 Sunday, as tm_wday */
	int minute;	 /* of the local day, 0..1439 */
	bool synced;
};

enum power_reason {
	POWER_ALWAYS,	    /* no schedule, no blank_after */
	POWER_SCHEDULED_ON, /* inside the schedule */
	POWER_NO_CLOCK,	    /* on because the wall clock is not synchronised */
	POWER_WOKEN,	    /* on outside the schedule: an input woke it */
	POWER_SCHEDULED_OFF,
	POWER_IDLE,	  /* off after blank_after without input */
	POWER_REMOTE_OFF, /* off by remote control until an input or "screen on" */
};

/* What power_update reports, as bits. */
#define POWER_CHANGED	   1u /* on changed: make the display sleep or wake */
#define POWER_SAY_UNSYNCED 2u /* the first time the clock was found unsynchronised */

struct power_state {
	struct power_config cfg;
	bool on;
	enum power_reason reason;
	uint64_t last_input_ns; /* for blank_after; the start counts as input */
	uint64_t woken_ns;	/* the last input outside the schedule; CLOCK_NEVER */
	bool said_unsynced;
	bool remote_off; /* remote control's "screen off" holds */
};

void power_init(struct power_state *p, const struct power_config *cfg, const struct power_clock *c);
/* Any input (button, key, touch) at c->now_ns; then power_update. */
unsigned power_input(struct power_state *p, const struct power_clock *c);
/* Remote control's "screen on" (an input) or "screen off" (held until
 * an input); then power_update. */
unsigned power_remote(struct power_state *p, const struct power_clock *c, bool on);
/* Where the clocks are now; returns POWER_* bits. */
unsigned power_update(struct power_state *p, const struct power_clock *c);
/* The next monotonic time at which idleness changes the state, or
 * CLOCK_NEVER. The schedule's own changes fall on minute boundaries of the
 * local clock: the loop also updates once a minute while there is one. */
uint64_t power_deadline(const struct power_state *p);
const char *power_reason_name(enum power_reason r);

#endif
