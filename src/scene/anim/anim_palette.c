/* Splitting a skinned primitive into draws whose joints fit the palette
 * (anim_palette.h): one pass over the triangles, every array bounded by
 * the index count, so a large primitive costs time in proportion. */
#include "scene/anim/anim_palette.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

uint32_t anim_palette_size(int max_vertex_uniform_vectors, int reserved)
{
	return max_vertex_uniform_vectors > reserved
		   ? (uint32_t)(max_vertex_uniform_vectors - reserved) / 3
		   : 0;
}

struct split {
	const uint16_t *joints;
	const float *weights;
	int32_t *local;	 /* skin joint -> its place in the open draw's palette, or -1 */
	uint32_t *stamp; /* input vertex -> 1 + the draw that copied it last */
	uint32_t *copy;	 /* input vertex -> its copy in that draw */
	uint32_t draws_room, joints_room;
	struct anim_palette *out;
};

/* The distinct joints of non-zero weight a triangle's vertices name. */
static int triangle_joints(const struct split *s, const uint32_t *tri, uint32_t joint_count,
			   uint16_t *found)
{
	int n = 0;

	for (int c = 0; c < 3; c++)
		for (int k = 0; k < 4; k++) {
			size_t at = (size_t)tri[c] * 4 + (size_t)k;
			uint16_t j = s->joints[at];
			int seen = 0;

			if (!(s->weights[at] != 0.0f))
				continue;
			if (j >= joint_count)
				return -EINVAL;
			for (int i = 0; i < n; i++)
				seen |= found[i] == j;
			if (!seen)
				found[n++] = j;
		}
	return n;
}

static int grow(void **p, uint32_t *room, uint32_t need, size_t size)
{
	if (need <= *room)
		return 0;
	uint32_t r = *room ? *room * 2 : 16;
	while (r < need)
		r *= 2;
	void *q = realloc(*p, (size_t)r * size);
	if (!q)
		return -ENOMEM;
	*p = q;
	*room = r;
	return 0;
}

/* Closes the open draw (if it drew anything) and opens an empty one. */
static int open_draw(struct split *s)
{
	struct anim_palette *o = s->out;

	if (o->draw_count > 0) {
		struct anim_palette_draw *d = &o->draws[o->draw_count - 1];

		if (d->index_count == 0)
			return 0;
		for (uint32_t i = 0; i < d->joint_count; i++)
			s->local[o->joints[d->joint_first + i]] = -1;
	}
	if (grow((void **)&o->draws, &s->draws_room, o->draw_count + 1, sizeof(*o->draws)))
		return -ENOMEM;
	struct anim_palette_draw *d = &o->draws[o->draw_count++];
	d->first_index = o->index_count;
	d->index_count = 0;
	d->joint_first = o->draw_count > 1 ? d[-1].joint_first + d[-1].joint_count : 0;
	d->joint_count = 0;
	return 0;
}

static int add_joints(struct split *s, const uint16_t *found, int n)
{
	struct anim_palette *o = s->out;
	struct anim_palette_draw *d = &o->draws[o->draw_count - 1];

	for (int i = 0; i < n; i++) {
		if (s->local[found[i]] >= 0)
			continue;
		if (grow((void **)&o->joints, &s->joints_room, d->joint_first + d->joint_count + 1,
			 sizeof(*o->joints)))
			return -ENOMEM;
		s->local[found[i]] = (int32_t)d->joint_count;
		o->joints[d->joint_first + d->joint_count++] = found[i];
	}
	return 0;
}

static void add_vertex(struct split *s, uint32_t v)
{
	struct anim_palette *o = s->out;

	if (s->stamp[v] != o->draw_count) {
		uint32_t c = o->vertex_count++;

		o->source[c] = v;
		for (int k = 0; k < 4; k++) {
			size_t at = (size_t)v * 4 + (size_t)k;

			o->vertex_joints[(size_t)c * 4 + (size_t)k] =
			    s->weights[at] != 0.0f ? (uint16_t)s->local[s->joints[at]] : 0;
		}
		s->stamp[v] = o->draw_count;
		s->copy[v] = c;
	}
	o->indices[o->index_count++] = s->copy[v];
	o->draws[o->draw_count - 1].index_count++;
}

static int split_all(struct split *s, const uint32_t *indices, uint32_t index_count,
		     uint32_t vertex_count, uint32_t joint_count, uint32_t palette)
{
	int ret = open_draw(s);

	for (uint32_t t = 0; !ret && t + 3 <= index_count; t += 3) {
		const uint32_t *tri = indices + t;
		uint16_t found[12];
		int n, fresh = 0;

		if (tri[0] >= vertex_count || tri[1] >= vertex_count || tri[2] >= vertex_count)
			return -EINVAL;
		n = triangle_joints(s, tri, joint_count, found);
		if (n < 0)
			return n;
		if ((uint32_t)n > palette)
			return -E2BIG;
		for (int i = 0; i < n; i++)
			fresh += s->local[found[i]] < 0;
		if (s->out->draws[s->out->draw_count - 1].joint_count + (uint32_t)fresh > palette)
			ret = open_draw(s);
		if (!ret)
			ret = add_joints(s, found, n);
		for (int c = 0; !ret && c < 3; c++)
			add_vertex(s, tri[c]);
	}
	return ret;
}

int anim_palette_split(const uint32_t *indices, uint32_t index_count, const uint16_t *joints,
		       const float *weights, uint32_t vertex_count, uint32_t joint_count,
		       uint32_t palette, struct anim_palette *out)
{
	struct split s = {.joints = joints, .weights = weights, .out = out};
	size_t n = index_count ? index_count : 1;
	int ret = -ENOMEM;

	memset(out, 0, sizeof(*out));
	s.local = malloc((joint_count ? joint_count : 1) * sizeof(*s.local));
	s.stamp = calloc(vertex_count ? vertex_count : 1, sizeof(*s.stamp));
	s.copy = malloc((vertex_count ? vertex_count : 1) * sizeof(*s.copy));
	out->source = malloc(n * sizeof(*out->source));
	out->vertex_joints = malloc(n * 4 * sizeof(*out->vertex_joints));
	out->indices = malloc(n * sizeof(*out->indices));
	if (s.local && s.stamp && s.copy && out->source && out->vertex_joints && out->indices) {
		for (uint32_t j = 0; j < joint_count; j++)
			s.local[j] = -1;
		ret = split_all(&s, indices, index_count, vertex_count, joint_count, palette);
	}
	if (!ret && out->draw_count && out->draws[out->draw_count - 1].index_count == 0)
		out->draw_count--; // nothing was drawn at all
	free(s.local);
	free(s.stamp);
	free(s.copy);
	if (ret)
		anim_palette_release(out);
	return ret;
}

void anim_palette_release(struct anim_palette *p)
{
	free(p->draws);
	free(p->joints);
	free(p->source);
	free(p->vertex_joints);
	free(p->indices);
	memset(p, 0, sizeof(*p));
}
