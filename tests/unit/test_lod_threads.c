/* The level of detail on several threads (lod_prepare_mesh_threads,
 * src/scene/mesh/lod_split.c): the model cut into clusters keeps what one
 * thread gives (the count, the error budget, no crack, the materials), past
 * creases, and the same bytes run to run. */
#include "scene/mesh/lod.h"
#include "scene/mesh/mesh.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "lod_fixture.h"

static int compare_edge(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return (x > y) - (x < y);
}

/* Edges, by position, that only one triangle uses: the border of an open
 * mesh, or a crack. */
static size_t open_edges(const struct mesh *m)
{
	uint32_t *rep = malloc((size_t)m->vertex_count * 4 + 1);
	uint64_t *e = malloc((size_t)m->index_count * 8 + 1);
	size_t open = 0;

	assert_int_equal(mesh_weld(m->positions, m->vertex_count, rep), 0);
	for (uint32_t i = 0; i < m->index_count; i++) {
		uint64_t a = rep[m->indices[i]], b = rep[m->indices[i - i % 3 + (i + 1) % 3]];

		e[i] = a < b ? a << 32 | b : b << 32 | a;
	}
	qsort(e, m->index_count, 8, compare_edge);
	for (uint32_t i = 0, j; i < m->index_count; i = j) {
		for (j = i; j < m->index_count && e[j] == e[i];)
			j++;
		open += j - i == 1 && e[i] >> 32 != (e[i] & 0xffffffffu);
	}
	free(rep);
	free(e);
	return open;
}

/* src simplified on `threads` threads into m (a copy). */
static struct lod_result prepare_on(const struct mesh *src, struct mesh *m, double pixels,
				    int width, int height, int threads)
{
	struct lod_result r;

	copy_mesh(src, m);
	if (src->colors) {
		assert_int_equal(mesh_alloc_colors(m), 0);
		memcpy(m->colors, src->colors, src->vertex_count * 16);
	}
	if (src->range_count) {
		assert_int_equal(mesh_alloc_ranges(m, src->range_count, src->range_count), 0);
		memcpy(m->ranges, src->ranges, src->range_count * sizeof(*m->ranges));
	}
	assert_int_equal(lod_prepare_mesh_threads(m, pixels, width, height, threads, &r), 0);
	return r;
}

/* The thread tests' common part: src simplified on one thread and on
 * `threads` (into m), the latter cut into that many clusters and keeping
 * what one thread gives: triangles within 10%, the error budget. */
static struct lod_result like_one_thread(const struct mesh *src, struct mesh *m, double pixels,
					 int width, int height, int threads)
{
	struct mesh one;
	struct lod_result r1 = prepare_on(src, &one, pixels, width, height, 1);
	struct lod_result r = prepare_on(src, m, pixels, width, height, threads);

	print_message("%dx%d, %d threads: %u triangles (1 thread: %u), %.2f px (%.2f)\n", width,
		      height, threads, r.triangles_after, r1.triangles_after, r.error_pixels,
		      r1.error_pixels);
	assert_int_equal(r1.clusters, 1);
	assert_int_equal(r.clusters, threads);
	assert_true(fabs((double)r.triangles_after - r1.triangles_after) <=
		    0.1 * r1.triangles_after);
	assert_true(r.error_pixels <= pixels);
	mesh_release(&one);
	return r;
}

/* On 2, 3 and 4 threads a large knot (65536 triangles: cut into that many
 * clusters) keeps what one thread gives: triangles within 10%, the same
 * error budget (meshoptimizer's estimate, and at 160x90, where it is cut
 * most, every original vertex within 1.8 budgets of the new surface as
 * surface_and_normals_within_bounds asks), and no open edge. */
static void threads_keep_the_bound_and_the_count(void **state)
{
	static const int sizes[][2] = {{160, 90}, {640, 360}, {1280, 720}};
	struct mesh knot;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 512, 64), 0);
	assert_int_equal(open_edges(&knot), 0);
	for (int i = 0; i < 3; i++) {
		for (int threads = 2; threads <= 4; threads++) {
			struct mesh m;
			double unit = lod_model_error(1.0, sizes[i][0], sizes[i][1]);

			like_one_thread(&knot, &m, 4.0, sizes[i][0], sizes[i][1], threads);
			assert_int_equal(open_edges(&m), 0);
			if (i == 0)
				assert_true(measure(&knot, &m).distance <= 1.8 * 4.0 * unit);
			mesh_release(&m);
		}
	}
	mesh_release(&knot);
}

/* Four materials of 32768 triangles each, every range cut in two:
 * each triangle stays in its part's range, no crack opens (no edge is
 * more open than before), and the count stays within 10% of one thread's. */
static void threads_keep_materials(void **state)
{
	struct mesh sphere, parts, m;
	size_t open;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&sphere, 256, 256), 0);
	four_parts(&sphere, &parts);
	open = open_edges(&parts);
	like_one_thread(&parts, &m, 4.0, 320, 240, 2);
	assert_true(open_edges(&m) <= open);
	assert_four_parts_in_order(&m);
	mesh_release(&m);
	mesh_release(&parts);
	mesh_release(&sphere);
}

