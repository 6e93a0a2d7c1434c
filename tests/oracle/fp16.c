#include "fp16.h"

#include <math.h>

double fp16_round(double x)
{
	double a = fabs(x), quantum, r;
	int e;

	if (!isfinite(x) || a == 0.0)
		return x;
	/* a = m 2^e with m in [0.5, 1): 11 significant bits keep steps of
	 * 2^(e - 11); below the normal range the step stays 2^-24. */
	frexp(a, &e);
	quantum = ldexp(1.0, (e < -13 ? -13 : e) - 11);
	/* a / quantum is exact (a power of two apart); rint rounds ties to
	 * even in the default rounding mode. */
	r = rint(a / quantum) * quantum;
	if (r > FP16_MAX)
		r = INFINITY;
	return copysign(r, x);
}
