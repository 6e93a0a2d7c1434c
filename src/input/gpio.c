#include "input/gpio.h"
#include "input/button.h"
#include "input/gpio_line.h"
#include "util/clock.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CONSUMER "matcap-kiosk"

const char *const gpio_button_names[GPIO_BUTTONS] = {"left", "right", "select"};

struct gpio_source {
	struct input_source base;
	struct gpio_chip *chip; /* owned: one handle per line keeps them apart */
	struct gpio_request *req;
	struct button button;
	bool lost;
	char name[128];
};

/* A resolved line, before it is requested. */
struct gpio_wire {
	int slot;
	struct gpio_chip *chip;
	unsigned offset;
};

static struct gpio_source *source_of(struct input_source *s)
{
	return (struct gpio_source *)((char *)s - offsetof(struct gpio_source, base));
}

static uint64_t distance(uint64_t a, uint64_t b)
{
	return a > b ? a - b : b - a;
}

/* Linux 5.7 and later stamp line events with CLOCK_MONOTONIC, the main
 * loop's clock; older kernels used CLOCK_REALTIME. A stamp nearer the
 * wall clock is moved onto the monotonic one. */
static uint64_t event_ns(uint64_t t)
{
	uint64_t mono = clock_ns(CLOCK_MONOTONIC), real = clock_ns(CLOCK_REALTIME);

	if (distance(t, real) < distance(t, mono))
		t = t + mono > real ? t + mono - real : 0;
	return t;
}

static bool all_digits(const char *s)
{
	if (!*s)
		return false;
	for (; *s; s++)
		if (*s < '0' || *s > '9')
			return false;
	return true;
}

static int chip_filter(const struct dirent *d)
{
	return !strncmp(d->d_name, "gpiochip", 8);
}

/* Whether the chip has a line called name (its offset in *offset). */
static bool match_line(struct gpio_chip *chip, const char *name, int *offset)
{
	*offset = gpio_chip_find_line(chip, name);
	return *offset >= 0;
}

static bool match_label(struct gpio_chip *chip, const char *label, int *offset)
{
	*offset = -1;
	return !strcmp(gpio_chip_label(chip), label);
}

/* Opens every chip in /dev in name order, as libgpiod 1's line search did
 * (libgpiod 2 has none: both APIs use this one), and returns the first one
 * that matches. A chip that cannot be opened is passed over; its error
 * (errno) is told only when no other chip matches, else ENOENT. */
static struct gpio_chip *chips_search(bool (*match)(struct gpio_chip *, const char *, int *),
				      const char *what, int *offset)
{
	struct dirent **dirs = NULL;
	struct gpio_chip *found = NULL;
	int n = scandir("/dev", &dirs, chip_filter, alphasort), err = n < 0 ? errno : ENOENT;
	char path[300];

	for (int i = 0; i < n && !found; i++) {
		struct gpio_chip *c;

		snprintf(path, sizeof(path), "/dev/%s", dirs[i]->d_name);
		c = gpio_chip_open(path);
		if (!c)
			err = errno;
		else if (match(c, what, offset))
			found = c;
		else
			gpio_chip_free(c);
	}
	for (int i = 0; i < n; i++)
		free(dirs[i]);
	free(dirs);
	errno = err;
	return found;
}

/* A chip as [buttons] chip names it: a number, a /dev path, a name in
 * /dev (gpiochip0) or a label (pinctrl-bcm2711), as gpiodetect shows. */
static struct gpio_chip *chip_lookup(const char *chip)
{
	struct gpio_chip *c;
	char path[300];
	int unused;

	if (all_digits(chip))
		snprintf(path, sizeof(path), "/dev/gpiochip%s", chip);
	else
		snprintf(path, sizeof(path), "%s%s", chip[0] == '/' ? "" : "/dev/", chip);
	c = gpio_chip_open(path);
	if (!c && !all_digits(chip) && chip[0] != '/')
		c = chips_search(match_label, chip, &unused);
	return c;
}

/* Finds the line a [buttons] key names: an offset on the configured chip
 * (gpiochip0 when none is set), or a line name on that chip or, with no
 * chip set, on every chip. Logs one line on failure. */
