/* The hard cases of the shading math, numerically: the C mirror in float
 * (rounded as a GPU's binary32) against the mirror in double, and the
 * loader's double-precision fit against exact values. Every result must
 * be finite and within the bound stated beside its assertion. Binary16
 * (mediump) has its own file, test_fp16.c. */
#include "scene/gltf/gltf.h"
#include "gltf_write.h"
#include "scene/mesh/mesh.h"
#include "oracle/oracle.h"
#include "scene/mesh/tangent.h"

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

/* binary32 against double, in uv units: 1e-5 is 1/400 of a texel of a
 * 256 matcap, 1/100 of one of 1024. */
#define FLOAT_UV_BOUND 1e-5
/* |r + z| below this is the SEM singularity's neighbourhood, where the map
 * itself turns by any angle along the rim (see sem_singularity_...). */
#define SEM_BAND 0.03

static void normalize3(double v[3])
{
	double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);

	for (int k = 0; k < 3; k++)
		v[k] /= l;
}

static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
	out[0] = a[1] * b[2] - a[2] * b[1];
	out[1] = a[2] * b[0] - a[0] * b[2];
	out[2] = a[0] * b[1] - a[1] * b[0];
}

static double radius(const double uv[2])
{
	return hypot(uv[0] - 0.5, uv[1] - 0.5);
}

static double uv_distance(const double a[2], const double b[2])
{
	return hypot(a[0] - b[0], a[1] - b[1]);
}

/* The direction from the eye through a point of a 16:9 frame seen by the
 * renderer's camera (30 degrees vertically), i and j in [-1, 1] at the
 * frame's edges; beyond them for the margin the tests add. */
static void screen_eye(double i, double j, double e[3])
{
	double t = tan(15.0 * M_PI / 180.0);

	e[0] = i * t * 16.0 / 9.0;
	e[1] = j * t;
	e[2] = -1.0;
	normalize3(e);
}

/* |r + z| for r = reflect(e, n): 0 at the SEM singularity. */
static double sem_distance(const double n[3], const double e[3])
{
	double d = dot3(n, e), r[3];

	for (int k = 0; k < 3; k++)
		r[k] = e[k] - 2.0 * d * n[k];
	return sqrt(r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0) * (r[2] + 1.0));
}

/* A unit vector normal to v. */
static void perpendicular(const double v[3], double out[3])
{
	double a[3] = {fabs(v[0]) < 0.6 ? 1.0 : 0.0, fabs(v[0]) < 0.6 ? 0.0 : 1.0, 0.0};

	cross3(v, a, out);
	normalize3(out);
}

static void sem_in(int fp, const double n[3], const double e[3], double uv[2])
{
	if (fp < 0)
		shading_uv_sem(n, e, uv);
	else
		shading_uv_sem_f((enum shading_fp)fp, n, e, uv);
}

/* r = reflect(e, n) = (0,0,-1) where n = n* = normalize(e + z): the
 * seed's m = 2|r + z| is 0 there. As r -> -z, (r + z).z = 1 + r.z
 * shrinks as |r.xy|^2, so h = normalize(r + z) reaches the rim: the exact
 * radius is 0.5 sqrt(1 - |r + z|^2 / 4), within |r + z|^2 / 16 of 0.5.
 * The angle along the rim depends on the side n comes from (every rim
 * point stands for r = -z), so the bound is on the radius. Checked for
 * n* and 12 directions around it at 65 distances from 1 to 1e-16 and 0,
 * at 81 places on the screen, in every precision. */
