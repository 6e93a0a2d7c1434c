/* The shading modes, and the C mirror of the shader math (src/shading.c):
 * the reference that the accuracy and stability tests compare against. */
#ifndef MK_SHADING_H
#define MK_SHADING_H

enum shading_mode {
	SHADING_NORMAL,	      /* seed 000: n.xy on the disk */
	SHADING_VIEW,	      /* view-corrected basis, as three.js and Blender */
	SHADING_SEM_VERTEX,   /* seed 003, reflection mapped per vertex */
	SHADING_SEM_FRAGMENT, /* seed 003, per fragment */
	SHADING_MODE_COUNT
};

const char *shading_mode_name(enum shading_mode mode);
/* Returns 0, or -EINVAL when name is not one of the modes. */
int shading_mode_parse(const char *name, enum shading_mode *out);
/* The #define that selects the mode in the shaders. */
const char *shading_mode_define(enum shading_mode mode);

/* Mirrors of shaders/mapping.glsl, in double. n is a unit view-space
 * normal, e the unit direction from the eye to the point. */
void shading_uv_normal(const double n[3], double uv[2]);
void shading_uv_view(const double n[3], const double e[3], double uv[2]);
void shading_uv_sem(const double n[3], const double e[3], double uv[2]);

#endif
