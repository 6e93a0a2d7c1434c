#include "input/knob_device.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <libudev.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

struct knob_source {
	struct input_source base;
	struct libevdev *dev;
	struct knob_decoder decoder;
	bool stamp_now; /* the device keeps CLOCK_REALTIME: stamp on reading */
	bool syncing;	/* after SYN_DROPPED, the state delta is being read */
	bool more;	/* events that did not fit: read again */
	bool lost;
	char name[224];
};

static struct knob_source *source_of(struct input_source *s)
{
	return (struct knob_source *)((char *)s - offsetof(struct knob_source, base));
}

int knob_device_axis(const struct libevdev *dev)
{
	bool has[REL_CNT] = {false};
	int n = (int)(sizeof(has) / sizeof(has[0]));

	/* A mouse or a touchpad moves a pointer: its wheel is not a knob. */
	if (libevdev_has_property(dev, INPUT_PROP_POINTER) ||
	    libevdev_has_event_code(dev, EV_REL, REL_Y) ||
	    libevdev_has_event_code(dev, EV_KEY, BTN_LEFT))
		return -1;
	for (int code = 0; code < n; code++)
		has[code] = libevdev_has_event_code(dev, EV_REL, (unsigned)code);
	return knob_axis(has, n);
}

static uint64_t event_ns(const struct knob_source *k, const struct input_event *ev, uint64_t now)
{
	if (k->stamp_now)
		return now;
	return (uint64_t)ev->input_event_sec * 1000000000ull +
	       (uint64_t)ev->input_event_usec * 1000ull;
}

static int knob_lose(struct knob_source *k, int err, uint64_t now, struct app_event *out)
{
	log_warn("%s: %s", k->base.name, err == ENODEV ? "unplugged" : strerror(err));
	k->lost = true;
	return knob_decoder_lost(&k->decoder, now, out);
}

static int knob_read(struct input_source *s, uint64_t now, struct app_event *out, int max)
{
	struct knob_source *k = source_of(s);
	struct input_event ev;
	int n = 0, rc;

	if (k->lost)
		return -ENODEV;
	k->more = false;
	if (knob_decoder_deadline(&k->decoder) <= now && n + KNOB_MAX_EVENTS <= max)
		n += knob_decoder_timeout(&k->decoder, now, out + n);
	while (n + KNOB_MAX_EVENTS <= max) {
		rc = libevdev_next_event(
		    k->dev, k->syncing ? LIBEVDEV_READ_FLAG_SYNC : LIBEVDEV_READ_FLAG_NORMAL, &ev);
		if (rc == -EAGAIN && k->syncing) {
			k->syncing = false;
			continue;
		}
		if (rc == -EAGAIN)
			return n;
		if (rc < 0)
			return n + knob_lose(k, -rc, now, out + n);
		/* SYN_DROPPED: detents were lost; the key's state comes back. */
		if (rc == LIBEVDEV_READ_STATUS_SYNC && !k->syncing) {
			k->syncing = true;
			continue;
		}
		n += knob_decoder_event(&k->decoder, event_ns(k, &ev, now), ev.type, ev.code,
					ev.value, out + n);
	}
	k->more = true;
	return n;
}

static uint64_t knob_deadline(struct input_source *s)
{
	struct knob_source *k = source_of(s);

	return k->more || k->syncing ? 0 : knob_decoder_deadline(&k->decoder);
}

static void knob_destroy(struct input_source *s)
{
	struct knob_source *k = source_of(s);

	close(libevdev_get_fd(k->dev));
	libevdev_free(k->dev);
	free(k);
}

