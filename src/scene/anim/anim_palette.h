/* Skinning on the GPU reads each vertex's joints from a palette of bone
 * matrices in vertex-shader uniforms, and a GPU has only so many
 * (GL_MAX_VERTEX_UNIFORM_VECTORS: 128 on the least GLES2 allows). A skinned
 * primitive with more joints than fit is split at load into draws, each with
 * a palette of its own that fits; a vertex two draws share is copied, its
 * joint indices renumbered into each draw's palette. Pure: no GL. */
#ifndef MK_ANIM_PALETTE_H
#define MK_ANIM_PALETTE_H

#include <stdint.h>

/* One draw: indices[first_index, +index_count) over its own vertices, its
 * palette joints[joint_first, +joint_count) (the skin's joint numbers). */
struct anim_palette_draw {
	uint32_t first_index, index_count;
	uint32_t joint_first, joint_count;
};

struct anim_palette {
	uint32_t draw_count;
	struct anim_palette_draw *draws;
	uint16_t *joints; /* every draw's palette, one after another */
	uint32_t vertex_count;
	uint32_t *source;	 /* out vertex -> the input vertex it copies */
	uint16_t *vertex_joints; /* 4 per out vertex, into its draw's palette */
	uint32_t index_count;
	uint32_t *indices; /* out vertices, three per triangle */
};

/* The bone matrices a vertex shader can hold: each joint a 4x3 matrix
 * (three vec4 uniforms; the fourth row of an affine matrix is 0 0 0 1),
 * after the `reserved` vectors the shader's other uniforms take. 0 when
 * not even one fits. */
uint32_t anim_palette_size(int max_vertex_uniform_vectors, int reserved);

/* Splits a triangle list (index_count indices into vertex_count vertices,
 * JOINTS_0 and WEIGHTS_0 four a vertex) into draws of at most `palette`
 * joints, greedily in the triangles' order. Only joints of non-zero weight
 * count. Returns 0; -EINVAL for a joint at or past joint_count or an index
 * past the vertices; -E2BIG when one triangle alone needs more joints than
 * the palette holds (that primitive takes the CPU path); -ENOMEM. */
int anim_palette_split(const uint32_t *indices, uint32_t index_count, const uint16_t *joints,
		       const float *weights, uint32_t vertex_count, uint32_t joint_count,
		       uint32_t palette, struct anim_palette *out);
void anim_palette_release(struct anim_palette *p);

#endif
