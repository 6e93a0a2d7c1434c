/* [output.NAME] sections: what one output of several ([display] outputs)
 * shows, read a key at a time by the settings reader (options_file.c). A
 * bad value is said with the file, the line and what was expected, and
 * that key keeps its default; the output still shows something. */
#ifndef MK_OUTPUT_SETTINGS_H
#define MK_OUTPUT_SETTINGS_H

#include "render/output_view.h"

#include <stdbool.h>

/* Whether [section] is an output's: "output." and a name. */
bool output_settings_section(const char *section);
/* One key = value of [section] at path:line into set. false: said, and
 * refused (an error for --check-config). */
bool output_settings_key(struct output_views *set, const char *path, int line, const char *section,
			 const char *key, const char *value);

#endif
