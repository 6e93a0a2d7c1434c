/* libFuzzer: the config file reader (inih and our table) on any bytes, as
 * /etc/matcap-kiosk/kiosk.ini would hand them over, over the defaults. */
#include "util/log.h"
#include "config/options.h"

#include <stdint.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	log_set_level((enum log_level)0);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *argv[] = {"matcap-kiosk", NULL};
	struct options o;

	if (options_parse(&o, 1, argv) == OPTIONS_OK)
		options_read_memory(&o, "fuzz.ini", (const char *)data, size);
	options_release(&o);
	return 0;
}
