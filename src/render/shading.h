/* The shading modes, as the config file names them and the shaders select
 * them. The C mirror of the shader math, the reference of the accuracy
 * tests, is not part of the program: tests/oracle/oracle.h. */
#ifndef MK_SHADING_H
#define MK_SHADING_H

#include <stdbool.h>

enum shading_mode {
	SHADING_NORMAL,	      /* n.xy on the disk */
	SHADING_VIEW,	      /* view-corrected basis, as three.js and Blender */
	SHADING_SEM_VERTEX,   /* reflection mapped per vertex */
	SHADING_SEM_FRAGMENT, /* reflection mapped per fragment */
	SHADING_MODE_COUNT
};

const char *shading_mode_name(enum shading_mode mode);
/* Returns 0, or -EINVAL when name is not one of the modes. */
int shading_mode_parse(const char *name, enum shading_mode *out);
/* The macro that selects the mode in the shaders (defined to 1). */
const char *shading_mode_macro(enum shading_mode mode);

#define SHADING_LIT_AMBIENT  0.15 /* LIT_AMBIENT */
#define SHADING_LIT_SPECULAR 0.5  /* LIT_SPECULAR */

#endif
