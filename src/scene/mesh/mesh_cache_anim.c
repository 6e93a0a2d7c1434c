/* What live playback keeps (struct anim_play and its struct mesh_anim) as
 * the bytes of a prepared-mesh cache entry's last section, and read back
 * from them. The entry's checksum finds damage; the reading checks every
 * count, index and sampler as well (as the glTF loader does), so that
 * bytes that pass the checksum but not these (a forgery, a bug of the
 * writer) are refused, never trusted: the model is parsed again. */
#include "scene/mesh/mesh_cache_anim.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ANIM_MAGIC   0x4e414b4du /* "MKAN" */
#define ANIM_VERSION 2u		 /* 2: a part's flat normals (bit 1 of has_normals) */
#define NO_NAME	     0xffffffffu
/* Joints a vertex at most: the loader reads three joint sets (gltf_play.cc). */
#define INFLUENCES_MAX 12u

/* A growing buffer of 32-bit words (a double: two). */
struct put {
	char *data;
	size_t size, cap;
	bool failed;
};

static void put_bytes(struct put *b, const void *data, size_t size)
{
	size_t padded = (size + 3) & ~(size_t)3;

	if (b->failed)
		return;
	if (b->size + padded > b->cap) {
		size_t cap = b->cap ? b->cap : 4096;
		char *grown;

		while (cap < b->size + padded)
			cap *= 2;
		grown = realloc(b->data, cap);
		if (!grown) {
			b->failed = true;
			return;
		}
		b->data = grown;
		b->cap = cap;
	}
	if (size)
		memcpy(b->data + b->size, data, size);
	memset(b->data + b->size + size, 0, padded - size);
	b->size += padded;
}

static void put_u32(struct put *b, uint32_t v)
{
	put_bytes(b, &v, 4);
}

static void put_f64(struct put *b, double v)
{
	put_bytes(b, &v, 8);
}

/* The reader: every take checks the bytes left, and fails for good. */
struct get {
	const char *p;
	size_t left;
	bool ok;
};

static bool get_bytes(struct get *g, void *out, size_t count, size_t width)
{
	size_t size, padded;

	if (!g->ok || (width && count > SIZE_MAX / 4 / width))
		return g->ok = false;
	size = count * width;
	padded = (size + 3) & ~(size_t)3;
	if (padded > g->left)
		return g->ok = false;
	if (size)
		memcpy(out, g->p, size);
	g->p += padded;
	g->left -= padded;
	return true;
}

static uint32_t get_u32(struct get *g)
{
	uint32_t v = 0;

	get_bytes(g, &v, 1, 4);
	return v;
}

static double get_f64(struct get *g)
{
	double v = 0;

	get_bytes(g, &v, 1, 8);
	return v;
}

/* count elements of width bytes, in an allocation of their own (NULL for
 * none, or on failure: g->ok says which). */
static void *get_array(struct get *g, size_t count, size_t width)
{
	void *a;

	if (!g->ok || !count || count > g->left / width) {
		g->ok = g->ok && !count;
		return NULL;
	}
	a = malloc(count * width);
	if (!a || !get_bytes(g, a, count, width)) {
		free(a);
		return g->ok = false, NULL;
	}
	return a;
}

/* A count that cannot exceed what is left: each of its items takes at
 * least min bytes (so that a damaged count allocates nothing huge). */
static uint32_t get_count(struct get *g, size_t min)
{
	uint32_t n = get_u32(g);

	if (g->ok && (size_t)n > g->left / min)
		g->ok = false;
	return g->ok ? n : 0;
}

static bool finite_all(const float *v, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!isfinite(v[i]))
			return false;
	return true;
}

static size_t sampler_values(const struct anim_sampler *s)
{
	return s->count * (size_t)s->width * (s->interp == ANIM_CUBICSPLINE ? 3 : 1);
}

