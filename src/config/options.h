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

/* Who wrote a settings file decides what it may set. */
struct options_rules {
	/* The keys it may hold (NULL: any); another is an error naming who
	 * ("a USB stick") and allowed_text (what it takes). */
	bool (*allowed)(const char *section, const char *key);
	const char *allowed_text, *who;
	/* A stranger's file: every path it names relative, without "..", or
	 * inside the file's own folder. */
	bool stick_paths;
};

/* The installed files': any key, any path. */
extern const struct options_rules options_rules_admin;
/* A USB stick's kiosk.ini, and the include --import writes from it. */
extern const struct options_rules options_rules_stick;

/* One file alone (no drop-ins, no include) under rules: a settings file
 * (a plain file, at most 1 MiB, that only its owner may write), relative
 * paths taken from its folder. */
enum options_status options_read_one(struct options *opts, const char *path,
				     const struct options_rules *rules);
/* Text already in memory, relative paths from dir (NULL: as written). */
enum options_status options_read_text(struct options *opts, const char *path, const char *dir,
				      const char *text, size_t size,
				      const struct options_rules *rules);
/* Two of the [buttons] on one line: the first such pair (kiosk.ini's
 * check and the command line's). */
bool options_buttons_clash(const struct options *opts, int *first, int *second);
void options_usage(FILE *out);

#endif
