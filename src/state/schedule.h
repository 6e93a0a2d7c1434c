/* When the screen is on, by weekday and local time: `[power] schedule`,
 * e.g. "Mon-Fri 08:00-20:00, Sat 10:00-16:00". Each entry is a day or a
 * range of days (Mon..Sun, or daily) and one or more spans HH:MM-HH:MM; a
 * span that ends before it starts runs past midnight into the next day
 * ("Fri 18:00-02:00"), and 24:00 ends a day. Pure: local time in, on or
 * off out; DST needs nothing special because only the wall clock counts. */
#ifndef MK_SCHEDULE_H
#define MK_SCHEDULE_H

#include <stdbool.h>
#include <stddef.h>

#define SCHEDULE_MAX_SPANS 32

struct schedule_span {
	unsigned days;	/* bit 0 Sunday ... bit 6 Saturday, as struct tm's tm_wday */
	int start, end; /* minutes after midnight; end < start: past midnight */
};

struct schedule {
	int count; /* 0: no schedule, always on */
	struct schedule_span spans[SCHEDULE_MAX_SPANS];
};

/* Parses text into s. Returns 0, or -EINVAL and writes into err (at most
 * err_size bytes) what was found where and what was expected. */
int schedule_parse(struct schedule *s, const char *text, char *err, size_t err_size);
/* True when the schedule has the screen on at minute (0..1439) of the
 * weekday wday (0 Sunday, as tm_wday); always true without a schedule. */
bool schedule_on(const struct schedule *s, int wday, int minute);

#endif
