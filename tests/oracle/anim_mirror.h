/* The C mirror of live playback's vertex shader (shaders/morph.glsl and
 * matcap.vert's SKIN_BONES): a vertex of the GPU path (scene/anim_play.h
 * anim_play_gpu_prepare, anim_play_morph_prepare) posed from its own
 * position and normal, its morph targets' deltas by the pose's weights,
 * then its four bones' rows over the weights' sum, in binary32 as the
 * vertex stage computes (GLES2's vertex language is highp). test_anim_play
 * holds it to the bake; the bench measures its error. */
#ifndef MK_ANIM_MIRROR_H
#define MK_ANIM_MIRROR_H

#include "scene/anim/anim_play.h"

#include <stdbool.h>
#include <stdint.h>

/* rows: anim_play_bones'; weights: anim_play_morph_weights'. half_deltas:
 * the deltas rounded to binary16 first (what arrays of half floats,
 * GL_OES_vertex_half_float, would cost). */
void anim_mirror_vertex(const struct anim_play *p, const float *rows, const float *weights,
			uint32_t v, bool half_deltas, float out[3], float n[3]);

#endif
