/* KHR_materials_variants on the GPU: the mesh's table of which material
 * each range draws in each variant, kept beside the draw list. Every
 * material is uploaded with the mesh (renderer_set_material), so showing
 * a variant changes the draw list's materials and nothing else: no
 * upload, no program built on the loop (every variant's programs are
 * marked used at upload). */
#include "render/render.h"
#include "render/render_priv.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static void table_free(struct render_variants *t)
{
	free(t->materials);
	free(t->defaults);
	free(t->colors);
	memset(t, 0, sizeof(*t));
}

void render_variants_drop(struct renderer *r)
{
	table_free(&r->looks);
	table_free(&r->looks_next);
	r->look = -1;
}

static int copy_table(struct render_variants *t, const struct mesh *m)
{
	size_t n = (size_t)m->variant_count * m->range_count;

	t->materials = malloc(n * sizeof(uint32_t) + 1);
	t->defaults = malloc((size_t)m->range_count * sizeof(uint32_t) + 1);
	t->colors = m->colors_by_material ? malloc((size_t)m->material_count * 16 + 1) : NULL;
	if (!t->materials || !t->defaults || (m->colors_by_material && !t->colors))
		return -ENOMEM;
	memcpy(t->materials, m->variant_materials, n * sizeof(uint32_t));
	for (uint32_t i = 0; i < m->range_count; i++)
		t->defaults[i] = m->ranges[i].material;
	for (uint32_t k = 0; t->colors && k < m->material_count; k++)
		mesh_material_vertex_color(&m->materials[k], t->colors + 4 * k);
	t->count = m->variant_count;
	t->ranges = m->range_count;
	t->surfaces = m->material_count;
	return 0;
}

int render_variants_take(struct renderer *r, const struct mesh *m)
{
	int ret = 0;

	table_free(&r->looks_next);
	/* Only for the ranges the table was made for (a split palette's
	 * draws have a table of their own: anim_play_split). */
	if (m->variant_count && m->variant_materials && m->variant_ranges == m->range_count)
		ret = copy_table(&r->looks_next, m);
	if (ret)
		table_free(&r->looks_next);
	return ret;
}

static const uint32_t *materials_of(const struct renderer *r, int v)
{
	const struct render_variants *t = &r->looks;

	return v >= 0 && (uint32_t)v < t->count ? t->materials + (size_t)v * t->ranges
						: t->defaults;
}

void render_variants_mark(struct renderer *r)
{
	struct draw_list *l = &r->list;

	table_free(&r->looks);
	r->looks = r->looks_next;
	memset(&r->looks_next, 0, sizeof(r->looks_next));
	r->look = -1;
	/* Each variant's programs, built with the mesh's (prepare_variants). */
	for (uint32_t v = 0; v < r->looks.count; v++) {
		draw_list_use_materials(l, materials_of(r, (int)v), r->looks.ranges, r->surfaces,
					r->surface_count);
		for (uint32_t i = 0; i < l->count; i++)
			r->variant_used[draw_item_variant(&l->items[i])] = true;
	}
	if (r->looks.count)
		draw_list_use_materials(l, r->looks.defaults, r->looks.ranges, r->surfaces,
					r->surface_count);
}

bool renderer_show_variant(struct renderer *r, int variant)
{
	if (variant < 0 || (uint32_t)variant >= r->looks.count)
		variant = -1;
	if (variant == r->look)
		return false;
	r->look = variant;
	draw_list_use_materials(&r->list, materials_of(r, variant), r->looks.ranges, r->surfaces,
				r->surface_count);
	return true;
}

int renderer_variant_count(const struct renderer *r)
{
	return (int)r->looks.count;
}

const float *render_variant_color(const struct renderer *r, uint32_t surface)
{
	const struct render_variants *t = &r->looks;

	return t->colors && surface < t->surfaces ? t->colors + 4 * surface : NULL;
}
