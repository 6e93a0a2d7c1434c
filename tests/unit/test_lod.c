/* The level of detail that the display can show (src/scene/mesh/lod.c): the error
 * budget follows the display, the simplified surface stays within it, UV
 * seams and attributes survive, and the normals' error is measured. */
#include "scene/mesh/lod.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/tangent.h"
#include "util/math3d.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "lod_fixture.h"

/* The budget is pixels on this display: a larger display keeps more
 * triangles of the same model (all of them, once its triangles are
 * larger than the budget), and none is ever added. */
static void follows_the_display(void **state)
{
	static const int sizes[][2] = {
	    {160, 90}, {320, 240}, {640, 360}, {1280, 720}, {3840, 2160}};
	uint32_t last = 0;
	struct mesh knot;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 256, 32), 0);
	for (int i = 0; i < 5; i++) {
		struct mesh m;
		struct lod_result r;
		double wanted = lod_triangles_wanted(&knot, 2.0, sizes[i][0], sizes[i][1]);

		copy_mesh(&knot, &m);
		assert_int_equal(lod_prepare_mesh(&m, 2.0, sizes[i][0], sizes[i][1], &r), 0);
		print_message("%dx%d: %u of %u triangles (%.0f wanted), %.2f px\n", sizes[i][0],
			      sizes[i][1], r.triangles_after, r.triangles_before, wanted,
			      r.error_pixels);
		assert_true(r.triangles_after >= last && r.triangles_after <= r.triangles_before);
		assert_true(r.error_pixels <= 2.0);
		/* Down to what is wanted, unless the error stops it first. */
		if (wanted >= r.triangles_before)
			assert_int_equal(r.triangles_after, r.triangles_before);
		else
			assert_true(r.triangles_after >= 0.9 * wanted);
		last = r.triangles_after;
		mesh_release(&m);
	}
	assert_true(last == knot.index_count / 3);
	/* 1 px at 1280x720 is this many model units (render.c's camera). */
	assert_true(fabs(lod_model_error(1.0, 1280, 720) * sphere_fit_pixels_per_unit(1280, 720) -
			 1.0) < 1e-12);
	/* Triangles of 1 px: a unit sphere (area 4 pi) at 1280x720 wants
	 * 4 pi ppu^2 / 2 of them. */
	{
		struct mesh s;
		double ppu = sphere_fit_pixels_per_unit(1280, 720);

		assert_int_equal(mesh_uv_sphere(&s, 256, 128), 0);
		assert_true(fabs(lod_triangles_wanted(&s, 1.0, 1280, 720) / (2 * M_PI * ppu * ppu) -
				 1.0) < 1e-3);
		mesh_release(&s);
	}
	mesh_release(&knot);
}

/* The simplified knot stays near the original: every original vertex
 * within 1.8 times the budget of the new surface (meshoptimizer's error
 * is an estimate), and the new surface's interpolated normal there, what
 * shading sees, within 2 degrees per pixel of budget on average and 15 at
 * most (measured at 160x90: 1.9 mean and 21 max at 2 px, 7.0 and 49 at 4
 * px; none simplified at 0.5 and 1, whose triangles are already larger).
 * The bench measures what that does to the image. */
static void surface_and_normals_within_bounds(void **state)
{
	static const double budgets[] = {0.5, 1.0, 2.0, 4.0};
	struct mesh knot;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 128, 16), 0);
	for (int i = 0; i < 4; i++) {
		struct mesh m;
		struct lod_result r;
		struct surface_error e;
		double unit = lod_model_error(1.0, 160, 90);

		copy_mesh(&knot, &m);
		assert_int_equal(lod_prepare_mesh(&m, budgets[i], 160, 90, &r), 0);
		e = measure(&knot, &m);
		print_message("%.1f px at 160x90: %u of %u triangles, farthest vertex %.2f px, "
			      "normals %.1f deg mean, %.1f max\n",
			      budgets[i], r.triangles_after, r.triangles_before, e.distance / unit,
			      e.normal_mean, e.normal_max);
		assert_true(e.distance <= 1.8 * budgets[i] * unit);
		assert_true(e.normal_mean <= 2.0 * budgets[i]);
		assert_true(e.normal_max <= 15.0 * budgets[i]);
		mesh_release(&m);
	}
	mesh_release(&knot);
}

/* Creases and UV seams everywhere no longer stop the simplifier: it
 * reaches the count wanted, within the error budget, and no triangle
 * spans the knot's UV seam (|du| < 0.5). */