/* A flat-shaded export (every corner on a crease: meshoptimizer alone
 * collapses nothing, the welded pass does it all, in each cluster too):
 * on 4 threads as on one, no crack, no triangle across the UV seam. */
static void threads_past_creases(void **state)
{
	struct mesh knot, flat, m;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 512, 64), 0);
	split_flat(&knot, &flat);
	like_one_thread(&flat, &m, 2.0, 640, 360, 4);
	assert_int_equal(open_edges(&m), 0);
	for (uint32_t t = 0; t < m.index_count; t += 3)
		for (int k = 0; k < 3; k++)
			assert_true(fabs(m.uvs[m.indices[t + k] * 2] -
					 m.uvs[m.indices[t + (k + 1) % 3] * 2]) < 0.5);
	mesh_release(&m);
	mesh_release(&flat);
	mesh_release(&knot);
}

static void assert_same_mesh(const struct mesh *a, const struct mesh *b)
{
	assert_int_equal(a->index_count, b->index_count);
	assert_int_equal(a->vertex_count, b->vertex_count);
	assert_memory_equal(a->indices, b->indices, a->index_count * 4);
	assert_memory_equal(a->positions, b->positions, a->vertex_count * 12);
	assert_memory_equal(a->normals, b->normals, a->vertex_count * 12);
	assert_memory_equal(a->uvs, b->uvs, a->vertex_count * 8);
}

/* The same bytes run to run on 3 threads (the cache's key holds the
 * count); one thread is lod_prepare_mesh, and a model too small to cut
 * (16384 triangles) is what it was on any count. */
static void threads_are_deterministic(void **state)
{
	struct mesh knot, small, a, b, c;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 512, 64), 0);
	prepare_on(&knot, &a, 4.0, 640, 360, 3);
	prepare_on(&knot, &b, 4.0, 640, 360, 3);
	assert_same_mesh(&a, &b);
	mesh_release(&a);
	mesh_release(&b);
	prepare_on(&knot, &a, 4.0, 640, 360, 1);
	copy_mesh(&knot, &b);
	assert_int_equal(lod_prepare_mesh(&b, 4.0, 640, 360, NULL), 0);
	assert_same_mesh(&a, &b);
	assert_int_equal(mesh_torus_knot(&small, 256, 32), 0);
	prepare_on(&small, &c, 4.0, 640, 360, 16);
	mesh_release(&b);
	copy_mesh(&small, &b);
	assert_int_equal(lod_prepare_mesh(&b, 4.0, 640, 360, NULL), 0);
	assert_same_mesh(&c, &b);
	mesh_release(&a);
	mesh_release(&b);
	mesh_release(&c);
	mesh_release(&small);
	mesh_release(&knot);
}

/* Memory (issue 34): meshoptimizer's simplifier holds some 110 bytes a
 * triangle of what one call is given (a 1M-triangle scan: 110 MB on top
 * of the mesh, most of a cold start's peak). A part over 65536 triangles
 * is cut into clusters on any thread count, one too, and no call is given
 * more than a cluster; the result keeps the error budget, no crack, and
 * the count wanted within 10%, on 1, 2 and 4 threads. */
static void large_parts_are_cut_on_any_count(void **state)
{
	struct mesh knot, one, m;
	struct lod_result r1, r;

	(void)state;
	assert_int_equal(mesh_torus_knot(&knot, 1024, 96), 0); /* 196608 triangles */
	r1 = prepare_on(&knot, &one, 4.0, 1280, 720, 1);
	print_message("1 thread: %u clusters, at most %u triangles a call, %u of %.0f wanted, "
		      "%.2f px\n",
		      r1.clusters, r1.largest_part, r1.triangles_after, r1.wanted, r1.error_pixels);
	assert_int_equal(r1.clusters, 3);
	assert_true(r1.largest_part <= 65536);
	assert_true(fabs(r1.triangles_after - r1.wanted) <= 0.1 * r1.wanted);
	assert_true(r1.error_pixels <= 4.0);
	assert_int_equal(open_edges(&one), 0);
	/* 2 threads: the same 3 clusters, the same mesh; 4: one a thread. */
	for (int threads = 2; threads <= 4; threads *= 2) {
		r = prepare_on(&knot, &m, 4.0, 1280, 720, threads);
		assert_true(r.largest_part <= 65536);
		assert_int_equal(r.clusters, threads < 3 ? 3 : threads);
		if (threads < 3)
			assert_same_mesh(&m, &one);
		assert_true(fabs(r.triangles_after - r.wanted) <= 0.1 * r.wanted);
		assert_true(r.error_pixels <= 4.0);
		assert_int_equal(open_edges(&m), 0);
		mesh_release(&m);
	}
	mesh_release(&one);
	mesh_release(&knot);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(threads_keep_the_bound_and_the_count),
	    cmocka_unit_test(threads_keep_materials),
	    cmocka_unit_test(threads_past_creases),
	    cmocka_unit_test(threads_are_deterministic),
	    cmocka_unit_test(large_parts_are_cut_on_any_count),
	};
	return cmocka_run_group_tests_name("lod_threads", tests, NULL, NULL);
}