static void put_anim(struct put *b, const struct mesh_anim *a)
{
	put_u32(b, (uint32_t)a->node_count);
	for (size_t i = 0; i < a->node_count; i++) {
		const struct anim_node *n = &a->nodes[i];

		put_u32(b, (uint32_t)n->parent);
		put_bytes(b, &n->rest, sizeof(n->rest));
		put_u32(b, n->has_matrix);
		put_bytes(b, n->matrix, sizeof(n->matrix));
		put_u32(b, (uint32_t)n->weight_offset);
		put_u32(b, (uint32_t)n->weight_count);
	}
	put_u32(b, (uint32_t)a->weight_total);
	put_bytes(b, a->rest_weights, a->weight_total * sizeof(float));
	put_u32(b, (uint32_t)a->clip_count);
	for (size_t c = 0; c < a->clip_count; c++) {
		const struct anim_clip *clip = &a->clips[c];

		put_u32(b, clip->name ? (uint32_t)strlen(clip->name) : NO_NAME);
		if (clip->name)
			put_bytes(b, clip->name, strlen(clip->name));
		put_u32(b, (uint32_t)clip->sampler_count);
		for (size_t s = 0; s < clip->sampler_count; s++) {
			const struct anim_sampler *sm = &clip->samplers[s];

			put_u32(b, (uint32_t)sm->count);
			put_u32(b, (uint32_t)sm->width);
			put_u32(b, (uint32_t)sm->interp);
			put_bytes(b, sm->input, sm->count * sizeof(float));
			put_bytes(b, sm->output, sampler_values(sm) * sizeof(float));
		}
		put_u32(b, (uint32_t)clip->channel_count);
		for (size_t k = 0; k < clip->channel_count; k++) {
			put_u32(b, (uint32_t)clip->channels[k].node);
			put_u32(b, (uint32_t)clip->channels[k].path);
			put_u32(b, (uint32_t)clip->channels[k].sampler);
		}
	}
}

static void put_play(struct put *b, const struct anim_play *p)
{
	size_t vc = p->vertex_count;

	put_bytes(b, p->center, sizeof(p->center));
	put_f64(b, p->scale);
	put_u32(b, p->vertex_count);
	put_bytes(b, p->positions, vc * 3 * sizeof(float));
	put_bytes(b, p->normals, vc * 3 * sizeof(float));
	put_u32(b, p->joints ? p->influences : 0);
	if (p->joints) {
		put_bytes(b, p->joints, vc * p->influences * sizeof(uint16_t));
		put_bytes(b, p->weights, vc * p->influences * sizeof(float));
	}
	put_u32(b, p->skin_count);
	for (uint32_t s = 0; s < p->skin_count; s++) {
		const struct anim_play_skin *sk = &p->skins[s];

		put_u32(b, sk->joint_count);
		put_bytes(b, sk->joints, sk->joint_count * sizeof(int));
		put_bytes(b, sk->inverse_bind, (size_t)sk->joint_count * 16 * sizeof(float));
	}
	put_u32(b, p->part_count);
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part *part = &p->parts[i];
		size_t deltas = (size_t)part->target_count * part->vertex_count * 3;

		put_u32(b, (uint32_t)part->node);
		put_u32(b, (uint32_t)part->skin);
		put_u32(b, part->at_root);
		put_u32(b, part->first_vertex);
		put_u32(b, part->vertex_count);
		put_u32(b, (uint32_t)part->has_normals | (uint32_t)part->flat << 1);
		put_u32(b, part->index_count);
		put_bytes(b, part->indices, part->index_count * sizeof(uint32_t));
		put_u32(b, part->target_count);
		put_u32(b, part->target_normals != NULL);
		put_bytes(b, part->target_positions, deltas * sizeof(float));
		if (part->target_normals)
			put_bytes(b, part->target_normals, deltas * sizeof(float));
	}
}

int mesh_cache_anim_encode(const struct anim_play *p, void **out, size_t *size)
{
	struct put b = {NULL, 0, 0, false};

	put_u32(&b, ANIM_MAGIC);
	put_u32(&b, ANIM_VERSION);
	put_anim(&b, p->anim);
	put_play(&b, p);
	if (b.failed) {
		free(b.data);
		return -ENOMEM;
	}
	*out = b.data;
	*size = b.size;
	return 0;
}

static bool get_node(struct get *g, struct anim_node *n, size_t node_count)
{
	uint32_t parent = get_u32(g);

	n->parent = (int)parent;
	get_bytes(g, &n->rest, 1, sizeof(n->rest));
	n->has_matrix = get_u32(g);
	get_bytes(g, n->matrix, 16, sizeof(float));
	n->weight_offset = get_u32(g);
	n->weight_count = get_u32(g);
	return g->ok && (parent == 0xffffffffu || parent < node_count) &&
	       finite_all((const float *)&n->rest, sizeof(n->rest) / sizeof(float)) &&
	       finite_all(n->matrix, 16);
}

