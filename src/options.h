/* Every setting, from the command line and from kiosk.ini. One table
 * (src/options.c) names each setting's option, its [section] key, its
 * type and range, and its help: the two sources cannot drift apart. */
#ifndef MK_OPTIONS_H
#define MK_OPTIONS_H

#include "shading.h"

#include <stdbool.h>
#include <stdio.h>

enum backend_kind { BACKEND_AUTO, BACKEND_KMS, BACKEND_OSMESA, BACKEND_EGL_HEADLESS };
enum verbosity { VERBOSITY_ERROR, VERBOSITY_WARNING, VERBOSITY_INFO, VERBOSITY_DEBUG };

/* Status of options_parse() besides 0. */
#define OPTIONS_USAGE   (-1000) /* a bad command line: exit 2 */
#define OPTIONS_CONFIG  (-1001) /* a bad config file: exit 78, EX_CONFIG */

struct options {
	/* [display] */
	int backend; /* enum backend_kind */
	int size[2]; /* offscreen width, height */
	int rotation;
	/* [scene] */
	char *model;  /* NULL: the built-in torus knot */
	char *matcap; /* a file or a folder; NULL: the shipped folder */
	int mode;     /* enum shading_mode */
	bool ortho;
	double yaw, pitch;
	/* [kiosk] */
	int log_level; /* enum verbosity */
	/* the command line only */
	char *config;
	char *output;
	char *shader_dir;
	int frames;
	bool stats;
	bool help, version;
};

/* Defaults, then the file named by --config, then the rest of the command
 * line over it. Returns 0, OPTIONS_USAGE or OPTIONS_CONFIG;
 * every error is one line naming the option, or the file, line and key,
 * and what is accepted. */
int options_parse(struct options *opts, int argc, char **argv);
/* Read one INI file over opts (used by options_parse and by reload). */
int options_read_file(struct options *opts, const char *path);
void options_release(struct options *opts);
void options_usage(FILE *out);
const char *backend_name(enum backend_kind kind);

#endif
