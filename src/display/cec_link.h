/* The TV's power through HDMI-CEC (display/cec.h) on a thread of its own:
 * claiming a logical address and a CEC_TRANSMIT both wait for the bus
 * (the TV's acknowledgement, retries: up to seconds), which the loop
 * thread must never do. The loop only says which power it wants; the
 * thread sends the last one wanted, in order, once each change. */
#ifndef MK_CEC_LINK_H
#define MK_CEC_LINK_H

#include <stdbool.h>

struct cec_link;

/* Opens path (/dev/cec0) and claims an address, on the thread: a device
 * that fails is said there, once, and power requests are then dropped.
 * NULL only when no thread can be had (logged). */
struct cec_link *cec_link_new(const char *path);
/* Sends what is pending, then closes the device. */
void cec_link_free(struct cec_link *l);
/* Wake (on) or standby the TV; returns at once. */
void cec_link_power(struct cec_link *l, bool on);

#endif
