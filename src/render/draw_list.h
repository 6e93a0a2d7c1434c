/* The draws of one mesh: its ranges (struct mesh_range) as the renderer
 * issues them, grouped so that programs and textures change as rarely as
 * possible (opaque, then masked, each by program variant, then by
 * material), then the blended ones farthest first. Without 32-bit
 * indices (OES_element_index_uint) a range over more than 65536 vertices
 * is cut into chunks of 16-bit indices, each relative to its own first
 * vertex (the attribute arrays are bound from there), not expanded into
 * unindexed triangles: each chunk's vertices are gathered into the arrays
 * uploaded (only those chunks share are copied twice). Pure logic: no GL. */
#ifndef MK_DRAW_LIST_H
#define MK_DRAW_LIST_H

#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"

#include <stdbool.h>
#include <stdint.h>

struct draw_item {
	uint32_t first, count; /* into the index buffer uploaded, in indices */
	uint32_t base_vertex;  /* added to each index (16-bit chunks), else 0 */
	uint32_t surface;      /* material.surfaces[] */
	int alpha_mode;	       /* enum mesh_alpha */
	bool double_sided;
	/* The model's features its material lacks (material_surface_missing
	 * against every surface's together): left out of its program. */
	unsigned missing;
	/* Its material's MATERIAL_PER_RANGE features: added to its program. */
	unsigned adds;
	float center[3]; /* model space: blended items are ordered by it */
	uint32_t range;	 /* the mesh range it draws (of a split palette: its bones) */
};

struct draw_list {
	struct draw_item *items;
	uint32_t count;
	uint32_t blend_first; /* items[blend_first..count) blend */
	bool wide;	      /* 32-bit indices in indices32; else indices16 */
	uint16_t *indices16;
	const uint32_t *indices32; /* borrowed: the mesh's own */
	uint32_t index_count;	   /* in indices16 or indices32 */
	/* Chunked: the arrays to upload are vertex gather[i] for each i
	 * (base_vertex counts in these); NULL: the arrays as they are. */
	uint32_t *gather;
	uint32_t gather_count;
};

/* ranges NULL (range_count 0): one range over every index with surface 0.
 * surfaces give each range's alpha mode, sides and features (NULL:
 * opaque, one sided, the model's program). wide: the GPU takes 32-bit indices. Returns 0 or
 * -ENOMEM. */
int draw_list_build(struct draw_list *l, const struct mesh_range *ranges, uint32_t range_count,
		    const uint32_t *indices, uint32_t index_count, uint32_t vertex_count,
		    const struct material_surface *surfaces, uint32_t surface_count, bool wide);
void draw_list_release(struct draw_list *l);

/* Each item draws with materials[item.range] (a KHR_materials_variants
 * variant's, or the ranges' own to go back): its surface, alpha mode,
 * sides and program variant follow, and the items are ordered again.
 * Indices and arrays stay as uploaded: a switch is this, no upload. An
 * item whose range is past range_count keeps its material. */
void draw_list_use_materials(struct draw_list *l, const uint32_t *materials, uint32_t range_count,
			     const struct material_surface *surfaces, uint32_t surface_count);

/* The renderer's program variants: an alpha mode, + 3 when double sided,
 * + 6 x which of the model's features the material lacks (none; the
 * detail map; its normal; iridescence; both the detail map and iridescence;
 * the normal and iridescence), + 36 x (unlit + 2 x its emission: none,
 * the factor, the factor and a map, the factor and a map on the second UV
 * set). Variant 0: the model's own program. */
enum { DRAW_SIDES_VARIANTS = 6, DRAW_LACKS_VARIANTS = 36, DRAW_VARIANTS = 36 * 8 };

static inline int draw_item_variant(const struct draw_item *it)
{
	int lacks = (it->missing & MATERIAL_DETAIL)	     ? 1
		    : (it->missing & MATERIAL_DETAIL_NORMAL) ? 2
							     : 0;

	int emits = (it->adds & MATERIAL_EMISSIVE_UV1)	 ? 3
		    : (it->adds & MATERIAL_EMISSIVE_MAP) ? 2
		    : (it->adds & MATERIAL_EMISSIVE)	 ? 1
							 : 0;

	if (it->missing & MATERIAL_IRIDESCENCE)
		lacks = lacks == 2 ? 5 : lacks + 3;
	return it->alpha_mode + (it->double_sided ? 3 : 0) + DRAW_SIDES_VARIANTS * lacks +
	       DRAW_LACKS_VARIANTS * (((it->adds & MATERIAL_UNLIT) ? 1 : 0) + 2 * emits);
}

/* The MATERIAL_PER_RANGE features variant v adds to the model's. */
static inline unsigned draw_variant_adds(int v)
{
	static const unsigned emits[4] = {
	    0, MATERIAL_EMISSIVE, MATERIAL_EMISSIVE | MATERIAL_EMISSIVE_MAP,
	    MATERIAL_EMISSIVE | MATERIAL_EMISSIVE_MAP | MATERIAL_EMISSIVE_UV1};
	int extra = v / DRAW_LACKS_VARIANTS;

	return (extra & 1 ? MATERIAL_UNLIT : 0u) | emits[extra / 2];
}

/* The features variant v leaves out of the model's. */
static inline unsigned draw_variant_missing(int v)
{
	static const unsigned d = MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL,
			      n = MATERIAL_DETAIL_NORMAL, i = MATERIAL_IRIDESCENCE | MATERIAL_RAMP;
	static const unsigned lacks[6] = {0, d, n, i, d | i, n | i};

	return lacks[v % DRAW_LACKS_VARIANTS / DRAW_SIDES_VARIANTS];
}

/* The blended items back to front for this model-view (column-major): the
 * farthest center (most negative eye-space z) first. */
void draw_list_sort_blended(struct draw_list *l, const float modelview[16]);

#endif