static void creases_do_not_stop_it(void **state)
{
	struct mesh knot, flat, m;
	struct lod_result r;
	double unit = lod_model_error(1.0, 160, 90);

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 128, 16), 0);
	split_flat(&knot, &flat);
	copy_mesh(&flat, &m);
	assert_int_equal(lod_prepare_mesh(&m, 2.0, 160, 90, &r), 0);
	double farthest = measure(&knot, &m).distance / unit;

	print_message("flat knot at 2 px, 160x90: %u of %u triangles (%.0f wanted), %.2f px "
		      "estimated, farthest vertex %.2f px\n",
		      r.triangles_after, r.triangles_before, r.wanted, r.error_pixels, farthest);
	assert_true(r.triangles_after <= 1.25 * r.wanted);
	assert_true(r.error_pixels <= 2.0);
	assert_true(farthest <= 1.8 * 2.0);
	for (uint32_t t = 0; t < m.index_count; t += 3)
		for (int k = 0; k < 3; k++)
			assert_true(fabs(m.uvs[m.indices[t + k] * 2] -
					 m.uvs[m.indices[t + (k + 1) % 3] * 2]) < 0.5);
	mesh_release(&m);
	mesh_release(&flat);
	mesh_release(&knot);
}

/* By value: the poles' -0.0 and 0.0 are one point. */
static bool same_point(const float *a, const float *b)
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* A UV sphere with tangents: its seam column repeats column 0 with u = 1
 * instead of 0. After simplification no triangle spans the seam (|du| <
 * 0.5), the surface is still closed (every edge, by position, has two
 * triangles), triangles face out, and every vertex is an original one,
 * attributes and all. */
static void keeps_seams_and_attributes(void **state)
{
	struct mesh sphere, m;
	struct lod_result r;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&sphere, 64, 32), 0);
	assert_int_equal(tangent_generate(&sphere), 0);
	copy_mesh(&sphere, &m);
	assert_int_equal(lod_prepare_mesh(&m, 4.0, 160, 90, &r), 0);
	assert_true(r.triangles_after < r.triangles_before / 2);
	for (uint32_t t = 0; t < m.index_count; t += 3) {
		const float *p[3], *uv[3];
		double e1[3], e2[3], fn[3], centre[3];

		for (int j = 0; j < 3; j++) {
			p[j] = vec_at(m.positions, m.indices[t + j], 3);
			uv[j] = vec_at(m.uvs, m.indices[t + j], 2);
		}
		for (int j = 0; j < 3; j++)
			assert_true(fabs(uv[j][0] - uv[(j + 1) % 3][0]) < 0.5);
		sub3(p[1], p[0], e1), sub3(p[2], p[0], e2);
		fn[0] = e1[1] * e2[2] - e1[2] * e2[1];
		fn[1] = e1[2] * e2[0] - e1[0] * e2[2];
		fn[2] = e1[0] * e2[1] - e1[1] * e2[0];
		for (int k = 0; k < 3; k++)
			centre[k] = p[0][k] + p[1][k] + p[2][k];
		/* Out, or about edge-on: meshoptimizer may fold a triangle into
		 * the seam's plane (its normal at 90 degrees), and its arm64
		 * build, rounding its collapse costs differently, a sliver a
		 * few degrees past that; the surface stays closed, and shading
		 * reads the vertex normals. So: within 10 degrees of edge-on. */
		assert_true(dot3(fn, centre) >= -0.17 * sqrt(dot3(fn, fn) * dot3(centre, centre)));
	}
	/* Closed: each directed edge (by position) has its reverse. */
	for (uint32_t t = 0; t < m.index_count; t++) {
		const float *a = vec_at(m.positions, m.indices[t], 3);
		const float *b = vec_at(m.positions, m.indices[t - t % 3 + (t + 1) % 3], 3);
		int found = 0;

		if (same_point(a, b))
			continue; /* collapsed to a point at a pole */
		for (uint32_t u = 0; u < m.index_count && !found; u++) {
			const float *c = vec_at(m.positions, m.indices[u], 3);
			const float *d = vec_at(m.positions, m.indices[u - u % 3 + (u + 1) % 3], 3);

			found = same_point(c, b) && same_point(d, a);
		}
		assert_true(found);
	}
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		int found = 0;

		for (uint32_t o = 0; o < sphere.vertex_count && !found; o++)
			found = memcmp(vec_at(m.positions, v, 3), vec_at(sphere.positions, o, 3),
				       12) == 0 &&
				memcmp(vec_at(m.normals, v, 3), vec_at(sphere.normals, o, 3), 12) ==
				    0 &&
				memcmp(vec_at(m.uvs, v, 2), vec_at(sphere.uvs, o, 2), 8) == 0 &&
				memcmp(vec_at(m.tangents, v, 4), vec_at(sphere.tangents, o, 4),
				       16) == 0;
		assert_true(found);
	}
	mesh_release(&m);
	mesh_release(&sphere);
}

/* A second UV set (an emissive map's own) follows simplification and the
 * vertex reorder as the first does: each kept vertex keeps its own pair. */
static void a_second_uv_set_follows(void **state)
{
	struct mesh m;
	struct lod_result r;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&m, 64, 32), 0);
	assert_int_equal(mesh_alloc_uv1(&m, NULL), 0);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		m.uv1[v * 2] = m.uvs[v * 2 + 1];
		m.uv1[v * 2 + 1] = m.uvs[v * 2];
	}
	assert_int_equal(lod_prepare_mesh(&m, 4.0, 160, 90, &r), 0);
	assert_true(r.triangles_after < r.triangles_before / 2);
	assert_non_null(m.uv1);
	for (uint32_t v = 0; v < m.vertex_count; v++)
		assert_true(m.uv1[v * 2] == m.uvs[v * 2 + 1] && m.uv1[v * 2 + 1] == m.uvs[v * 2]);
	mesh_release(&m);
}