static void sem_singularity_is_on_the_rim(void **state)
{
	double worst_far = 0.0, worst_rim = 0.0;

	(void)state;
	for (int fp = -1; fp < SHADING_FP_COUNT; fp++) {
		/* binary16 rounds h.xy and then uv to 11 bits: up to 0.0025
		 * (0.64 texel of 256) beyond the rim; the matcap is clamped. */
		double over = fp >= SHADING_FP16_HIGHP ? 0.0025 : 2e-7;

		for (int i = -4; i <= 4; i++)
			for (int j = -4; j <= 4; j++) {
				double e[3], ns[3], t1[3], t2[3];

				screen_eye(i / 4.0 * 1.1, j / 4.0 * 1.1, e);
				ns[0] = e[0], ns[1] = e[1], ns[2] = e[2] + 1.0;
				if (i == 0 && j == 0)
					ns[0] = 1.0, ns[2] = 0.0; /* e = -z: any n with n.z = 0 */
				normalize3(ns);
				perpendicular(ns, t1);
				cross3(ns, t1, t2);
				for (int a = 0; a < 12; a++)
					for (int k = 0; k <= 64; k++) {
						double t = k == 64 ? 0.0 : pow(10.0, -k / 4.0);
						double c = cos(a * M_PI / 6) * t,
						       s = sin(a * M_PI / 6) * t;
						double n[3], uv[2], exact[2], l;

						for (int q = 0; q < 3; q++)
							n[q] = ns[q] + c * t1[q] + s * t2[q];
						normalize3(n);
						if (dot3(n, e) > 0.0)
							continue; /* a back face: culled */
						sem_in(fp, n, e, uv);
						shading_uv_sem(n, e, exact);
						assert_true(isfinite(uv[0]) && isfinite(uv[1]));
						assert_true(radius(uv) <= 0.5 + over);
						l = sem_distance(n, e);
						if (l < SEM_BAND) {
							/* On the rim, as the limit is. */
							double rim = 0.5 - l * l / 16.0 - over;

							assert_true(radius(uv) >= rim);
							worst_rim =
							    fmax(worst_rim, 0.5 - radius(uv));
						} else if (fp == SHADING_FP32) {
							double d = uv_distance(uv, exact);

							assert_true(d <= FLOAT_UV_BOUND);
							worst_far = fmax(worst_far, d);
						}
					}
			}
	}
	print_message("SEM: float within %.2g uv of double away from the singularity; every "
		      "precision within %.2g of the rim near it\n",
		      worst_far, worst_rim);
}

/* Surfaces seen edge-on: n.e = 0 exactly, and within 1e-16 .. 1e-1 of
 * it on both sides (the far side is culled, but interpolation reaches
 * it). Every mode stays on its disk, and float follows double. */
static void grazing_normals_stay_on_the_disk(void **state)
{
	double worst = 0.0;

	(void)state;
	for (int i = -4; i <= 4; i++)
		for (int j = -4; j <= 4; j++)
			for (int a = 0; a < 24; a++)
				for (int k = -1; k <= 64; k++) {
					double e[3], t1[3], t2[3], n[3], uv[2], uvf[2];
					double t =
					    k < 0 ? 0.0 : pow(10.0, -k / 4.0) * (k % 2 ? -1 : 1);

					screen_eye(i / 4.0, j / 4.0, e);
					perpendicular(e, t1);
					cross3(e, t1, t2);
					for (int q = 0; q < 3; q++)
						n[q] = cos(a * M_PI / 12) * t1[q] +
						       sin(a * M_PI / 12) * t2[q] - t * e[q];
					normalize3(n);
					for (int mode = 0; mode < 3; mode++) {
						double limit = mode == 1 ? 0.495 : 0.5;

						if (mode == 0) {
							shading_uv_normal(n, uv);
							shading_uv_normal_f(SHADING_FP32, n, uvf);
						} else if (mode == 1) {
							shading_uv_view(n, e, uv);
							shading_uv_view_f(SHADING_FP32, n, e, uvf);
						} else {
							shading_uv_sem(n, e, uv);
							shading_uv_sem_f(SHADING_FP32, n, e, uvf);
						}
						assert_true(isfinite(uvf[0]) && isfinite(uvf[1]));
						assert_true(radius(uv) <= limit + 1e-12);
						assert_true(radius(uvf) <= limit + 2e-7);
						if (mode == 2 && sem_distance(n, e) < SEM_BAND)
							continue;
						assert_true(uv_distance(uv, uvf) <= FLOAT_UV_BOUND);
						worst = fmax(worst, uv_distance(uv, uvf));
					}
				}
	print_message("grazing: float within %.2g uv of double\n", worst);
}

