#include "input/keyboard.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define INPUT_DIR "/dev/input"

static const struct {
	unsigned int code;
	enum app_action action;
} keys[] = {
    {KEY_LEFT, ACTION_TURN_LEFT},
    {KEY_RIGHT, ACTION_TURN_RIGHT},
    {KEY_UP, ACTION_TURN_UP},
    {KEY_DOWN, ACTION_TURN_DOWN},
    {KEY_SPACE, ACTION_NEXT_MATCAP},
    {KEY_ENTER, ACTION_NEXT_MATCAP},
    {KEY_KPENTER, ACTION_NEXT_MATCAP},
    {KEY_BACKSPACE, ACTION_PREV_MATCAP},
    {KEY_C, ACTION_TOGGLE_CAMERA},
    {KEY_M, ACTION_NEXT_MODE},
    {KEY_R, ACTION_RESET},
    {KEY_PAGEDOWN, ACTION_NEXT_MODEL},
    {KEY_N, ACTION_NEXT_MODEL},
    {KEY_PAGEUP, ACTION_PREV_MODEL},
    {KEY_P, ACTION_PREV_MODEL},
    {KEY_DOT, ACTION_NEXT_STOP},
    {KEY_COMMA, ACTION_PREV_STOP},
    {KEY_K, ACTION_PLAY_PAUSE},
    {KEY_PLAYPAUSE, ACTION_PLAY_PAUSE},
    {KEY_A, ACTION_NEXT_ANIMATION},
    {KEY_V, ACTION_NEXT_VARIANT},
    {KEY_L, ACTION_NEXT_LANGUAGE},
};

#define N_KEYS (sizeof(keys) / sizeof(keys[0]))

struct keyboard_source {
	struct input_source base;
	struct libevdev *dev;
	bool stamp_now; /* the device keeps CLOCK_REALTIME: stamp on reading */
	bool syncing;	/* after SYN_DROPPED, the state delta is being read */
	bool more;	/* libevdev holds events that did not fit: read again */
	bool lost;
	bool down[N_KEYS];
	char name[192];
};

static struct keyboard_source *source_of(struct input_source *s)
{
	return (struct keyboard_source *)((char *)s - offsetof(struct keyboard_source, base));
}

static int key_index(unsigned int code)
{
	for (size_t i = 0; i < N_KEYS; i++)
		if (keys[i].code == code)
			return (int)i;
	return -1;
}

/* 1 when the event is a press or release of a mapped key, written to out. */
static int key_event(struct keyboard_source *k, const struct input_event *ev, uint64_t now,
		     struct app_event *out)
{
	int i = ev->type == EV_KEY ? key_index(ev->code) : -1;
	bool down = ev->value == 1;

	/* value 2 is the key's autorepeat: the app has its own hold. */
	if (i < 0 || ev->value == 2 || down == k->down[i])
		return 0;
	k->down[i] = down;
	*out = (struct app_event){.action = keys[i].action, .pressed = down, .time_ns = now};
	if (!k->stamp_now)
		out->time_ns = (uint64_t)ev->input_event_sec * 1000000000ull +
			       (uint64_t)ev->input_event_usec * 1000ull;
	return 1;
}

/* Unplugged: release what is held, so nothing turns forever. */
static int keyboard_lose(struct keyboard_source *k, int err, uint64_t now, struct app_event *out,
			 int max)
{
	int n = 0;

	log_warn("%s: %s", k->base.name, err == ENODEV ? "unplugged" : strerror(err));
	k->lost = true;
	for (size_t i = 0; i < N_KEYS && n < max; i++)
		if (k->down[i]) {
			k->down[i] = false;
			out[n++] = (struct app_event){
			    .action = keys[i].action, .pressed = false, .time_ns = now};
		}
	return n;
}