static int wire_find(const struct gpio_config *c, int slot, struct gpio_wire *w)
{
	const char *spec = c->buttons[slot].line, *button = gpio_button_names[slot];
	const char *chip = c->chip && *c->chip ? c->chip : NULL;
	int ret = 0, offset;

	*w = (struct gpio_wire){.slot = slot};
	if (!chip && !all_digits(spec)) {
		w->chip = chips_search(match_line, spec, &offset);
		w->offset = (unsigned)offset;
		ret = w->chip ? 0 : -errno;
		if (ret == -ENOENT)
			log_err(
			    "button %s: no GPIO line named %s on any chip (gpioinfo lists them); "
			    "running without this button",
			    button, spec);
		else if (ret)
			log_err("button %s: cannot look through the GPIO chips for line %s: %s; "
				"running without this button",
				button, spec, strerror(-ret));
		return ret;
	}
	if (!chip)
		chip = "gpiochip0";
	w->chip = chip_lookup(chip);
	if (!w->chip) {
		ret = -errno;
		log_err("button %s: GPIO chip %s not found (%s); running without the button on "
			"line %s",
			button, chip, strerror(errno), spec);
		return ret;
	}
	if (all_digits(spec)) {
		unsigned long o = strtoul(spec, NULL, 10);

		offset = o < gpio_chip_num_lines(w->chip) ? (int)o : -1;
	} else {
		offset = gpio_chip_find_line(w->chip, spec);
	}
	if (offset < 0) {
		log_err("button %s: GPIO chip %s has no line %s (it has lines 0 to %u); running "
			"without this button",
			button, gpio_chip_name(w->chip), spec, gpio_chip_num_lines(w->chip) - 1);
		gpio_chip_free(w->chip);
		w->chip = NULL;
		return -ENOENT;
	}
	w->offset = (unsigned)offset;
	return 0;
}

/* GPIO17 and 17 may be one line: two requests would fight over it. */
static int check_clash(const struct gpio_config *c, const struct gpio_wire *w, int n)
{
	for (int i = 0; i < n; i++)
		for (int j = i + 1; j < n; j++)
			if (w[i].offset == w[j].offset &&
			    !strcmp(gpio_chip_name(w[i].chip), gpio_chip_name(w[j].chip))) {
				log_err("[buttons] %s = %s and %s = %s are the same line (%s "
					"offset %u); each button needs its own line",
					gpio_button_names[w[i].slot], c->buttons[w[i].slot].line,
					gpio_button_names[w[j].slot], c->buttons[w[j].slot].line,
					gpio_chip_name(w[i].chip), w[i].offset);
				return -EEXIST;
			}
	return 0;
}

/* Both edges, with the bias and polarity asked for; a kernel or chip that
 * cannot set the bias still gives the button, as the line is wired. */
static struct gpio_request *line_request(const struct gpio_config *c, const struct gpio_wire *w,
					 const char *name)
{
	struct gpio_line_settings s = {.bias = c->bias,
				       .active_low = c->active == BUTTON_ACTIVE_LOW};
	struct gpio_request *req = gpio_request_new(w->chip, w->offset, &s, CONSUMER);
	char user[64];

	if (!req && (errno == EINVAL || errno == EOPNOTSUPP) && s.bias != BUTTON_BIAS_AS_IS) {
		s.bias = BUTTON_BIAS_AS_IS;
		req = gpio_request_new(w->chip, w->offset, &s, CONSUMER);
		if (req)
			log_warn("%s: the chip cannot set the line's bias; add a pull resistor if "
				 "the button reads wrong",
				 name);
	}
	if (!req && errno == EBUSY)
		log_err("%s: the line is used by another program (%s); running without this "
			"button",
			name,
			gpio_chip_line_consumer(w->chip, w->offset, user, sizeof(user))
			    ? user
			    : "unnamed");
	else if (!req)
		log_err("%s: cannot watch the line: %s; running without this button", name,
			strerror(errno));
	return req;
}

/* The line's level once its queue is empty: a burst that overflowed the
 * kernel's queue must not leave the button down (or up). */
static int catch_up(struct gpio_source *g, uint64_t now, struct app_event *out)
{
	int v = gpio_request_get_value(g->req);

	if (v < 0 || (v == 1) == g->button.raw)
		return 0;
	return button_edge(&g->button, now, v == 1, out);
}

static int gpio_lose(struct gpio_source *g, uint64_t now, struct app_event *out, int err)
{
	log_err("%s: cannot read the line: %s", g->base.name, strerror(err));
	g->lost = true;
	return button_lost(&g->button, now, out);
}

