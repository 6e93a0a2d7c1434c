/* Display hotplug through udev: a descriptor for poll() that becomes
 * readable when the DRM device reports a change (a cable in or out). */
#ifndef MK_HOTPLUG_H
#define MK_HOTPLUG_H

#include <stdbool.h>
#include <sys/types.h>

struct hotplug;

/* Watch the DRM device with this device number (st_rdev of its node).
 * NULL when udev cannot be watched: the caller then polls instead. */
struct hotplug *hotplug_new(dev_t device);
void hotplug_free(struct hotplug *h);
int hotplug_fd(const struct hotplug *h);
/* Drain the pending events; true when one was a change of our device,
 * which the caller answers by probing its connectors again. */
bool hotplug_read(struct hotplug *h);

#endif
