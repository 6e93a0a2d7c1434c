/* The settings table, shared by the two files that read settings
 * (src/app/options.c: the config file and the command line) and the one
 * that holds the table and what is done with one setting
 * (src/app/options_table.c). Not for other modules: they see struct
 * options and their own config structs only. */
#ifndef MK_OPTIONS_TABLE_H
#define MK_OPTIONS_TABLE_H

#include "app/options.h"

#include <stddef.h>

/* K_DEGREES: read in degrees, kept in radians. K_LEVEL: a log level by
 * its name. K_CHOICE: an index into choices, kept as an enum (or a bool
 * for a choice of two). */
enum option_kind { K_FLAG, K_STRING, K_INT, K_DOUBLE, K_DEGREES, K_SIZE, K_CHOICE, K_LEVEL };

/* The command line only: no [section] key. */
#define OPTION_CLI OPTIONS_SECTIONS

struct option_def {
	const char *name; /* --name */
	char short_name;
	enum options_section section; /* in kiosk.ini; OPTION_CLI: the command line only */
	const char *key;
	enum option_kind kind;
	size_t offset, size;
	double lo, hi, step; /* numbers: the accepted range (and step) */
	const char *const *choices;
	const char *arg;
	const char *help;
};

/* The table's length: the compiler refuses an entry more, and
 * tests/unit/test_options.c one less. */
#define OPTION_DEFS 68
extern const struct option_def option_defs[OPTION_DEFS];

void option_defaults(struct options *o);
/* What a setting accepts, for error messages and --help. */
void option_accepted(const struct option_def *d, char *buf, size_t n);
/* Store value; false when it is not one the setting accepts. */
bool option_set_value(struct options *o, const struct option_def *d, const char *value);

#endif
