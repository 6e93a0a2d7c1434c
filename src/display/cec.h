/* A TV's power through HDMI-CEC, with the kernel's CEC API (/dev/cecN):
 * the kiosk claims a playback device's logical address, and sleeping
 * sends Standby to the TV, waking sends Image View On and then Active
 * Source with the kiosk's physical address, so the TV also switches to
 * its input. A TV that does not answer is said once in the journal, and
 * each later change is tried once, never in a loop. */
#ifndef MK_CEC_H
#define MK_CEC_H

#include <stdbool.h>

/* How the CEC adapter is reached: ioctl(2) on the device, or a fake in
 * the tests. Returns 0 or -1 with errno set, as ioctl does. */
struct cec_io {
	int (*ioctl)(void *ctx, unsigned long request, void *arg);
	void *ctx;
};

struct cec;

/* Opens path (/dev/cec0) and claims a logical address. NULL after one
 * error line naming the device and what failed. */
struct cec *cec_new(const char *path);
/* The same over io; name is used in messages. */
struct cec *cec_new_io(const struct cec_io *io, const char *name);
void cec_free(struct cec *c);
/* Wake (on) or standby the TV. Returns 0, or a negative errno when the
 * TV did not take it (logged once until it answers again). */
int cec_power(struct cec *c, bool on);

#endif
