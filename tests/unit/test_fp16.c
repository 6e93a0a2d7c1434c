/* Half precision. Mali and Adreno GPUs run mediump in binary16; the C
 * mirror rounds every operation so (tests/oracle/fp16.c, SHADING_FP16_HIGHP and
 * SHADING_FP16) and is held against the mirror in double:
 *   - the matcap mappings stay within 3/4 of a texel of a 256 matcap at
 *     mediump (off the SEM singularity's neighbourhood, where
 *     test_stability.c bounds the radius), so the shaders leave them at
 *     mediump;
 *   - the lit mode's highlight and the iridescent hue do not (up to 52/255
 *     and 8/255 of colour): the shaders make them highp where the GPU has
 *     it (SHADE_P), and with that they stay within 1/255.
 * The second point is shown both ways: SHADING_FP16 (no highp) fails the
 * bound that SHADING_FP16_HIGHP passes. */
#include "oracle/fp16.h"
#include "oracle/oracle.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define TEXEL_256   (1.0 / 256.0)
#define UV_BOUND    (0.75 * TEXEL_256) /* the mappings at mediump */
#define COLOR_BOUND (1.0 / 255.0)      /* the highp values */

/* The binary16 value of a bit pattern (sign, 5-bit exponent, 10 bits). */
static double half_value(uint16_t bits)
{
	int e = (bits >> 10) & 31, m = bits & 1023;
	double v = e == 0    ? ldexp(m, -24)
		   : e == 31 ? (m ? NAN : INFINITY)
			     : ldexp(1024 + m, e - 25);

	return bits & 0x8000 ? -v : v;
}

/* Every finite binary16 value rounds to itself; every midpoint between
 * neighbours to the even one, and a hair off it to the nearer one. */
static void rounds_every_half_exactly(void **state)
{
	(void)state;
	for (uint32_t b = 0; b < 0x7c00; b++) {
		/* Above the largest finite value, the next step would be 2^16. */
		double v = half_value((uint16_t)b),
		       next = b + 1 < 0x7c00 ? half_value((uint16_t)(b + 1)) : 65536.0;
		double mid = (v + next) / 2.0, hair = (next - v) * 1e-6;
		double even = b % 2 ? next : v;

		assert_true(fp16_round(v) == v && fp16_round(-v) == -v);
		if (b + 1 == 0x7c00) /* that midpoint overflows */
			even = INFINITY;
		assert_true(fp16_round(mid) == even);
		assert_true(fp16_round(-mid) == -even);
		assert_true(fp16_round(mid - hair) == v);
		if (b + 1 < 0x7c00)
			assert_true(fp16_round(mid + hair) == next);
	}
}

static void rounds_the_edges(void **state)
{
	(void)state;
	/* Overflow: 65504 is the largest; from 65520 (the midpoint to 2^16) on, infinity. */
	assert_true(fp16_round(65519.99) == FP16_MAX);
	assert_true(isinf(fp16_round(65520.0)) && fp16_round(-65520.0) < 0);
	assert_true(isinf(fp16_round(1e300)));
	/* Gradual underflow: 2^-24 is the smallest; half of it ties to 0. */
	assert_true(fp16_round(FP16_MIN_SUBNORMAL) == FP16_MIN_SUBNORMAL);
	assert_true(fp16_round(FP16_MIN_SUBNORMAL / 2) == 0.0);
	assert_true(fp16_round(FP16_MIN_SUBNORMAL * 0.5000001) == FP16_MIN_SUBNORMAL);
	assert_true(fp16_round(FP16_MIN_SUBNORMAL * 1.5) == 2 * FP16_MIN_SUBNORMAL);
	assert_true(fp16_round(FP16_MIN_NORMAL * (1 - 1.0 / 2048)) == FP16_MIN_NORMAL);
	assert_true(fp16_round(1e-6) == 17 * FP16_MIN_SUBNORMAL);
	assert_true(fp16_round(1.0 + FP16_EPSILON / 2) == 1.0);
	assert_true(fp16_round(1.0 + FP16_EPSILON * 0.51) == 1.0 + FP16_EPSILON);
	/* Signs, infinities and NaN pass through. */
	assert_true(signbit(fp16_round(-0.0)) && fp16_round(-1e-30) == 0 &&
		    signbit(fp16_round(-1e-30)));
	assert_true(isinf(fp16_round(-INFINITY)) && isnan(fp16_round(NAN)));
}