static bool get_sampler(struct get *g, struct anim_sampler *s)
{
	uint32_t interp;

	s->count = get_count(g, 4);
	s->width = (int)get_u32(g);
	interp = get_u32(g);
	if (!g->ok || interp > ANIM_CUBICSPLINE || s->width < 1 || s->width > 65536 || !s->count)
		return g->ok = false;
	s->interp = (enum anim_interp)interp;
	s->input = get_array(g, s->count, sizeof(float));
	/* Checked before the product is made (a 32-bit size_t). */
	if (g->ok && (size_t)s->width * (s->interp == ANIM_CUBICSPLINE ? 3 : 1) >
			 g->left / sizeof(float) / s->count)
		return g->ok = false;
	s->output = get_array(g, sampler_values(s), sizeof(float));
	return g->ok && !anim_sampler_check(s);
}

/* A channel as the loader lets it be (gltf_anim.cc read_channel). */
static bool channel_sane(const struct mesh_anim *a, const struct anim_clip *clip,
			 const struct anim_channel *c)
{
	size_t want;

	if (c->node < 0 || (size_t)c->node >= a->node_count || c->sampler < 0 ||
	    (size_t)c->sampler >= clip->sampler_count)
		return false;
	want = c->path == ANIM_ROTATION	 ? 4
	       : c->path == ANIM_WEIGHTS ? a->nodes[c->node].weight_count
					 : 3;
	return (size_t)clip->samplers[c->sampler].width == want &&
	       (c->path == ANIM_WEIGHTS || !a->nodes[c->node].has_matrix);
}

static bool get_clip(struct get *g, const struct mesh_anim *a, struct anim_clip *clip)
{
	uint32_t len = get_u32(g);

	if (g->ok && len != NO_NAME) {
		if (len > g->left || !(clip->name = calloc(1, (size_t)len + 1)))
			return g->ok = false;
		get_bytes(g, clip->name, len, 1);
		if (g->ok && strlen(clip->name) != len)
			return g->ok = false;
	}
	clip->sampler_count = get_count(g, 16);
	clip->samplers = calloc(clip->sampler_count + 1, sizeof(*clip->samplers));
	if (!clip->samplers)
		return clip->sampler_count = 0, g->ok = false;
	for (size_t s = 0; g->ok && s < clip->sampler_count; s++)
		if (get_sampler(g, &clip->samplers[s]))
			clip->duration = fmax(clip->duration,
					      clip->samplers[s].input[clip->samplers[s].count - 1]);
	clip->channel_count = get_count(g, 12);
	clip->channels = calloc(clip->channel_count + 1, sizeof(*clip->channels));
	if (!clip->channels)
		return clip->channel_count = 0, g->ok = false;
	for (size_t k = 0; g->ok && k < clip->channel_count; k++) {
		struct anim_channel *c = &clip->channels[k];
		uint32_t path;

		c->node = (int)get_u32(g);
		path = get_u32(g);
		c->sampler = (int)get_u32(g);
		/* The path in range before it is an enum. */
		c->path = path <= ANIM_WEIGHTS ? (enum anim_path)path : ANIM_TRANSLATION;
		if (g->ok && (path > ANIM_WEIGHTS || !channel_sane(a, clip, c)))
			g->ok = false;
	}
	return g->ok;
}

static bool get_anim(struct get *g, struct mesh_anim *a)
{
	a->node_count = get_count(g, 120);
	a->nodes = calloc(a->node_count + 1, sizeof(*a->nodes));
	a->order = calloc(a->node_count + 1, sizeof(*a->order));
	if (!a->nodes || !a->order)
		return g->ok = false;
	for (size_t i = 0; g->ok && i < a->node_count; i++)
		if (!get_node(g, &a->nodes[i], a->node_count))
			g->ok = false;
	a->weight_total = get_count(g, 4);
	for (size_t i = 0; g->ok && i < a->node_count; i++)
		if (a->nodes[i].weight_offset > a->weight_total ||
		    a->nodes[i].weight_count > a->weight_total - a->nodes[i].weight_offset)
			g->ok = false;
	a->rest_weights = get_array(g, a->weight_total, sizeof(float));
	if (!g->ok || !anim_order(a->nodes, a->node_count, a->order))
		return g->ok = false;
	a->clip_count = get_count(g, 12);
	a->clips = calloc(a->clip_count + 1, sizeof(*a->clips));
	if (!a->clips)
		return a->clip_count = 0, g->ok = false;
	for (size_t c = 0; g->ok && c < a->clip_count; c++)
		get_clip(g, a, &a->clips[c]);
	return g->ok;
}

