/* What live playback keeps (struct anim_play and its struct mesh_anim) as
 * the bytes of a prepared-mesh cache entry's last section, and read back
 * from them: every struct of the rig described once in a member table
 * (scene/mesh/mesh_cache_nest.h), written and read by the one walker, as
 * the material and range records' tables (mesh_cache_fields.c) are. The entry's
 * checksum finds damage; the reading checks every word, count, index and
 * sampler as well (as the glTF loader does), so that bytes that pass the
 * checksum but not these (a forgery, a bug of the writer) are refused,
 * never trusted: the journal says where, and the model is parsed again.
 * The format is the entry's (mesh_cache.c CACHE_VERSION). */
#include "scene/mesh/mesh_cache_anim.h"
#include "scene/mesh/mesh_cache_nest.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ANIM_MAGIC 0x4e414b4du /* "MKAN" */
/* Joints a vertex at most: the loader reads three joint sets (gltf_play.cc). */
#define INFLUENCES_MAX 12u
/* A sampler's floats a key at most (a weights sampler: a node's targets). */
#define WIDTH_MAX 65536

#define MEMBER MESH_NEST_MEMBER
#define TABLE  MESH_NEST_TABLE

/* What the reader checks against: the play read so far, the mesh's size. */
struct rig_ctx {
	struct anim_play *play;
	uint32_t vertex_count;
};

static uint64_t mul3(uint64_t a, uint64_t b, uint64_t c)
{
	/* Each a 32-bit word at most: no product wraps in 64 bits but a
	 * third factor's, saturated. */
	uint64_t ab = a * b;

	return c && ab > UINT64_MAX / c ? UINT64_MAX : ab * c;
}

/* Counts of the arrays, from the members before them. */
static uint64_t sampler_inputs(const void *o)
{
	return ((const struct anim_sampler *)o)->count;
}

static uint64_t sampler_outputs(const void *o)
{
	const struct anim_sampler *s = o;

	return mul3(s->count, (uint32_t)s->width, s->interp == ANIM_CUBICSPLINE ? 3 : 1);
}

static uint64_t clip_samplers(const void *o)
{
	return ((const struct anim_clip *)o)->sampler_count;
}

static uint64_t clip_channels(const void *o)
{
	return ((const struct anim_clip *)o)->channel_count;
}

static uint64_t anim_nodes(const void *o)
{
	return ((const struct mesh_anim *)o)->node_count;
}

static uint64_t anim_weights(const void *o)
{
	return ((const struct mesh_anim *)o)->weight_total;
}

static uint64_t anim_clips(const void *o)
{
	return ((const struct mesh_anim *)o)->clip_count;
}

static uint64_t skin_joints(const void *o)
{
	return ((const struct anim_play_skin *)o)->joint_count;
}

static uint64_t skin_matrices(const void *o)
{
	return mul3(((const struct anim_play_skin *)o)->joint_count, 16, 1);
}

static uint64_t part_indices(const void *o)
{
	return ((const struct anim_play_part *)o)->index_count;
}

static uint64_t part_deltas(const void *o)
{
	const struct anim_play_part *p = o;

	return mul3(p->target_count, p->vertex_count, 3);
}

static uint64_t play_xyz(const void *o)
{
	return mul3(((const struct anim_play *)o)->vertex_count, 3, 1);
}

static uint64_t play_influences(const void *o)
{
	const struct anim_play *p = o;

	return mul3(p->vertex_count, p->influences, 1);
}

static uint64_t play_skins(const void *o)
{
	return ((const struct anim_play *)o)->skin_count;
}

static uint64_t play_parts(const void *o)
{
	return ((const struct anim_play *)o)->part_count;
}

