#include "anim_mirror.h"
#include "fp16.h"

#include <math.h>
#include <stddef.h>

static float delta(const float *d, bool half)
{
	return half ? (float)fp16_round(*d) : *d;
}

/* morph(): target by target, position += w * delta (normal likewise). */
static void morph(const struct anim_play *p, const float *weights, uint32_t v, bool half,
		  float at[3], float nv[3])
{
	size_t array = (size_t)p->vertex_count * 3, o = (size_t)v * 3;

	for (uint32_t t = 0; t < p->morph_targets; t++) {
		const float *dp = p->gpu_morph + t * array + o;
		const float *dn = p->gpu_morph + (p->morph_targets + t) * array + o;

		for (int k = 0; k < 3; k++) {
			at[k] += weights[t] * delta(dp + k, half);
			if (p->morph_normals)
				nv[k] += weights[t] * delta(dn + k, half);
		}
	}
}

void anim_mirror_vertex(const struct anim_play *p, const float *rows, const float *weights,
			uint32_t v, bool half_deltas, float out[3], float n[3])
{
	const float *j = p->gpu_joints + (size_t)v * 4, *w = p->gpu_weights + (size_t)v * 4;
	float total = w[0] + w[1] + w[2] + w[3], r[12] = {0}, len = 0;
	float at[3], nv[3];

	for (int k = 0; k < 3; k++) {
		at[k] = p->positions[(size_t)v * 3 + k];
		nv[k] = p->normals[(size_t)v * 3 + k];
	}
	if (p->morph_targets)
		morph(p, weights, v, half_deltas, at, nv);
	for (int k = 0; k < 4; k++) {
		float share = w[k] / total;

		for (int i = 0; i < 12; i++)
			r[i] += share * rows[(size_t)(int)(j[k] + 0.5f) * 12 + i];
	}
	for (int i = 0; i < 3; i++) {
		out[i] =
		    r[i * 4] * at[0] + r[i * 4 + 1] * at[1] + r[i * 4 + 2] * at[2] + r[i * 4 + 3];
		n[i] = r[i * 4] * nv[0] + r[i * 4 + 1] * nv[1] + r[i * 4 + 2] * nv[2];
		len += n[i] * n[i];
	}
	len = sqrtf(len);
	for (int i = 0; i < 3; i++)
		n[i] = len > 0 ? n[i] / len : (float)(i == 2);
}