static bool get_skin(struct get *g, struct anim_play_skin *s, size_t node_count)
{
	s->joint_count = get_count(g, 68);
	s->joints = get_array(g, s->joint_count, sizeof(int));
	s->inverse_bind = get_array(g, (size_t)s->joint_count * 16, sizeof(float));
	for (uint32_t j = 0; g->ok && j < s->joint_count; j++)
		if (s->joints[j] < 0 || (size_t)s->joints[j] >= node_count)
			g->ok = false;
	if (g->ok && !finite_all(s->inverse_bind, (size_t)s->joint_count * 16))
		g->ok = false;
	return g->ok;
}

/* A part's fields, each in range: its vertices in the mesh, its
 * triangles among its own vertices (the normals generated from them),
 * its node and skin among those that exist. */
static bool get_part(struct get *g, const struct anim_play *p, struct anim_play_part *part)
{
	size_t deltas;
	bool has_normals;
	uint32_t flags;

	part->node = (int)get_u32(g);
	part->skin = (int)get_u32(g);
	part->at_root = get_u32(g);
	part->first_vertex = get_u32(g);
	part->vertex_count = get_u32(g);
	flags = get_u32(g);
	part->has_normals = flags & 1;
	part->flat = (flags >> 1) & 1;
	part->index_count = get_count(g, 4);
	if (!g->ok || part->node < 0 || (size_t)part->node >= p->anim->node_count ||
	    part->skin < -1 || (part->skin >= 0 && (uint32_t)part->skin >= p->skin_count) ||
	    (part->skin >= 0 && !p->joints) || part->first_vertex > p->vertex_count ||
	    part->vertex_count > p->vertex_count - part->first_vertex || part->index_count % 3)
		return g->ok = false;
	part->indices = get_array(g, part->index_count, sizeof(uint32_t));
	for (uint32_t i = 0; g->ok && i < part->index_count; i++)
		if (part->indices[i] < part->first_vertex ||
		    part->indices[i] - part->first_vertex >= part->vertex_count)
			g->ok = false;
	part->target_count = get_u32(g);
	deltas = (size_t)part->target_count * part->vertex_count * 3;
	if (!g->ok || (part->vertex_count && part->target_count > g->left / 4 / part->vertex_count))
		return g->ok = false;
	has_normals = get_u32(g);
	part->target_positions = get_array(g, deltas, sizeof(float));
	if (has_normals)
		part->target_normals = get_array(g, deltas, sizeof(float));
	return g->ok && finite_all(part->target_positions, part->target_positions ? deltas : 0) &&
	       finite_all(part->target_normals, part->target_normals ? deltas : 0);
}

static bool get_play(struct get *g, struct anim_play *p, uint32_t vertex_count)
{
	size_t vc;

	get_bytes(g, p->center, 3, sizeof(double));
	p->scale = get_f64(g);
	p->vertex_count = get_u32(g);
	vc = p->vertex_count;
	if (!g->ok || p->vertex_count != vertex_count || !vc || vc > g->left / 24 ||
	    !isfinite(p->scale) || !(p->scale > 0) || !isfinite(p->center[0]) ||
	    !isfinite(p->center[1]) || !isfinite(p->center[2]))
		return g->ok = false;
	p->positions = get_array(g, vc * 3, sizeof(float));
	p->normals = get_array(g, vc * 3, sizeof(float));
	/* Joints a vertex: 4 a joint set (JOINTS_0, _1, ...), 4 without. */
	p->influences = get_u32(g);
	if (g->ok && p->influences) {
		if (p->influences % 4 || p->influences > INFLUENCES_MAX ||
		    p->influences > g->left / 6 / vc)
			return g->ok = false;
		p->joints = get_array(g, vc * p->influences, sizeof(uint16_t));
		p->weights = get_array(g, vc * p->influences, sizeof(float));
	}
	p->influences = p->influences ? p->influences : 4;
	p->skin_count = get_count(g, 4);
	p->skins = calloc(p->skin_count + 1, sizeof(*p->skins));
	if (!p->skins)
		return g->ok = false;
	for (uint32_t s = 0; g->ok && s < p->skin_count; s++)
		get_skin(g, &p->skins[s], p->anim->node_count);
	p->part_count = get_count(g, 36);
	p->parts = calloc(p->part_count + 1, sizeof(*p->parts));
	if (!p->parts)
		return g->ok = false;
	for (uint32_t i = 0; g->ok && i < p->part_count; i++)
		get_part(g, p, &p->parts[i]);
	return g->ok;
}

