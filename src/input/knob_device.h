/* Knobs through evdev (libevdev): every device udev finds with a relative
 * axis a knob turns (REL_DIAL, REL_WHEEL or REL_X) and no pointer (a
 * mouse has REL_Y too), or the one named; each an input source whose
 * events go through the decoder (src/input/knob.h). */
#ifndef MK_KNOB_DEVICE_H
#define MK_KNOB_DEVICE_H

#include "input/input.h"
#include "input/knob.h"

struct libevdev;

/* Writes up to max sources into out and returns their count; a device
 * that cannot be opened is said in the log and left out. */
int knob_open(const struct knob_config *c, struct input_source **out, int max);

/* The axis the device turns (REL_ code), or -1 when it is no knob. */
int knob_device_axis(const struct libevdev *dev);

#endif
