/* Displacement along the normal made to show: GLES2 has no tessellation stage, so
 * the mesh is subdivided on the CPU at load time to the density the display
 * needs, displaced there, and given the normals of the displaced surface.
 *
 * Why the CPU and not the vertex shader: a texture fetch in the vertex
 * shader is optional in GLES2 (GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS may be 0
 * on SBC GPUs), new normals need each vertex's neighbours, which a vertex
 * shader never sees, and the displaced shape does not change from frame
 * to frame: done once here, it costs the GPU nothing per frame. */
#ifndef MK_SUBDIVIDE_H
#define MK_SUBDIVIDE_H

#include "util/image.h"
#include "scene/mesh/mesh.h"

/* The largest number of segments per edge subdivide_mesh accepts. */
#define SUBDIVIDE_MAX_SEGMENTS 64

/* Split each triangle into n x n (n segments along every edge; n = 1
 * copies). New points lie on the triangle's Phong-tessellation patch
 * (Boubekeur and Alexa 2008): a coarse sphere subdivides towards the
 * sphere, not into flat facets. UVs, normals and tangents are
 * interpolated. Edges shared by index are shared in the result, and an
 * edge split at a seam (same positions, other indices) gets bitwise the
 * same points on both sides, so nothing cracks. out's material is the
 * default one (the caller moves in's across). Returns 0, -EINVAL or
 * -ENOMEM (out empty). */
int subdivide_mesh(const struct mesh *in, int n, struct mesh *out);

/* Segments per edge so that the edges of the displaced mesh are about
 * target_px pixels long on screen (px_per_unit: pixels per model unit at
 * the front of the unit sphere) but no finer than the height map's texels
 * and within max_triangles. Judged on the 90th percentile edge, so a few
 * long edges do not multiply the whole mesh. At least 1. */
int subdivide_segments(const struct mesh *m, double px_per_unit, double target_px,
		       const struct image *height, uint64_t max_triangles);

/* P' = P + N * d * scale, d = 0.30 R + 0.59 G + 0.11 B of the height map at
 * the vertex's UV (bilinear, repeating). Vertices at one position (seams,
 * poles) move together, by their mean height along their mean normal, so
 * the surface stays closed. Then the normals are those of the displaced
 * surface (area-weighted, smooth). Returns 0, -EINVAL (no UVs) or -ENOMEM. */
int displace_mesh(struct mesh *m, const struct image *height, double scale);

#endif
