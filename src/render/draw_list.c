#include "render/draw_list.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* A 16-bit index reaches this many vertices past a chunk's first. */
#define CHUNK_SPAN 65536u

static int item_order(const void *a, const void *b)
{
	const struct draw_item *x = a, *y = b;

	/* Opaque, then masked (early depth first), then blended; within
	 * each, one material after another; then the index order kept. */
	if (x->alpha_mode != y->alpha_mode)
		return x->alpha_mode - y->alpha_mode;
	if (draw_item_variant(x) != draw_item_variant(y))
		return draw_item_variant(x) - draw_item_variant(y);
	if (x->surface != y->surface)
		return x->surface < y->surface ? -1 : 1;
	return x->first < y->first ? -1 : x->first > y->first;
}

/* What an item takes from its material: how it blends, its sides, and
 * the model's features it lacks (its program variant). */
static void item_surface(struct draw_item *it, uint32_t s, const struct material_surface *surfaces,
			 uint32_t surface_count, unsigned model)
{
	it->surface = s;
	it->alpha_mode = MESH_ALPHA_OPAQUE;
	it->double_sided = false;
	it->missing = 0;
	it->adds = 0;
	if (surfaces && s < surface_count) {
		it->alpha_mode = surfaces[s].alpha_mode;
		it->double_sided = surfaces[s].double_sided;
		it->missing = material_surface_missing(model, &surfaces[s]);
		it->adds = surfaces[s].features & MATERIAL_PER_RANGE;
	}
}

static unsigned model_features(const struct material_surface *surfaces, uint32_t surface_count)
{
	unsigned model = 0;

	for (uint32_t k = 0; surfaces && k < surface_count; k++)
		model |= surfaces[k].features;
	return model;
}

/* Opaque first, blended last, each group in the order item_order keeps. */
static void order_items(struct draw_list *l)
{
	if (l->count > 1)
		qsort(l->items, l->count, sizeof(*l->items), item_order);
	l->blend_first = l->count;
	while (l->blend_first > 0 && l->items[l->blend_first - 1].alpha_mode == MESH_ALPHA_BLEND)
		l->blend_first--;
}

static bool push(struct draw_list *l, uint32_t *cap, const struct draw_item *it)
{
	if (l->count == *cap) {
		uint32_t grown = *cap ? *cap * 2 : 8;
		struct draw_item *p = realloc(l->items, grown * sizeof(*p));

		if (!p)
			return false;
		l->items = p;
		*cap = grown;
	}
	l->items[l->count++] = *it;
	return true;
}

/* Where each vertex is in the chunk being filled (stamp: which chunk
 * numbered it), and the vertices the chunks gather, in order. */
struct gather {
	uint32_t *local, *stamp;
	uint32_t chunk, used, cap;
};

static bool gather_push(struct draw_list *l, struct gather *g, uint32_t v)
{
	if (l->gather_count == g->cap) {
		uint32_t grown = g->cap ? g->cap * 2 : 1024;
		uint32_t *p = realloc(l->gather, grown * sizeof(*p));

		if (!p)
			return false;
		l->gather = p;
		g->cap = grown;
	}
	g->stamp[v] = g->chunk;
	g->local[v] = g->used++;
	l->gather[l->gather_count++] = v;
	return true;
}

/* The range's triangles into chunks of at most 65536 vertices each: a
 * chunk's vertices are gathered (copied) into the arrays uploaded, in
 * the order its triangles first use them, and its indices count from its
 * first, in 16 bits. Only the vertices two chunks share are copied
 * twice. */
static bool split_range(struct draw_list *l, uint32_t *cap, struct gather *g, const uint32_t *idx,
			const struct draw_item *range)
{
	struct draw_item it = *range;
	uint32_t end = range->first + range->count;

	it.count = 0;
	for (uint32_t t = range->first; t < end; t += 3) {
		uint32_t fresh = 0;

		for (int k = 0; k < 3 && it.count; k++)
			fresh += g->stamp[idx[t + k]] != g->chunk;
		if (!it.count || g->used + fresh > CHUNK_SPAN) {
			if (it.count && !push(l, cap, &it))
				return false;
			g->chunk++;
			g->used = 0;
			it.first = l->index_count;
			it.count = 0;
			it.base_vertex = l->gather_count;
		}
		for (int k = 0; k < 3; k++) {
			uint32_t v = idx[t + k];

			if (g->stamp[v] != g->chunk && !gather_push(l, g, v))
				return false;
			l->indices16[l->index_count++] = (uint16_t)g->local[v];
		}
		it.count += 3;
	}
	return !it.count || push(l, cap, &it);
}