#ifdef __FLT16_MAX__
/* The compiler's own conversion, where it has _Float16, agrees on random
 * doubles over the whole range. */
static void agrees_with_float16(void **state)
{
	uint64_t s = 88172645463325252ull;

	(void)state;
	for (int i = 0; i < 2000000; i++) {
		double x;

		s ^= s << 13, s ^= s >> 7, s ^= s << 17;
		x = ldexp((double)(s >> 11) / 9007199254740992.0, (int)(s % 48) - 30);
		x = s & (1ull << 10) ? -x : x;
		assert_true(fp16_round(x) == (double)(_Float16)x);
	}
}
#endif

static void normalize3(double v[3])
{
	double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);

	for (int k = 0; k < 3; k++)
		v[k] /= l;
}

/* A pixel of the fitted unit sphere seen by the renderer's camera (16:9,
 * 30 degrees): the varyings v_normal (shrunk as interpolation shrinks
 * it, by up to 5%) and v_eye (the view-space position). Returns false for
 * a point on the far side. */
static bool sphere_pixel(uint64_t *s, double normal[3], double eye[3])
{
	double dist = 1.08 / sin(15.0 * M_PI / 180.0), p[3], shrink;

	for (int k = 0; k < 3; k++) {
		*s ^= *s << 13, *s ^= *s >> 7, *s ^= *s << 17;
		p[k] = (double)(*s >> 11) / 4503599627370496.0 - 1.0;
	}
	normalize3(p);
	shrink = 0.95 + 0.05 * (double)(*s % 1000) / 1000.0;
	for (int k = 0; k < 3; k++)
		normal[k] = p[k] * shrink;
	eye[0] = p[0], eye[1] = p[1], eye[2] = p[2] - dist;
	return p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2] < 0.0;
}

/* The fragment's mapping: safe_normalize both varyings, then the mode. */
static void fragment_uv(int fp, int mode, const double normal[3], const double eye[3], double uv[2])
{
	double n[3], e[3];

	if (fp < 0) {
		shading_safe_normalize(normal, n);
		shading_safe_normalize(eye, e);
		if (mode == 0)
			shading_uv_normal(n, uv);
		else if (mode == 1)
			shading_uv_view(n, e, uv);
		else
			shading_uv_sem(n, e, uv);
		return;
	}
	shading_safe_normalize_f((enum shading_fp)fp, normal, n);
	shading_safe_normalize_f((enum shading_fp)fp, eye, e);
	if (mode == 0)
		shading_uv_normal_f((enum shading_fp)fp, n, uv);
	else if (mode == 1)
		shading_uv_view_f((enum shading_fp)fp, n, e, uv);
	else
		shading_uv_sem_f((enum shading_fp)fp, n, e, uv);
}

static double sem_distance(const double normal[3], const double eye[3])
{
	double n[3] = {normal[0], normal[1], normal[2]}, e[3] = {eye[0], eye[1], eye[2]}, d;

	normalize3(n);
	normalize3(e);
	d = n[0] * e[0] + n[1] * e[1] + n[2] * e[2];
	return hypot(hypot(e[0] - 2 * d * n[0], e[1] - 2 * d * n[1]), e[2] - 2 * d * n[2] + 1.0);
}

/* A pixel of a 600 x 600 grid over the sphere's disk at the frame's
 * centre, out to its rim, where normals graze. */
static bool grid_pixel(int i, double normal[3], double eye[3])
{
	double dist = 1.08 / sin(15.0 * M_PI / 180.0);
	double x = (i % 600 + 0.5) / 300.0 - 1.0, y = (i / 600 + 0.5) / 300.0 - 1.0;

	if (x * x + y * y >= 1.0)
		return false;
	normal[0] = x, normal[1] = y, normal[2] = sqrt(1.0 - x * x - y * y);
	eye[0] = x, eye[1] = y, eye[2] = normal[2] - dist;
	return true;
}

