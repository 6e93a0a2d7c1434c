#include "input/touch.h"
#include "input/touch_decode.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <libudev.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <sys/stat.h>
#include <unistd.h>

/* More touchscreens than a kiosk has; the rest are said and left out. */
#define TOUCH_MAX_DEVICES 8

struct touch_device {
	struct libevdev *dev;
	int fd;
	dev_t devnum;
	bool stamp_now; /* the device keeps CLOCK_REALTIME: stamp on reading */
	bool syncing;	/* after SYN_DROPPED, the state delta is being read */
	bool more;	/* events that did not fit: read again */
	struct touch_decoder decoder;
	struct gesture_state gestures;
	char name[224];
};

struct touch {
	char *device; /* NULL: every touchscreen */
	int rotation;
	int epoll_fd; /* the devices and the udev monitor, as one descriptor */
	struct udev *udev;
	struct udev_monitor *mon;
	struct touch_device *devs[TOUCH_MAX_DEVICES];
	int count;
};

bool touch_is_touchscreen(const struct libevdev *dev, bool *multitouch)
{
	bool direct = libevdev_has_property(dev, INPUT_PROP_DIRECT);
	bool mt = libevdev_has_event_code(dev, EV_ABS, ABS_MT_SLOT) &&
		  libevdev_has_event_code(dev, EV_ABS, ABS_MT_POSITION_X) &&
		  libevdev_has_event_code(dev, EV_ABS, ABS_MT_POSITION_Y);
	bool single = libevdev_has_event_code(dev, EV_KEY, BTN_TOUCH) &&
		      libevdev_has_event_code(dev, EV_ABS, ABS_X) &&
		      libevdev_has_event_code(dev, EV_ABS, ABS_Y);

	*multitouch = mt;
	/* A touchpad or a mouse moves a pointer: what it touches is not the
	 * screen. Old single-touch drivers do not all say "direct". */
	if (libevdev_has_property(dev, INPUT_PROP_POINTER) ||
	    libevdev_has_event_code(dev, EV_REL, REL_X))
		return false;
	if (!direct && (libevdev_has_event_code(dev, EV_KEY, BTN_TOOL_FINGER) ||
			libevdev_has_event_code(dev, EV_KEY, BTN_TOOL_PEN)))
		return false;
	return mt || single;
}

static void device_free(struct touch_device *d)
{
	if (!d)
		return;
	libevdev_free(d->dev);
	if (d->fd >= 0)
		close(d->fd);
	free(d);
}

static void device_setup(struct touch_device *d, bool mt, int rotation)
{
	unsigned int cx = mt ? ABS_MT_POSITION_X : ABS_X, cy = mt ? ABS_MT_POSITION_Y : ABS_Y;
	int rx[2] = {libevdev_get_abs_minimum(d->dev, cx), libevdev_get_abs_maximum(d->dev, cx)};
	int ry[2] = {libevdev_get_abs_minimum(d->dev, cy), libevdev_get_abs_maximum(d->dev, cy)};
	struct gesture_config cfg;

	touch_decoder_init(&d->decoder, mt, rx, ry, rotation);
	if (mt)
		d->decoder.slot = libevdev_get_current_slot(d->dev);
	gesture_config_defaults(&cfg);
	gesture_init(&d->gestures, &cfg);
	d->stamp_now = libevdev_set_clock_id(d->dev, CLOCK_MONOTONIC) != 0;
}

/* Returns 0 with *out set, 0 with *out NULL when the device is no
 * touchscreen (said when it was named), or a negative errno after one
 * line in the log. */
static int device_new(const char *path, bool named, int rotation, struct touch_device **out)
{
	struct touch_device *d = calloc(1, sizeof(*d));
	struct stat st;
	bool mt;
	int ret = -ENOMEM;

	*out = NULL;
	if (!d)
		goto fail;
	d->fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
	if (d->fd < 0 || fstat(d->fd, &st)) {
		ret = -errno;
		log_err("%s: cannot open the touchscreen: %s%s", path, strerror(errno),
			errno == EACCES ? " (the service's user needs the input group)" : "");
		goto fail;
	}
	ret = libevdev_new_from_fd(d->fd, &d->dev);
	if (ret) {
		log_err("%s: not an input event device: %s", path, strerror(-ret));
		goto fail;
	}
	ret = 0;
	if (!touch_is_touchscreen(d->dev, &mt)) {
		if (named)
			log_warn("%s (%s): no touchscreen, ignored", path,
				 libevdev_get_name(d->dev));
		goto fail;
	}
	d->devnum = st.st_rdev;
	device_setup(d, mt, rotation);
	snprintf(d->name, sizeof(d->name), "touchscreen %s (%s, %s)", libevdev_get_name(d->dev),
		 path, mt ? "multitouch" : "single touch");
	log_info("%s", d->name);
	*out = d;
	return 0;
fail:
	device_free(d);
	return ret;
}