/* An interpolated normal can shrink to nothing (opposed vertex normals)
 * or arrive denormal. safe_normalize gives a unit vector, or (0,0,1)
 * where |v|^2 <= 1e-6, in both precisions alike; never NaN. */
static void zero_and_denormal_normals(void **state)
{
	static const double lengths[] = {0.0,	  4.9e-324, 1e-300, 1.4e-45, FLT_MIN, 1e-20,
					 9.99e-4, 1.001e-3, 1e-2,   1.0,     1e3,     1e18};

	(void)state;
	for (size_t i = 0; i < sizeof(lengths) / sizeof(lengths[0]); i++)
		for (int a = 0; a < 16; a++) {
			double dir[3] = {cos(a * 0.7) * sin(a * 0.3 + 0.1),
					 sin(a * 0.7) * sin(a * 0.3 + 0.1), cos(a * 0.3 + 0.1)};
			double v[3], out[3], outf[3], uv[2], e[3] = {0, 0, -1};

			for (int k = 0; k < 3; k++)
				v[k] = dir[k] * lengths[i];
			shading_safe_normalize(v, out);
			shading_safe_normalize_f(SHADING_FP32, v, outf);
			for (int k = 0; k < 3; k++) {
				assert_true(isfinite(out[k]) && isfinite(outf[k]));
				if (lengths[i] * lengths[i] <= 0.99e-6) {
					assert_true(out[k] == (k == 2) && outf[k] == (k == 2));
				} else if (lengths[i] * lengths[i] > 1.01e-6) {
					assert_true(fabs(out[k] - dir[k]) <= 1e-12);
					assert_true(fabs(outf[k] - dir[k]) <= 1e-6);
				}
			}
			shading_uv_sem_f(SHADING_FP32, outf, e, uv);
			assert_true(isfinite(uv[0]) && radius(uv) <= 0.5 + 1e-7);
		}
}

/* The tangent frame and the lit mode where their inputs degenerate: a
 * tangent along the normal, a map texel off the unit disk, the light
 * exactly opposite the eye (l - e = 0), a normal facing away. */
static void detail_and_lit_degenerate_inputs(void **state)
{
	double n[3] = {0, 0, 1}, along[4] = {0, 0, 1, 1}, zero[4] = {0, 0, 0, -1};
	double corners[4][2] = {{0, 0}, {1, 1}, {0.5, 0.5}, {1, 0}};
	double e[3] = {0, 0, -1}, base[3] = {0.8, 0.6, 0.4}, out[3], rgb[3];

	(void)state;
	for (int c = 0; c < 4; c++)
		for (int fp = -1; fp < SHADING_FP_COUNT; fp++) {
			if (fp < 0)
				shading_detail_normal(n, c % 2 ? along : zero, corners[c], out);
			else
				shading_detail_normal_f((enum shading_fp)fp, n,
							c % 2 ? along : zero, corners[c], out);
			assert_true(fabs(dot3(out, out) - 1.0) < 2e-3);
		}
	for (int fp = -1; fp < SHADING_FP_COUNT; fp++) {
		/* l = e: h = safe_normalize(l - e) has nothing to normalize. */
		double l[3] = {0, 0, -1}, away[3] = {0, 0, -1};

		if (fp < 0)
			shading_blinn_phong(n, e, l, base, 48, rgb);
		else
			shading_blinn_phong_f((enum shading_fp)fp, n, e, l, base, 256, rgb);
		for (int k = 0; k < 3; k++)
			assert_true(fabs(rgb[k] - base[k] * SHADING_LIT_AMBIENT) < 1e-3);
		/* Lit from behind, facing away: pow(0, s) = 0, no NaN. */
		if (fp < 0)
			shading_blinn_phong(away, e, l, base, 48, rgb);
		else
			shading_blinn_phong_f((enum shading_fp)fp, away, e, l, base, 48, rgb);
		for (int k = 0; k < 3; k++)
			assert_true(fabs(rgb[k] - base[k]) < 2e-3);
	}
}

