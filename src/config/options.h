/* Reading the settings: the command line and kiosk.ini, through the
 * table of src/config/settings.h, into struct options. */
#ifndef MK_OPTIONS_H
#define MK_OPTIONS_H

#include "config/settings.h"

#include <stdbool.h>
#include <stdio.h>

enum options_status {
	OPTIONS_OK,
	OPTIONS_USAGE,	/* a bad command line: exit 2 */
	OPTIONS_CONFIG, /* a bad config file: exit 78, EX_CONFIG */
};

/* Defaults, then the file named by --config, then the rest of the command
 * line over it. Every error is one line naming the option, or the file,
 * line and key, and what is accepted. opts is to be released whatever
 * the status. */
enum options_status options_parse(struct options *opts, int argc, char **argv);
/* Read an INI file over opts: the file, its drop-ins (PATH.d/ *.ini in
 * name order) and its include. A relative path in a file is taken from
 * that file's folder. */
enum options_status options_read_file(struct options *opts, const char *path);
/* The same without the include: what is installed. */
enum options_status options_read_installed(struct options *opts, const char *path);
/* The same from memory (for the fuzzer); name is used in messages only. */
enum options_status options_read_memory(struct options *opts, const char *name, const char *text,
					size_t size);
/* One stream (no drop-ins, no include), relative paths from dir (NULL:
 * as written), taking only the keys allowed(section, key) accepts (NULL:
 * all); another is an error naming allowed_text. */
enum options_status options_read_stream(struct options *opts, const char *path, const char *dir,
					FILE *f,
					bool (*allowed)(const char *section, const char *key),
					const char *allowed_text);
void options_usage(FILE *out);

#endif
