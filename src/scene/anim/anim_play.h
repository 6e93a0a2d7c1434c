/* What live playback keeps beside the baked mesh (scene/mesh.h), so that
 * the loop thread poses the model each frame from the clip's samplers and
 * the node worlds alone: no file, no re-bake. Each part (a glTF primitive
 * as a node shows it) remembers its vertices in the mesh, the node it
 * follows, its skin and its morph targets; the vertices keep their
 * primitive's own (mesh-local) positions and normals, and its joint sets
 * (JOINTS_0 and WEIGHTS_0, and JOINTS_1/_2 where the file has them: the
 * bake blends them all). anim_play_pose writes the mesh's positions and normals as the
 * loader's bake would at that pose (the same maths: morphs, then the skin
 * or the node's world, then the clip's fit), on the CPU. Pure: no GL. */
#ifndef MK_ANIM_PLAY_H
#define MK_ANIM_PLAY_H

#include "scene/anim/anim.h"
#include "scene/mesh/mesh.h"

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct anim_play_skin {
	uint32_t joint_count;
	int *joints;	     /* node of each joint */
	float *inverse_bind; /* 16 a joint, column-major (identity when the file has none) */
	/* Its joints' first matrix in anim_play.joint_matrices (anim_play_finish). */
	uint32_t first;
};

struct anim_play_part {
	int node; /* the node that shows it: its world, its morph weights */
	int skin; /* into anim_play.skins; -1: rigid, it follows node */
	/* The node has a skin this primitive does not use: drawn as it is
	 * (at the skeleton's root, as the spec says), its morphs alone. */
	bool at_root;
	uint32_t first_vertex, vertex_count;
	/* Its normals as the file gives them; false: generated each pose
	 * from its triangles (indices: index_count, into the mesh's vertices). */
	bool has_normals;
	/* Generated flat: each triangle's own vertices given its face normal
	 * (the loader split it, as glTF requires without NORMAL); false: smooth
	 * ([scene] normals = smooth). */
	bool flat;
	uint32_t index_count;
	uint32_t *indices;
	/* Morph targets: target_count deltas of vertex_count xyz each
	 * (normals NULL when the targets move none). */
	uint32_t target_count;
	float *target_positions, *target_normals;
};

struct anim_play {
	struct mesh_anim *anim;
	/* The clip's fit: drawn positions are (world - center) * scale. */
	double center[3], scale;
	uint32_t vertex_count;
	float *positions, *normals; /* each part's own, xyz per mesh vertex */
	uint16_t *joints;	    /* influences per vertex; NULL: no part is skinned */
	float *weights;		    /* influences per vertex */
	/* Joints a vertex in joints and weights: 4 a set the file's skinned
	 * parts have at most (4: JOINTS_0 alone, the arrays a model without
	 * JOINTS_1 always had; 8 with JOINTS_1; 12 with JOINTS_2); a part
	 * with fewer sets has weights of 0 past its own. */
	uint32_t influences;
	uint32_t part_count, skin_count;
	struct anim_play_part *parts;
	struct anim_play_skin *skins;
	/* Scratch of a pose (sized at load: no allocation a frame): node
	 * worlds; every skin's joint matrices, world x inverse bind in double
	 * (anim_play_joints: the one place they are made, for the CPU's
	 * blend and the GPU's palette alike); a part's morphed vertices. */
	float (*worlds)[16];
	double (*joint_matrices)[16];
	float *morphed;
	uint32_t joint_total, part_vertex_max;
	/* The GPU path (anim_play_gpu_prepare): one palette of bones for the
	 * whole model, bone 0 the fit alone, then every skin's joints, then
	 * the nodes rigid parts follow; each vertex's four bones (as floats,
	 * as the shader reads them) and weights. bones 0: the CPU path. */
	uint32_t bones;
	float *gpu_joints, *gpu_weights;
	int *node_bone; /* per node, the bone of the rigid parts it shows; 0: none */
	float *rows;	/* bones x 12: the palette at the last pose (the GPU path's scratch) */
	bool morphs;	/* some part has targets: its own arrays change a frame */
	/* Morph targets on the GPU (anim_play_morph_prepare): morph_targets
	 * deltas a vertex (0: none there; the CPU moves them when morphs),
	 * the weights of morph_node's; gpu_morph: morph_targets arrays of
	 * xyz per vertex (positions), then as many of normals where
	 * morph_normals (a vertex of a part without targets: zeros). */
	uint32_t morph_targets;
	bool morph_normals;
	int morph_node;
	float *gpu_morph;
};

/* The allocations of the scratch, once parts and skins are filled. 0 or
 * -ENOMEM. */
