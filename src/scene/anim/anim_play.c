/* Live playback's CPU pose: the loader's bake (scene/gltf_pose.cc,
 * gltf_mesh.cc) again, from the pose's node worlds, for the vertices the
 * parts remember: morph targets added to the part's own positions and
 * normals, then the skin's blended joint matrices (normalised by the
 * weights' sum, a vertex of no weight left where it was bound) or the
 * node's world and its normal matrix, then the clip's fit. */
#include "scene/anim/anim_play.h"
#include "scene/mesh/mesh.h"
#include "util/math3d.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int anim_play_finish(struct anim_play *p)
{
	uint32_t joints = 0, verts = 1;

	for (uint32_t s = 0; s < p->skin_count; s++) {
		p->skins[s].first = joints;
		joints += p->skins[s].joint_count;
	}
	for (uint32_t i = 0; i < p->part_count; i++)
		verts = p->parts[i].vertex_count > verts ? p->parts[i].vertex_count : verts;
	p->joint_total = joints;
	p->part_vertex_max = verts;
	p->worlds = calloc(p->anim->node_count + 1, sizeof(*p->worlds));
	p->joint_matrices = calloc(joints + 1, sizeof(*p->joint_matrices));
	p->morphed = calloc((size_t)verts * 6, sizeof(float));
	return p->worlds && p->joint_matrices && p->morphed ? 0 : -ENOMEM;
}

/* out = a x b (b NULL: the identity), summed in double and kept so: the
 * GPU's palette takes it as it is, the CPU's blend as the float the
 * bake's product is (the same sums, rounded once). */
static void mat_mul(const float *a, const float *b, double out[16])
{
	for (int c = 0; c < 4; c++)
		for (int row = 0; row < 4; row++) {
			double s = 0;

			for (int k = 0; k < 4; k++)
				s += (double)a[k * 4 + row] * (b ? b[c * 4 + k] : (k == c));
			out[c * 4 + row] = s;
		}
}

void anim_play_joints(struct anim_play *p, const struct anim_pose *pose)
{
	anim_pose_world(p->anim, pose, p->worlds);
	for (uint32_t s = 0; s < p->skin_count; s++) {
		const struct anim_play_skin *skin = &p->skins[s];

		for (uint32_t j = 0; j < skin->joint_count; j++)
			mat_mul(p->worlds[skin->joints[j]], skin->inverse_bind + (size_t)j * 16,
				p->joint_matrices[skin->first + j]);
	}
}

/* The part's positions and normals with its morph weights added, into
 * p->morphed (xyz positions, then xyz normals). */
static void morph_part(struct anim_play *p, const struct anim_play_part *part,
		       const struct anim_pose *pose)
{
	const struct anim_node *n = &p->anim->nodes[part->node];
	size_t count = (size_t)part->vertex_count * 3;
	float *pos = p->morphed, *nrm = p->morphed + count;

	memcpy(pos, p->positions + (size_t)part->first_vertex * 3, count * sizeof(float));
	memcpy(nrm, p->normals + (size_t)part->first_vertex * 3, count * sizeof(float));
	for (uint32_t t = 0; t < part->target_count && t < n->weight_count; t++) {
		float w = pose->weights[n->weight_offset + t];
		const float *dp = part->target_positions + t * count;
		const float *dn = part->target_normals ? part->target_normals + t * count : NULL;

		if (w == 0.0f)
			continue;
		for (size_t i = 0; i < count; i++)
			pos[i] += w * dp[i];
		for (size_t i = 0; dn && i < count; i++)
			nrm[i] += w * dn[i];
	}
}

void anim_play_morph(struct anim_play *p, const struct anim_pose *pose, float *positions,
		     float *normals)
{
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];
		size_t at = (size_t)part->first_vertex * 3, count = (size_t)part->vertex_count * 3;

		morph_part(p, part, pose);
		memcpy(positions + at, p->morphed, count * sizeof(float));
		memcpy(normals + at, p->morphed + count, count * sizeof(float));
	}
}

/* The cofactor matrix of m's 3x3 (the normal matrix up to a scale), as
 * the bake takes it: negated where m mirrors. */
static void normal_matrix(const float *m, double n[9])
{
	double d[16];

	for (int k = 0; k < 16; k++)
		d[k] = m[k];
	mat4_normal_matrix(d, n);
}

static void put_normal(const double n[3], float *out)
{
	double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);

	for (int k = 0; k < 3; k++)
		out[k] = len > 0 && isfinite(len) ? (float)(n[k] / len) : (float)(k == 2);
}

static void put_position(const struct anim_play *p, const double w[3], float *out)
{
	for (int k = 0; k < 3; k++)
		out[k] = (float)((w[k] - p->center[k]) * p->scale);
}

