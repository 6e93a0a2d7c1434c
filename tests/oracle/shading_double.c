/* The mirror in double: the reference. No rounding beyond double's own,
 * which is some 2^29 times finer than the binary32 of a GPU. */
#include "oracle.h"

typedef double real;
typedef enum { EXACT } prec;

#define MIRROR(name) name
#define FP_PARAM
#define FP_ARG
#define MEDIUMP		EXACT
#define HIGHP		EXACT
#define VERTEX		EXACT
#define SHADE_PRECISION EXACT
#define UV_PRECISION	EXACT
#define round_to(p, x)	((void)(p), (double)(x))

#include "shading_mirror.h"
