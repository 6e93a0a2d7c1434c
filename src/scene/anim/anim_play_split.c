/* The GPU path for a model with more bones than one palette holds: each
 * draw range cut by anim_palette_split into draws whose bones fit, so a
 * rigged figure of sixty joints still skins in the vertex shader of a
 * GPU with GLES2's 128 uniform vectors. Done once, at upload. */
#include "scene/anim/anim_play.h"
#include "scene/anim/anim_palette.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

void anim_play_split_release(struct anim_play_split *s)
{
	free(s->source);
	free(s->indices);
	free(s->ranges);
	free(s->variant_materials);
	free(s->origin);
	free(s->palette_first);
	free(s->palette_count);
	free(s->bones);
	free(s->joints);
	free(s->weights);
	free(s->positions);
	free(s->normals);
	memset(s, 0, sizeof(*s));
}

void anim_play_split_gather(const struct anim_play_split *s, const float *from, int width,
			    float *to)
{
	for (uint32_t i = 0; i < s->vertex_count; i++)
		memcpy(to + (size_t)i * width, from + (size_t)s->source[i] * width,
		       (size_t)width * sizeof(float));
}

/* Room for one more range's split: everything grows by what it holds. */
static int grow(struct anim_play_split *o, const struct anim_palette *sp, uint32_t bones)
{
	size_t v = (size_t)o->vertex_count + sp->vertex_count, n = o->index_count + sp->index_count;
	size_t r = (size_t)o->range_count + sp->draw_count;
	void *a = realloc(o->source, v * 4 + 4), *b = realloc(o->indices, n * 4 + 4);

	o->source = a ? a : o->source;
	o->indices = b ? b : o->indices;
	if (!a || !b)
		return -ENOMEM;
	a = realloc(o->joints, v * 16 + 16), b = realloc(o->weights, v * 16 + 16);
	o->joints = a ? a : o->joints;
	o->weights = b ? b : o->weights;
	if (!a || !b)
		return -ENOMEM;
	a = realloc(o->ranges, r * sizeof(*o->ranges) + 1);
	o->ranges = a ? a : o->ranges;
	b = realloc(o->palette_first, r * 4 + 4);
	o->palette_first = b ? b : o->palette_first;
	if (!a || !b)
		return -ENOMEM;
	a = realloc(o->origin, r * 4 + 4);
	o->origin = a ? a : o->origin;
	if (!a)
		return -ENOMEM;
	a = realloc(o->palette_count, r * 4 + 4);
	o->palette_count = a ? a : o->palette_count;
	b = realloc(o->bones, (bones + (size_t)sp->draws[sp->draw_count - 1].joint_first +
			       sp->draws[sp->draw_count - 1].joint_count) *
				      2 +
				  2);
	o->bones = b ? b : o->bones;
	return a && b ? 0 : -ENOMEM;
}

/* One range's split appended to out; bones: how many out holds so far. */
static int append(struct anim_play_split *o, const struct anim_play *p,
		  const struct mesh_range *range, uint32_t from, const struct anim_palette *sp,
		  uint32_t *bones)
{
	uint32_t v0 = o->vertex_count, i0 = o->index_count;
	int ret = sp->draw_count ? grow(o, sp, *bones) : 0;

	if (ret || !sp->draw_count)
		return ret;
	for (uint32_t v = 0; v < sp->vertex_count; v++) {
		o->source[v0 + v] = sp->source[v];
		for (int k = 0; k < 4; k++) {
			o->joints[(size_t)(v0 + v) * 4 + k] = sp->vertex_joints[(size_t)v * 4 + k];
			o->weights[(size_t)(v0 + v) * 4 + k] =
			    p->gpu_weights[(size_t)sp->source[v] * 4 + k];
		}
	}
	for (uint32_t i = 0; i < sp->index_count; i++)
		o->indices[i0 + i] = sp->indices[i] + v0;
	for (uint32_t d = 0; d < sp->draw_count; d++) {
		const struct anim_palette_draw *w = &sp->draws[d];
		uint32_t r = o->range_count++;

		o->ranges[r] = *range;
		o->origin[r] = from;
		o->ranges[r].first_index = i0 + w->first_index;
		o->ranges[r].index_count = w->index_count;
		o->palette_first[r] = *bones + w->joint_first;
		o->palette_count[r] = w->joint_count;
		if (w->joint_count > o->palette_max)
			o->palette_max = w->joint_count;
	}
	memcpy(o->bones + *bones, sp->joints,
	       ((size_t)sp->draws[sp->draw_count - 1].joint_first +
		sp->draws[sp->draw_count - 1].joint_count) *
		   2);
	*bones +=
	    sp->draws[sp->draw_count - 1].joint_first + sp->draws[sp->draw_count - 1].joint_count;
	o->vertex_count += sp->vertex_count;
	o->index_count += sp->index_count;
	return 0;
}

/* Each variant's table over the split's draws: a draw shows, in every
 * variant, what the range it was cut from shows, so that a switch stays a
 * change of materials (render_variant.c) on these draws too. */
static int split_variants(struct anim_play_split *o, const struct mesh *m)
{
	size_t n = (size_t)m->variant_count * o->range_count;

	if (!m->variant_count || !m->variant_materials || m->variant_ranges != m->range_count)
		return 0;
	o->variant_materials = malloc(n * sizeof(uint32_t) + 1);
	if (!o->variant_materials)
		return -ENOMEM;
	for (uint32_t v = 0; v < m->variant_count; v++)
		for (uint32_t r = 0; r < o->range_count; r++)
			o->variant_materials[(size_t)v * o->range_count + r] =
			    m->variant_materials[(size_t)v * m->range_count + o->origin[r]];
	return 0;
}

int anim_play_split(const struct anim_play *p, const struct mesh *m, uint32_t palette,
		    struct anim_play_split *out)
{
	struct mesh_range whole = {0, m->index_count, 0, {0, 0, 0}};
	const struct mesh_range *ranges = m->range_count ? m->ranges : &whole;
	uint32_t count = m->range_count ? m->range_count : 1, bones = 0;
	uint16_t *joints = malloc((size_t)m->vertex_count * 8 + 8);
	int ret = joints ? 0 : -ENOMEM;

	memset(out, 0, sizeof(*out));
	for (size_t i = 0; joints && i < (size_t)m->vertex_count * 4; i++)
		joints[i] = (uint16_t)p->gpu_joints[i];
	for (uint32_t r = 0; !ret && r < count; r++) {
		struct anim_palette sp;

		ret = anim_palette_split(m->indices + ranges[r].first_index, ranges[r].index_count,
					 joints, p->gpu_weights, m->vertex_count, p->bones, palette,
					 &sp);
		if (!ret)
			ret = append(out, p, &ranges[r], r, &sp, &bones);
		anim_palette_release(&sp); /* a failed split left it empty */
	}
	free(joints);
	if (!ret)
		ret = split_variants(out, m);
	if (!ret) {
		out->positions = malloc((size_t)out->vertex_count * 12 + 4);
		out->normals = malloc((size_t)out->vertex_count * 12 + 4);
		ret = out->positions && out->normals ? 0 : -ENOMEM;
	}
	if (ret)
		anim_play_split_release(out);
	return ret;
}
