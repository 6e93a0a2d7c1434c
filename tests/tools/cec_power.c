/* Sends the kiosk's CEC power messages from the command line, through the
 * same code as the kiosk (src/display/cec.c): for the virtual board's CEC
 * test against vivid's emulated HDMI devices.
 *   cec_power /dev/cec1 on|off...
 * Exits 0 when every message was acknowledged, 1 when one was not, 2 when
 * the adapter could not be used. */
#include "display/cec.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
	struct cec *c;
	int status = 0;

	if (argc < 3) {
		fprintf(stderr, "usage: %s /dev/cecN on|off...\n", argv[0]);
		return 2;
	}
	c = cec_new(argv[1]);
	if (!c)
		return 2;
	for (int i = 2; i < argc; i++)
		if (cec_power(c, strcmp(argv[i], "off") != 0))
			status = 1;
	cec_free(c);
	return status;
}
