/* Push buttons on GPIO lines through libgpiod (the v1 API of Debian 12's
 * 1.6.3): one input source per wired button, woken by the line's edge
 * events in the main poll loop, debounced by src/button.c with the
 * kernel's timestamps. */
#ifndef MK_GPIO_H
#define MK_GPIO_H

#include "input.h"
#include "options.h"

/* Opens the lines of the [buttons] settings. A chip or line that cannot
 * be had (missing, or held by another program) is one error line naming
 * both, and that button is left out. Writes up to max sources into out
 * and returns their count, or OPTIONS_CONFIG when two buttons turn out to
 * be the same line (GPIO17 and 17, say): a config error. */
int gpio_open_buttons(const struct options *o, struct input_source **out, int max);

#endif
