/* Live playback's GPU path (scene/anim_play.h): one palette of bones for
 * the whole model, so that its draws are today's (no range is split):
 * bone 0 holds the clip's fit alone (an unweighted vertex, a part drawn
 * at the skeleton's root), then every skin's joints (world x inverse
 * bind), then each node rigid parts follow (its world), all with the fit.
 * A model with more bones than the GPU's palette is split into draws
 * (anim_play_split.c); one with more than four joints a vertex
 * (JOINTS_1) plays on the CPU. */
#include "scene/anim/anim_play.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static uint32_t count_bones(struct anim_play *p)
{
	uint32_t bones = 1 + p->joint_total; /* bone 0, then every skin's joints */

	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];

		if (part->skin < 0 && !part->at_root && !p->node_bone[part->node])
			p->node_bone[part->node] = (int)bones++;
	}
	return bones;
}

/* A skinned vertex's bones: its joints of weight, else bone 0. */
static void skinned_vertex(struct anim_play *p, const struct anim_play_part *part, uint32_t v)
{
	const struct anim_play_skin *s = &p->skins[part->skin];
	float *j = p->gpu_joints + (size_t)v * 4, *w = p->gpu_weights + (size_t)v * 4;
	float total = 0;

	for (int k = 0; k < 4; k++) {
		uint16_t joint = p->joints[(size_t)v * p->influences + k];
		float weight = p->weights[(size_t)v * p->influences + k];
		bool used = weight != 0.0f && joint < s->joint_count;

		j[k] = used ? (float)(1 + s->first + joint) : 0.0f;
		w[k] = used ? weight : 0.0f;
		total += w[k];
	}
	if (total == 0.0f)
		w[0] = 1.0f; /* bone 0, where the bake leaves it */
}

static void drop_gpu(struct anim_play *p)
{
	free(p->node_bone);
	free(p->gpu_joints);
	free(p->gpu_weights);
	free(p->rows);
	p->node_bone = NULL;
	p->gpu_joints = p->gpu_weights = p->rows = NULL;
	p->bones = 0;
	p->morphs = false;
}

int anim_play_gpu_prepare(struct anim_play *p, uint32_t palette)
{
	size_t n = (size_t)p->vertex_count * 4;

	drop_gpu(p); /* a model uploaded again decides again */
	/* Normals generated from the posed triangles: the CPU's. */
	for (uint32_t i = 0; i < p->part_count; i++)
		if (!p->parts[i].has_normals)
			return -ENOTSUP;
	/* The shader blends one vec4 of bones: a second set (JOINTS_1) would
	 * need two more attributes and a longer blend in every skinned
	 * program, for the rare model that has it; the CPU blends them all. */
	if (p->joints && p->influences > 4)
		return -ERANGE;
	p->node_bone = calloc(p->anim->node_count + 1, sizeof(*p->node_bone));
	if (!p->node_bone)
		return -ENOMEM;
	p->bones = count_bones(p);
	p->gpu_joints = calloc(n + 1, sizeof(float));
	p->gpu_weights = calloc(n + 1, sizeof(float));
	p->rows = calloc((size_t)p->bones * 12, sizeof(float));
	if (!p->gpu_joints || !p->gpu_weights || !p->rows) {
		p->bones = 0;
		return -ENOMEM;
	}
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];
		int bone = part->skin < 0 && !part->at_root ? p->node_bone[part->node] : 0;

		p->morphs |= part->target_count > 0;
		for (uint32_t v = part->first_vertex; v < part->first_vertex + part->vertex_count;
		     v++) {
			if (part->skin >= 0) {
				skinned_vertex(p, part, v);
				continue;
			}
			p->gpu_joints[(size_t)v * 4] = (float)bone;
			p->gpu_weights[(size_t)v * 4] = 1.0f;
		}
	}
	return p->bones > palette ? -E2BIG : 0;
}

const char *anim_play_gpu_why(int err)
{
	switch (err) {
	case 0:
		return NULL;
	case -E2BIG:
		return "a triangle's bones alone outnumber the GPU's palette";
	case -ENOTSUP:
		return "a part's normals come from its posed triangles";
	case -ERANGE:
		return "its vertices have more than four joints (JOINTS_1), the vertex shader "
		       "blends four";
	case -ENOMEM:
		return "out of memory";
	default:
		return "an unknown reason";
	}
}

/* rows = fit x m, as 3 rows of 4 (double on the way: the fit's centre
 * may be far from the origin). */
static void put_bone(const struct anim_play *p, const double m[16], float *rows)
{
	for (int r = 0; r < 3; r++) {
		for (int c = 0; c < 4; c++)
			rows[r * 4 + c] = (float)(m[c * 4 + r] * p->scale);
		rows[r * 4 + 3] -= (float)(p->center[r] * p->scale);
	}
}

void anim_play_bones(struct anim_play *p, const struct anim_pose *pose, float *rows)
{
	static const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
	double m[16];

	anim_play_joints(p, pose);
	put_bone(p, identity, rows);
	for (uint32_t j = 0; j < p->joint_total; j++)
		put_bone(p, p->joint_matrices[j], rows + (size_t)(1 + j) * 12);
	for (size_t n = 0; n < p->anim->node_count; n++) {
		if (!p->node_bone[n])
			continue;
		for (int k = 0; k < 16; k++)
			m[k] = p->worlds[n][k];
		put_bone(p, m, rows + (size_t)p->node_bone[n] * 12);
	}
}
