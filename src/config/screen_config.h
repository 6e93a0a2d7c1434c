/* [power] in kiosk.ini: when the screen is on. Plain data, so that the
 * settings need not know the screen's service (src/ops/screen.h). */
#ifndef MK_SCREEN_CONFIG_H
#define MK_SCREEN_CONFIG_H

#include <stdbool.h>

struct screen_config {
	char *schedule;	    /* "Mon-Fri 08:00-20:00, ..."; NULL or "": always on */
	double blank_after; /* minutes without input; 0: never */
	bool cec;	    /* also tell an HDMI-CEC TV */
	char *cec_device;   /* NULL: /dev/cec0 */
};

#endif
