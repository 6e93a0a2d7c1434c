/* [hotspot.NAME] sections: a model's hotspots in its NAME.ini (or every
 * model's in kiosk.ini), read by the settings reader (options_file.c) a
 * key at a time and kept whole at the end of each file. A bad hotspot is
 * dropped with an error naming the file, the line and what was expected;
 * the file's other settings and hotspots stay (the kiosk shows the rest). */
#ifndef MK_HOTSPOT_SETTINGS_H
#define MK_HOTSPOT_SETTINGS_H

#include "state/hotspot.h"

#include <stdbool.h>

/* One file's hotspots while it is read. */
struct hotspot_read {
	struct hotspot_set pending;
	bool bad[HOTSPOTS];
	int seen[HOTSPOTS][6]; /* the line of each key (hotspot_keys' order) */
	bool full_said;
};

/* Whether [section] is a hotspot's: "hotspot." and a name. */
bool hotspot_settings_section(const char *section);
/* One key = value of [section] at path:line. */
void hotspot_settings_key(struct hotspot_read *rd, const char *path, int line, const char *section,
			  const char *key, const char *value);
/* The file's good hotspots into set: a name set already is replaced (a
 * model's own file over kiosk.ini's), a new one added. The count of
 * hotspots dropped, each said in the journal. */
int hotspot_settings_finish(struct hotspot_read *rd, const char *path, struct hotspot_set *set);

#endif