static void pose_rigid(struct anim_play *p, const struct anim_play_part *part, float *positions,
		       float *normals)
{
	static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
	const float *m = part->at_root ? identity : p->worlds[part->node];
	const float *pos = p->morphed, *nrm = p->morphed + (size_t)part->vertex_count * 3;
	double nm[9];

	normal_matrix(m, nm);
	for (uint32_t i = 0; i < part->vertex_count; i++) {
		const float *v = pos + (size_t)i * 3, *n = nrm + (size_t)i * 3;
		size_t o = (size_t)(part->first_vertex + i) * 3;
		double w[3], d[3];

		for (int k = 0; k < 3; k++) {
			w[k] = (double)m[k] * v[0] + (double)m[4 + k] * v[1] +
			       (double)m[8 + k] * v[2] + m[12 + k];
			d[k] = nm[k] * n[0] + nm[3 + k] * n[1] + nm[6 + k] * n[2];
		}
		put_position(p, w, positions + o);
		put_normal(d, normals + o);
	}
}

/* Vertex v's blend of its skin's joint matrices, every set of them (as
 * the bake's, from its float matrices); false for a vertex of no weight
 * (it stays where it was bound). The one CPU blend. */
static bool blend(const struct anim_play *p, const struct anim_play_skin *s, uint32_t v,
		  double b[16])
{
	const size_t at = (size_t)v * p->influences;
	double total = 0;

	memset(b, 0, 16 * sizeof(double));
	for (uint32_t k = 0; k < p->influences; k++) {
		float w = p->weights[at + k];
		uint16_t j = p->joints[at + k];

		if (w == 0.0f || j >= s->joint_count)
			continue;
		for (int c = 0; c < 16; c++)
			b[c] += w * (double)(float)p->joint_matrices[s->first + j][c];
		total += w;
	}
	if (total == 0.0)
		return false;
	for (int c = 0; c < 16; c++)
		b[c] /= total;
	return true;
}

static void pose_skinned(struct anim_play *p, const struct anim_play_part *part, float *positions,
			 float *normals)
{
	const struct anim_play_skin *s = &p->skins[part->skin];
	const float *pos = p->morphed, *nrm = p->morphed + (size_t)part->vertex_count * 3;

	for (uint32_t i = 0; i < part->vertex_count; i++) {
		const float *v = pos + (size_t)i * 3, *n = nrm + (size_t)i * 3;
		size_t o = (size_t)(part->first_vertex + i) * 3;
		double b[16], w[3], d[3];

		if (!blend(p, s, part->first_vertex + i, b)) {
			for (int k = 0; k < 3; k++) {
				w[k] = v[k];
				d[k] = n[k];
			}
		} else {
			/* Bind poses are rigid in practice: the blended 3x3 turns
			 * the normal (as the bake does). */
			for (int k = 0; k < 3; k++) {
				w[k] = b[k] * v[0] + b[4 + k] * v[1] + b[8 + k] * v[2] + b[12 + k];
				d[k] = b[k] * n[0] + b[4 + k] * n[1] + b[8 + k] * n[2];
			}
		}
		put_position(p, w, positions + o);
		put_normal(d, normals + o);
	}
}

void anim_play_pose(struct anim_play *p, const struct anim_pose *pose, float *positions,
		    float *normals)
{
	anim_play_joints(p, pose);
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];

		morph_part(p, part, pose);
		if (part->skin >= 0)
			pose_skinned(p, part, positions, normals);
		else
			pose_rigid(p, part, positions, normals);
	}
	/* Generated normals follow the fitted positions, as at load (a
	 * fallback that allocates: a file without normals is rare). */
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];

		if (!part->has_normals && part->flat)
			mesh_flat_normals(positions, part->indices, part->index_count, normals);
		else if (!part->has_normals)
			mesh_generate_normals(positions, part->indices, part->index_count,
					      part->first_vertex, part->vertex_count, normals);
	}
}

void anim_play_free(struct anim_play *p)
{
	if (!p)
		return;
	for (uint32_t i = 0; p->parts && i < p->part_count; i++) {
		free(p->parts[i].indices);
		free(p->parts[i].target_positions);
		free(p->parts[i].target_normals);
	}
	for (uint32_t s = 0; p->skins && s < p->skin_count; s++) {
		free(p->skins[s].joints);
		free(p->skins[s].inverse_bind);
	}
	free(p->parts);
	free(p->skins);
	free(p->positions);
	free(p->normals);
	free(p->joints);
	free(p->weights);
	free(p->worlds);
	free(p->joint_matrices);
	free(p->morphed);
	free(p->gpu_joints);
	free(p->gpu_weights);
	free(p->rows);
	free(p->node_bone);
	free(p->gpu_morph);
	mesh_anim_free(p->anim);
	free(p);
}
