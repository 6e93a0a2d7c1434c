#include "display/hotplug.h"
#include "util/log.h"

#include <libudev.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct hotplug {
	struct udev *udev;
	struct udev_monitor *mon;
	dev_t device;
};

struct hotplug *hotplug_new(dev_t device)
{
	struct hotplug *h = calloc(1, sizeof(*h));
	/* Events processed by udevd when it runs (a normal system), else the
	 * kernel's own, so a minimal system still sees cables. */
	const char *source = access("/run/udev/control", F_OK) == 0 ? "udev" : "kernel";

	if (!h)
		return NULL;
	h->device = device;
	h->udev = udev_new();
	h->mon = h->udev ? udev_monitor_new_from_netlink(h->udev, source) : NULL;
	if (!h->mon || udev_monitor_filter_add_match_subsystem_devtype(h->mon, "drm", NULL) ||
	    udev_monitor_enable_receiving(h->mon)) {
		log_warn("kms: cannot watch udev for display hotplug; probing every few "
			 "seconds instead while no display is connected");
		hotplug_free(h);
		return NULL;
	}
	return h;
}

void hotplug_free(struct hotplug *h)
{
	if (!h)
		return;
	if (h->mon)
		udev_monitor_unref(h->mon);
	if (h->udev)
		udev_unref(h->udev);
	free(h);
}

int hotplug_fd(const struct hotplug *h)
{
	return udev_monitor_get_fd(h->mon);
}

/* A connector change is a "change" event of the card with HOTPLUG=1. Any
 * change event of our card is taken, not only those: a re-probe that
 * finds nothing new does nothing, and drivers without hotplug detection
 * (vkms) or a forced connector (`status` in sysfs) can then be followed
 * with a synthetic event (`udevadm trigger -c change -s drm`). */
bool hotplug_read(struct hotplug *h)
{
	struct udev_device *dev;
	bool changed = false;

	while ((dev = udev_monitor_receive_device(h->mon))) {
		const char *action = udev_device_get_action(dev);

		if (udev_device_get_devnum(dev) == h->device && action &&
		    strcmp(action, "change") == 0) {
			const char *hp = udev_device_get_property_value(dev, "HOTPLUG");

			log_debug("kms: udev reports a change of the display device%s",
				  hp && strcmp(hp, "1") == 0 ? " (hotplug)" : "");
			changed = true;
		}
		udev_device_unref(dev);
	}
	return changed;
}
