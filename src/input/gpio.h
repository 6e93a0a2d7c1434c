/* Push buttons on GPIO lines through libgpiod: one input source per wired
 * button, woken by the line's edge events in the main poll loop, debounced
 * by src/input/button.c with the kernel's timestamps. */
#ifndef MK_GPIO_H
#define MK_GPIO_H

#include "input/input.h"
#include "input/wiring.h"

/* The buttons a board has: left, right, select (gpio_button_names). */
#define GPIO_BUTTONS 3
extern const char *const gpio_button_names[GPIO_BUTTONS];

struct gpio_button {
	const char *line; /* GPIO17, 17...; NULL, "" or "none": not wired */
	enum app_action press;
	enum app_action long_press; /* ACTION_NONE: no long press */
};

/* [buttons] in kiosk.ini. */
struct gpio_config {
	const char *chip; /* NULL or "": line names are looked for on every chip */
	enum button_active active;
	enum button_bias bias;
	int debounce_ms, long_press_ms, repeat_ms;
	struct gpio_button buttons[GPIO_BUTTONS];
};

/* Opens the lines of the wired buttons. A chip or line that cannot be had
 * (missing, or held by another program) is one error line naming both,
 * and that button is left out. Writes up to max sources into out and
 * returns their count, or -EEXIST when two buttons turn out to be the same
 * line (GPIO17 and 17, say): a config error. */
int gpio_open_buttons(const struct gpio_config *c, struct input_source **out, int max);

#endif