/* HSV is periodic in the hue: negative hues and hues of many turns give
 * the colour of their fraction, in [0, v], and float follows double to
 * 2e-6 per turn of magnitude (hues reach about 2 turns from glTF). */
static void hue_wraps_around(void **state)
{
	(void)state;
	for (int i = 0; i <= 1000; i++) {
		double h = i / 1000.0, base[3];

		shading_hsv_to_rgb(h, 0.7, 0.8, base);
		for (int turns = -5; turns <= 5; turns++) {
			double rgb[3], rgbf[3], hh = h + turns;

			shading_hsv_to_rgb(hh, 0.7, 0.8, rgb);
			shading_hsv_to_rgb_f(SHADING_FP32, hh, 0.7, 0.8, rgbf);
			for (int k = 0; k < 3; k++) {
				assert_true(fabs(rgb[k] - base[k]) <= 1e-12);
				assert_true(rgb[k] >= 0.0 && rgb[k] <= 0.8 + 1e-12);
				assert_true(fabs(rgbf[k] - rgb[k]) <= 2e-6 * (1 + fabs(hh)));
			}
		}
	}
	/* The hue formula itself, at its ends: n.e = +-1 (facing), 0 (edge). */
	assert_true(shading_iridescence_hue(-1.0, 0.4, -0.7, 0.2, 1.0) == -0.7);
	assert_true(fabs(shading_iridescence_hue(0.0, 0.4, 2.5, 0.2, 0.0) - 2.7) < 1e-15);
	assert_true(fabs(shading_iridescence_hue_f(SHADING_FP32, 0.0, 0.4, 2.5, 0.2, 0.0) - 2.7) <
		    1e-6);
}

/* Zero-area (collinear, coincident) and needle (1e-7 wide) triangles:
 * generated normals and tangents stay finite and unit length, and the
 * needle's normal is its plane's. */
static void degenerate_triangles(void **state)
{
	static const float pos[] = {
	    0, 0, 0, 1, 0, 0, 2,    0,	   0, /* collinear */
	    5, 5, 5, 5, 5, 5, 5,    5,	   5, /* one point, three times */
	    0, 0, 1, 1, 0, 1, 0.5f, 1e-7f, 1, /* a needle in the z = 1 plane */
	};
	static const float uvs[] = {0, 0, 1, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0.5f, 1e-7f};
	struct mesh m;

	(void)state;
	assert_int_equal(mesh_alloc(&m, 9, 9, true), 0);
	memcpy(m.positions, pos, sizeof(pos));
	memcpy(m.uvs, uvs, sizeof(uvs));
	for (uint32_t i = 0; i < 9; i++)
		m.indices[i] = i;
	assert_int_equal(mesh_generate_normals(m.positions, m.indices, 9, 0, 9, m.normals), 0);
	assert_int_equal(tangent_generate(&m), 0);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *n = m.normals + v * 3, *t = m.tangents + v * 4;

		for (int k = 0; k < 3; k++)
			assert_true(isfinite(n[k]) && isfinite(t[k]));
		assert_true(fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-6);
		assert_true(fabs(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] - 1.0) < 1e-5);
		assert_true(fabs(n[0] * t[0] + n[1] * t[1] + n[2] * t[2]) < 1e-5);
	}
	for (uint32_t v = 6; v < 9; v++)
		assert_true(m.normals[v * 3 + 2] > 0.999999f);
	mesh_release(&m);
}

