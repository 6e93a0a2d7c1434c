#include "util/image.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/subdivide.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

/* A coarse sphere: 24 x 12 quads, edges of 15 degrees. Flat facets would
 * sit up to 0.9% inside the unit sphere at edge midpoints. */
#define SLICES 24
#define STACKS 12

static void grey(struct image *img, int size, uint8_t level)
{
	assert_int_equal(image_alloc(img, size, size), 0);
	for (int i = 0; i < size * size; i++) {
		img->rgba[i * 4] = img->rgba[i * 4 + 1] = img->rgba[i * 4 + 2] = level;
		img->rgba[i * 4 + 3] = 255;
	}
}

static double angle_deg(const float *a, const double *b)
{
	double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
	double lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
	double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);

	return acos(fmin(1.0, c)) * 180.0 / M_PI;
}

/* The check: subdividing and displacing a sphere by a constant
 * height gives a sphere of radius 1 + d * scale, and the recomputed
 * normals are the analytic ones (p / |p|). Stated tolerances: radius
 * within 0.05%, normals within 0.5 degrees. */
static void constant_height_gives_a_sphere(void **state)
{
	const double scale = 0.2, d = 128 / 255.0, radius = 1.0 + d * scale;
	struct mesh coarse, fine;
	struct image height;
	double worst_r = 0, worst_a = 0;

	(void)state;
	grey(&height, 8, 128);
	assert_int_equal(mesh_uv_sphere(&coarse, SLICES, STACKS), 0);
	assert_int_equal(subdivide_mesh(&coarse, 8, &fine), 0);
	assert_int_equal(fine.index_count, coarse.index_count * 64);
	assert_int_equal(displace_mesh(&fine, &height, scale), 0);
	for (uint32_t v = 0; v < fine.vertex_count; v++) {
		const float *p = fine.positions + v * 3;
		double pd[3] = {p[0], p[1], p[2]};
		double r = sqrt(pd[0] * pd[0] + pd[1] * pd[1] + pd[2] * pd[2]);

		worst_r = fmax(worst_r, fabs(r - radius) / radius);
		worst_a = fmax(worst_a, angle_deg(fine.normals + v * 3, pd));
	}
	printf("# radius error %.5f%%, normal error %.3f degrees\n", worst_r * 100, worst_a);
	assert_true(worst_r < 0.0005);
	assert_true(worst_a < 0.5);
	mesh_release(&coarse);
	mesh_release(&fine);
	image_release(&height);
}

/* Flat facets (no Phong patch) would miss by far more: the subdivision
 * must put the new points on the curved surface, not only the old ones. */
static void new_points_lie_on_the_sphere(void **state)
{
	struct mesh coarse, fine;
	double worst = 0;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&coarse, SLICES, STACKS), 0);
	assert_int_equal(subdivide_mesh(&coarse, 4, &fine), 0);
	for (uint32_t v = coarse.vertex_count; v < fine.vertex_count; v++) {
		const float *p = fine.positions + v * 3;

		worst = fmax(worst, fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0));
	}
	assert_true(worst < 0.0005);
	mesh_release(&coarse);
	mesh_release(&fine);
}

static int compare_edge(const void *a, const void *b)
{
	const uint64_t *x = a, *y = b;

	return (*x > *y) - (*x < *y);
}

/* Closed: with vertices welded by position, every directed edge a->b has
 * its b->a. A crack at a seam (points off by one bit) would break it. */
static void assert_closed(const struct mesh *m)
{
	uint32_t *rep = malloc(m->vertex_count * sizeof(*rep));
	uint64_t *fwd = malloc(m->index_count * sizeof(*fwd));
	uint64_t *back = malloc(m->index_count * sizeof(*back));
	size_t n = 0;

	assert_int_equal(mesh_weld(m->positions, m->vertex_count, rep), 0);
	for (uint32_t i = 0; i < m->index_count; i++) {
		uint32_t t = i / 3 * 3, a = rep[m->indices[i]],
			 b = rep[m->indices[t + (i + 1) % 3]];

		if (a == b)
			continue;
		fwd[n] = (uint64_t)a << 32 | b;
		back[n++] = (uint64_t)b << 32 | a;
	}
	qsort(fwd, n, sizeof(*fwd), compare_edge);
	qsort(back, n, sizeof(*back), compare_edge);
	assert_memory_equal(fwd, back, n * sizeof(*fwd));
	free(rep);
	free(fwd);
	free(back);
}

