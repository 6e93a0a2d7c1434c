#include "scene/mesh/mesh.h"
#include "scene/mesh/tangent.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

/* Orthonormal and finite: unit tangent, normal to the unit normal, w = +-1. */
static void assert_frames(const struct mesh *m)
{
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		const float *t = m->tangents + v * 4, *n = m->normals + v * 3;
		double len = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
		double d = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];

		assert_true(isfinite(t[0]) && isfinite(t[1]) && isfinite(t[2]));
		assert_true(fabs(len - 1.0) < 1e-5);
		assert_true(fabs(d) < 1e-5);
		assert_true(t[3] == 1.0f || t[3] == -1.0f);
	}
}

static void make_mesh(struct mesh *m, const float *pos, const float *uv, uint32_t nv,
		      const uint32_t *idx, uint32_t ni)
{
	assert_int_equal(mesh_alloc(m, nv, ni, true), 0);
	memcpy(m->positions, pos, nv * 12);
	memcpy(m->uvs, uv, nv * 8);
	memcpy(m->indices, idx, ni * 4);
	for (uint32_t v = 0; v < nv; v++) {
		m->normals[v * 3] = 0;
		m->normals[v * 3 + 1] = 0;
		m->normals[v * 3 + 2] = 1;
	}
}

/* A quad in z = 0, x right and y up, UVs as an image seen from the front
 * (v down): tangent +x, bitangent +y, right-handed. */
static void quad_is_right_handed(void **state)
{
	static const float pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
	static const float uv[] = {0, 1, 1, 1, 1, 0, 0, 0};
	static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
	struct mesh m;

	(void)state;
	make_mesh(&m, pos, uv, 4, idx, 6);
	assert_int_equal(tangent_generate(&m), 0);
	assert_int_equal(m.vertex_count, 4);
	assert_frames(&m);
	for (int v = 0; v < 4; v++) {
		assert_true(fabs(m.tangents[v * 4] - 1.0) < 1e-6);
		assert_true(m.tangents[v * 4 + 3] == 1.0f);
	}
	mesh_release(&m);
}

/* Two quads share their middle column of vertices; the left one's UVs are
 * the right one's mirrored (u = |x|), as a symmetric model is unwrapped.
 * The shared vertices must be split, each side keeping its own frame. */
static void mirrored_uvs_split_the_seam(void **state)
{
	static const float pos[] = {-1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 1, 0, 0, 1, 0, 1, 1, 0};
	static const float uv[] = {1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0};
	static const uint32_t idx[] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
	struct mesh m;

	(void)state;
	make_mesh(&m, pos, uv, 6, idx, 12);
	assert_int_equal(tangent_generate(&m), 0);
	assert_int_equal(m.vertex_count, 8); /* vertices 1 and 4 have twins */
	assert_frames(&m);
	for (uint32_t t = 0; t < 4; t++)
		for (int k = 0; k < 3; k++) {
			const float *tan = m.tangents + m.indices[t * 3 + k] * 4;
			/* Left triangles: tangent -x, mirrored; right: +x. */
			float sx = t < 2 ? -1.0f : 1.0f;

			assert_true(fabs(tan[0] - sx) < 1e-6);
			assert_true(tan[3] == sx);
			/* The twin sits where its original does. */
			assert_true(m.positions[m.indices[t * 3 + k] * 3] ==
				    pos[idx[t * 3 + k] * 3]);
		}
	mesh_release(&m);
}

/* The same seam on a coloured mesh: the twins carry their originals'
 * colours, and the colour array has room for them (ASan reads past it
 * otherwise). */
static void mirrored_twins_keep_their_colours(void **state)
{
	static const float pos[] = {-1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 1, 0, 0, 1, 0, 1, 1, 0};
	static const float uv[] = {1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0};
	static const uint32_t idx[] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
	struct mesh m;

	(void)state;
	make_mesh(&m, pos, uv, 6, idx, 12);
	assert_int_equal(mesh_alloc_colors(&m), 0);
	for (uint32_t i = 0; i < 6 * 4; i++)
		m.colors[i] = (float)i / 32.0f;
	assert_int_equal(tangent_generate(&m), 0);
	assert_int_equal(m.vertex_count, 8);
	for (uint32_t t = 0; t < 4; t++)
		for (int k = 0; k < 3; k++) {
			const float *got = m.colors + m.indices[t * 3 + k] * 4;

			for (int c = 0; c < 4; c++)
				assert_true(got[c] == (float)(idx[t * 3 + k] * 4 + c) / 32.0f);
		}
	mesh_release(&m);
}

/* Zero-area triangles (collinear, collapsed to a point), collapsed UVs, a
 * NaN UV: every frame is still finite. */
static void degenerate_input_stays_finite(void **state)
{
	float pos[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 5, 5, 5, 0, 1, 0, 1, 1, 0, 9, 9, 9};
	float uv[] = {0, 0, 0.5f, 0, 1, 0, 0.3f, 0.3f, 0.2f, 0.2f, 0.2f, 0.2f, 0, 0};
	static const uint32_t idx[] = {0, 1, 2, 3, 3, 3, 0, 1, 5, 4, 5, 1, 1, 5, 4, 4, 6, 5};
	struct mesh m;

	(void)state;
	uv[13] = NAN;
	make_mesh(&m, pos, uv, 7, idx, 18);
	assert_int_equal(tangent_generate(&m), 0);
	assert_frames(&m);
	mesh_release(&m);
}

/* All at once, in one strip of three quads (x from -1 to 2, y 0 to 1): a
 * mirror seam at x = 0 (shared vertices, u = |x|), a wrapping UV seam at
 * x = 1 (split vertices, u back from 1 to 0), and two zero-area
 * triangles. Every frame finite and orthonormal; the mirror seam split
 * into two handednesses, the wrapping seam's copies sharing one frame. */