static struct knob_source *source_make(const struct knob_config *c, struct libevdev *dev, int axis,
				       const char *path)
{
	struct knob_source *k = calloc(1, sizeof(*k));

	if (!k)
		return NULL;
	k->dev = dev;
	knob_decoder_init(&k->decoder, c, (unsigned)axis, 1);
	k->stamp_now = libevdev_set_clock_id(dev, CLOCK_MONOTONIC) != 0;
	snprintf(k->name, sizeof(k->name), "knob %s (%s, %s)", libevdev_get_name(dev), path,
		 libevdev_event_code_get_name(EV_REL, (unsigned)axis));
	k->base = (struct input_source){.name = k->name,
					.kind = INPUT_KIND_KNOB,
					.fd = libevdev_get_fd(dev),
					.read = knob_read,
					.deadline = knob_deadline,
					.destroy = knob_destroy};
	return k;
}

/* Returns 0 with *out set, 0 with *out NULL when the device is no knob
 * (said when it was named), or a negative errno after logging. */
static int source_new(const struct knob_config *c, const char *path, bool named,
		      struct input_source **out)
{
	struct knob_source *k = NULL;
	struct libevdev *dev = NULL;
	int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC), ret, axis;

	*out = NULL;
	/* A device found by the scan that the service may not read (a mouse,
	 * without the input group) is no knob worth a line. */
	if (fd < 0 && !named && errno == EACCES)
		return -EACCES;
	if (fd < 0) {
		ret = -errno;
		log_err("%s: cannot open the knob: %s%s", path, strerror(errno),
			errno == EACCES ? " (the service's user needs the input group)" : "");
		return ret;
	}
	ret = libevdev_new_from_fd(fd, &dev);
	if (ret) {
		log_err("%s: not an input event device: %s", path, strerror(-ret));
		goto fail;
	}
	axis = knob_device_axis(dev);
	if (axis < 0) {
		if (named)
			log_warn("%s (%s): [knob] device: expected a knob (REL_DIAL, REL_WHEEL "
				 "or REL_X, no pointer); ignored",
				 path, libevdev_get_name(dev));
		goto fail;
	}
	k = source_make(c, dev, axis, path);
	if (!k) {
		ret = -ENOMEM;
		goto fail;
	}
	log_info("%s: a detent %s", k->name, knob_turns_names[k->decoder.turns]);
	*out = &k->base;
	return 0;
fail:
	libevdev_free(dev);
	close(fd);
	return ret;
}

/* udev's input devices with a relative axis: those it calls mice too
 * (ID_INPUT_MOUSE is any device with REL_X), told apart by libevdev. */
static int scan(const struct knob_config *c, struct input_source **out, int max)
{
	struct udev *udev = udev_new();
	struct udev_enumerate *e = udev ? udev_enumerate_new(udev) : NULL;
	struct udev_list_entry *entry;
	int count = 0;

	if (!e || udev_enumerate_add_match_subsystem(e, "input") ||
	    udev_enumerate_add_match_sysname(e, "event*") || udev_enumerate_scan_devices(e))
		goto out;
	udev_list_entry_foreach(entry, udev_enumerate_get_list_entry(e))
	{
		struct udev_device *dev =
		    udev_device_new_from_syspath(udev, udev_list_entry_get_name(entry));
		const char *node = dev ? udev_device_get_devnode(dev) : NULL;
		const char *rel = dev ? udev_device_get_sysattr_value(udev_device_get_parent(dev),
								      "capabilities/rel")
				      : NULL;
		struct input_source *s = NULL;

		/* No relative axis at all: not worth opening. */
		if (node && rel && strcmp(rel, "0") && count < max &&
		    !source_new(c, node, false, &s) && s)
			out[count++] = s;
		if (dev)
			udev_device_unref(dev);
	}
out:
	udev_enumerate_unref(e);
	udev_unref(udev);
	return count;
}

int knob_open(const struct knob_config *c, struct input_source **out, int max)
{
	const char *device = c->device;
	struct input_source *s = NULL;
	int n;

	if (max < 1 || (device && (!strcmp(device, "none") || !strcmp(device, "off"))))
		return 0;
	if (device && *device && strcmp(device, "auto"))
		return !source_new(c, device, true, &s) && s ? (out[0] = s, 1) : 0;
	n = scan(c, out, max);
	if (!n)
		log_info("no knob under /dev/input");
	return n;
}
