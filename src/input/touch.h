/* Touchscreens through evdev (libevdev), with no window system: every
 * touchscreen there is, or the one named, opened now and whenever udev
 * says one came, dropped when it goes. Events go through the decoder
 * (src/input/touch_decode.c) and the gesture machine (src/input/gesture.c):
 * what comes out are gestures, in screen fractions after the panel's
 * rotation. The loop polls one descriptor for all of it. */
#ifndef MK_TOUCH_H
#define MK_TOUCH_H

#include "input/gesture.h"

#include <stdbool.h>
#include <stdint.h>

/* [touch] in kiosk.ini. */
struct touch_config {
	/* NULL or "auto": every touchscreen; "off": none; else the one
	 * device named (/dev/input/eventN), whenever it is there. */
	char *device;
};

struct touch;
struct libevdev;

/* NULL when touch is off (or out of memory, said in the log). A device
 * that cannot be opened is said in the log and left out; the others and
 * those that come later are still taken. */
struct touch *touch_new(const struct touch_config *c, int rotation);
void touch_free(struct touch *t);
/* Readable when a device has events or udev news: then touch_dispatch. */
int touch_fd(const struct touch *t);
/* The panel's rotation changed (a reload): new touches follow it. */
void touch_set_rotation(struct touch *t, int rotation);
/* Reads what is ready and what is due at now_ns: up to max gestures into
 * out; returns their count. */
int touch_dispatch(struct touch *t, uint64_t now_ns, struct gesture *out, int max);
/* When touch_dispatch must be called without the descriptor (a long press
 * coming due, events that did not fit), or CLOCK_NEVER. */
uint64_t touch_deadline(const struct touch *t);
/* The device count, for the log and the tests. */
int touch_count(const struct touch *t);

/* A touchscreen: type-B multitouch (ABS_MT_SLOT) or single touch
 * (BTN_TOUCH with ABS_X/Y), and no touchpad, mouse or tablet. *multitouch
 * says which protocol to decode. */
bool touch_is_touchscreen(const struct libevdev *dev, bool *multitouch);

#endif
