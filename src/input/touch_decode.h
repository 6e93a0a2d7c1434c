/* What a touchscreen says, as the kernel's evdev events, turned into the
 * frames of touch points that src/input/gesture.c reads. Both protocols:
 * type-B multitouch (ABS_MT_SLOT, ABS_MT_TRACKING_ID, ABS_MT_POSITION_X/Y)
 * and single touch (BTN_TOUCH with ABS_X/Y). Pure: event codes in, frames
 * out, so the tests replay made-up devices. */
#ifndef MK_TOUCH_DECODE_H
#define MK_TOUCH_DECODE_H

#include "input/gesture.h"

#include <stdbool.h>

struct touch_slot {
	int id; /* tracking id; -1: no finger in this slot */
	int x, y;
};

struct touch_decoder {
	bool multitouch;
	int range_x[2], range_y[2]; /* the device's axis ranges */
	int rotation;		    /* of the panel, degrees */
	int slot;		    /* the slot the next ABS_MT_* events are for */
	struct touch_slot slots[GESTURE_MAX_POINTS];
	struct touch_slot single; /* single touch: id 0 while BTN_TOUCH is down */
};

void touch_decoder_init(struct touch_decoder *d, bool multitouch, const int range_x[2],
			const int range_y[2], int rotation);
/* One event. At SYN_REPORT writes the fingers down now into pts (screen
 * fractions, in slot order) and their count into n, and returns 1;
 * otherwise returns 0. Slots beyond GESTURE_MAX_POINTS are ignored. */
int touch_decoder_event(struct touch_decoder *d, unsigned int type, unsigned int code, int value,
			struct gesture_point *pts, int *n);

#endif
