#include "scene/mesh/mesh.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

static void tri_normal(const struct mesh *m, uint32_t t, double n[3])
{
	const float *a = m->positions + m->indices[t] * 3,
		    *b = m->positions + m->indices[t + 1] * 3,
		    *c = m->positions + m->indices[t + 2] * 3;
	double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
	double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};

	n[0] = e1[1] * e2[2] - e1[2] * e2[1];
	n[1] = e1[2] * e2[0] - e1[0] * e2[2];
	n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

/* Front faces wind counter-clockwise seen from outside, and normals point
 * out: what back-face culling and the matcap both rely on. */
static void assert_outward(const struct mesh *m)
{
	for (uint32_t t = 0; t < m->index_count; t += 3) {
		double n[3], area;

		tri_normal(m, t, n);
		area = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		if (area < 1e-9)
			continue;
		const float *vn = m->normals + m->indices[t] * 3;
		assert_true((n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2]) / area > 0.5);
	}
}

static void sphere_is_unit_and_outward(void **state)
{
	struct mesh m;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&m, 32, 16), 0);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *p = m.positions + v * 3, *n = m.normals + v * 3;
		assert_true(fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1) < 1e-6);
		assert_true(p[0] * n[0] + p[1] * n[1] + p[2] * n[2] > 0.999);
	}
	assert_outward(&m);
	mesh_release(&m);
}

static void knot_fits_and_is_outward(void **state)
{
	struct mesh m;
	double r2max = 0;

	(void)state;
	assert_int_equal(mesh_torus_knot(&m, 64, 8), 0);
	assert_int_equal(m.index_count, 64 * 8 * 6);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *p = m.positions + v * 3;
		r2max = fmax(r2max, p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
	}
	assert_true(fabs(sqrt(r2max) - 1.0) < 1e-5);
	assert_outward(&m);
	mesh_release(&m);
}

/* A model far from the origin or at an extreme scale keeps its shape: the
 * fit is computed in double before anything is rounded to float. */
static void fit_survives_offsets_and_scales(void **state)
{
	/* (offset, scale): far away, tiny, huge, and both far and huge. */
	static const double cases[][2] = {{0, 1},    {1e5, 1}, {-3e7, 1},
					  {0, 1e-6}, {0, 1e6}, {1e5, 1e6}};
	static const double tetra[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
	/* Its corners lie sqrt(0.75) from the centre of its box. */
	double r = sqrt(0.75);
	float out[12];

	(void)state;
	for (int i = 0; i < 6; i++) {
		double w[12];

		for (int k = 0; k < 12; k++)
			w[k] = tetra[k] * cases[i][1] + cases[i][0];
		mesh_fit_positions(w, 4, out);
		assert_true(fabs(out[0] - (-0.5 / r)) < 1e-6);
		assert_true(fabs(out[3] - (0.5 / r)) < 1e-6);
		assert_true(fabs(out[7] - (0.5 / r)) < 1e-6);
	}
}

static void fit_degenerate_is_finite(void **state)
{
	double w[6] = {5, 5, 5, 5, 5, 5};
	float out[6];

	(void)state;
	mesh_fit_positions(w, 2, out);
	for (int k = 0; k < 6; k++)
		assert_true(out[k] == 0.0f);
}

static void generated_normals_weld_and_weight(void **state)
{
	/* Two triangles of a folded quad, with the shared edge duplicated
	 * (split vertices, as at a UV seam), plus a zero-area triangle. */
	float pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0,  /* tri A in z=0 */
		       1, 0, 0, 0, 1, 0, 1, 1, 1,  /* tri B, its own copies */
		       2, 2, 2, 2, 2, 2, 2, 2, 2}; /* zero area */
	uint32_t idx[] = {0, 1, 2, 3, 5, 4, 6, 7, 8};
	float nrm[27];

	(void)state;
	assert_int_equal(mesh_generate_normals(pos, idx, 9, 0, 9, nrm), 0);
	/* Vertex 1 and 3 share a position: same normal. */
	for (int k = 0; k < 3; k++)
		assert_true(nrm[1 * 3 + k] == nrm[3 * 3 + k]);
	for (int v = 0; v < 9; v++) {
		double l = sqrt(nrm[v * 3] * nrm[v * 3] + nrm[v * 3 + 1] * nrm[v * 3 + 1] +
				nrm[v * 3 + 2] * nrm[v * 3 + 2]);
		assert_true(isfinite(l) && fabs(l - 1) < 1e-6);
	}
	/* Vertex 0 belongs only to tri A, flat in z=0 and wound CCW. */
	assert_true(fabs(nrm[2] - 1.0) < 1e-6);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(sphere_is_unit_and_outward),
	    cmocka_unit_test(knot_fits_and_is_outward),
	    cmocka_unit_test(fit_survives_offsets_and_scales),
	    cmocka_unit_test(fit_degenerate_is_finite),
	    cmocka_unit_test(generated_normals_weld_and_weight),
	};
	return cmocka_run_group_tests_name("mesh", tests, NULL, NULL);
}
