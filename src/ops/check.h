/* --check-config: the settings as the kiosk reads them, then every file
 * they name loaded the way the kiosk loads it, so that "valid" means the
 * kiosk starts with no stand-in (knot, clay matcap, background). */
#ifndef MK_CHECK_H
#define MK_CHECK_H

#include "config/exit_codes.h"
#include "config/settings.h"

#include <stdio.h>

/* The exit status: 0 valid; CHECK_BAD_SETTINGS (78, EX_CONFIG) for a
 * settings error (an included file with errors too); CHECK_BAD_FILE (66,
 * EX_NOINPUT) when the settings are right but a file they name is missing
 * or does not load. Each problem, and a failed verdict, is logged (stderr)
 * with file, line and cause; the files read, where each value came from
 * and a "valid" verdict go to out. */
enum { CHECK_BAD_FILE = EXIT_CODE_NOINPUT, CHECK_BAD_SETTINGS = EXIT_CODE_CONFIG };
int check_config_run(const struct options *o, FILE *out);
/* Each model of cfg's [scene] model with a NAME.ini: that file read over
 * cfg, its errors logged with file and line; each one read is said on out
 * (NULL: not). stick: held to a USB stick's rules (--import). Returns
 * how many have errors. */
int check_model_settings(const struct content_config *cfg, FILE *out, bool stick);

#endif