static int find_devnum(const struct touch *t, dev_t devnum)
{
	for (int i = 0; i < t->count; i++)
		if (t->devs[i]->devnum == devnum)
			return i;
	return -1;
}

/* An input event node that is ours to take: any under auto, else the
 * one named (by a link such as /dev/input/by-id/... too). */
static bool wanted(const struct touch *t, const char *node)
{
	struct stat a, b;

	if (!node || strncmp(node, "/dev/input/event", 16))
		return false;
	if (!t->device)
		return true;
	return !strcmp(node, t->device) ||
	       (!stat(node, &a) && !stat(t->device, &b) && a.st_rdev == b.st_rdev);
}

static void add_device(struct touch *t, const char *node, bool is_touch)
{
	struct touch_device *d = NULL;
	struct epoll_event ev = {.events = EPOLLIN};
	struct stat st;

	/* The named device is tried at the start whatever its path; udev's
	 * news are of input devices too, with no node. */
	if (!node || (node != t->device && !wanted(t, node)) ||
	    (stat(node, &st) == 0 && find_devnum(t, st.st_rdev) >= 0))
		return;
	/* Nodes udev does not call touchscreens need not be readable: only
	 * a touchscreen that cannot be opened is worth a line. */
	if (!t->device && !is_touch && access(node, R_OK))
		return;
	if (device_new(node, t->device != NULL, t->rotation, &d) || !d)
		return;
	ev.data.ptr = d;
	if (t->count == TOUCH_MAX_DEVICES || epoll_ctl(t->epoll_fd, EPOLL_CTL_ADD, d->fd, &ev)) {
		log_warn("%s: too many touchscreens, ignored", d->name);
		device_free(d);
		return;
	}
	t->devs[t->count++] = d;
}

static void remove_device(struct touch *t, int i, const char *why)
{
	log_warn("%s: %s", t->devs[i]->name, why);
	epoll_ctl(t->epoll_fd, EPOLL_CTL_DEL, t->devs[i]->fd, NULL);
	device_free(t->devs[i]);
	memmove(&t->devs[i], &t->devs[i + 1], sizeof(t->devs[0]) * (size_t)(t->count - i - 1));
	t->count--;
}

static bool udev_is_touch(struct udev_device *dev)
{
	const char *v = udev_device_get_property_value(dev, "ID_INPUT_TOUCHSCREEN");

	return v && strcmp(v, "1") == 0;
}

static void scan(struct touch *t)
{
	struct udev_enumerate *e = udev_enumerate_new(t->udev);
	struct udev_list_entry *entry;

	if (!e || udev_enumerate_add_match_subsystem(e, "input") ||
	    udev_enumerate_add_match_sysname(e, "event*") || udev_enumerate_scan_devices(e))
		goto out;
	udev_list_entry_foreach(entry, udev_enumerate_get_list_entry(e))
	{
		struct udev_device *dev =
		    udev_device_new_from_syspath(t->udev, udev_list_entry_get_name(entry));

		if (!dev)
			continue;
		add_device(t, udev_device_get_devnode(dev), udev_is_touch(dev));
		udev_device_unref(dev);
	}
out:
	udev_enumerate_unref(e);
}

static int watch(struct touch *t)
{
	/* Events processed by udevd when it runs (so the node has its
	 * permissions), else the kernel's own. */
	const char *source = access("/run/udev/control", F_OK) == 0 ? "udev" : "kernel";
	struct epoll_event ev = {.events = EPOLLIN, .data.ptr = NULL};

	t->udev = udev_new();
	t->mon = t->udev ? udev_monitor_new_from_netlink(t->udev, source) : NULL;
	if (!t->mon || udev_monitor_filter_add_match_subsystem_devtype(t->mon, "input", NULL) ||
	    udev_monitor_enable_receiving(t->mon) ||
	    epoll_ctl(t->epoll_fd, EPOLL_CTL_ADD, udev_monitor_get_fd(t->mon), &ev)) {
		log_warn("touch: cannot watch udev: touchscreens plugged in later are not seen");
		return -ENODEV;
	}
	return 0;
}

static bool named(const struct touch_config *c)
{
	return c->device && *c->device && strcmp(c->device, "auto");
}

struct touch *touch_new(const struct touch_config *c, int rotation)
{
	struct touch *t = NULL;

