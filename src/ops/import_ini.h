/* A USB stick's kiosk.ini as it goes into the content folder. */
#ifndef MK_IMPORT_INI_H
#define MK_IMPORT_INI_H

#include <stddef.h>

/* The stick's paths are relative to its matcap-kiosk/ folder; a relative
 * path in a settings file is read from that file's folder, and the import
 * puts the stick's files in model/ and its matcaps/ in matcaps/ beside
 * the kiosk.ini it writes. So each path of [scene] model, matcap and the
 * [material] maps gets model/ before it, but matcaps/...; every other
 * line, and the line count, stay as they were. *out: malloc'd. Returns 0
 * or -ENOMEM. */
int import_ini_rebase(const char *ini, size_t size, char **out, size_t *out_size);

#endif
