/* What lets the level of detail (lod.c) run on several cores: a mesh's
 * triangles cut into spatial clusters, and a few threads that run jobs
 * side by side. Both are deterministic: the clusters depend only on the
 * triangles and their count, and each job writes only its own results,
 * whichever thread runs it. */
#ifndef MK_LOD_SPLIT_H
#define MK_LOD_SPLIT_H

#include <stddef.h>

/* The threads [kiosk] prepare_threads asks for, at most LOD_THREADS_MAX;
 * 0 (auto): one a core online (1 when that cannot be read). */
#define LOD_THREADS_MAX 16
int lod_threads(int asked);

/* The triangles (index_count / 3) of indices into out, ordered by the
 * cell of a 32x32x32 grid over the vertices' bounds that holds their
 * centroid, the cells along a Z-order curve (positions: 3 floats a
 * vertex, vertex_count of them): any run
 * of them lies close together, so that cutting the result into equal
 * runs gives compact clusters with short borders. A cell's triangles keep
 * their input order. Returns 0 or -ENOMEM. */
int lod_split_order(const unsigned *indices, size_t index_count, const float *positions,
		    size_t vertex_count, unsigned *out);

/* job(arg, j) for every j < jobs, on up to `threads` threads (the caller
 * being one of them). A thread that cannot be started leaves its share
 * to the others: every job runs, whatever happens. */
void lod_pool_run(int threads, unsigned jobs, void (*job)(void *arg, unsigned j), void *arg);

#endif
