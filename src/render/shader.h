/* The one shader builder: a program from a list of #defines and, per
 * stage, the files that follow them. The renderer's matcap programs and
 * the camera's conversion pass are both built here. */
#ifndef MK_SHADER_H
#define MK_SHADER_H

#include "render/gl.h"
#include "render/shading.h"

#include <stdbool.h>

/* Read a shader source: from dir when it is set (for development, so a
 * shader can be edited without a rebuild), else the built-in copy.
 * Returns a malloc'd string, or NULL after logging why. */
char *shader_read(const char *dir, const char *name);

/* The fixed attribute locations: the renderer enables only the arrays a
 * program reads. */
enum shader_attribute {
	SHADER_ATTR_POSITION,
	SHADER_ATTR_NORMAL,
	SHADER_ATTR_UV,
	SHADER_ATTR_TANGENT,
	SHADER_ATTR_COLOR,
	SHADER_ATTR_UV1, /* an emissive map's own UV set (EMISSIVE_UV1) */
	SHADER_ATTR_COUNT,
	/* A skinning program's (SKIN_BONES) bone indices and weights: after
	 * the mesh's arrays, bound only where a program skins. */
	SHADER_ATTR_JOINTS = SHADER_ATTR_COUNT,
	SHADER_ATTR_WEIGHTS,
	SHADER_ATTR_ALL
};
/* The locations a program may bind: a model's morph targets take the
 * ones its program leaves free (render_morph.c), below the GPU's
 * GL_MAX_VERTEX_ATTRIBS. */
#define SHADER_MAX_ATTRIBUTES 16

#define SHADER_MAX_DEFINES 16
#define SHADER_MAX_FILES   3

/* What a program is made of. Each stage's text is the #version line, the
 * precision statement (fragment stage only), "#define NAME 1" for each
 * define, then the stage's files in order, each after a #line that gives
 * it the next source number (1, 2, ...), so a driver's "2:40" reads as
 * line 40 of the stage's second file; the log names them. */
struct shader_source {
	const char *dir;       /* NULL: the built-in copies */
	const char *precision; /* NULL: the stage's default */
	const char *defines[SHADER_MAX_DEFINES];
	int define_count;
	const char *vertex[SHADER_MAX_FILES]; /* file names, up to the first NULL */
	const char *fragment[SHADER_MAX_FILES];
	const char *attributes[SHADER_MAX_ATTRIBUTES]; /* bound at their index; NULL: none */
	/* > 0: "#define SKIN_BONES bones", the skinning palette's size. */
	int bones;
	/* > 0: "#define MORPH_TARGETS morph_targets" (and MORPH_NORMALS 1
	 * where they move normals): the deltas shaders/morph.glsl adds. */
	int morph_targets;
	bool morph_normals;
};

/* Add "#define name 1". Returns 0, or -ENOSPC when the list is full. */
int shader_source_define(struct shader_source *s, const char *name);

/* The matcap program for these material features (enum material_feature),
 * mapping mode, camera and lit: sem-vertex becomes sem-fragment when a
 * feature needs the normal per fragment; highp makes every float of the
 * fragment stage highp where the GPU has it. Returns 0 or -ENOSPC. */
int shader_source_matcap(struct shader_source *s, const char *dir, unsigned features,
			 enum shading_mode mode, bool ortho, bool lit, bool highp);

/* Compile and link. Returns 0 with the program in *program, or -EINVAL
 * (-ENOMEM) after logging the driver's log once, naming the files; every
 * shader and program made on the way is deleted exactly once, and
 * *program is left as it was. */
int shader_program_build(const struct gl *gl, const struct shader_source *s, GLuint *program);

#endif
