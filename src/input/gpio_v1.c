/* src/input/gpio_line.h on libgpiod 1.x (Debian 12): lines are objects
 * owned by their chip, requested one at a time with request flags. */
#include "input/gpio_line.h"

#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>

struct gpio_chip {
	struct gpiod_chip *chip;
};

struct gpio_request {
	struct gpiod_line *line;
};

struct gpio_chip *gpio_chip_open(const char *path)
{
	struct gpio_chip *c = calloc(1, sizeof(*c));
	int err;

	if (!c)
		return NULL;
	c->chip = gpiod_chip_open(path);
	if (!c->chip) {
		err = errno;
		free(c);
		errno = err;
		return NULL;
	}
	return c;
}

void gpio_chip_free(struct gpio_chip *chip)
{
	if (!chip)
		return;
	gpiod_chip_close(chip->chip);
	free(chip);
}

const char *gpio_chip_name(struct gpio_chip *chip)
{
	return gpiod_chip_name(chip->chip);
}

const char *gpio_chip_label(struct gpio_chip *chip)
{
	return gpiod_chip_label(chip->chip);
}

unsigned gpio_chip_num_lines(struct gpio_chip *chip)
{
	return gpiod_chip_num_lines(chip->chip);
}

int gpio_chip_find_line(struct gpio_chip *chip, const char *name)
{
	struct gpiod_line *line;

	errno = 0;
	line = gpiod_chip_find_line(chip->chip, name);
	if (!line) {
		if (!errno)
			errno = ENOENT;
		return -1;
	}
	return (int)gpiod_line_offset(line);
}

const char *gpio_chip_line_consumer(struct gpio_chip *chip, unsigned offset, char *buf,
				    unsigned len)
{
	struct gpiod_line *line = gpiod_chip_get_line(chip->chip, offset);
	const char *user;

	if (!line || gpiod_line_update(line) < 0)
		return NULL;
	user = gpiod_line_consumer(line);
	if (!user)
		return NULL;
	snprintf(buf, len, "%s", user);
	return buf;
}

static int request_flags(const struct gpio_line_settings *s)
{
	static const int bias[] = {
	    [BUTTON_BIAS_PULL_UP] = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP,
	    [BUTTON_BIAS_PULL_DOWN] = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN,
	    [BUTTON_BIAS_DISABLE] = GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE,
	    [BUTTON_BIAS_AS_IS] = 0,
	};

	return bias[s->bias] | (s->active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0);
}

struct gpio_request *gpio_request_new(struct gpio_chip *chip, unsigned offset,
				      const struct gpio_line_settings *s, const char *consumer)
{
	struct gpio_request *r = calloc(1, sizeof(*r));
	int err = ENOMEM;

	if (!r)
		goto fail;
	r->line = gpiod_chip_get_line(chip->chip, offset);
	if (!r->line ||
	    gpiod_line_request_both_edges_events_flags(r->line, consumer, request_flags(s)) < 0) {
		err = errno;
		goto fail;
	}
	return r;
fail:
	free(r);
	errno = err;
	return NULL;
}

void gpio_request_free(struct gpio_request *req)
{
	if (!req)
		return;
	gpiod_line_release(req->line);
	free(req);
}

int gpio_request_fd(struct gpio_request *req)
{
	return gpiod_line_event_get_fd(req->line);
}

int gpio_request_read_edge(struct gpio_request *req, struct gpio_edge *edge)
{
	struct gpiod_line_event ev;

	if (gpiod_line_event_read_fd(gpiod_line_event_get_fd(req->line), &ev) < 0)
		return -1;
	edge->ns = (uint64_t)ev.ts.tv_sec * 1000000000ull + (uint64_t)ev.ts.tv_nsec;
	edge->rising = ev.event_type == GPIOD_LINE_EVENT_RISING_EDGE;
	return 0;
}

int gpio_request_get_value(struct gpio_request *req)
{
	return gpiod_line_get_value(req->line);
}
