/* The one plain data model every consumer reads (as cgltf has one): a
 * single indexed triangle list in model space, already centred on the
 * origin and scaled to fit the unit sphere. */
#ifndef MK_MESH_H
#define MK_MESH_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct mesh {
	uint32_t vertex_count;
	uint32_t index_count; /* three per triangle */
	float *positions;     /* xyz per vertex */
	float *normals;	      /* xyz per vertex, unit length */
	float *uvs;	      /* uv per vertex, NULL when the model has none */
	uint32_t *indices;
};

int mesh_alloc(struct mesh *m, uint32_t vertex_count, uint32_t index_count, bool with_uvs);
void mesh_release(struct mesh *m);

/* Centre world-space positions (computed in double, so a model placed far
 * from the origin or at an extreme scale keeps its precision) and scale
 * them into the unit sphere. A degenerate extent leaves the scale at 1. */
void mesh_fit_positions(const double *world, uint32_t count, float *out);

/* Area-weighted smooth normals for the triangles idx[0..index_count) over
 * vertices [first, first + count): vertices at the same position share one
 * normal, so split UV seams shade smoothly. Degenerate areas get +Z. */
int mesh_generate_normals(const float *positions, const uint32_t *idx, uint32_t index_count,
			  uint32_t first, uint32_t count, float *normals);

/* The built-in models, already in the unit sphere. */
int mesh_torus_knot(struct mesh *m, int tubular, int radial);
int mesh_uv_sphere(struct mesh *m, int slices, int stacks);

#ifdef __cplusplus
}
#endif

#endif
