/* Something that turns the outside world into app actions: GPIO buttons,
 * a keyboard. The main loop polls fd and asks for the events; a source
 * with timers of its own (debounce, hold-to-repeat, long press) says when
 * it next needs to be asked, without an fd. */
#ifndef MK_INPUT_H
#define MK_INPUT_H

#include "input/action.h"
#include "util/clock.h"

struct input_source {
	const char *name;
	enum input_kind kind;
	int fd; /* -1: timers only */
	/* Read what is ready (fd readable, or a deadline passed at now_ns):
	 * up to max events into out. Returns the count, or a negative errno
	 * after logging, and then the loop drops the source. */
	int (*read)(struct input_source *s, uint64_t now_ns, struct app_event *out, int max);
	/* When the source next wants read() without its fd, or CLOCK_NEVER. */
	uint64_t (*deadline)(struct input_source *s);
	void (*destroy)(struct input_source *s);
};

#endif