static const char *sampler_check(void *o, void *ctx)
{
	const struct anim_sampler *s = o;

	(void)ctx;
	if (!s->count)
		return "a sampler of no keys";
	if (s->width < 1 || s->width > WIDTH_MAX)
		return "a sampler's width out of range";
	return anim_sampler_check(s);
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

/* Its channels against the nodes, and its length made again. */
static const char *clip_check(void *o, void *ctx)
{
	struct anim_clip *clip = o;
	const struct rig_ctx *r = ctx;

	for (size_t k = 0; k < clip->channel_count; k++)
		if (!channel_sane(r->play->anim, clip, &clip->channels[k]))
			return "a channel's node, sampler or width is not one the loader allows";
	for (size_t s = 0; s < clip->sampler_count; s++)
		clip->duration =
		    fmax(clip->duration, clip->samplers[s].input[clip->samplers[s].count - 1]);
	return NULL;
}

static const char *node_check(void *o, void *ctx)
{
	const struct anim_node *n = o;
	const struct mesh_anim *a = ((const struct rig_ctx *)ctx)->play->anim;

	if (n->parent < -1 || (n->parent >= 0 && (size_t)n->parent >= a->node_count))
		return "a parent that is not a node";
	if (n->weight_offset > a->weight_total ||
	    n->weight_count > a->weight_total - n->weight_offset)
		return "morph weights past the weights there are";
	return NULL;
}

/* The nodes' order, made again (parents first). */
static const char *anim_check(void *o, void *ctx)
{
	struct mesh_anim *a = o;

	(void)ctx;
	a->order = calloc(a->node_count + 1, sizeof(*a->order));
	if (!a->order)
		return "out of memory";
	return anim_order(a->nodes, a->node_count, a->order) ? NULL : "the parents make a cycle";
}

static const char *skin_check(void *o, void *ctx)
{
	const struct anim_play_skin *s = o;
	const struct mesh_anim *a = ((const struct rig_ctx *)ctx)->play->anim;

	for (uint32_t j = 0; j < s->joint_count; j++)
		if (s->joints[j] < 0 || (size_t)s->joints[j] >= a->node_count)
			return "a joint that is not a node";
	return NULL;
}

/* Its vertices in the mesh, its triangles among its own vertices (the
 * normals generated from them), its node and skin among those there are. */
static const char *part_check(void *o, void *ctx)
{
	const struct anim_play_part *part = o;
	const struct anim_play *p = ((const struct rig_ctx *)ctx)->play;

	if (part->node < 0 || (size_t)part->node >= p->anim->node_count)
		return "its node is not a node";
	if (part->skin < -1 || (part->skin >= 0 && (uint32_t)part->skin >= p->skin_count) ||
	    (part->skin >= 0 && !p->joints))
		return "its skin is not a skin";
	if (part->first_vertex > p->vertex_count ||
	    part->vertex_count > p->vertex_count - part->first_vertex)
		return "its vertices past the mesh's";
	if (part->index_count % 3)
		return "its indices are not triangles";
	for (uint32_t i = 0; i < part->index_count; i++)
		if (part->indices[i] < part->first_vertex ||
		    part->indices[i] - part->first_vertex >= part->vertex_count)
			return "an index past its vertices";
	return NULL;
}

static const char *play_check(void *o, void *ctx)
{
	const struct anim_play *p = o;

	if (!p->vertex_count || p->vertex_count != ((const struct rig_ctx *)ctx)->vertex_count)
		return "its vertex count is not the mesh's";
	if (!(p->scale > 0))
		return "a fit of no scale";
	if (p->influences < 4 || p->influences % 4 || !p->joints != !p->weights)
		return "its joints a vertex are not whole sets of four";
	return NULL;
}

static const struct mesh_nest_member sampler_members[] = {
    MEMBER(anim_sampler, count, MESH_NEST_SIZE),
    MEMBER(anim_sampler, width, MESH_NEST_INT),
    MEMBER(anim_sampler, interp, MESH_NEST_ENUM, .n = ANIM_CUBICSPLINE),
    MEMBER(anim_sampler, input, MESH_NEST_F32S, .count = sampler_inputs),
    MEMBER(anim_sampler, output, MESH_NEST_F32S, .count = sampler_outputs),
};
static const struct mesh_nest sampler_table = TABLE(anim_sampler, sampler_members, sampler_check);

static const struct mesh_nest_member channel_members[] = {
    MEMBER(anim_channel, node, MESH_NEST_INT),
    MEMBER(anim_channel, path, MESH_NEST_ENUM, .n = ANIM_WEIGHTS),
    MEMBER(anim_channel, sampler, MESH_NEST_INT),
};
static const struct mesh_nest channel_table = TABLE(anim_channel, channel_members, NULL);

static const struct mesh_nest_member clip_members[] = {
    MEMBER(anim_clip, name, MESH_NEST_STRING),
    MEMBER(anim_clip, sampler_count, MESH_NEST_SIZE),
    MEMBER(anim_clip, samplers, MESH_NEST_STRUCTS, .count = clip_samplers, .sub = &sampler_table,
	   .count_at = offsetof(struct anim_clip, sampler_count)),
    MEMBER(anim_clip, channel_count, MESH_NEST_SIZE),
    MEMBER(anim_clip, channels, MESH_NEST_STRUCTS, .count = clip_channels, .sub = &channel_table,
	   .count_at = offsetof(struct anim_clip, channel_count)),
    /* The last key of its samplers: made again (clip_check). */
    MEMBER(anim_clip, duration, MESH_NEST_NONE),
};
static const struct mesh_nest clip_table = TABLE(anim_clip, clip_members, clip_check);

static const struct mesh_nest_member node_members[] = {
    MEMBER(anim_node, parent, MESH_NEST_INT),
    MEMBER(anim_node, rest, MESH_NEST_FLOATS, .n = sizeof(struct anim_trs) / sizeof(float)),
    MEMBER(anim_node, has_matrix, MESH_NEST_BOOL),
    MEMBER(anim_node, matrix, MESH_NEST_FLOATS, .n = 16),
    MEMBER(anim_node, weight_offset, MESH_NEST_SIZE),
    MEMBER(anim_node, weight_count, MESH_NEST_SIZE),
};
static const struct mesh_nest node_table = TABLE(anim_node, node_members, node_check);

static const struct mesh_nest_member anim_members[] = {
    MEMBER(mesh_anim, node_count, MESH_NEST_SIZE),
    MEMBER(mesh_anim, weight_total, MESH_NEST_SIZE),
    MEMBER(mesh_anim, nodes, MESH_NEST_STRUCTS, .count = anim_nodes, .sub = &node_table,
	   .count_at = offsetof(struct mesh_anim, node_count)),
    /* Parents first: made again (anim_check). */
    MEMBER(mesh_anim, order, MESH_NEST_NONE),
    MEMBER(mesh_anim, rest_weights, MESH_NEST_F32S, .count = anim_weights),
    MEMBER(mesh_anim, clip_count, MESH_NEST_SIZE),
    MEMBER(mesh_anim, clips, MESH_NEST_STRUCTS, .count = anim_clips, .sub = &clip_table,
	   .count_at = offsetof(struct mesh_anim, clip_count)),
};
static const struct mesh_nest anim_table = TABLE(mesh_anim, anim_members, anim_check);

static const struct mesh_nest_member skin_members[] = {
    MEMBER(anim_play_skin, joint_count, MESH_NEST_U32),
    MEMBER(anim_play_skin, joints, MESH_NEST_INTS, .count = skin_joints),
    MEMBER(anim_play_skin, inverse_bind, MESH_NEST_F32S, .count = skin_matrices),
    /* Its place among every skin's matrices: anim_play_finish's. */
    MEMBER(anim_play_skin, first, MESH_NEST_NONE),
};
static const struct mesh_nest skin_table = TABLE(anim_play_skin, skin_members, skin_check);

static const struct mesh_nest_member part_members[] = {
    MEMBER(anim_play_part, node, MESH_NEST_INT),
    MEMBER(anim_play_part, skin, MESH_NEST_INT),
    MEMBER(anim_play_part, at_root, MESH_NEST_BOOL),
    MEMBER(anim_play_part, first_vertex, MESH_NEST_U32),
    MEMBER(anim_play_part, vertex_count, MESH_NEST_U32),
    MEMBER(anim_play_part, has_normals, MESH_NEST_BOOL),
    MEMBER(anim_play_part, flat, MESH_NEST_BOOL),
    MEMBER(anim_play_part, index_count, MESH_NEST_U32),
    MEMBER(anim_play_part, indices, MESH_NEST_U32S, .count = part_indices),
    MEMBER(anim_play_part, target_count, MESH_NEST_U32),
    MEMBER(anim_play_part, target_positions, MESH_NEST_F32S, .count = part_deltas),
    MEMBER(anim_play_part, target_normals, MESH_NEST_F32S, .count = part_deltas, .optional = true),
};
static const struct mesh_nest part_table = TABLE(anim_play_part, part_members, part_check);

static const struct mesh_nest_member play_members[] = {
    MEMBER(anim_play, anim, MESH_NEST_STRUCT, .sub = &anim_table),
    MEMBER(anim_play, center, MESH_NEST_DOUBLES, .n = 3),
    MEMBER(anim_play, scale, MESH_NEST_DOUBLES, .n = 1),
    MEMBER(anim_play, vertex_count, MESH_NEST_U32),
    MEMBER(anim_play, positions, MESH_NEST_F32S, .count = play_xyz),
    MEMBER(anim_play, normals, MESH_NEST_F32S, .count = play_xyz),
    MEMBER(anim_play, influences, MESH_NEST_U32, .n = INFLUENCES_MAX),
    MEMBER(anim_play, joints, MESH_NEST_U16S, .count = play_influences, .optional = true),
    MEMBER(anim_play, weights, MESH_NEST_F32S, .count = play_influences, .optional = true),
    MEMBER(anim_play, skin_count, MESH_NEST_U32),
    MEMBER(anim_play, skins, MESH_NEST_STRUCTS, .count = play_skins, .sub = &skin_table,
	   .count_at = offsetof(struct anim_play, skin_count), .count_u32 = true),
    MEMBER(anim_play, part_count, MESH_NEST_U32),
    MEMBER(anim_play, parts, MESH_NEST_STRUCTS, .count = play_parts, .sub = &part_table,
	   .count_at = offsetof(struct anim_play, part_count), .count_u32 = true),
    /* A pose's scratch: anim_play_finish makes it. */
    MEMBER(anim_play, worlds, MESH_NEST_NONE),
    MEMBER(anim_play, joint_matrices, MESH_NEST_NONE),
    MEMBER(anim_play, morphed, MESH_NEST_NONE),
    MEMBER(anim_play, joint_total, MESH_NEST_NONE),
    MEMBER(anim_play, part_vertex_max, MESH_NEST_NONE),
    /* The GPU's arrays: the upload makes them (anim_play_gpu_prepare,
     * anim_play_morph_prepare), for the display it runs on. */
    MEMBER(anim_play, bones, MESH_NEST_NONE),
    MEMBER(anim_play, gpu_joints, MESH_NEST_NONE),
    MEMBER(anim_play, gpu_weights, MESH_NEST_NONE),
    MEMBER(anim_play, node_bone, MESH_NEST_NONE),
    MEMBER(anim_play, rows, MESH_NEST_NONE),
    MEMBER(anim_play, morphs, MESH_NEST_NONE),
    MEMBER(anim_play, morph_targets, MESH_NEST_NONE),
    MEMBER(anim_play, morph_normals, MESH_NEST_NONE),
    MEMBER(anim_play, morph_node, MESH_NEST_NONE),
    MEMBER(anim_play, gpu_morph, MESH_NEST_NONE),
};
static const struct mesh_nest play_table = TABLE(anim_play, play_members, play_check);

const struct mesh_nest *mesh_cache_anim_table(void)
{
	return &play_table;
}

int mesh_cache_anim_encode(const struct anim_play *p, void **out, size_t *size)
{
	struct mesh_nest_out b = {NULL, 0, 0, false};

	mesh_nest_put_u32(&b, ANIM_MAGIC);
	mesh_nest_write(&b, &play_table, p);
	if (b.failed) {
		free(b.data);
		return -ENOMEM;
	}
	*out = b.data;
	*size = b.size;
	return 0;
}

int mesh_cache_anim_decode(const void *data, size_t size, uint32_t vertex_count,
			   struct anim_play **out)
{
	struct anim_play *p = calloc(1, sizeof(*p));
	struct rig_ctx ctx = {p, vertex_count};
	struct mesh_nest_in g = {data, size, true, &ctx, ""};
	int ret = -ENOMEM;

	*out = NULL;
	if (!p)
		goto fail;
	ret = -EBADMSG;
	if (mesh_nest_get_u32(&g) != ANIM_MAGIC && g.ok)
		mesh_nest_fail(&g, "its first word", "not MKAN");
	if (!g.ok || !mesh_nest_read(&g, &play_table, p))
		goto fail;
	if (g.left) {
		mesh_nest_fail(&g, "its end", "bytes left over");
		goto fail;
	}
	ret = anim_play_finish(p);
	if (ret)
		goto fail;
	*out = p;
	return 0;
fail:
	if (ret == -EBADMSG)
		log_warn("a cache entry's live playback section is refused at %s%s",
			 g.why[0] == ':' ? "the rig" : "", g.why);
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
	float **to[MESH_ARRAYS] = {&out->positions, &out->normals, &out->uvs,
				   &out->tangents,  &out->colors,  &out->uv1};
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