/* Simplified, a model of four materials keeps each triangle in its part's
 * range (all its corners of that part) and opens no crack between parts:
 * every directed edge, by position, still has its reverse, across the
 * parts' borders too. */
static void several_materials_keep_their_triangles_and_no_crack(void **state)
{
	struct mesh sphere, m;
	struct lod_result r;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&sphere, 64, 32), 0);
	four_parts(&sphere, &m);
	assert_int_equal(lod_prepare_mesh(&m, 4.0, 160, 90, &r), 0);
	assert_true(r.triangles_after < r.triangles_before / 2);
	assert_int_equal(m.range_count, 4);
	assert_four_parts_in_order(&m);
	for (uint32_t t = 0; t < m.index_count; t++) {
		const float *a = vec_at(m.positions, m.indices[t], 3);
		const float *b = vec_at(m.positions, m.indices[t - t % 3 + (t + 1) % 3], 3);
		int found = 0;

		if (same_point(a, b))
			continue;
		for (uint32_t u = 0; u < m.index_count && !found; u++) {
			const float *c = vec_at(m.positions, m.indices[u], 3);
			const float *d = vec_at(m.positions, m.indices[u - u % 3 + (u + 1) % 3], 3);

			found = same_point(c, b) && same_point(d, a);
		}
		if (!found)
			fail_msg("triangle %u: its edge has no neighbour: a crack", t / 3);
	}
	mesh_release(&m);
	mesh_release(&sphere);
}

static int compare_triangle(const void *a, const void *b)
{
	return memcmp(a, b, 36);
}

/* Each triangle as its three positions, starting from the smallest, so
 * that a reordered mesh compares equal. */
static float *canonical_triangles(const struct mesh *m)
{
	uint32_t n = m->index_count / 3;
	float *tri = malloc((size_t)n * 36 + 1);

	for (uint32_t t = 0; t < n; t++) {
		int first = 0;

		for (int j = 1; j < 3; j++)
			if (memcmp(vec_at(m->positions, m->indices[t * 3 + j], 3),
				   vec_at(m->positions, m->indices[t * 3 + first], 3), 12) < 0)
				first = j;
		for (int j = 0; j < 3; j++)
			memcpy(tri + t * 9 + j * 3,
			       vec_at(m->positions, m->indices[t * 3 + (first + j) % 3], 3), 12);
	}
	qsort(tri, n, 36, compare_triangle);
	return tri;
}

/* 0 px: nothing is simplified, only reordered for the GPU. */
static void zero_budget_only_reorders(void **state)
{
	struct mesh knot, m;
	float *a, *b;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 64, 8), 0);
	copy_mesh(&knot, &m);
	assert_int_equal(lod_prepare_mesh(&m, 0.0, 1280, 720, NULL), 0);
	assert_int_equal(m.index_count, knot.index_count);
	a = canonical_triangles(&knot);
	b = canonical_triangles(&m);
	assert_memory_equal(a, b, (size_t)knot.index_count * 12);
	free(a);
	free(b);
	mesh_release(&m);
	mesh_release(&knot);
}

/* No triangles, one triangle, every vertex at one point: no failure. */
static void degenerate_meshes(void **state)
{
	struct mesh m;

	(void)state;
	assert_int_equal(mesh_alloc(&m, 0, 0, false), 0);
	assert_int_equal(lod_prepare_mesh(&m, 1.0, 640, 480, NULL), 0);
	assert_int_equal(m.index_count, 0);
	mesh_release(&m);
	for (int same = 0; same < 2; same++) {
		assert_int_equal(mesh_alloc(&m, 3, 3, false), 0);
		for (int k = 0; k < 9; k++)
			m.positions[k] = same ? 0.5f : (float)(k % 4 == 0),
			m.normals[k] = k % 3 == 2;
		for (uint32_t i = 0; i < 3; i++)
			m.indices[i] = i;
		assert_int_equal(lod_prepare_mesh(&m, 4.0, 640, 480, NULL), 0);
		for (uint32_t i = 0; i < m.index_count; i++)
			assert_true(m.indices[i] < m.vertex_count);
		mesh_release(&m);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(follows_the_display),
	    cmocka_unit_test(surface_and_normals_within_bounds),
	    cmocka_unit_test(keeps_seams_and_attributes),
	    cmocka_unit_test(a_second_uv_set_follows),
	    cmocka_unit_test(several_materials_keep_their_triangles_and_no_crack),
	    cmocka_unit_test(creases_do_not_stop_it),
	    cmocka_unit_test(zero_budget_only_reorders),
	    cmocka_unit_test(degenerate_meshes),
	};
	return cmocka_run_group_tests_name("lod", tests, NULL, NULL);
}