struct loader {
	char dir[64];
	struct mesh sphere;
};

static int loader_setup(void **state)
{
	struct loader *f = calloc(1, sizeof(*f));

	strcpy(f->dir, "/tmp/mk-stability-XXXXXX");
	if (!f || !mkdtemp(f->dir) || mesh_uv_sphere(&f->sphere, 24, 12))
		return -1;
	*state = f;
	return 0;
}

static int loader_teardown(void **state)
{
	struct loader *f = *state;
	char cmd[128];

	snprintf(cmd, sizeof(cmd), "rm -rf %s", f->dir);
	mesh_release(&f->sphere);
	free(f);
	return system(cmd);
}

static void load_with_node(struct loader *f, const char *node, struct mesh *out)
{
	struct gltf_write_opts o = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	char path[128];

	o.node = node;
	snprintf(path, sizeof(path), "%s/m.glb", f->dir);
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
	assert_int_equal(gltf_load(path, out), 0);
}

/* What a double holds of a model of size `scale` placed `offset` away, in
 * units of the fitted model: its own rounding, a few ulps of the offset. */
static double placement_bound(double offset, double scale)
{
	return 5e-7 + 4.0 * DBL_EPSILON * fabs(offset) / scale;
}

/* A unit sphere placed 1e5 units away, scaled by 1e-6 or 1e6, or both:
 * the loader transforms and fits in double, so the fitted sphere is the
 * original to binary32's rounding (6e-8; bound 5e-7) in position and
 * normal, plus what double itself cannot hold: a 1e-6 model at 1e5 keeps
 * 1e-5 of its size (the bound allows 9e-5). In float, 1e5 + 1e-6 is 1e5:
 * that model would collapse to a point. */
static void far_and_scaled_models(void **state)
{
	static const struct {
		const char *node;
		double offset, scale;
	} cases[] = {
	    {"\"translation\":[100000,100000,-100000]", 1e5, 1.0},
	    {"\"scale\":[1e-6,1e-6,1e-6]", 0.0, 1e-6},
	    {"\"scale\":[1e6,1e6,1e6]", 0.0, 1e6},
	    {"\"translation\":[100000,0,0],\"scale\":[1e-6,1e-6,1e-6]", 1e5, 1e-6},
	    {"\"translation\":[-1e7,0,3e6],\"scale\":[1e6,1e6,1e6]", 1e7, 1e6},
	};
	struct loader *f = *state;

	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		struct mesh m;
		double worst = 0.0, worst_normal = 0.0;

		load_with_node(f, cases[i].node, &m);
		assert_int_equal(m.vertex_count, f->sphere.vertex_count);
		for (uint32_t k = 0; k < m.vertex_count * 3; k++) {
			assert_true(isfinite(m.positions[k]) && isfinite(m.normals[k]));
			worst = fmax(worst, fabs(m.positions[k] - f->sphere.positions[k]));
			worst_normal =
			    fmax(worst_normal, fabs(m.normals[k] - f->sphere.normals[k]));
		}
		assert_true(worst <= placement_bound(cases[i].offset, cases[i].scale));
		assert_true(worst_normal <= 5e-7);
		print_message("%s: positions within %.2g, normals %.2g\n", cases[i].node, worst,
			      worst_normal);
		mesh_release(&m);
	}
}

/* mesh_fit_positions on its own, at offsets and scales beyond any float,
 * within what the double input holds (placement_bound). */
static void fit_in_double(void **state)
{
	static const double scales[] = {1e-6, 1.0, 1e6}, offsets[] = {0.0, 1e5, -1e7};
	struct loader *f = *state;
	uint32_t n = f->sphere.vertex_count;
	double *world = malloc(n * 3 * sizeof(double));
	float *out = malloc(n * 3 * sizeof(float));

	assert_non_null(world);
	assert_non_null(out);
	for (int s = 0; s < 3; s++)
		for (int o = 0; o < 3; o++) {
			for (uint32_t k = 0; k < n * 3; k++)
				world[k] = f->sphere.positions[k] * scales[s] + offsets[o];
			mesh_fit_positions(world, n, out);
			for (uint32_t k = 0; k < n * 3; k++)
				assert_true(fabs(out[k] - f->sphere.positions[k]) <=
					    placement_bound(offsets[o], scales[s]));
		}
	free(world);
	free(out);
}

