/* libFuzzer: the settings reader (src/util/ini.c and the table) on any
 * bytes, as each kind of settings file hands them over: the first byte
 * picks the kind, the rest is the file.
 *   0  kiosk.ini or a drop-in, over the defaults (any key, any path)
 *   1  a USB stick's kiosk.ini (a stick's keys and paths)
 *   2  a model's NAME.ini, installed; 3 the same from a stick
 *   4  the include --import writes: a stick's file as it is rebased, then
 *      read again with a stick's rules, as the live kiosk reads it.
 * Checked beyond the sanitizers: a stick's file that is accepted is
 * accepted again once rebased, setting the same keys in the same lines
 * (the bytes installed are the bytes checked: libinih split a long line
 * after the rebase and let a padded value smuggle in a [display]). */
#include "config/model_settings.h"
#include "config/options.h"
#include "ops/import_ini.h"
#include "util/log.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	log_set_level((enum log_level)0);
	return 0;
}

/* Each setting's line, as what it set: equal for the file and its rebase. */
static void lines_of(const struct options *o, int *lines)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		lines[i] = options_origin(o, &option_defs[i]).line;
}

static void rebased_same(const char *text, size_t size)
{
	struct options a, b;
	int before[OPTION_DEFS], after[OPTION_DEFS];
	char *out = NULL;
	size_t n = 0;

	option_defaults(&a);
	option_defaults(&b);
	if (options_read_text(&a, "stick.ini", NULL, text, size, &options_rules_stick))
		goto out;
	if (import_ini_rebase(text, size, &out, &n))
		goto out;
	/* Read from the content folder, as the kiosk reads the include. */
	if (options_read_text(&b, "/content/kiosk.ini", "/content", out, n, &options_rules_stick))
		__builtin_trap();
	lines_of(&a, before);
	lines_of(&b, after);
	if (memcmp(before, after, sizeof(before)))
		__builtin_trap();
out:
	free(out);
	options_release(&a);
	options_release(&b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct options_rules model = {model_settings_allowed, "the model's keys",
				      "a model's own file", false};
	const char *text = (const char *)data + 1;
	struct options o;

	if (!size)
		return 0;
	size--;
	option_defaults(&o);
	switch (data[0] % 5) {
	case 0:
		options_read_memory(&o, "kiosk.ini", text, size);
		break;
	case 1:
		options_read_text(&o, "stick.ini", NULL, text, size, &options_rules_stick);
		break;
	case 2:
	case 3:
		model.stick_paths = data[0] % 5 == 3;
		options_read_text(&o, "/m/NAME.ini", "/m", text, size, &model);
		break;
	default:
		rebased_same(text, size);
		break;
	}
	options_release(&o);
	return 0;
}
