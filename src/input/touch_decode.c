#include "input/touch_decode.h"

#include <linux/input.h>
#include <string.h>

void touch_decoder_init(struct touch_decoder *d, bool multitouch, const int range_x[2],
			const int range_y[2], int rotation)
{
	memset(d, 0, sizeof(*d));
	d->multitouch = multitouch;
	memcpy(d->range_x, range_x, sizeof(d->range_x));
	memcpy(d->range_y, range_y, sizeof(d->range_y));
	d->rotation = rotation;
	for (int i = 0; i < GESTURE_MAX_POINTS; i++)
		d->slots[i].id = -1;
	d->single.id = -1;
}

static void point(const struct touch_decoder *d, const struct touch_slot *s,
		  struct gesture_point *p)
{
	p->id = s->id;
	gesture_map(s->x, s->y, d->range_x, d->range_y, d->rotation, &p->x, &p->y);
}

static int frame(const struct touch_decoder *d, struct gesture_point *pts)
{
	int n = 0;

	if (!d->multitouch) {
		if (d->single.id >= 0)
			point(d, &d->single, &pts[n++]);
		return n;
	}
	for (int i = 0; i < GESTURE_MAX_POINTS; i++)
		if (d->slots[i].id >= 0)
			point(d, &d->slots[i], &pts[n++]);
	return n;
}

/* The slot protocol: events name a slot once, then change what is in it. */
static void mt_event(struct touch_decoder *d, unsigned int code, int value)
{
	struct touch_slot *s;

	if (code == ABS_MT_SLOT) {
		d->slot = value;
		return;
	}
	if (d->slot < 0 || d->slot >= GESTURE_MAX_POINTS)
		return;
	s = &d->slots[d->slot];
	if (code == ABS_MT_TRACKING_ID)
		s->id = value < 0 ? -1 : value;
	else if (code == ABS_MT_POSITION_X)
		s->x = value;
	else if (code == ABS_MT_POSITION_Y)
		s->y = value;
}

int touch_decoder_event(struct touch_decoder *d, unsigned int type, unsigned int code, int value,
			struct gesture_point *pts, int *n)
{
	if (type == EV_SYN && code == SYN_REPORT) {
		*n = frame(d, pts);
		return 1;
	}
	if (type == EV_ABS && d->multitouch)
		mt_event(d, code, value);
	else if (type == EV_ABS && code == ABS_X)
		d->single.x = value;
	else if (type == EV_ABS && code == ABS_Y)
		d->single.y = value;
	else if (type == EV_KEY && code == BTN_TOUCH && !d->multitouch)
		d->single.id = value ? 0 : -1;
	return 0;
}