static int keyboard_read(struct input_source *s, uint64_t now, struct app_event *out, int max)
{
	struct keyboard_source *k = source_of(s);
	struct input_event ev;
	int n = 0, rc;

	if (k->lost)
		return -ENODEV;
	k->more = false;
	while (n < max) {
		rc = libevdev_next_event(
		    k->dev, k->syncing ? LIBEVDEV_READ_FLAG_SYNC : LIBEVDEV_READ_FLAG_NORMAL, &ev);
		if (rc == -EAGAIN && k->syncing) {
			k->syncing = false;
			continue;
		}
		if (rc == -EAGAIN)
			return n;
		if (rc < 0)
			return n + keyboard_lose(k, -rc, now, out + n, max - n);
		/* SYN_DROPPED: the kernel's queue overflowed; the delta that
		 * follows (a key released meanwhile) keeps the held set true. */
		if (rc == LIBEVDEV_READ_STATUS_SYNC && !k->syncing) {
			k->syncing = true;
			continue;
		}
		n += key_event(k, &ev, now, out + n);
	}
	k->more = true;
	return n;
}

static uint64_t keyboard_deadline(struct input_source *s)
{
	struct keyboard_source *k = source_of(s);

	return k->more || k->syncing ? 0 : CLOCK_NEVER;
}

static void keyboard_destroy(struct input_source *s)
{
	struct keyboard_source *k = source_of(s);

	close(libevdev_get_fd(k->dev));
	libevdev_free(k->dev);
	free(k);
}

static bool is_keyboard(const struct libevdev *dev)
{
	return libevdev_has_event_type(dev, EV_KEY) &&
	       libevdev_has_event_code(dev, EV_KEY, KEY_A) &&
	       libevdev_has_event_code(dev, EV_KEY, KEY_Z) &&
	       libevdev_has_event_code(dev, EV_KEY, KEY_SPACE);
}

/* Returns 0 with *out set, 0 with *out NULL when the device is no
 * keyboard and must_be is false, or a negative errno after logging. */
static int source_new(const char *path, bool must_be, struct input_source **out)
{
	struct keyboard_source *k = NULL;
	struct libevdev *dev = NULL;
	int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC), ret;

	*out = NULL;
	if (fd < 0) {
		ret = -errno;
		if (must_be || errno != EACCES)
			log_err("%s: cannot open the keyboard: %s", path, strerror(errno));
		return ret;
	}
	ret = libevdev_new_from_fd(fd, &dev);
	if (ret) {
		log_err("%s: not an input event device: %s", path, strerror(-ret));
		goto fail;
	}
	if (!is_keyboard(dev) && !must_be)
		goto fail;
	k = calloc(1, sizeof(*k));
	if (!k) {
		ret = -ENOMEM;
		goto fail;
	}
	k->dev = dev;
	k->stamp_now = libevdev_set_clock_id(dev, CLOCK_MONOTONIC) != 0;
	snprintf(k->name, sizeof(k->name), "keyboard %s (%s)", libevdev_get_name(dev), path);
	k->base = (struct input_source){.name = k->name,
					.kind = INPUT_KIND_KEY,
					.fd = fd,
					.read = keyboard_read,
					.deadline = keyboard_deadline,
					.destroy = keyboard_destroy};
	log_info("%s", k->name);
	*out = &k->base;
	return 0;
fail:
	libevdev_free(dev);
	close(fd);
	return ret;
}

static int is_event_node(const struct dirent *d)
{
	return strncmp(d->d_name, "event", 5) == 0;
}

static int scan(struct input_source **out, int max)
{
	struct dirent **names = NULL;
	int count = 0, denied = 0, total = scandir(INPUT_DIR, &names, is_event_node, versionsort);

	for (int i = 0; i < total; i++) {
		char path[300];
		struct input_source *s = NULL;

		snprintf(path, sizeof(path), INPUT_DIR "/%s", names[i]->d_name);
		if (count < max && source_new(path, false, &s) == -EACCES)
			denied++;
		if (s)
			out[count++] = s;
		free(names[i]);
	}
	free(names);
	if (!count && denied)
		log_warn("no keyboard: %d devices under " INPUT_DIR " may not be read (the "
			 "service's user needs the input group)",
			 denied);
	else if (!count)
		log_info("no keyboard under " INPUT_DIR);
	return count;
}

int keyboard_open(const struct keyboard_config *c, struct input_source **out, int max)
{
	const char *device = c->device;
	struct input_source *s;

	if (max < 1 || (device && !strcmp(device, "none")))
		return 0;
	if (!device || !*device || !strcmp(device, "auto"))
		return scan(out, max);
	if (source_new(device, true, &s))
		return 0;
	out[0] = s;
	return 1;
}
