/* A model's own settings: NAME.ini beside NAME.glb (or NAME.gltf) holds
 * the keys that make sense per model ([frame], [material], some of
 * [scene] with its matcaps, and [display] background), read over
 * kiosk.ini's while that model is shown. One table (model_settings.c)
 * says which keys those are. The one precedence: the command line over
 * NAME.ini over the drop-ins over kiosk.ini. */
#ifndef MK_MODEL_SETTINGS_H
#define MK_MODEL_SETTINGS_H

#include "config/options.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Whether a model's own file may hold [section] key. */
bool model_settings_allowed(const char *section, const char *key);
/* The settings file of the model at model: NAME.ini; false when model
 * has no .glb or .gltf name, or out is too small. */
bool model_settings_path(const char *model, char *out, size_t n);
/* Read model's NAME.ini, where there is one, over c. OPTIONS_OK (none
 * there counts), or OPTIONS_CONFIG after logging every error with its
 * file and line (c is then left as it was). */
enum options_status model_settings_read(struct content_config *c, const char *model);
/* The same for a USB stick's model: its paths held to a stick's rules
 * (relative, inside its folder, without ".."). */
enum options_status model_settings_read_stick(struct content_config *c, const char *model);
/* Either, saying on out each setting the file holds, its value and line,
 * or that the command line's value is in effect over it. */
enum options_status model_settings_read_listed(struct content_config *c, const char *model,
					       bool stick, FILE *out);

#endif