/* m^-T = cofactor matrix / det (column-major 3x3, m[col * 3 + row]). */
static void inverse_transpose(const double m[9], double out[9])
{
	double a = m[0], b = m[3], c = m[6], d = m[1], e = m[4], f = m[7], g = m[2], h = m[5],
	       i = m[8];
	double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
	/* C(row, col), stored column by column */
	double cof[9] = {e * i - f * h,	   -(b * i - c * h), b * f - c * e,
			 -(d * i - f * g), a * i - c * g,    -(a * f - c * d),
			 d * h - e * g,	   -(a * h - b * g), a * e - b * d};

	for (int k = 0; k < 9; k++)
		out[k] = cof[k] / det;
}

/* Non-uniform, mirrored (negative determinant) and sheared transforms: the
 * normals must be the ellipsoid's, m^-T n, and point out, to 1e-5. */
static void normals_follow_the_inverse_transpose(void **state)
{
	static const struct {
		const char *node;
		double m[9]; /* column-major */
	} cases[] = {
	    {"\"scale\":[3,0.5,1]", {3, 0, 0, 0, 0.5, 0, 0, 0, 1}},
	    {"\"scale\":[-1,1,1]", {-1, 0, 0, 0, 1, 0, 0, 0, 1}},
	    {"\"scale\":[-2,-0.25,4]", {-2, 0, 0, 0, -0.25, 0, 0, 0, 4}},
	    {"\"matrix\":[1,0,0,0, 1.5,1,0,0, 0,0,-0.5,0, 10,20,30,1]",
	     {1, 0, 0, 1.5, 1, 0, 0, 0, -0.5}},
	    {"\"matrix\":[0,2,0,0, -1,0,0,0, 0,0,1e-3,0, 0,0,0,1]",
	     {0, 2, 0, -1, 0, 0, 0, 0, 1e-3}},
	};
	struct loader *f = *state;

	for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
		double it[9];
		struct mesh m;

		inverse_transpose(cases[c].m, it);
		load_with_node(f, cases[c].node, &m);
		for (uint32_t v = 0; v < m.vertex_count; v++) {
			const float *p = f->sphere.normals + v * 3, *n = m.normals + v * 3;
			const float *q = m.positions + v * 3;
			double want[3];

			for (int r = 0; r < 3; r++)
				want[r] = it[r] * p[0] + it[3 + r] * p[1] + it[6 + r] * p[2];
			normalize3(want);
			for (int k = 0; k < 3; k++)
				assert_true(fabs(n[k] - want[k]) <= 1e-5);
			/* Outward: the fitted ellipsoid is centred on the origin. */
			assert_true(n[0] * q[0] + n[1] * q[1] + n[2] * q[2] > 0.0);
		}
		mesh_release(&m);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(sem_singularity_is_on_the_rim),
	    cmocka_unit_test(grazing_normals_stay_on_the_disk),
	    cmocka_unit_test(zero_and_denormal_normals),
	    cmocka_unit_test(detail_and_lit_degenerate_inputs),
	    cmocka_unit_test(hue_wraps_around),
	    cmocka_unit_test(degenerate_triangles),
	    cmocka_unit_test(far_and_scaled_models),
	    cmocka_unit_test(fit_in_double),
	    cmocka_unit_test(normals_follow_the_inverse_transpose),
	};
	/* The loader cases share one folder and one sphere. */
	return cmocka_run_group_tests_name("stability", tests, loader_setup, loader_teardown);
}