static int gpio_read(struct input_source *s, uint64_t now, struct app_event *out, int max)
{
	struct gpio_source *g = source_of(s);
	struct gpio_edge ev;
	int n = 0, edges = 0;
	uint64_t t;

	if (g->lost)
		return -ENODEV;
	/* Edges first, in their order (each settles what was due before
	 * it), then what is due by now. One at a time, so that an edge is
	 * read only when its events fit: the rest stays queued and wakes
	 * poll again. */
	while (max - n >= 2 * BUTTON_MAX_EVENTS) {
		if (gpio_request_read_edge(g->req, &ev) < 0) {
			if (errno != EAGAIN)
				return n + gpio_lose(g, now, out + n, errno);
			if (edges)
				n += catch_up(g, now, out + n);
			break;
		}
		edges++;
		t = event_ns(ev.ns);
		log_debug("%s: %s at %.3f s, read %.2f ms later", g->name,
			  ev.rising ? "pressed" : "released", (double)t / 1e9,
			  now > t ? (double)(now - t) / 1e6 : 0.0);
		n += button_edge(&g->button, t, ev.rising, out + n);
	}
	if (max - n < BUTTON_MAX_EVENTS)
		return n;
	return n + button_timeout(&g->button, now, out + n);
}

static uint64_t gpio_deadline(struct input_source *s)
{
	return button_deadline(&source_of(s)->button);
}

static void gpio_destroy(struct input_source *s)
{
	struct gpio_source *g = source_of(s);

	gpio_request_free(g->req);
	gpio_chip_free(g->chip);
	free(g);
}

static void button_config_from(const struct gpio_config *c, int slot, struct button_config *b)
{
	*b = (struct button_config){
	    .press = c->buttons[slot].press,
	    .long_press = c->buttons[slot].long_press,
	    .debounce_ns = (uint64_t)c->debounce_ms * 1000000ull,
	    .long_ns = (uint64_t)c->long_press_ms * 1000000ull,
	    .repeat_ns = (uint64_t)c->repeat_ms * 1000000ull,
	};
}

/* Takes the wire's chip: on success the source owns it. */
static struct input_source *source_new(const struct gpio_config *c, struct gpio_wire *w)
{
	struct gpio_source *g = calloc(1, sizeof(*g));
	struct button_config cfg;
	int fd, level;

	if (!g)
		goto fail;
	snprintf(g->name, sizeof(g->name), "button %s (%s on %s)", gpio_button_names[w->slot],
		 c->buttons[w->slot].line, gpio_chip_name(w->chip));
	g->req = line_request(c, w, g->name);
	if (!g->req)
		goto fail;
	fd = gpio_request_fd(g->req);
	/* Read also when only a deadline passed: it must not block. */
	if (fd < 0) {
		log_err("%s: the line gave no event descriptor", g->name);
		goto fail;
	}
	if (fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK) < 0) {
		log_err("%s: no event descriptor: %s", g->name, strerror(errno));
		goto fail;
	}
	level = gpio_request_get_value(g->req);
	button_config_from(c, w->slot, &cfg);
	button_init(&g->button, &cfg, level == 1);
	if (level == 1)
		log_warn("%s: pressed at start-up; it counts once released", g->name);
	g->chip = w->chip;
	g->base = (struct input_source){.name = g->name,
					.kind = INPUT_KIND_BUTTON,
					.fd = fd,
					.read = gpio_read,
					.deadline = gpio_deadline,
					.destroy = gpio_destroy};
	log_info("%s: %s, long press %s", g->name, app_action_names[cfg.press],
		 app_action_names[cfg.long_press]);
	return &g->base;
fail:
	if (g)
		gpio_request_free(g->req);
	free(g);
	gpio_chip_free(w->chip);
	return NULL;
}

int gpio_open_buttons(const struct gpio_config *c, struct input_source **out, int max)
{
	struct gpio_wire w[GPIO_BUTTONS];
	int n = 0, count = 0, ret;

	for (int slot = 0; slot < GPIO_BUTTONS; slot++) {
		const char *spec = c->buttons[slot].line;

		if (spec && *spec && strcmp(spec, "none") && wire_find(c, slot, &w[n]) == 0)
			n++;
	}
	ret = check_clash(c, w, n);
	for (int i = 0; i < n; i++) {
		struct input_source *s = NULL;

		if (!ret && count < max)
			s = source_new(c, &w[i]);
		else
			gpio_chip_free(w[i].chip);
		if (s)
			out[count++] = s;
	}
	if (ret) {
		for (int i = 0; i < count; i++)
			out[i]->destroy(out[i]);
		return ret;
	}
	return count;
}
