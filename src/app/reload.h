/* Changing what the kiosk shows while it runs, without a black screen:
 * the new content is built completely beside the one on screen (which stays
 * scanned out meanwhile), and swapped in only when every part of it
 * loaded and reached the GPU. */
#ifndef MK_RELOAD_H
#define MK_RELOAD_H

#include "content/content.h"
#include "config/options.h"
#include "render/render.h"

/* The content of cfg, fitted to a width x height display, into shown and
 * the renderer. Returns 0, or a negative errno after logging, and then
 * shown is what it was and still on the GPU. */
/* Logs that the reload failed: what, and the cause, the last error logged
 * since the reload began (the file, line and reason), so that --status,
 * which shows the last error, names it. */
void reload_failed(const char *what);
int reload_content(struct content *shown, const struct content_config *cfg, struct renderer *r,
		   int width, int height);
/* What a reload must do about the settings it read (fresh), against those
 * the kiosk started with and those it applied last: a bit
 * (1u << enum options_section) for each section whose devices must be
 * opened again. Says in the journal which settings wait for a restart. */
unsigned reload_reopen(const struct options *started, const struct options *applied,
		       const struct options *fresh);

#endif
