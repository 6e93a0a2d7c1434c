/* The level of detail's time on 1, 2, 4 ... threads (issue 34), for
 * `make bench`: a generated torus knot of about the bench's 1M model's
 * size simplified for a display, the median of a few runs per thread
 * count, with what must not change: the triangles kept (within 10% of one
 * thread's), the error estimate (under the budget) and no open edge.
 * Usage: bench_lod_threads [TUBULAR RADIAL [WxH [PIXELS [RUNS [THREADS...]]]]] */
#include "bench_clock.h"
#include "scene/mesh/lod.h"
#include "scene/mesh/mesh.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* CPU time of every thread of the process: what the threads cost
 * together, where the machine is too loaded for the wall clock to show
 * them side by side. */
static double cpu_ms(void)
{
	struct timespec t;

	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int compare_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return (x > y) - (x < y);
}

/* Edges used by one triangle only, by position: a crack (the knot has
 * none). */
static size_t open_edges(const struct mesh *m)
{
	uint32_t *rep = malloc((size_t)m->vertex_count * sizeof(uint32_t) + 1);
	uint64_t *e = malloc((size_t)m->index_count * sizeof(uint64_t) + 1);
	size_t open = 0;

	if (!rep || !e || mesh_weld(m->positions, m->vertex_count, rep))
		open = SIZE_MAX;
	for (uint32_t i = 0; open != SIZE_MAX && i < m->index_count; i++) {
		uint64_t a = rep[m->indices[i]], b = rep[m->indices[i - i % 3 + (i + 1) % 3]];

		e[i] = a < b ? a << 32 | b : b << 32 | a;
	}
	if (open != SIZE_MAX)
		qsort(e, m->index_count, sizeof(uint64_t), compare_u64);
	for (uint32_t i = 0; open != SIZE_MAX && i < m->index_count;) {
		uint32_t j = i;

		while (j < m->index_count && e[j] == e[i])
			j++;
		open += j - i == 1;
		i = j;
	}
	free(rep);
	free(e);
	return open;
}

static int copy_mesh(const struct mesh *src, struct mesh *dst)
{
	if (mesh_alloc(dst, src->vertex_count, src->index_count, src->uvs != NULL))
		return -1;
	memcpy(dst->positions, src->positions, (size_t)src->vertex_count * 12);
	memcpy(dst->normals, src->normals, (size_t)src->vertex_count * 12);
	if (src->uvs)
		memcpy(dst->uvs, src->uvs, (size_t)src->vertex_count * 8);
	memcpy(dst->indices, src->indices, (size_t)src->index_count * 4);
	return 0;
}

int main(int argc, char **argv)
{
	int tubular = argc > 2 ? atoi(argv[1]) : 4096, radial = argc > 2 ? atoi(argv[2]) : 128;
	int width = 1920, height = 1080, runs = argc > 5 ? atoi(argv[5]) : 3;
	double pixels = argc > 4 ? atof(argv[4]) : 4.0;
	static const int fallback[] = {1, 2, 4};
	struct mesh knot;
	uint32_t one = 0;

	if (argc > 3 && sscanf(argv[3], "%dx%d", &width, &height) != 2)
		return fprintf(stderr, "%s: WxH expected, not '%s'\n", argv[0], argv[3]), 2;
	if (mesh_torus_knot(&knot, tubular, radial))
		return 1;
	printf("| threads | triangles | after | vs 1 thread | error px | open edges | most a "
	       "simplifier call | ms (median of %d) | CPU ms |\n"
	       "|---|---|---|---|---|---|---|---|---|\n",
	       runs);
	for (int t = 0; t < (argc > 6 ? argc - 6 : 3); t++) {
		int threads = argc > 6 ? atoi(argv[6 + t]) : fallback[t];
		double ms[16], cpu[16];
		struct lod_result r = {0};
		size_t open = 0;

		for (int k = 0; k < runs && k < 16; k++) {
			struct mesh m;
			double start, cpu_start;

			if (copy_mesh(&knot, &m))
				return 1;
			start = bench_now_ms();
			cpu_start = cpu_ms();
			if (lod_prepare_mesh_threads(&m, pixels, width, height, threads, &r))
				return 1;
			ms[k] = bench_now_ms() - start;
			cpu[k] = cpu_ms() - cpu_start;
			if (!k)
				open = open_edges(&m);
			mesh_release(&m);
		}
		if (threads == 1)
			one = r.triangles_after;
		printf("| %d | %u | %u | %+.1f%% | %.2f | %zu | %u | %.0f | %.0f |\n", threads,
		       r.triangles_before, r.triangles_after,
		       one ? 100.0 * ((double)r.triangles_after - one) / one : 0.0, r.error_pixels,
		       open, r.largest_part, bench_median(ms, runs < 16 ? runs : 16),
		       bench_median(cpu, runs < 16 ? runs : 16));
	}
	mesh_release(&knot);
	return 0;
}
