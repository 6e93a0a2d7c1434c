/* Palette splitting for GPU skinning (src/scene/anim/anim_palette.c): every
 * draw's palette fits, every triangle survives with each vertex naming the
 * same skin joints through its draw's palette, a primitive that fits stays
 * one draw with no copies, and what cannot fit is refused. */
#include "scene/anim/anim_palette.h"

#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

/* A strip of quads along x, vertex pair i bound to joint i (weight 0.75)
 * and joint i + 1 (0.25): a chain of `n` joints, as an arm or a tail. */
struct strip {
	uint32_t vertex_count, index_count;
	uint16_t joints[4 * 64];
	float weights[4 * 64];
	uint32_t indices[6 * 32];
};

static void make_strip(struct strip *s, uint32_t quads)
{
	memset(s, 0, sizeof(*s));
	s->vertex_count = 2 * (quads + 1);
	for (uint32_t v = 0; v < s->vertex_count; v++) {
		uint16_t j = (uint16_t)(v / 2);
		s->joints[v * 4] = j;
		s->joints[v * 4 + 1] = (uint16_t)(j + 1);
		s->joints[v * 4 + 2] = 7; // weight 0: never counted
		s->weights[v * 4] = 0.75f;
		s->weights[v * 4 + 1] = 0.25f;
	}
	for (uint32_t q = 0; q < quads; q++) {
		uint32_t a = 2 * q, t[6] = {a, a + 1, a + 2, a + 2, a + 1, a + 3};
		memcpy(s->indices + s->index_count, t, sizeof(t));
		s->index_count += 6;
	}
}

/* Each output triangle is the input's, and each of its vertices names,
 * through its draw's palette, the joints its source named. */
static void check_split(const struct strip *s, const struct anim_palette *p, uint32_t palette)
{
	assert_int_equal(p->index_count, s->index_count);
	for (uint32_t d = 0; d < p->draw_count; d++) {
		const struct anim_palette_draw *dr = &p->draws[d];
		assert_true(dr->joint_count <= palette);
		for (uint32_t i = dr->first_index; i < dr->first_index + dr->index_count; i++) {
			uint32_t v = p->indices[i], src = p->source[v];
			assert_int_equal(src, s->indices[i]);
			for (int k = 0; k < 4; k++) {
				if (s->weights[src * 4 + k] == 0.0f)
					continue;
				uint16_t local = p->vertex_joints[v * 4 + k];
				assert_true(local < dr->joint_count);
				assert_int_equal(p->joints[dr->joint_first + local],
						 s->joints[src * 4 + k]);
			}
		}
	}
}

static void splits_to_fit(void **state)
{
	(void)state;
	struct strip s;
	struct anim_palette p;

	make_strip(&s, 12); // 14 joints (0 .. 13) named with weight
	assert_int_equal(anim_palette_split(s.indices, s.index_count, s.joints, s.weights,
					    s.vertex_count, 16, 4, &p),
			 0);
	assert_true(p.draw_count > 1);
	check_split(&s, &p, 4);
	// A quad needs 3 joints; with 4 a draw holds two quads: 6 draws.
	assert_int_equal(p.draw_count, 6);
	// The copies: each draw but the first repeats its first vertex pair.
	assert_int_equal(p.vertex_count, s.vertex_count + 2 * (p.draw_count - 1));
	uint32_t covered = 0;
	for (uint32_t d = 0; d < p.draw_count; d++) {
		assert_int_equal(p.draws[d].first_index, covered);
		covered += p.draws[d].index_count;
	}
	assert_int_equal(covered, s.index_count);
	anim_palette_release(&p);
}

static void fits_in_one(void **state)
{
	(void)state;
	struct strip s;
	struct anim_palette p;

	make_strip(&s, 12);
	assert_int_equal(anim_palette_split(s.indices, s.index_count, s.joints, s.weights,
					    s.vertex_count, 16, 14, &p),
			 0);
	assert_int_equal(p.draw_count, 1);
	assert_int_equal(p.vertex_count, s.vertex_count); // no copies
	check_split(&s, &p, 14);
	anim_palette_release(&p);
}

static void refuses_what_cannot_fit(void **state)
{
	(void)state;
	struct strip s;
	struct anim_palette p;

	make_strip(&s, 4);
	// A triangle of 2 joints and a palette of 1: the CPU path.
	assert_int_equal(anim_palette_split(s.indices, s.index_count, s.joints, s.weights,
					    s.vertex_count, 16, 1, &p),
			 -E2BIG);
	assert_null(p.draws);
	// A joint past the skin's.
	assert_int_equal(anim_palette_split(s.indices, s.index_count, s.joints, s.weights,
					    s.vertex_count, 3, 8, &p),
			 -EINVAL);
	s.indices[4] = 999; // an index past the vertices
	assert_int_equal(anim_palette_split(s.indices, s.index_count, s.joints, s.weights,
					    s.vertex_count, 16, 8, &p),
			 -EINVAL);
	assert_int_equal(
	    anim_palette_split(s.indices, 0, s.joints, s.weights, s.vertex_count, 16, 8, &p), 0);
	assert_int_equal(p.draw_count, 0);
	anim_palette_release(&p);
}

static void size_from_the_gpu(void **state)
{
	(void)state;
	assert_int_equal(anim_palette_size(128, 14), 38); // GLES2's least: 38 joints
	assert_int_equal(anim_palette_size(256, 16), 80);
	assert_int_equal(anim_palette_size(10, 16), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(splits_to_fit),
	    cmocka_unit_test(fits_in_one),
	    cmocka_unit_test(refuses_what_cannot_fit),
	    cmocka_unit_test(size_from_the_gpu),
	};
	return cmocka_run_group_tests_name("anim_palette", tests, NULL, NULL);
}
