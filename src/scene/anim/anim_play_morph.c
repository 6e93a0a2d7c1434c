/* Morph targets on the GPU path (scene/anim_play.h): each target's
 * position deltas (and normal deltas where the targets move normals) as
 * vertex arrays of their own, the weights a uniform set a frame, so the
 * vertex shader (shaders/morph.glsl) adds them before the skin, as the
 * CPU's morph_part does. One program draws the model: the targets of
 * every part are weighed by one node's weights; a model whose targets
 * need more attributes than the GPU has, or several nodes' weights, is
 * morphed on the CPU (its arrays replaced a frame), skinned on the GPU
 * still. */
#include "scene/anim/anim_play.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* The targets a vertex carries and whether they move normals; -EXDEV when
 * parts of two nodes have targets. */
static int count_targets(const struct anim_play *p, uint32_t *targets, bool *normals, int *node)
{
	*targets = 0;
	*normals = false;
	*node = -1;
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];

		if (!part->target_count)
			continue;
		if (*node >= 0 && *node != part->node)
			return -EXDEV;
		*node = part->node;
		*targets = part->target_count > *targets ? part->target_count : *targets;
		*normals |= part->target_normals != NULL;
	}
	return 0;
}

uint32_t anim_play_morph_attributes(const struct anim_play *p)
{
	uint32_t targets;
	bool normals;
	int node;

	if (count_targets(p, &targets, &normals, &node))
		return 0;
	return targets * (normals ? 2 : 1);
}

/* The parts' deltas into the per-vertex arrays. */
static void fill(struct anim_play *p)
{
	size_t array = (size_t)p->vertex_count * 3;

	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];
		size_t count = (size_t)part->vertex_count * 3, at = (size_t)part->first_vertex * 3;

		for (uint32_t t = 0; t < part->target_count; t++) {
			float *to = p->gpu_morph + t * array + at;

			memcpy(to, part->target_positions + t * count, count * sizeof(float));
			if (part->target_normals)
				memcpy(to + p->morph_targets * array,
				       part->target_normals + t * count, count * sizeof(float));
		}
	}
}

int anim_play_morph_prepare(struct anim_play *p, uint32_t room, const char **why)
{
	uint32_t targets;
	bool normals;
	int node, ret = count_targets(p, &targets, &normals, &node);

	free(p->gpu_morph); /* a model uploaded again decides again */
	p->gpu_morph = NULL;
	p->morph_targets = 0;
	p->morph_normals = false;
	p->morph_node = -1;
	p->morphs = targets > 0; /* on the CPU unless they fit */
	*why = NULL;
	if (ret == -EXDEV)
		*why = "parts of several nodes have targets, each with its own weights";
	else if (targets > ANIM_PLAY_MORPH_MAX)
		ret = -E2BIG, *why = "more targets than the vertex shader adds";
	else if (targets * (normals ? 2 : 1) > room)
		ret = -ENOSPC,
		*why = "the targets need more vertex attributes than the GPU has left";
	if (ret || !targets)
		return ret;
	p->gpu_morph =
	    calloc((size_t)p->vertex_count * 3 * targets * (normals ? 2 : 1) + 1, sizeof(float));
	if (!p->gpu_morph)
		return -ENOMEM;
	p->morph_targets = targets;
	p->morph_normals = normals;
	p->morph_node = node;
	fill(p);
	p->morphs = false; /* the arrays stay the parts' own */
	return 0;
}

void anim_play_morph_weights(const struct anim_play *p, const struct anim_pose *pose,
			     float *weights)
{
	const struct anim_node *n = p->morph_node >= 0 ? &p->anim->nodes[p->morph_node] : NULL;

	for (uint32_t t = 0; t < ANIM_PLAY_MORPH_MAX; t++)
		weights[t] = n && t < p->morph_targets && t < n->weight_count
				 ? pose->weights[n->weight_offset + t]
				 : 0.0f;
}
