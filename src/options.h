/* The command line, parsed into a plain struct: no I/O but the messages. */
#ifndef MK_OPTIONS_H
#define MK_OPTIONS_H

#include "shading.h"

#include <stdio.h>

#include <stdbool.h>

enum backend_kind { BACKEND_AUTO, BACKEND_KMS, BACKEND_OSMESA, BACKEND_EGL_HEADLESS };

struct options {
	enum backend_kind backend;
	const char *model;  /* NULL: the built-in torus knot */
	const char *matcap; /* a file or a folder; NULL: the shipped folder */
	const char *output; /* PNG to write after the last frame */
	const char *shader_dir;
	int width, height;
	enum shading_mode mode;
	bool ortho;
	int frames;   /* frames to draw offscreen before writing */
	double yaw;   /* degrees, about the vertical axis */
	double pitch; /* degrees, about the horizontal axis */
	int rotation; /* of the panel */
	bool stats;
	int verbosity; /* 0 info, -1 quiet, 1 debug */
	bool help, version;
};

/* Fills opts from argv. Returns 0, or -EINVAL after printing one line that
 * names the option and what it accepts. */
int options_parse(struct options *opts, int argc, char **argv);
void options_usage(FILE *out);
const char *backend_name(enum backend_kind kind);

#endif
