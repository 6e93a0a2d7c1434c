/* The renderer's draw list (src/render/draw_list.c): ranges grouped so that
 * programs and textures change least (opaque, masked, blended; by
 * material), blended ranges ordered back to front as the model turns, and
 * a mesh past 65536 vertices cut into 16-bit chunks without 32-bit indices
 * (every triangle kept, in order, none expanded). */
#include "render/draw_list.h"
#include "util/math3d.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

static void one_range_is_one_draw(void **state)
{
	uint32_t idx[6] = {0, 1, 2, 2, 1, 3};
	struct draw_list l;

	(void)state;
	/* No ranges (a built-in model): one draw of every index, 16 bits. */
	assert_int_equal(draw_list_build(&l, NULL, 0, idx, 6, 4, NULL, 0, true), 0);
	assert_int_equal(l.count, 1);
	assert_false(l.wide);
	assert_null(l.gather);
	assert_int_equal(l.items[0].first, 0);
	assert_int_equal(l.items[0].count, 6);
	assert_int_equal(l.items[0].base_vertex, 0);
	assert_int_equal(l.blend_first, 1);
	for (int i = 0; i < 6; i++)
		assert_int_equal(l.indices16[i], idx[i]);
	draw_list_release(&l);
}

static struct material_surface surface(int alpha, bool sides)
{
	return (struct material_surface){.alpha_mode = alpha, .alpha = 1, .double_sided = sides};
}

/* Opaque first, then masked, then blended; within each by material. */
static void grouped_by_alpha_then_material(void **state)
{
	uint32_t idx[15] = {0};
	struct mesh_range r[5] = {
	    {0, 3, 3, {0}}, {3, 3, 1, {0}}, {6, 3, 2, {0}}, {9, 3, 0, {0}}, {12, 3, 4, {0}}};
	struct material_surface s[5] = {
	    surface(MESH_ALPHA_OPAQUE, false), surface(MESH_ALPHA_BLEND, false),
	    surface(MESH_ALPHA_MASK, true), surface(MESH_ALPHA_OPAQUE, true),
	    surface(MESH_ALPHA_BLEND, false)};
	static const uint32_t order[5] = {0, 3, 2, 1, 4};
	struct draw_list l;

	(void)state;
	assert_int_equal(draw_list_build(&l, r, 5, idx, 15, 3, s, 5, true), 0);
	assert_int_equal(l.count, 5);
	assert_int_equal(l.blend_first, 3);
	for (int i = 0; i < 5; i++) {
		assert_int_equal(l.items[i].surface, order[i]);
		assert_int_equal(l.items[i].alpha_mode, s[order[i]].alpha_mode);
		assert_int_equal(l.items[i].double_sided, s[order[i]].double_sided);
	}
	assert_int_equal(draw_item_variant(&l.items[1]), 3);	 /* opaque, double sided */
	assert_int_equal(draw_item_variant(&l.items[2]), 1 + 3); /* masked, double sided */
	draw_list_release(&l);
}

/* Three blended panes along z; seen from the front the one at -z (the
 * farthest) is drawn first; turned half round, the one at +z. */
static void blended_farthest_first(void **state)
{
	uint32_t idx[12] = {0};
	struct mesh_range r[4] = {{0, 3, 0, {0, 0, 0}},
				  {3, 3, 1, {0, 0, 0.5f}},
				  {6, 3, 1, {0, 0, -0.5f}},
				  {9, 3, 1, {0, 0, 0.1f}}};
	struct material_surface s[2] = {surface(MESH_ALPHA_OPAQUE, false),
					surface(MESH_ALPHA_BLEND, false)};
	float mv[16], rot[16], move[16];
	struct draw_list l;

	(void)state;
	assert_int_equal(draw_list_build(&l, r, 4, idx, 12, 3, s, 2, true), 0);
	assert_int_equal(l.blend_first, 1);
	mat4_translate(mv, 0, 0, -3);
	draw_list_sort_blended(&l, mv);
	assert_true(l.items[1].center[2] == -0.5f && l.items[2].center[2] == 0.1f &&
		    l.items[3].center[2] == 0.5f);
	assert_true(l.items[0].alpha_mode == MESH_ALPHA_OPAQUE); /* the opaque stay first */
	mat4_from_quat(rot, quat_from_axis_angle(0, 1, 0, 3.14159265f));
	mat4_translate(move, 0, 0, -3);
	mat4_multiply(mv, move, rot);
	draw_list_sort_blended(&l, mv);
	assert_true(l.items[1].center[2] == 0.5f && l.items[2].center[2] == 0.1f &&
		    l.items[3].center[2] == -0.5f);
	draw_list_release(&l);
}

/* 100000 vertices, triangles that reach across all of them (vertex i
 * with i + 50000 and the last): without 32-bit indices each chunk holds
 * at most 65536 vertices, gathered, and reading the chunks back through
 * the gather gives every triangle of each range, in order. */
static void large_mesh_in_16_bit_chunks(void **state)
{
	enum { NV = 100000, NT = 100000 };
	uint32_t *idx = malloc(NT * 3 * sizeof(uint32_t)), at[2] = {0, 0};
	struct mesh_range r[2] = {{0, NT / 2 * 3, 0, {0}}, {NT / 2 * 3, NT / 2 * 3, 1, {0}}};
	struct material_surface s[2] = {surface(MESH_ALPHA_OPAQUE, false),
					surface(MESH_ALPHA_OPAQUE, false)};
	struct draw_list l;

	(void)state;
	for (uint32_t t = 0; t < NT; t++) {
		idx[t * 3] = t % NV;
		idx[t * 3 + 1] = (t + 50000) % NV;
		idx[t * 3 + 2] = NV - 1;
	}
	assert_int_equal(draw_list_build(&l, r, 2, idx, NT * 3, NV, s, 2, false), 0);
	assert_false(l.wide);
	assert_non_null(l.gather);
	assert_true(l.count > 2);
	assert_int_equal(l.index_count, NT * 3);
	for (uint32_t i = 0; i < l.count; i++) {
		const struct draw_item *it = &l.items[i];
		uint32_t most = 0;

		assert_int_equal(it->count % 3, 0);
		for (uint32_t j = 0; j < it->count; j++) {
			uint32_t local = l.indices16[it->first + j];
			uint32_t g = it->base_vertex + local;

			most = local > most ? local : most;
			assert_true(g < l.gather_count);
			assert_int_equal(l.gather[g],
					 idx[r[it->surface].first_index + at[it->surface]++]);
		}
		assert_true(most < 65536);
		assert_true(i + 1 == l.count || l.items[i + 1].base_vertex >= it->base_vertex);
	}
	assert_int_equal(at[0], NT / 2 * 3);
	assert_int_equal(at[1], NT / 2 * 3);
	/* With 32-bit indices: the ranges as they are. */
	draw_list_release(&l);
	assert_int_equal(draw_list_build(&l, r, 2, idx, NT * 3, NV, s, 2, true), 0);
	assert_true(l.wide && l.count == 2 && !l.gather && l.indices32 == idx);
	draw_list_release(&l);
	free(idx);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(one_range_is_one_draw),
	    cmocka_unit_test(grouped_by_alpha_then_material),
	    cmocka_unit_test(blended_farthest_first),
	    cmocka_unit_test(large_mesh_in_16_bit_chunks),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