int draw_list_build(struct draw_list *l, const struct mesh_range *ranges, uint32_t range_count,
		    const uint32_t *indices, uint32_t index_count, uint32_t vertex_count,
		    const struct material_surface *surfaces, uint32_t surface_count, bool wide)
{
	struct mesh_range whole = {0, index_count, 0, {0, 0, 0}};
	bool split = !wide && vertex_count > CHUNK_SPAN;
	struct gather gat = {NULL, NULL, 0, 0, 0};
	uint32_t cap = 0;
	unsigned model = 0;
	int ret = -ENOMEM;

	memset(l, 0, sizeof(*l));
	if (!ranges || !range_count)
		ranges = &whole, range_count = 1;
	l->wide = wide && vertex_count > CHUNK_SPAN;
	l->indices32 = indices;
	l->indices16 = l->wide ? NULL : malloc((size_t)index_count * 2 + 1);
	if (split) {
		gat.local = malloc((size_t)vertex_count * sizeof(uint32_t));
		/* 0 is no chunk: chunks count from 1. */
		gat.stamp = calloc(vertex_count, sizeof(uint32_t));
	}
	if ((!l->wide && !l->indices16) || (split && (!gat.local || !gat.stamp)))
		goto out;
	for (uint32_t i = 0; !l->wide && !split && i < index_count; i++)
		l->indices16[i] = (uint16_t)indices[i];
	l->index_count = split ? 0 : index_count;
	model = model_features(surfaces, surface_count);
	for (uint32_t r = 0; r < range_count; r++) {
		const struct mesh_range *g = &ranges[r];
		uint32_t s = g->material < surface_count ? g->material : 0;
		struct draw_item it = {g->first_index,
				       g->index_count,
				       0,
				       s,
				       MESH_ALPHA_OPAQUE,
				       false,
				       0,
				       0,
				       {g->center[0], g->center[1], g->center[2]},
				       r};

		item_surface(&it, s, surfaces, surface_count, model);
		if (!g->index_count)
			continue;
		if (!(split ? split_range(l, &cap, &gat, indices, &it) : push(l, &cap, &it)))
			goto out;
	}
	order_items(l);
	ret = 0;
out:
	free(gat.local);
	free(gat.stamp);
	if (ret)
		draw_list_release(l);
	return ret;
}

void draw_list_use_materials(struct draw_list *l, const uint32_t *materials, uint32_t range_count,
			     const struct material_surface *surfaces, uint32_t surface_count)
{
	unsigned model = model_features(surfaces, surface_count);

	for (uint32_t i = 0; i < l->count; i++) {
		struct draw_item *it = &l->items[i];
		uint32_t s = it->range < range_count ? materials[it->range] : it->surface;

		item_surface(it, s < surface_count ? s : 0, surfaces, surface_count, model);
	}
	order_items(l);
}

void draw_list_release(struct draw_list *l)
{
	free(l->items);
	free(l->indices16);
	free(l->gather);
	memset(l, 0, sizeof(*l));
}

static float eye_z(const float mv[16], const float c[3])
{
	return mv[2] * c[0] + mv[6] * c[1] + mv[10] * c[2] + mv[14];
}

/* Insertion sort: few blended parts, and nearly in order from the frame
 * before, so it does next to nothing as the model turns. */
void draw_list_sort_blended(struct draw_list *l, const float modelview[16])
{
	for (uint32_t i = l->blend_first + 1; i < l->count; i++) {
		struct draw_item it = l->items[i];
		float z = eye_z(modelview, it.center);
		uint32_t j = i;

		while (j > l->blend_first && eye_z(modelview, l->items[j - 1].center) > z) {
			l->items[j] = l->items[j - 1];
			j--;
		}
		l->items[j] = it;
	}
}