/* 400k random pixels of the sphere anywhere on the frame and the 280k of
 * a grid out to its rim, in each mode: the uv at mediump stays within 3/4
 * of a texel of a 256 matcap (3 texels of a 1024 one). The SEM
 * singularity's neighbourhood, where only the radius is defined, is
 * test_stability's. */
static void mappings_hold_at_mediump(void **state)
{
	const char *names[] = {"normal", "view", "sem"};

	(void)state;
	for (int fp = SHADING_FP16_HIGHP; fp <= SHADING_FP16; fp++)
		for (int mode = 0; mode < 3; mode++) {
			uint64_t s = 1234567;
			double worst = 0.0;

			for (int i = 0; i < 400000 + 360000; i++) {
				double normal[3], eye[3], uv[2], exact[2];
				bool on = i < 400000 ? sphere_pixel(&s, normal, eye)
						     : grid_pixel(i - 400000, normal, eye);

				if (!on || (mode == 2 && sem_distance(normal, eye) < 0.03))
					continue;
				fragment_uv(fp, mode, normal, eye, uv);
				fragment_uv(-1, mode, normal, eye, exact);
				worst = fmax(worst, hypot(uv[0] - exact[0], uv[1] - exact[1]));
			}
			print_message("%s, %s: %.2f texel of 256\n", shading_fp_name(fp),
				      names[mode], worst / TEXEL_256);
			assert_true(worst <= UV_BOUND);
		}
}

/* Interpolated normals shrink between opposed vertex normals. From
 * |v| = 2^-7 on, dot(v, v) is a normal binary16 number and the bound
 * holds; below it is subnormal (or flushed to 0 on some GPUs): the result
 * stays finite and on the disk, and at |v|^2 <= 1e-6 it is (0,0,1) as in
 * double. */
static void short_normals_at_mediump(void **state)
{
	double eye[3] = {0.3, -0.2, -4.0};

	(void)state;
	for (int k = 0; k <= 160; k++) {
		double len = pow(2.0, -k / 8.0);

		for (int a = 0; a < 32; a++) {
			double normal[3] = {cos(a * 0.4) * 0.6 * len, sin(a * 0.4) * 0.6 * len,
					    0.8 * len};
			double uv[2], exact[2];

			for (int mode = 0; mode < 3; mode++) {
				fragment_uv(SHADING_FP16_HIGHP, mode, normal, eye, uv);
				fragment_uv(-1, mode, normal, eye, exact);
				assert_true(isfinite(uv[0]) && isfinite(uv[1]));
				assert_true(hypot(uv[0] - 0.5, uv[1] - 0.5) <= 0.5025);
				if (len >= 1.0 / 128)
					assert_true(hypot(uv[0] - exact[0], uv[1] - exact[1]) <=
						    UV_BOUND);
			}
		}
	}
}

/* sem-vertex: computed in binary32 by the vertex stage, the uv reaches
 * the fragment as a mediump varying, rounded to 2^-12 on [0.5, 1). */
