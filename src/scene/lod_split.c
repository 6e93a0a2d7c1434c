#include "scene/lod_split.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int lod_threads_online(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);

	return n < 1 ? 1 : n > LOD_THREADS_MAX ? LOD_THREADS_MAX : (int)n;
}

/* 10 bits of x spread to every third bit. */
static uint32_t spread_bits(uint32_t x)
{
	x &= 0x3ff;
	x = (x | (x << 16)) & 0x030000ff;
	x = (x | (x << 8)) & 0x0300f00f;
	x = (x | (x << 4)) & 0x030c30c3;
	x = (x | (x << 2)) & 0x09249249;
	return x;
}

static void bounds(const unsigned *indices, size_t index_count, const float *positions, float lo[3],
		   float hi[3])
{
	for (int k = 0; k < 3; k++)
		lo[k] = INFINITY, hi[k] = -INFINITY;
	for (size_t i = 0; i < index_count; i++)
		for (int k = 0; k < 3; k++) {
			float v = positions[(size_t)indices[i] * 3 + k];

			lo[k] = fminf(lo[k], v);
			hi[k] = fmaxf(hi[k], v);
		}
}

/* Each triangle's 30-bit Morton code of its centroid in the bounds. */
static void morton_codes(const unsigned *indices, size_t tris, const float *positions,
			 const float lo[3], const float hi[3], uint32_t *code)
{
	float scale[3];

	for (int k = 0; k < 3; k++)
		scale[k] = hi[k] > lo[k] ? 1023.0f / (hi[k] - lo[k]) : 0.0f;
	for (size_t t = 0; t < tris; t++) {
		uint32_t c = 0;

		for (int k = 0; k < 3; k++) {
			float sum = positions[(size_t)indices[t * 3] * 3 + k] +
				    positions[(size_t)indices[t * 3 + 1] * 3 + k] +
				    positions[(size_t)indices[t * 3 + 2] * 3 + k];
			float q = (sum / 3.0f - lo[k]) * scale[k];

			/* NaN and out-of-range coordinates land on an edge. */
			c |= spread_bits(q > 0.0f ? (uint32_t)fminf(q, 1023.0f) : 0) << k;
		}
		code[t] = c;
	}
}

/* A stable LSD radix sort of the triangle numbers by code, 10 bits a pass
 * (stable: equal codes keep the input order, hence deterministic). */
static void radix_sort(const uint32_t *code, size_t tris, uint32_t *order, uint32_t *tmp)
{
	for (size_t t = 0; t < tris; t++)
		order[t] = (uint32_t)t;
	for (int shift = 0; shift < 30; shift += 10) {
		size_t count[1025] = {0};

		for (size_t t = 0; t < tris; t++)
			count[((code[order[t]] >> shift) & 1023) + 1]++;
		for (int b = 0; b < 1024; b++)
			count[b + 1] += count[b];
		for (size_t t = 0; t < tris; t++)
			tmp[count[(code[order[t]] >> shift) & 1023]++] = order[t];
		memcpy(order, tmp, tris * sizeof(uint32_t));
	}
}

int lod_split_order(const unsigned *indices, size_t index_count, const float *positions,
		    unsigned *out)
{
	size_t tris = index_count / 3;
	/* calloc: gcc -O1 cannot see that morton_codes fills it. */
	uint32_t *code = calloc(tris + 1, sizeof(uint32_t));
	uint32_t *order = malloc(tris * sizeof(uint32_t) + 1);
	uint32_t *tmp = malloc(tris * sizeof(uint32_t) + 1);
	float lo[3], hi[3];
	int ret = -ENOMEM;

	if (!code || !order || !tmp)
		goto out;
	bounds(indices, tris * 3, positions, lo, hi);
	morton_codes(indices, tris, positions, lo, hi, code);
	radix_sort(code, tris, order, tmp);
	for (size_t t = 0; t < tris; t++)
		memcpy(out + t * 3, indices + (size_t)order[t] * 3, 3 * sizeof(unsigned));
	ret = 0;
out:
	free(code);
	free(order);
	free(tmp);
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
