/* src/input/gpio_line.h on libgpiod 2.x (Debian 13): a request is built
 * from settings and configs and stands apart from the chip; edges are read
 * through an event buffer (of one: the caller reads them one at a time). */
#include "input/gpio_line.h"

#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>

struct gpio_chip {
	struct gpiod_chip *chip;
	char name[64], label[64];
	unsigned num_lines;
};

struct gpio_request {
	struct gpiod_line_request *req;
	struct gpiod_edge_event_buffer *events;
	unsigned offset;
};

struct gpio_chip *gpio_chip_open(const char *path)
{
	struct gpio_chip *c = calloc(1, sizeof(*c));
	struct gpiod_chip_info *info = NULL;
	int err = ENOMEM;

	if (!c)
		goto fail;
	c->chip = gpiod_chip_open(path);
	info = c->chip ? gpiod_chip_get_info(c->chip) : NULL;
	if (!info) {
		err = errno;
		goto fail;
	}
	snprintf(c->name, sizeof(c->name), "%s", gpiod_chip_info_get_name(info));
	snprintf(c->label, sizeof(c->label), "%s", gpiod_chip_info_get_label(info));
	c->num_lines = (unsigned)gpiod_chip_info_get_num_lines(info);
	gpiod_chip_info_free(info);
	return c;
fail:
	gpio_chip_free(c);
	errno = err;
	return NULL;
}

void gpio_chip_free(struct gpio_chip *chip)
{
	if (!chip)
		return;
	if (chip->chip)
		gpiod_chip_close(chip->chip);
	free(chip);
}

const char *gpio_chip_name(struct gpio_chip *chip)
{
	return chip->name;
}

const char *gpio_chip_label(struct gpio_chip *chip)
{
	return chip->label;
}

unsigned gpio_chip_num_lines(struct gpio_chip *chip)
{
	return chip->num_lines;
}

int gpio_chip_find_line(struct gpio_chip *chip, const char *name)
{
	errno = 0;
	int offset = gpiod_chip_get_line_offset_from_name(chip->chip, name);

	if (offset < 0 && !errno)
		errno = ENOENT;
	return offset < 0 ? -1 : offset;
}

const char *gpio_chip_line_consumer(struct gpio_chip *chip, unsigned offset, char *buf,
				    unsigned len)
{
	struct gpiod_line_info *info = gpiod_chip_get_line_info(chip->chip, offset);
	const char *user = info ? gpiod_line_info_get_consumer(info) : NULL;

	if (user)
		snprintf(buf, len, "%s", user);
	if (info)
		gpiod_line_info_free(info);
	return user ? buf : NULL;
}

static struct gpiod_line_settings *settings_new(const struct gpio_line_settings *s)
{
	static const enum gpiod_line_bias bias[] = {
	    [BUTTON_BIAS_PULL_UP] = GPIOD_LINE_BIAS_PULL_UP,
	    [BUTTON_BIAS_PULL_DOWN] = GPIOD_LINE_BIAS_PULL_DOWN,
	    [BUTTON_BIAS_DISABLE] = GPIOD_LINE_BIAS_DISABLED,
	    [BUTTON_BIAS_AS_IS] = GPIOD_LINE_BIAS_AS_IS,
	};
	struct gpiod_line_settings *ls = gpiod_line_settings_new();

	if (ls && (gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_INPUT) < 0 ||
		   gpiod_line_settings_set_edge_detection(ls, GPIOD_LINE_EDGE_BOTH) < 0 ||
		   gpiod_line_settings_set_bias(ls, bias[s->bias]) < 0)) {
		gpiod_line_settings_free(ls);
		return NULL;
	}
	if (ls)
		gpiod_line_settings_set_active_low(ls, s->active_low);
	return ls;
}

/* The line request proper: settings, line config and request config are
 * only needed while it is made. */
static struct gpiod_line_request *lines_request(struct gpio_chip *chip, unsigned offset,
						const struct gpio_line_settings *s,
						const char *consumer)
{
	struct gpiod_line_settings *ls = settings_new(s);
	struct gpiod_line_config *lc = gpiod_line_config_new();
	struct gpiod_request_config *rc = gpiod_request_config_new();
	struct gpiod_line_request *req = NULL;
	int err = ENOMEM;

	if (!ls || !lc || !rc)
		goto cleanup;
	gpiod_request_config_set_consumer(rc, consumer);
	if (gpiod_line_config_add_line_settings(lc, &offset, 1, ls) < 0) {
		err = errno;
		goto cleanup;
	}
	req = gpiod_chip_request_lines(chip->chip, rc, lc);
	err = errno;
cleanup:
	/* libgpiod does not promise that its _free functions take NULL. */
	if (rc)
		gpiod_request_config_free(rc);
	if (lc)
		gpiod_line_config_free(lc);
	if (ls)
		gpiod_line_settings_free(ls);
	errno = err;
	return req;
}

struct gpio_request *gpio_request_new(struct gpio_chip *chip, unsigned offset,
				      const struct gpio_line_settings *s, const char *consumer)
{
	struct gpio_request *r = calloc(1, sizeof(*r));
	int err = ENOMEM;

	if (!r || !(r->events = gpiod_edge_event_buffer_new(1)))
		goto fail;
	r->offset = offset;
	r->req = lines_request(chip, offset, s, consumer);
	if (!r->req) {
		err = errno;
		goto fail;
	}
	return r;
fail:
	gpio_request_free(r);
	errno = err;
	return NULL;
}

void gpio_request_free(struct gpio_request *req)
{
	if (!req)
		return;
	if (req->req)
		gpiod_line_request_release(req->req);
	if (req->events)
		gpiod_edge_event_buffer_free(req->events);
	free(req);
}

int gpio_request_fd(struct gpio_request *req)
{
	return gpiod_line_request_get_fd(req->req);
}

int gpio_request_read_edge(struct gpio_request *req, struct gpio_edge *edge)
{
	struct gpiod_edge_event *ev;
	int n = gpiod_line_request_read_edge_events(req->req, req->events, 1);

	if (n <= 0) {
		if (n == 0)
			errno = EAGAIN;
		return -1;
	}
	ev = gpiod_edge_event_buffer_get_event(req->events, 0);
	edge->ns = gpiod_edge_event_get_timestamp_ns(ev);
	edge->rising = gpiod_edge_event_get_event_type(ev) == GPIOD_EDGE_EVENT_RISING_EDGE;
	return 0;
}

int gpio_request_get_value(struct gpio_request *req)
{
	enum gpiod_line_value v = gpiod_line_request_get_value(req->req, req->offset);

	return v == GPIOD_LINE_VALUE_ERROR ? -1 : v == GPIOD_LINE_VALUE_ACTIVE;
}
