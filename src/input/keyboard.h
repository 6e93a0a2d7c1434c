/* Keyboards through evdev (libevdev), with no window system: the arrows
 * turn, space or enter cycles the matcaps, backspace goes back, c toggles
 * the camera, m the shading mode, r resets. The key's own autorepeat is
 * ignored: the app turns while an arrow is held. */
#ifndef MK_KEYBOARD_H
#define MK_KEYBOARD_H

#include "input/input.h"

/* [keyboard] in kiosk.ini. */
struct keyboard_config {
	/* NULL or "auto": every keyboard under /dev/input (event devices
	 * with letter keys); "none": none; else the one device named. */
	char *device;
};

/* Writes up to max sources into out and returns their count; a device
 * that cannot be opened is logged and left out. */
int keyboard_open(const struct keyboard_config *c, struct input_source **out, int max);

#endif