static void mirror_seam_wrap_seam_and_slivers(void **state)
{
	static const float pos[] = {-1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 1, 0, 0, 1, 0,
				    1,	1, 0, 1, 0, 0, 1, 1, 0, 2,  0, 0, 2, 1, 0};
	static const float uv[] = {1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 1, 0};
	static const uint32_t idx[] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4,
				       6, 8, 9, 6, 9, 7, 0, 1, 2, 4, 4, 4};
	struct mesh m;

	(void)state;
	make_mesh(&m, pos, uv, 10, idx, 24);
	assert_int_equal(tangent_generate(&m), 0);
	assert_frames(&m);
	assert_int_equal(m.vertex_count, 12); /* vertices 1 and 4 got twins */
	/* The wrapping seam: 2 | 6 and 5 | 7 are one point each, one frame. */
	assert_memory_equal(m.tangents + 2 * 4, m.tangents + 6 * 4, 16);
	assert_memory_equal(m.tangents + 5 * 4, m.tangents + 7 * 4, 16);
	assert_true(m.tangents[2 * 4] == 1.0f && m.tangents[2 * 4 + 3] == 1.0f);
	/* The mirror seam: its two copies face opposite ways. */
	assert_true(m.tangents[1 * 4 + 3] * m.tangents[10 * 4 + 3] == -1.0f);
	assert_true(m.tangents[4 * 4 + 3] * m.tangents[11 * 4 + 3] == -1.0f);
	mesh_release(&m);
}

/* A fan round one shared apex, its u going all the way round: the
 * tangents of the faces cancel there, and the apex still gets a frame. */
static void shared_apex_gets_a_frame(void **state)
{
	enum { RING = 8 };
	float pos[(RING + 2) * 3], uv[(RING + 2) * 2];
	uint32_t idx[RING * 3];
	struct mesh m;

	(void)state;
	pos[0] = pos[1] = 0;
	pos[2] = 1;
	uv[0] = 0.5f;
	uv[1] = 0;
	for (int i = 0; i <= RING; i++) {
		double a = 2 * M_PI * i / RING;

		pos[(i + 1) * 3] = (float)cos(a);
		pos[(i + 1) * 3 + 1] = (float)sin(a);
		pos[(i + 1) * 3 + 2] = 0;
		uv[(i + 1) * 2] = (float)i / RING;
		uv[(i + 1) * 2 + 1] = 1;
	}
	for (int i = 0; i < RING; i++) {
		idx[i * 3] = 0;
		idx[i * 3 + 1] = (uint32_t)i + 1;
		idx[i * 3 + 2] = (uint32_t)i + 2;
	}
	make_mesh(&m, pos, uv, RING + 2, idx, RING * 3);
	assert_int_equal(tangent_generate(&m), 0);
	assert_frames(&m);
	mesh_release(&m);
}

/* On the built-in sphere (seam column duplicated, poles split per column)
 * the tangent is the analytic east direction, right-handed, and the same
 * on both copies of the seam. */
static void sphere_matches_analytic(void **state)
{
	struct mesh m;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&m, 32, 16), 0);
	assert_int_equal(tangent_generate(&m), 0);
	assert_frames(&m);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *p = m.positions + v * 3, *t = m.tangents + v * 4;
		double r = hypot(p[0], p[2]);
		/* East: the direction of growing u seen from outside. */
		double east[3] = {p[2] / r, 0, -p[0] / r};

		if (r < 0.2) /* near the poles the discrete frame turns fast */
			continue;
		assert_true(east[0] * t[0] + east[2] * t[2] > cos(3.0 * M_PI / 180));
		assert_true(t[3] == 1.0f);
	}
	/* The seam's two columns (u = 1 and u = 0) share one frame. */
	for (uint32_t i = 0; i <= 16; i++)
		assert_memory_equal(m.tangents + i * 4, m.tangents + (32 * 17 + i) * 4, 16);
	mesh_release(&m);
}

static void orthonormalize_repairs_anything(void **state)
{
	struct mesh m;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&m, 8, 4), 0);
	assert_int_equal(mesh_alloc_tangents(&m), 0);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		float *t = m.tangents + v * 4;
		const float *n = m.normals + v * 3;

		switch (v % 4) {
		case 0: /* along the normal */
			memcpy(t, n, 12);
			break;
		case 1:
			t[0] = t[1] = t[2] = 0;
			break;
		case 2:
			t[0] = NAN, t[1] = 1, t[2] = INFINITY;
			break;
		default:
			t[0] = 3, t[1] = -2, t[2] = 1;
		}
		t[3] = v % 2 ? -0.5f : 7.0f;
	}
	tangent_orthonormalize(&m);
	assert_frames(&m);
	for (uint32_t v = 0; v < m.vertex_count; v++)
		assert_true(m.tangents[v * 4 + 3] == (v % 2 ? -1.0f : 1.0f));
	mesh_release(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(quad_is_right_handed),
	    cmocka_unit_test(mirrored_uvs_split_the_seam),
	    cmocka_unit_test(mirrored_twins_keep_their_colours),
	    cmocka_unit_test(degenerate_input_stays_finite),
	    cmocka_unit_test(mirror_seam_wrap_seam_and_slivers),
	    cmocka_unit_test(shared_apex_gets_a_frame),
	    cmocka_unit_test(sphere_matches_analytic),
	    cmocka_unit_test(orthonormalize_repairs_anything),
	};
	return cmocka_run_group_tests_name("tangent", tests, NULL, NULL);
}
