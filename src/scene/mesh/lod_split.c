#include "scene/mesh/lod_split.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The grid the triangles are sorted on: 32 cells a side, fine enough that
 * a cut between clusters runs through a cell at most a 32nd of the model
 * wide, coarse enough that one counting sort does it. */
#define SPLIT_BITS  5
#define SPLIT_CELLS (1u << (3 * SPLIT_BITS))

int lod_threads(int asked)
{
	long n = asked > 0 ? asked : sysconf(_SC_NPROCESSORS_ONLN);

	return n < 1 ? 1 : n > LOD_THREADS_MAX ? LOD_THREADS_MAX : (int)n;
}

/* 5 bits of x spread to every third bit. */
static uint32_t spread_bits(uint32_t x)
{
	uint32_t out = 0;

	for (int b = 0; b < SPLIT_BITS; b++)
		out |= ((x >> b) & 1u) << (3 * b);
	return out;
}

/* Over the vertex array in its order, not through the indices: reading
 * the positions at random was most of the split's time. */
static void bounds(const float *positions, size_t vertex_count, float lo[3], float hi[3])
{
	for (int k = 0; k < 3; k++)
		lo[k] = INFINITY, hi[k] = -INFINITY;
	/* Comparisons, not fminf (a call each); a NaN is passed by. */
	for (size_t i = 0; i < vertex_count * 3; i += 3)
		for (int k = 0; k < 3; k++) {
			float v = positions[i + k];

			lo[k] = v < lo[k] ? v : lo[k];
			hi[k] = v > hi[k] ? v : hi[k];
		}
}

/* Each triangle's cell: the Morton code of its centroid on a grid of
 * SPLIT_CELLS over the bounds. */
static void cell_codes(const unsigned *indices, size_t tris, const float *positions,
		       const float lo[3], const float hi[3], uint16_t *code)
{
	const float top = (float)((1 << SPLIT_BITS) - 1);
	uint32_t spread[1 << SPLIT_BITS];
	float scale[3];

	for (uint32_t x = 0; x < 1u << SPLIT_BITS; x++)
		spread[x] = spread_bits(x);
	for (int k = 0; k < 3; k++)
		scale[k] = hi[k] > lo[k] ? (top + 1.0f) / (hi[k] - lo[k]) / 3.0f : 0.0f;
	for (size_t t = 0; t < tris; t++) {
		uint32_t c = 0;

		for (int k = 0; k < 3; k++) {
			float sum = positions[(size_t)indices[t * 3] * 3 + k] +
				    positions[(size_t)indices[t * 3 + 1] * 3 + k] +
				    positions[(size_t)indices[t * 3 + 2] * 3 + k];
			float q = (sum - 3.0f * lo[k]) * scale[k];

			/* NaN and out-of-range coordinates land on an edge. */
			c |= spread[q > 0.0f ? (uint32_t)(q < top ? q : top) : 0] << k;
		}
		code[t] = (uint16_t)c;
	}
}

int lod_split_order(const unsigned *indices, size_t index_count, const float *positions,
		    size_t vertex_count, unsigned *out)
{
	size_t tris = index_count / 3;
	/* calloc: gcc -O1 cannot see that cell_codes fills it. */
	uint16_t *code = calloc(tris + 1, sizeof(uint16_t));
	size_t *at = calloc(SPLIT_CELLS + 1, sizeof(size_t));
	float lo[3], hi[3];
	int ret = -ENOMEM;

	if (!code || !at)
		goto out;
	bounds(positions, vertex_count, lo, hi);
	cell_codes(indices, tris, positions, lo, hi, code);
	/* A counting sort by cell: one pass to count, one to place, each
	 * cell's triangles in their input order. */
	for (size_t t = 0; t < tris; t++)
		at[code[t] + 1]++;
	for (size_t c = 0; c < SPLIT_CELLS; c++)
		at[c + 1] += at[c];
	for (size_t t = 0; t < tris; t++)
		memcpy(out + at[code[t]]++ * 3, indices + t * 3, 3 * sizeof(unsigned));
	ret = 0;
out:
	free(code);
	free(at);
	return ret;
}

struct pool {
	void (*job)(void *arg, unsigned j);
	void *arg;
	unsigned jobs;
	atomic_uint next;
};

/* Jobs taken in turn until none is left: which thread runs which job
 * does not matter, each job writes only its own results. */
static void *pool_worker(void *p)
{
	struct pool *pool = p;

	for (unsigned j; (j = atomic_fetch_add(&pool->next, 1)) < pool->jobs;)
		pool->job(pool->arg, j);
	return NULL;
}

void lod_pool_run(int threads, unsigned jobs, void (*job)(void *arg, unsigned j), void *arg)
{
	pthread_t tid[LOD_THREADS_MAX];
	struct pool pool = {job, arg, jobs, 0};
	int started = 0;

	if (threads > LOD_THREADS_MAX)
		threads = LOD_THREADS_MAX;
	while (started + 1 < threads && (unsigned)started + 1 < jobs &&
	       !pthread_create(&tid[started], NULL, pool_worker, &pool))
		started++;
	pool_worker(&pool);
	while (started > 0)
		pthread_join(tid[--started], NULL);
}