	if (c->device && (!strcmp(c->device, "off") || !strcmp(c->device, "none")))
		goto out;
	t = calloc(1, sizeof(*t));
	if (!t || (t->epoll_fd = epoll_create1(EPOLL_CLOEXEC)) < 0 ||
	    (named(c) && !(t->device = strdup(c->device)))) {
		log_err("touch: out of resources; running without touch");
		touch_free(t);
		t = NULL;
		goto out;
	}
	t->rotation = rotation;
	watch(t);
	if (t->device)
		add_device(t, t->device, true);
	else if (t->udev)
		scan(t);
	if (!t->count)
		log_info("touch: no touchscreen yet; taking one when it comes");
out:
	return t;
}

void touch_free(struct touch *t)
{
	if (!t)
		return;
	for (int i = 0; i < t->count; i++)
		device_free(t->devs[i]);
	if (t->mon)
		udev_monitor_unref(t->mon);
	if (t->udev)
		udev_unref(t->udev);
	if (t->epoll_fd >= 0)
		close(t->epoll_fd);
	free(t->device);
	free(t);
}

int touch_fd(const struct touch *t)
{
	return t->epoll_fd;
}

int touch_count(const struct touch *t)
{
	return t->count;
}

void touch_set_rotation(struct touch *t, int rotation)
{
	t->rotation = rotation;
	for (int i = 0; i < t->count; i++)
		t->devs[i]->decoder.rotation = rotation;
}

static void read_udev(struct touch *t)
{
	struct udev_device *dev;

	while (t->mon && (dev = udev_monitor_receive_device(t->mon))) {
		const char *action = udev_device_get_action(dev);
		int i = find_devnum(t, udev_device_get_devnum(dev));

		if (action && !strcmp(action, "add"))
			add_device(t, udev_device_get_devnode(dev), udev_is_touch(dev));
		else if (action && !strcmp(action, "remove") && i >= 0)
			remove_device(t, i, "unplugged");
		udev_device_unref(dev);
	}
}

static uint64_t event_ns(const struct touch_device *d, const struct input_event *ev, uint64_t now)
{
	if (d->stamp_now)
		return now;
	return (uint64_t)ev->input_event_sec * 1000000000ull +
	       (uint64_t)ev->input_event_usec * 1000ull;
}

/* One event through the decoder; a whole frame through the gestures. */
static int device_event(struct touch_device *d, const struct input_event *ev, uint64_t now,
			struct gesture *out)
{
	struct gesture_point pts[GESTURE_MAX_POINTS];
	int n = 0;

	if (!touch_decoder_event(&d->decoder, ev->type, ev->code, ev->value, pts, &n))
		return 0;
	return gesture_frame(&d->gestures, event_ns(d, ev, now), pts, n, out);
}

/* Returns the gestures read, or -errno when the device is gone. */
static int device_read(struct touch_device *d, uint64_t now, struct gesture *out, int max)
{
	struct input_event ev;
	int n = 0, rc;

	d->more = false;
	while (n + GESTURE_MAX_EVENTS <= max) {
		rc = libevdev_next_event(
		    d->dev, d->syncing ? LIBEVDEV_READ_FLAG_SYNC : LIBEVDEV_READ_FLAG_NORMAL, &ev);
		if (rc == -EAGAIN && d->syncing) {
			d->syncing = false;
			continue;
		}
		if (rc == -EAGAIN)
			return n;
		if (rc < 0)
			return rc;
		/* SYN_DROPPED: the kernel's queue overflowed; the delta that
		 * follows brings the slots up to date. */
		if (rc == LIBEVDEV_READ_STATUS_SYNC && !d->syncing) {
			d->syncing = true;
			continue;
		}
		n += device_event(d, &ev, now, out + n);
	}
	d->more = true;
	return n;
}

int touch_dispatch(struct touch *t, uint64_t now_ns, struct gesture *out, int max)
{
	int n = 0;

	read_udev(t);
	for (int i = t->count - 1; i >= 0; i--) {
		struct touch_device *d = t->devs[i];
		int got = device_read(d, now_ns, out + n, max - n);

		if (got < 0) {
			remove_device(t, i, got == -ENODEV ? "unplugged" : strerror(-got));
			continue;
		}
		n += got;
		if (n < max && gesture_deadline(&d->gestures) <= now_ns)
			n += gesture_timeout(&d->gestures, now_ns, out + n);
	}
	return n;
}

uint64_t touch_deadline(const struct touch *t)
{
	uint64_t due = CLOCK_NEVER;

	for (int i = 0; i < t->count; i++) {
		uint64_t d = t->devs[i]->more || t->devs[i]->syncing
				 ? 0
				 : gesture_deadline(&t->devs[i]->gestures);

		due = d < due ? d : due;
	}
	return due;
}
