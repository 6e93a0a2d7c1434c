/* The member tables of what a cache entry keeps of a material, of a draw
 * range and of the model's colour facts, for the one walker of
 * mesh_cache_nest.c (which the rig's tables, mesh_cache_anim.c, use too):
 * every field of struct mesh_material and struct mesh_range is either
 * stored (and checked when read back) or named as not stored, with why.
 * tests/unit/test_mesh_cache.c fails when a field of either struct is in
 * neither: a field added to the data model cannot be forgotten by the
 * cache. */
#include "scene/mesh/mesh_cache.h"
#include "scene/mesh/mesh_cache_nest.h"

#include <stddef.h>

#define M(f, k, ...) MESH_NEST_MEMBER(mesh_material, f, k, __VA_ARGS__)
#define FLOATS(f)    MESH_NEST_FLOATS_OF(mesh_material, f)

static const struct mesh_nest_member material_members[] = {
    M(present, MESH_NEST_BOOL),
    FLOATS(base_color),
    FLOATS(base_alpha),
    M(alpha_mode, MESH_NEST_ENUM, .n = MESH_ALPHA_BLEND),
    FLOATS(alpha_cutoff),
    M(double_sided, MESH_NEST_BOOL),
    M(iridescence, MESH_NEST_BOOL),
    FLOATS(iridescence_factor),
    FLOATS(iridescence_ior),
    FLOATS(thickness_min),
    FLOATS(thickness_max),
    M(has_normal_map, MESH_NEST_BOOL),
    M(has_occlusion_map, MESH_NEST_BOOL),
    M(has_thickness_map, MESH_NEST_BOOL),
    FLOATS(normal_scale),
    FLOATS(occlusion_strength),
    M(has_base_map, MESH_NEST_BOOL),
    M(images_decoded, MESH_NEST_U32),
    FLOATS(base_transform),
    M(base_wrap[0], MESH_NEST_ENUM, .n = MESH_WRAP_MIRROR), /* wrapS, wrapT */
    M(base_wrap[1], MESH_NEST_ENUM, .n = MESH_WRAP_MIRROR),
    M(base_no_mipmaps, MESH_NEST_BOOL),
    M(unlit, MESH_NEST_BOOL),
    FLOATS(emissive),
    M(has_emissive_map, MESH_NEST_BOOL),
    FLOATS(emissive_transform),
    M(emissive_wrap[0], MESH_NEST_ENUM, .n = MESH_WRAP_MIRROR), /* wrapS, wrapT */
    M(emissive_wrap[1], MESH_NEST_ENUM, .n = MESH_WRAP_MIRROR),
    M(emissive_no_mipmaps, MESH_NEST_BOOL),
    M(emissive_uv1, MESH_NEST_BOOL),
    /* Images are not stored: an entry is written only for a scene that
     * decodes none (src/app/content.c), and read back with none. */
    M(normal_map, MESH_NEST_NONE),
    M(occlusion_map, MESH_NEST_NONE),
    M(thickness_map, MESH_NEST_NONE),
    M(base_map, MESH_NEST_NONE),
    M(emissive_map, MESH_NEST_NONE),
};
static const struct mesh_nest material_table =
    MESH_NEST_TABLE(mesh_material, material_members, NULL);

/* The ranges in order, covering every index once (the rest is checked
 * when the last is read), each a whole number of triangles with a
 * material that exists. */
static const char *range_check(void *o, void *ctx)
{
	const struct mesh_range *g = o;
	struct mesh_cache_ranges *r = ctx;

	if (g->first_index != r->at)
		return "it does not start where the range before it ends";
	if (g->index_count % 3 || g->index_count > r->index_count - r->at)
		return "its indices are not whole triangles among the mesh's";
	if (g->material >= r->material_count)
		return "its material is not one the entry holds";
	r->at += g->index_count;
	return NULL;
}

static const struct mesh_nest_member range_members[] = {
    MESH_NEST_MEMBER(mesh_range, first_index, MESH_NEST_U32),
    MESH_NEST_MEMBER(mesh_range, index_count, MESH_NEST_U32),
    MESH_NEST_MEMBER(mesh_range, material, MESH_NEST_U32),
    MESH_NEST_FLOATS_OF(mesh_range, center),
};
static const struct mesh_nest range_table = MESH_NEST_TABLE(mesh_range, range_members, range_check);

/* The model's colour facts, which no material holds: the rest of struct
 * mesh is the entry's arrays, ranges and materials (not a whole struct's
 * table: the test checks material and range). */
static const struct mesh_nest_member color_members[] = {
    MESH_NEST_MEMBER(mesh, has_colors, MESH_NEST_BOOL),
    MESH_NEST_FLOATS_OF(mesh, vertex_color),
    MESH_NEST_MEMBER(mesh, fit, MESH_NEST_DOUBLES, .n = 4),
};
static const struct mesh_nest color_table = MESH_NEST_TABLE(mesh, color_members, NULL);

/* A named node: its name as the loader kept it (mesh_node_name_ok: it
 * reaches the journal), its index and origin. */
static const char *node_check(void *o, void *ctx)
{
	const struct mesh_node *n = o;

	(void)ctx;
	return mesh_node_name_ok(n->name) ? NULL : "its name is not printable UTF-8";
}

static const struct mesh_nest_member node_members[] = {
    MESH_NEST_MEMBER(mesh_node, name, MESH_NEST_CHARS, .n = MESH_NODE_NAME),
    MESH_NEST_MEMBER(mesh_node, index, MESH_NEST_U32),
    MESH_NEST_MEMBER(mesh_node, origin, MESH_NEST_DOUBLES, .n = 3),
};
static const struct mesh_nest node_table = MESH_NEST_TABLE(mesh_node, node_members, node_check);

const struct mesh_nest *mesh_cache_table(enum mesh_cache_table t)
{
	if (t == MESH_CACHE_NODE)
		return &node_table;
	if (t == MESH_CACHE_RANGE)
		return &range_table;
	if (t == MESH_CACHE_COLORS)
		return &color_table;
	return &material_table;
}
