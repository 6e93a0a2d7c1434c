/* Compiling the shader variants: each program holds only the features its
 * scene uses, chosen by #define lines put before the sources. */
#ifndef MK_SHADER_H
#define MK_SHADER_H

#include "render/gl.h"

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
	SHADER_ATTR_COUNT
};

/* Build a program from the vertex and fragment files, each preceded by
 * the #version line, the defines and mapping.glsl (and, for the fragment
 * stage, material.glsl). Returns 0 and the program, or -EINVAL after
 * printing the driver's log with file names. */
int shader_build(const struct gl *gl, const char *dir, const char *defines, GLuint *program);

#endif
