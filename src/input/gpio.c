#include "input/gpio.h"
#include "util/clock.h"
#include "input/button.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <gpiod.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CONSUMER "matcap-kiosk"

const char *const gpio_button_names[GPIO_BUTTONS] = {"left", "right", "select"};

struct gpio_source {
	struct input_source base;
	struct gpiod_chip *chip; /* owned: one handle per line keeps them apart */
	struct gpiod_line *line;
	struct button button;
	bool lost;
	char name[128];
};

/* A resolved line, before it is requested. */
struct gpio_wire {
	int slot;
	struct gpiod_chip *chip;
	struct gpiod_line *line;
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
static uint64_t event_ns(const struct timespec *ts)
{
	uint64_t t = (uint64_t)ts->tv_sec * 1000000000ull + (uint64_t)ts->tv_nsec;
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

/* Finds the line a [buttons] key names: an offset on the configured chip
 * (gpiochip0 when none is set), or a line name on that chip or, with no
 * chip set, on every chip. Logs one line on failure. */
static int wire_find(const struct gpio_config *c, int slot, struct gpio_wire *w)
{
	const char *spec = c->buttons[slot].line, *button = gpio_button_names[slot];
	const char *chip = c->chip && *c->chip ? c->chip : NULL;
	int ret = 0;

	*w = (struct gpio_wire){.slot = slot};
	if (!chip && !all_digits(spec)) {
		errno = 0;
		w->line = gpiod_line_find(spec);
		if (!w->line && (errno == ENOENT || !errno)) {
			log_err(
			    "button %s: no GPIO line named %s on any chip (gpioinfo lists them); "
			    "running without this button",
			    button, spec);
			return -ENOENT;
		}
		if (!w->line) {
			ret = -errno;
			log_err("button %s: cannot look through the GPIO chips for line %s: %s; "
				"running without this button",
				button, spec, strerror(errno));
			return ret;
		}
		w->chip = gpiod_line_get_chip(w->line);
		return 0;
	}
	if (!chip)
		chip = "gpiochip0";
	w->chip = gpiod_chip_open_lookup(chip);
	if (!w->chip) {
		ret = -errno;
		log_err("button %s: GPIO chip %s not found (%s); running without the button on "
			"line %s",
			button, chip, strerror(errno), spec);
		return ret;
	}
	if (all_digits(spec))
		w->line = gpiod_chip_get_line(w->chip, (unsigned)strtoul(spec, NULL, 10));
	else
		w->line = gpiod_chip_find_line(w->chip, spec);
	if (!w->line) {
		ret = errno ? -errno : -ENOENT;
		log_err("button %s: GPIO chip %s has no line %s (it has lines 0 to %u); running "
			"without this button",
			button, gpiod_chip_name(w->chip), spec, gpiod_chip_num_lines(w->chip) - 1);
		gpiod_chip_close(w->chip);
		w->chip = NULL;
	}
	return ret;
}

/* GPIO17 and 17 may be one line: two requests would fight over it. */
static int check_clash(const struct gpio_config *c, const struct gpio_wire *w, int n)
{
	for (int i = 0; i < n; i++)
		for (int j = i + 1; j < n; j++)
			if (gpiod_line_offset(w[i].line) == gpiod_line_offset(w[j].line) &&
			    !strcmp(gpiod_chip_name(w[i].chip), gpiod_chip_name(w[j].chip))) {
				log_err("[buttons] %s = %s and %s = %s are the same line (%s "
					"offset %u); each button needs its own line",
					gpio_button_names[w[i].slot], c->buttons[w[i].slot].line,
					gpio_button_names[w[j].slot], c->buttons[w[j].slot].line,
					gpiod_chip_name(w[i].chip), gpiod_line_offset(w[i].line));
				return -EEXIST;
			}
	return 0;
}

static int request_flags(const struct gpio_config *c)
{
	static const int bias[] = {
	    [BUTTON_BIAS_PULL_UP] = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP,
	    [BUTTON_BIAS_PULL_DOWN] = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN,
	    [BUTTON_BIAS_DISABLE] = GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE,
	    [BUTTON_BIAS_AS_IS] = 0,
	};

	return bias[c->bias] |
	       (c->active == BUTTON_ACTIVE_LOW ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0);
}

/* Both edges, with the bias and polarity asked for; a kernel or chip that
 * cannot set the bias still gives the button, as the line is wired. */
static int line_request(struct gpiod_line *line, int flags, const char *name)
{
	const int bias = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP |
			 GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN |
			 GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
	const char *user;

	if (gpiod_line_request_both_edges_events_flags(line, CONSUMER, flags) == 0)
		return 0;
	if ((errno == EINVAL || errno == EOPNOTSUPP) && (flags & bias) &&
	    gpiod_line_request_both_edges_events_flags(line, CONSUMER, flags & ~bias) == 0) {
		log_warn("%s: the chip cannot set the line's bias; add a pull resistor if the "
			 "button reads wrong",
			 name);
		return 0;
	}
	if (errno == EBUSY) {
		gpiod_line_update(line);
		user = gpiod_line_consumer(line);
		log_err("%s: the line is used by another program (%s); running without this "
			"button",
			name, user ? user : "unnamed");
		return -EBUSY;
	}
	log_err("%s: cannot watch the line: %s; running without this button", name,
		strerror(errno));
	return -errno;
}

/* The line's level once its queue is empty: a burst that overflowed the
 * kernel's queue must not leave the button down (or up). */
static int catch_up(struct gpio_source *g, uint64_t now, struct app_event *out)
{
	int v = gpiod_line_get_value(g->line);

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
	struct gpiod_line_event ev;
	int n = 0, edges = 0;
	uint64_t t;
	bool down;

	if (g->lost)
		return -ENODEV;
	/* Edges first, in their order (each settles what was due before
	 * it), then what is due by now. One at a time, so that an edge is
	 * read only when its events fit: the rest stays queued and wakes
	 * poll again. */
	while (max - n >= 2 * BUTTON_MAX_EVENTS) {
		if (gpiod_line_event_read_fd(s->fd, &ev) < 0) {
			if (errno != EAGAIN)
				return n + gpio_lose(g, now, out + n, errno);
			if (edges)
				n += catch_up(g, now, out + n);
			break;
		}
		edges++;
		t = event_ns(&ev.ts);
		down = ev.event_type == GPIOD_LINE_EVENT_RISING_EDGE;
		log_debug("%s: %s at %.3f s, read %.2f ms later", g->name,
			  down ? "pressed" : "released", (double)t / 1e9,
			  now > t ? (double)(now - t) / 1e6 : 0.0);
		n += button_edge(&g->button, t, down, out + n);
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

	gpiod_line_release(g->line);
	gpiod_chip_close(g->chip);
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

/* Takes the wire's chip and line: on success the source owns them. */
static struct input_source *source_new(const struct gpio_config *c, struct gpio_wire *w)
{
	struct gpio_source *g = calloc(1, sizeof(*g));
	struct button_config cfg;
	int fd, level;

	if (!g)
		goto fail;
	snprintf(g->name, sizeof(g->name), "button %s (%s on %s)", gpio_button_names[w->slot],
		 c->buttons[w->slot].line, gpiod_chip_name(w->chip));
	if (line_request(w->line, request_flags(c), g->name))
		goto fail;
	fd = gpiod_line_event_get_fd(w->line);
	/* Read also when only a deadline passed: it must not block. */
	if (fd < 0 || fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK) < 0) {
		log_err("%s: no event descriptor: %s", g->name, strerror(errno));
		gpiod_line_release(w->line);
		goto fail;
	}
	level = gpiod_line_get_value(w->line);
	button_config_from(c, w->slot, &cfg);
	button_init(&g->button, &cfg, level == 1);
	if (level == 1)
		log_warn("%s: pressed at start-up; it counts once released", g->name);
	g->chip = w->chip;
	g->line = w->line;
	g->base = (struct input_source){.name = g->name,
					.fd = fd,
					.read = gpio_read,
					.deadline = gpio_deadline,
					.destroy = gpio_destroy};
	log_info("%s: %s, long press %s", g->name, app_action_names[cfg.press],
		 app_action_names[cfg.long_press]);
	return &g->base;
fail:
	free(g);
	gpiod_chip_close(w->chip);
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
			gpiod_chip_close(w[i].chip);
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
