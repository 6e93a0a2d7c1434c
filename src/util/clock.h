/* Nanoseconds on a clock. The app, the inputs (the kernel stamps GPIO and
 * evdev events on CLOCK_MONOTONIC) and the loop all count time in these. */
#ifndef MK_CLOCK_H
#define MK_CLOCK_H

#include <stdint.h>
#include <time.h>

/* A deadline that never comes. */
#define CLOCK_NEVER UINT64_MAX

static inline uint64_t clock_ns(clockid_t id)
{
	struct timespec ts;

	clock_gettime(id, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

static inline uint64_t monotonic_ns(void)
{
	return clock_ns(CLOCK_MONOTONIC);
}

#endif