static void sem_vertex_varying(void **state)
{
	static const double mv[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -4.17, 1};
	static const double nm[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
	uint64_t s = 99;

	(void)state;
	for (int i = 0; i < 100000; i++) {
		double normal[3], eye[3], pos[3], v_eye[3], v_normal[3], uv[2], uvf[2], exact[2];

		if (!sphere_pixel(&s, normal, eye) || sem_distance(normal, eye) < 0.03)
			continue;
		pos[0] = eye[0], pos[1] = eye[1], pos[2] = eye[2] + 4.17;
		shading_vertex(mv, nm, false, pos, normal, v_eye, v_normal, exact);
		shading_vertex_f(SHADING_FP16_HIGHP, mv, nm, false, pos, normal, v_eye, v_normal,
				 uv);
		for (int k = 0; k < 2; k++)
			uvf[k] = fp16_round(uv[k]);
		assert_true(fabs(uvf[0] - exact[0]) <= 1.0 / 4096 + 1e-6);
		assert_true(fabs(uvf[1] - exact[1]) <= 1.0 / 4096 + 1e-6);
	}
}

static void constant_matcap(const void *texture, double u, double v, double rgba[4])
{
	(void)texture, (void)u, (void)v;
	rgba[0] = 0.2, rgba[1] = 0.4, rgba[2] = 0.6, rgba[3] = 1.0;
}

/* The worst colour error of fp against double over the sphere's pixels. */
static double worst_color(int fp, struct shading_fragment f)
{
	uint64_t s = 4242;
	double worst = 0.0;

	for (int i = 0; i < 100000; i++) {
		double rgb[3], exact[3];

		if (!sphere_pixel(&s, f.normal, f.eye))
			continue;
		shading_fragment(&f, exact);
		shading_fragment_f((enum shading_fp)fp, &f, rgb);
		for (int k = 0; k < 3; k++)
			worst = fmax(worst, fabs(rgb[k] - exact[k]));
	}
	return worst;
}

/* Hue range and average, shift: the defaults, what a glTF film of 400 nm
 * makes (two turns), a negative average (wrapping below 0) and a wide
 * range of several turns. Fully opaque, so the colour is the film's. */
static void iridescence_needs_highp(void **state)
{
	static const double hues[][3] = {
	    {0.4, 0.33, 0.2}, {-0.0559, 1.8909, 0.9455}, {0.4, -0.7, 0.2}, {2.5, 3.3, 0.2}};

	(void)state;
	for (size_t i = 0; i < sizeof(hues) / sizeof(hues[0]); i++) {
		struct shading_fragment f = {.mode = SHADING_VIEW,
					     .iridescence = true,
					     .hsv = {0.7, 0.8},
					     .sample = constant_matcap};
		double with, without;

		memcpy(f.iridescence_uniform, hues[i], sizeof(hues[i]));
		f.iridescence_uniform[3] = 1.0;
		with = worst_color(SHADING_FP16_HIGHP, f);
		without = worst_color(SHADING_FP16, f);
		print_message("hue range %g, average %g: %.2f/255 with highp, %.2f/255 without\n",
			      hues[i][0], hues[i][1], with * 255, without * 255);
		assert_true(with <= COLOR_BOUND);
		assert_true(worst_color(SHADING_FP32, f) <= 0.01 * COLOR_BOUND);
		/* Without highp the bound fails (the glTF film's case sits at it). */
		if (i != 1)
			assert_true(without > COLOR_BOUND);
	}
}

/* The lit mode: pow(n.h, shininess) multiplies n.h's error by the
 * exponent; the default shininess is 48. */
static void lit_needs_highp(void **state)
{
	(void)state;
	for (double shininess = 8; shininess <= 256; shininess *= 2) {
		struct shading_fragment f = {.mode = SHADING_VIEW,
					     .lit = true,
					     .light = {-0.5499, 0.6198, 0.5599},
					     .base_color = {0.8, 0.8, 0.8},
					     .shininess = shininess,
					     .sample = constant_matcap};
		double with = worst_color(SHADING_FP16_HIGHP, f),
		       without = worst_color(SHADING_FP16, f);

		print_message("shininess %g: %.2f/255 with highp, %.2f/255 without\n", shininess,
			      with * 255, without * 255);
		assert_true(with <= COLOR_BOUND);
		assert_true(without > 1.5 * COLOR_BOUND);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(rounds_every_half_exactly), cmocka_unit_test(rounds_the_edges),
#ifdef __FLT16_MAX__
	    cmocka_unit_test(agrees_with_float16),
#endif
	    cmocka_unit_test(mappings_hold_at_mediump),	 cmocka_unit_test(short_normals_at_mediump),
	    cmocka_unit_test(sem_vertex_varying),	 cmocka_unit_test(iridescence_needs_highp),
	    cmocka_unit_test(lit_needs_highp),
	};
	return cmocka_run_group_tests_name("fp16", tests, NULL, NULL);
}
