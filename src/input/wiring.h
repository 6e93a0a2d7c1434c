/* How a button is wired to its GPIO line: which level means pressed, and
 * the pull the line needs. Shared by the buttons' settings (gpio.h) and
 * the libgpiod backends (gpio_line.h), which must not include each other. */
#ifndef MK_WIRING_H
#define MK_WIRING_H

enum button_active { BUTTON_ACTIVE_LOW, BUTTON_ACTIVE_HIGH };
enum button_bias {
	BUTTON_BIAS_PULL_UP,
	BUTTON_BIAS_PULL_DOWN,
	BUTTON_BIAS_DISABLE,
	BUTTON_BIAS_AS_IS
};

#endif
