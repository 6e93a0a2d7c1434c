/* The part of libgpiod whose API changed between 1.x (Debian 12) and 2.x
 * (Debian 13): opening a chip, finding a line on it, and requesting one
 * input line for both edges. The Makefile compiles exactly one of
 * gpio_v1.c and gpio_v2.c, picked from pkg-config's libgpiod version;
 * src/input/gpio.c holds everything else and sees only this header. */
#ifndef MK_GPIO_LINE_H
#define MK_GPIO_LINE_H

#include "input/wiring.h"

#include <stdbool.h>
#include <stdint.h>

struct gpio_chip;
struct gpio_request;

/* How a button line is requested: always an input watched on both edges. */
struct gpio_line_settings {
	enum button_bias bias;
	bool active_low;
};

/* One edge, in the logical sense (rising: the button went active). */
struct gpio_edge {
	uint64_t ns; /* the kernel's stamp, on the clock it used */
	bool rising;
};

/* Opens the chip at a /dev path; NULL with errno set when it cannot, or
 * when the file is not a GPIO chip. */
struct gpio_chip *gpio_chip_open(const char *path);
void gpio_chip_free(struct gpio_chip *chip);
const char *gpio_chip_name(struct gpio_chip *chip);  /* gpiochip0 */
const char *gpio_chip_label(struct gpio_chip *chip); /* pinctrl-bcm2711 */
unsigned gpio_chip_num_lines(struct gpio_chip *chip);
/* The offset of the line called name, or -1 (errno ENOENT when none). */
int gpio_chip_find_line(struct gpio_chip *chip, const char *name);
/* Who holds the line, or NULL; copied into buf of size len. */
const char *gpio_chip_line_consumer(struct gpio_chip *chip, unsigned offset, char *buf,
				    unsigned len);

/* Requests the line at offset as an input with edge events on both edges;
 * NULL with errno set (EBUSY: held by another program; EINVAL or
 * EOPNOTSUPP: the chip or kernel cannot do the settings). The request
 * needs the chip open until it is freed. */
struct gpio_request *gpio_request_new(struct gpio_chip *chip, unsigned offset,
				      const struct gpio_line_settings *s, const char *consumer);
void gpio_request_free(struct gpio_request *req);
/* The descriptor poll watches for edges. */
int gpio_request_fd(struct gpio_request *req);
/* Reads one queued edge: 0, or -1 with errno (EAGAIN: none queued, with
 * the descriptor non-blocking). */
int gpio_request_read_edge(struct gpio_request *req, struct gpio_edge *edge);
/* The logical level: 1 active, 0 inactive, -1 with errno on failure. */
int gpio_request_get_value(struct gpio_request *req);

#endif