int mesh_cache_anim_decode(const void *data, size_t size, uint32_t vertex_count,
			   struct anim_play **out)
{
	struct get g = {data, size, true};
	struct anim_play *p = calloc(1, sizeof(*p));
	int ret = -ENOMEM;

	*out = NULL;
	if (!p || !(p->anim = calloc(1, sizeof(*p->anim))))
		goto fail;
	ret = -EBADMSG;
	if (get_u32(&g) != ANIM_MAGIC || get_u32(&g) != ANIM_VERSION || !get_anim(&g, p->anim) ||
	    !get_play(&g, p, vertex_count) || g.left)
		goto fail;
	ret = anim_play_finish(p);
	if (ret)
		goto fail;
	*out = p;
	return 0;
fail:
	anim_play_free(p);
	return ret;
}

int mesh_cache_pack_live(const struct mesh *m, struct mesh_packed *out)
{
	size_t offset[MESH_ARRAYS], total = 0;
	char *block;
	int ret = mesh_pack(m, VERTEX_FLOAT32, out);

	if (ret)
		return ret;
	for (int a = 0; a < MESH_ARRAYS; a++) {
		offset[a] = total;
		if (out->arrays[a])
			total += (size_t)m->vertex_count *
				 mesh_array_stride(VERTEX_FLOAT32, (enum mesh_array)a);
	}
	block = malloc(total + (size_t)m->index_count * 4 + 1);
	if (!block) {
		mesh_packed_release(out);
		return -ENOMEM;
	}
	for (int a = 0; a < MESH_ARRAYS; a++)
		if (out->arrays[a]) {
			memcpy(block + offset[a], out->arrays[a],
			       (size_t)m->vertex_count *
				   mesh_array_stride(VERTEX_FLOAT32, (enum mesh_array)a));
			out->arrays[a] = block + offset[a];
		}
	memcpy(block + total, m->indices, (size_t)m->index_count * 4);
	out->indices = (const uint32_t *)(const void *)(block + total);
	out->owned = block;
	return 0;
}

static void *copy_of(const void *from, size_t size)
{
	void *to = malloc(size + 1);

	if (to && size)
		memcpy(to, from, size);
	return to;
}

int mesh_cache_unpack_live(const struct mesh_packed *p, struct mesh *out)
{
	float **to[MESH_ARRAYS] = {&out->positions, &out->normals, &out->uvs, &out->tangents,
				   &out->colors,    &out->uv1};
	bool ok = true;

	if (p->format != VERTEX_FLOAT32)
		return -EBADMSG;
	out->vertex_count = p->vertex_count;
	out->index_count = p->index_count;
	for (int a = 0; a < MESH_ARRAYS; a++)
		if (p->arrays[a])
			ok &= !!(*to[a] = copy_of(
				     p->arrays[a],
				     (size_t)p->vertex_count *
					 mesh_array_stride(VERTEX_FLOAT32, (enum mesh_array)a)));
	ok &= !!(out->indices = copy_of(p->indices, (size_t)p->index_count * 4));
	if (p->range_count) {
		ok &= !!(out->ranges = copy_of(p->ranges, p->range_count * sizeof(*p->ranges)));
		out->range_count = p->range_count;
	}
	if (ok)
		return 0;
	for (int a = 0; a < MESH_ARRAYS; a++) {
		free(*to[a]);
		*to[a] = NULL;
	}
	free(out->indices);
	free(out->ranges);
	out->indices = NULL;
	out->ranges = NULL;
	out->range_count = 0;
	return -ENOMEM;
}
