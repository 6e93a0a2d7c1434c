/* The mirror in float, rounded as a GPU rounds: binary32 for highp and
 * for everything on a GPU whose mediump is 32-bit, binary16 for mediump
 * where the GPU has 16-bit floats (enum shading_fp). Values are kept in
 * float, which holds every binary16 value exactly; each operation is
 * computed in double and rounded once, which gives the correctly rounded
 * binary32 or binary16 result (double has more than twice their bits). */
#include "fp16.h"
#include "oracle.h"

typedef float real;
typedef enum { BINARY32, BINARY16 } prec;

static real round_to(prec p, double x)
{
	return p == BINARY16 ? (float)fp16_round(x) : (float)x;
}

#define MIRROR(name) name##_f
#define FP_PARAM     enum shading_fp fp,
#define FP_ARG	     fp,
/* A value declared mediump, or highp, in the fragment shader. */
#define MEDIUMP (fp == SHADING_FP32 ? BINARY32 : BINARY16)
#define HIGHP	(fp == SHADING_FP16 ? BINARY16 : BINARY32)
/* Every GLES2 GPU runs the vertex stage in binary32, whatever fp says. */
#define VERTEX ((void)fp, BINARY32)
/* The values that the shaders declare highp (where the GPU has it). */
#define SHADE_PRECISION HIGHP
#define UV_PRECISION	HIGHP

#include "shading_mirror.h"

const char *shading_fp_name(enum shading_fp fp)
{
	static const char *const names[SHADING_FP_COUNT] = {"fp32", "fp16+highp", "fp16"};

	return fp < SHADING_FP_COUNT ? names[fp] : "?";
}