static void subdivided_and_displaced_stays_closed(void **state)
{
	struct mesh coarse, fine;
	struct image height;

	(void)state;
	/* A height that differs where the seam's copies sample it. */
	assert_int_equal(image_alloc(&height, 16, 16), 0);
	for (int i = 0; i < 16 * 16; i++)
		height.rgba[i * 4] = height.rgba[i * 4 + 1] = height.rgba[i * 4 + 2] =
		    (uint8_t)(i * 37 % 251);
	assert_int_equal(mesh_uv_sphere(&coarse, 7, 5), 0);
	for (int n = 1; n <= 5; n++) {
		assert_int_equal(subdivide_mesh(&coarse, n, &fine), 0);
		assert_int_equal(fine.index_count, coarse.index_count * n * n);
		assert_closed(&fine);
		assert_int_equal(displace_mesh(&fine, &height, 0.3), 0);
		assert_closed(&fine);
		for (uint32_t i = 0; i < fine.vertex_count * 3; i++)
			assert_true(isfinite(fine.positions[i]) && isfinite(fine.normals[i]));
		mesh_release(&fine);
	}
	mesh_release(&coarse);
	image_release(&height);
}

static void segments_follow_screen_texels_and_budget(void **state)
{
	struct mesh m;
	struct image fine_map, coarse_map;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&m, SLICES, STACKS), 0);
	grey(&fine_map, 1024, 0);
	grey(&coarse_map, 32, 0);
	int big = subdivide_segments(&m, 400, 2, &fine_map, 100000000);
	int small = subdivide_segments(&m, 400, 16, &fine_map, 100000000);
	/* 576 triangles: a budget of 10000 allows 4 segments (9216). */
	int budget = subdivide_segments(&m, 400, 2, &fine_map, 10000);
	int texels = subdivide_segments(&m, 400, 2, &coarse_map, 100000000);

	assert_true(big > small && small >= 1);
	assert_int_equal(budget, 4);
	/* 32 texels over 24 slices: an edge spans 1.3 to 3 texels. */
	assert_true(texels <= 3);
	assert_int_equal(subdivide_segments(&m, 0.1, 8, NULL, 100000000), 1);
	assert_true(subdivide_segments(&m, 1e9, 1, NULL, UINT64_MAX) == SUBDIVIDE_MAX_SEGMENTS);
	mesh_release(&m);
	image_release(&fine_map);
	image_release(&coarse_map);
}

static void refuses_what_it_cannot_do(void **state)
{
	struct mesh m, out;
	struct image height;

	(void)state;
	grey(&height, 4, 10);
	assert_int_equal(mesh_uv_sphere(&m, 6, 4), 0);
	assert_int_equal(subdivide_mesh(&m, 0, &out), -EINVAL);
	assert_int_equal(subdivide_mesh(&m, SUBDIVIDE_MAX_SEGMENTS + 1, &out), -EINVAL);
	free(m.uvs);
	m.uvs = NULL;
	assert_int_equal(displace_mesh(&m, &height, 1), -EINVAL);
	mesh_release(&m);
	image_release(&height);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(constant_height_gives_a_sphere),
	    cmocka_unit_test(new_points_lie_on_the_sphere),
	    cmocka_unit_test(subdivided_and_displaced_stays_closed),
	    cmocka_unit_test(segments_follow_screen_texels_and_budget),
	    cmocka_unit_test(refuses_what_it_cannot_do),
	};
	return cmocka_run_group_tests_name("subdivide", tests, NULL, NULL);
}