int anim_play_finish(struct anim_play *p);
/* The pose's node worlds (p->worlds) and every skin's joint matrices
 * (p->joint_matrices): the one place a pose becomes joints. */
void anim_play_joints(struct anim_play *p, const struct anim_pose *pose);
/* positions and normals (xyz per vertex, p->vertex_count) at a pose. */
void anim_play_pose(struct anim_play *p, const struct anim_pose *pose, float *positions,
		    float *normals);
/* The GPU path: the bones the model needs in one palette; with no more
 * than `palette`, its vertices' bones and weights (an unweighted vertex
 * and a part at the skeleton's root take bone 0). 0, -E2BIG (more bones:
 * the arrays are made for anim_play_split to cut), -ENOTSUP (a part's normals are generated from
 * its posed triangles: the CPU path), -ERANGE (more than four joints a
 * vertex, JOINTS_1: the shader blends four; the CPU path) or -ENOMEM.
 * Called again, it decides again. */
int anim_play_gpu_prepare(struct anim_play *p, uint32_t palette);
/* Why anim_play_gpu_prepare's answer (or anim_play_split's -E2BIG) leaves
 * the model to the CPU, for the journal: a sentence, or NULL for 0. */
const char *anim_play_gpu_why(int err);
/* The palette at a pose: 3 rows of 4 floats a bone (a 3x4 matrix), the
 * joint matrices of anim_play_joints (and the rigid parts' node worlds)
 * with the clip's fit. */
void anim_play_bones(struct anim_play *p, const struct anim_pose *pose, float *rows);
/* The parts' own positions and normals with the pose's morph weights
 * (the GPU path's arrays; the CPU path's before its skin). */
void anim_play_morph(struct anim_play *p, const struct anim_pose *pose, float *positions,
		     float *normals);
/* The most targets the vertex shader adds (shaders/morph.glsl). */
#define ANIM_PLAY_MORPH_MAX 8
/* After anim_play_gpu_prepare: the morph targets to the GPU when their
 * deltas fit `room` vertex attributes (a position a target, and a normal
 * where the targets move normals) and one program holds them (every part
 * with targets shown by one node: one set of weights); p->morphs is then
 * false (the arrays stay the parts' own). 0 (none to move, or on the
 * GPU); else *why says why the CPU moves them (p->morphs stays true):
 * -ENOSPC (more attributes than room), -E2BIG (more targets than
 * ANIM_PLAY_MORPH_MAX), -EXDEV (parts of several nodes); or -ENOMEM. */
int anim_play_morph_prepare(struct anim_play *p, uint32_t room, const char **why);
/* The attributes the model's targets take on the GPU (0: no targets). */
uint32_t anim_play_morph_attributes(const struct anim_play *p);
/* The pose's weights of the GPU's targets: ANIM_PLAY_MORPH_MAX floats,
 * those past morph_targets 0. */
void anim_play_morph_weights(const struct anim_play *p, const struct anim_pose *pose,
			     float *weights);
/* The GPU path when the bones outnumber the palette: every draw range
 * of m split (scene/anim_palette.h) into draws of at most `palette`
 * bones, the vertices two draws share copied, each vertex's bones
 * renumbered into its draw's palette. A vertex of the split is the mesh's
 * vertex source[i]. */
struct anim_play_split {
	uint32_t vertex_count, index_count, range_count;
	uint32_t *source;
	uint32_t *indices;
	struct mesh_range *ranges; /* one a draw, its range's material */
	/* KHR_materials_variants: variant v draws range r with
	 * variant_materials[v * range_count + r], the material of the mesh
	 * range it was cut from in v (NULL: the mesh has no variants). */
	uint32_t *variant_materials;
	uint32_t *origin;	 /* per range: the mesh's range it was cut from */
	uint32_t *palette_first; /* per range, into bones */
	uint32_t *palette_count;
	uint16_t *bones;	    /* the draws' palettes, one after another */
	uint32_t palette_max;	    /* the largest draw's */
	float *joints, *weights;    /* 4 per vertex of the split */
	float *positions, *normals; /* xyz per vertex of the split: room to gather into */
};
/* Anim_play_gpu_prepare's bones split so; 0, -E2BIG (a triangle alone
 * needs more: the CPU path) or -ENOMEM. */
int anim_play_split(const struct anim_play *p, const struct mesh *m, uint32_t palette,
		    struct anim_play_split *out);
void anim_play_split_release(struct anim_play_split *s);
/* to[i] = from[source[i]], `width` floats each, for the split's vertices. */
void anim_play_split_gather(const struct anim_play_split *s, const float *from, int width,
			    float *to);
/* Frees p, its anim and everything it holds (NULL: nothing). */
void anim_play_free(struct anim_play *p);

#ifdef __cplusplus
}
#endif

#endif
