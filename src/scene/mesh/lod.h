/* Only what the display can show. Triangles smaller than about a pixel
 * are wasted: a mesh is simplified (meshoptimizer) until its triangles
 * average `pixels` pixels across on this display, as long as its surface
 * moves by less than `pixels` pixels, for the renderer's camera and a
 * model fitted to the unit sphere; then it is ordered for the GPU's vertex
 * cache, for overdraw and for vertex fetch. Never a fixed triangle count:
 * the same model keeps more triangles on a larger display, and a model
 * whose triangles are already larger keeps them all. */
#ifndef MK_LOD_H
#define MK_LOD_H

#include "scene/mesh/mesh.h"

/* The largest distance, in model units, that stays under `pixels` pixels
 * anywhere on a width x height frame (src/render/render.c's camera magnifies the
 * front of the unit sphere most). */
double lod_model_error(double pixels, int width, int height);

/* How many triangles m needs so that they average `pixels` x `pixels`
 * on screen (INFINITY for pixels <= 0). Seen from all sides, a closed
 * surface shows a quarter of its area A (Cauchy's formula) on about half
 * of its N triangles, A ppu^2 / (2 N) square pixels each, ppu the pixels
 * per model unit at the front of the unit sphere: so N = A ppu^2 /
 * (2 pixels^2). */
double lod_triangles_wanted(const struct mesh *m, double pixels, int width, int height);

struct lod_result {
	uint32_t triangles_before, triangles_after;
	uint32_t vertices_before, vertices_after;
	double wanted;	     /* lod_triangles_wanted */
	double error;	     /* meshoptimizer's estimate, in model units */
	double error_pixels; /* ... and in pixels at the front of the sphere */
	unsigned clusters;   /* the most any part was cut into: 1 without threads */
	/* The most triangles one call of the simplifier was given at once:
	 * its memory follows them (lod.c's CLUSTER_MAX_TRIANGLES). */
	uint32_t largest_part;
};

/* Simplify m in place for a width x height display (pixels <= 0: keep
 * every triangle) and order it for drawing: vertices equal in every
 * attribute merged, then meshopt_simplify down to lod_triangles_wanted
 * unless the error would reach `pixels` first (positions only; seams
 * kept, or, where seams stop it short, over the positions welded and
 * each corner given back its own side's wedge), then ordered for the vertex cache, for overdraw and
 * for vertex fetch, without the vertices no triangle uses. Every vertex left keeps its own
 * attributes. The error is meshoptimizer's estimate: the farthest original vertex lies up to 1.7
 * times as far (tests/unit/test_lod.c). result may be NULL. Returns 0, or -ENOMEM (m is then
 * unchanged). */
int lod_prepare_mesh(struct mesh *m, double pixels, int width, int height,
		     struct lod_result *result);

/* lod_prepare_mesh on up to `threads` threads (the caller's among them;
 * [kiosk] prepare_threads): a part of 32768 triangles or more is cut into spatial clusters
 * simplified side by side, their borders locked, then joined and simplified once more together
 * (lod.c's simplify_clustered). The same error budget, no crack, every range its own; the triangle
 * count within 10% of one thread's. A part over 65536 triangles is cut so on any count, one too:
 * the simplifier's memory follows what one call is given (issue 34; lod_result.largest_part). The
 * result depends on the thread count (the cache's key holds it), and 1 is exactly lod_prepare_mesh.
 */
int lod_prepare_mesh_threads(struct mesh *m, double pixels, int width, int height, int threads,
			     struct lod_result *result);

#endif
