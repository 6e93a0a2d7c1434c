/* IEEE 754 binary16 ("half") rounding, to emulate the mediump floats of
 * SBC GPUs (Mali, Adreno, PowerVR run mediump as 16-bit) in the C mirror
 * of the shaders: every operation is computed exactly enough in double and
 * rounded here, as the GPU rounds its own result. */
#ifndef MK_FP16_H
#define MK_FP16_H

#define FP16_MAX	   65504.0		  /* the largest finite value */
#define FP16_MIN_NORMAL	   6.103515625e-05	  /* 2^-14 */
#define FP16_MIN_SUBNORMAL 5.9604644775390625e-08 /* 2^-24 */
#define FP16_EPSILON	   9.765625e-04		  /* 2^-10: the spacing just above 1 */

/* x rounded to the nearest binary16 value, ties to even, with gradual
 * underflow (subnormals down to 2^-24) and overflow to +-infinity at
 * 65520; NaN, infinities and signed zeros pass through. */
double fp16_round(double x);

#endif
