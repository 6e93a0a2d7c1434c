/* KHR_materials_variants: the names and per-primitive mappings read into
 * the mesh (every material a variant uses resident), a file naming a
 * material or variant it lacks refused by name, and a switch in the draw
 * list (materials changed, nothing else). What a variant looks like on
 * screen: tests/suite.sh's variants check (--variant blue). */
#include "gltf_variants.h"
#include "offscreen.h"
#include "app/kiosk_anim.h"
#include "config/settings.h"
#include "content/content.h"
#include "render/draw_list.h"
#include "render/render.h"
#include "scene/anim/anim_play.h"
#include "scene/gltf/gltf.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "util/log.h"

#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static int load(enum gltf_variants_fault fault, unsigned textures, struct mesh *m)
{
	char path[64];
	int ret;

	snprintf(path, sizeof(path), "/tmp/mk-variants-%d-%d.gltf", (int)getpid(), (int)fault);
	assert_int_equal(gltf_write_variants(path, fault), 0);
	ret = gltf_load_textures(path, textures, m);
	unlink(path);
	return ret;
}

static const float *base_of(const struct mesh *m, uint32_t k)
{
	assert_true(k < m->material_count);
	return m->materials[k].base_color;
}

/* Both variants' materials are loaded (blue is used by a variant alone),
 * and the one range draws red, or blue in "blue". */
static void test_names_and_mapping(void **state)
{
	struct mesh m;

	(void)state;
	assert_int_equal(load(VARIANTS_OK, GLTF_TEXTURE_BASE_COLOR, &m), 0);
	assert_int_equal(m.variant_count, 2);
	assert_string_equal(m.variant_names[0], "red");
	assert_string_equal(m.variant_names[1], "blue");
	assert_int_equal(mesh_variant_find(&m, "blue"), 1);
	assert_int_equal(mesh_variant_find(&m, "green"), -1);
	assert_int_equal(m.material_count, 2);
	assert_int_equal(m.range_count, 1);
	assert_int_equal(m.index_count, 36);
	assert_true(base_of(&m, mesh_range_material(&m, -1, 0))[0] == 1.0f);
	assert_true(base_of(&m, mesh_range_material(&m, 0, 0))[0] == 1.0f);
	assert_true(base_of(&m, mesh_range_material(&m, 1, 0))[2] == 1.0f);
	assert_true(base_of(&m, mesh_range_material(&m, 1, 0))[0] == 0.0f);
	/* The colour follows the material, not the vertices. */
	assert_null(m.colors);
	assert_true(m.colors_by_material);
	assert_true(m.has_colors);
	mesh_release(&m);
}

/* "blue" maps the second primitive alone: the two are drawn as two
 * ranges, only the second's changes. */
static void test_per_primitive(void **state)
{
	struct mesh m;
	uint32_t blue = 0;

	(void)state;
	assert_int_equal(load(VARIANTS_SPLIT, 0, &m), 0);
	assert_int_equal(m.range_count, 2);
	assert_int_equal(m.material_count, 2);
	assert_int_equal(m.ranges[0].index_count, 18);
	assert_int_equal(mesh_range_material(&m, 1, 0), m.ranges[0].material);
	blue = mesh_range_material(&m, 1, 1);
	assert_int_not_equal(blue, m.ranges[1].material);
	assert_true(base_of(&m, blue)[2] == 1.0f && base_of(&m, blue)[0] == 0.0f);
	assert_int_equal(mesh_range_material(&m, 0, 1), m.ranges[1].material);
	mesh_release(&m);
}

static void assert_refused(enum gltf_variants_fault fault, const char *field, const char *expected)
{
	struct mesh m;
	char err[512];

	log_clear_last_error();
	assert_int_equal(load(fault, 0, &m), -EINVAL);
	log_last_error(err, sizeof(err));
	if (!strstr(err, field) || !strstr(err, expected))
		fail_msg("expected '%s' and '%s' in: %s", field, expected, err);
}

static void test_missing_material_refused(void **state)
{
	(void)state;
	assert_refused(VARIANTS_MISSING_MATERIAL,
		       "meshes[0].primitives[1].extensions.KHR_materials_variants.mappings[0]."
		       "material",
		       "expected one of the file's 2 materials");
}

static void test_missing_variant_refused(void **state)
{
	(void)state;
	assert_refused(VARIANTS_MISSING_VARIANT, "mappings[0].variants[0]",
		       "expected one of the 2 variants");
}

static void test_too_many_refused(void **state)
{
	(void)state;
	assert_refused(VARIANTS_TOO_MANY, "extensions.KHR_materials_variants.variants",
		       "257 variants, expected at most 256");
}

/* The draw list's switch: each item's surface, alpha mode and program
 * follow the variant's material; the indices stay. */
static void test_draw_list_switch(void **state)
{
	struct mesh_range ranges[2] = {{0, 6, 0, {0, 0, 0}}, {6, 6, 0, {0, 0, 0}}};
	uint32_t idx[12] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
	struct material_surface surfaces[3] = {{0}};
	uint32_t blue[2] = {0, 2}, back[2] = {0, 0};
	struct draw_list l;

	(void)state;
	surfaces[2].alpha_mode = MESH_ALPHA_BLEND;
	surfaces[2].double_sided = true;
	assert_int_equal(draw_list_build(&l, ranges, 2, idx, 12, 8, surfaces, 3, true), 0);
	assert_int_equal(l.count, 2);
	assert_int_equal(l.blend_first, 2);
	draw_list_use_materials(&l, blue, 2, surfaces, 3);
	assert_int_equal(l.blend_first, 1);
	assert_int_equal(l.items[1].range, 1);
	assert_int_equal(l.items[1].surface, 2);
	assert_int_equal(l.items[1].alpha_mode, MESH_ALPHA_BLEND);
	assert_true(l.items[1].double_sided);
	assert_int_equal(l.items[1].first, 6);
	assert_int_equal(l.items[0].surface, 0);
	draw_list_use_materials(&l, back, 2, surfaces, 3);
	assert_int_equal(l.blend_first, 2);
	assert_int_equal(l.items[0].surface, 0);
	assert_int_equal(l.items[1].surface, 0);
	assert_false(l.items[1].double_sided);
	draw_list_release(&l);
}

#define W 48

/* The centre pixel of the frame drawn. */
static void centre(struct display *d, struct renderer *r, const struct view *v, uint8_t rgb[3])
{
	struct image f;

	renderer_draw(r, v, W, W);
	assert_int_equal(d->read_frame(d, &f), 0);
	memcpy(rgb, f.rgba + ((size_t)(W / 2) * (size_t)f.width + W / 2) * 4, 3);
	image_release(&f);
}

/* The kiosk's own path: loaded (not cached: the cache holds no variant
 * table), uploaded once, drawn red; "blue" shown is drawn blue with
 * nothing uploaded again, and the default comes back. A white matcap
 * leaves the base colour as it is. */
static void test_switch_draws_the_variant(void **state)
{
	char dir[] = "/tmp/mk-variants-draw-XXXXXX", model[96], white[96], cmd[128];
	struct display *d = offscreen_open(W, W);
	struct renderer *r = d ? renderer_new(&d->gl, NULL) : NULL;
	struct renderer_stats before, after;
	struct content s;
	struct options o;
	struct image img;
	struct view v;
	uint8_t px[3];

	(void)state;
	assert_non_null(r);
	assert_non_null(mkdtemp(dir));
	snprintf(model, sizeof(model), "%s/variants.gltf", dir);
	snprintf(white, sizeof(white), "%s/white.png", dir);
	assert_int_equal(gltf_write_variants(model, VARIANTS_OK), 0);
	assert_int_equal(image_alloc(&img, 8, 8), 0);
	memset(img.rgba, 255, 8 * 8 * 4);
	assert_int_equal(image_write_png(white, &img), 0);
	image_release(&img);
	setenv("XDG_CACHE_HOME", dir, 1);
	option_defaults(&o);
	o.content.model = model;
	o.content.matcap = white;
	for (int pass = 0; pass < 2; pass++) { /* the second start: still not cached */
		assert_int_equal(content_load(&s, &o.content, true), 0);
		assert_null(s.cached);
		assert_int_equal(content_prepare(&s, &o.content, W, W), 0);
		assert_non_null(s.mesh.positions); /* not packed for the cache */
		assert_int_equal(content_upload(&s, r), 0);
		if (pass == 0)
			content_release(&s);
	}
	assert_int_equal(renderer_set_mode(r, o.content.mode, false), 0);
	assert_int_equal(renderer_variant_count(r), 2);
	v = content_view(&o.content);
	centre(d, r, &v, px);
	assert_true(px[0] > 200 && px[1] < 40 && px[2] < 40);
	renderer_get_stats(r, &before);
	assert_true(renderer_show_variant(r, content_variant_find(&s, "blue")));
	assert_false(renderer_show_variant(r, 1)); /* shown already */
	centre(d, r, &v, px);
	assert_true(px[2] > 200 && px[0] < 40 && px[1] < 40);
	renderer_get_stats(r, &after);
	assert_int_equal(after.vertex_bytes, before.vertex_bytes);
	assert_true(renderer_show_variant(r, -1));
	centre(d, r, &v, px);
	assert_true(px[0] > 200 && px[2] < 40);
	content_release(&s);
	renderer_free(r);
	unsetenv("XDG_CACHE_HOME");
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
}

/* A white matcap (the base colour as it is) and a model written by
 * `write` in a folder of their own, which is the cache too. */
struct scene_dir {
	char dir[40], model[96], white[96];
};

static void scene_dir_make(struct scene_dir *t,
			   int (*write)(const char *, enum gltf_variants_fault),
			   enum gltf_variants_fault fault)
{
	struct image img;

	snprintf(t->dir, sizeof(t->dir), "/tmp/mk-variants-skin-XXXXXX");
	assert_non_null(mkdtemp(t->dir));
	snprintf(t->model, sizeof(t->model), "%s/variants.gltf", t->dir);
	snprintf(t->white, sizeof(t->white), "%s/white.png", t->dir);
	assert_int_equal(write(t->model, fault), 0);
	assert_int_equal(image_alloc(&img, 8, 8), 0);
	memset(img.rgba, 255, 8 * 8 * 4);
	assert_int_equal(image_write_png(t->white, &img), 0);
	image_release(&img);
	setenv("XDG_CACHE_HOME", t->dir, 1);
}

static void scene_dir_remove(struct scene_dir *t)
{
	char cmd[64];

	unsetenv("XDG_CACHE_HOME");
	snprintf(cmd, sizeof(cmd), "rm -rf %s", t->dir);
	assert_int_equal(system(cmd), 0);
}

/* The live kiosk's GPU skinning (bones: the palette at most; 1 splits the
 * draws, a joint each): posed once by the player, drawn red, "blue" drawn
 * blue with nothing uploaded again, the default back. */
static void skinned_switch(uint32_t bones, bool split)
{
	struct display *d = offscreen_open(W, W);
	struct renderer *r = d ? renderer_new(&d->gl, NULL) : NULL;
	struct kiosk_anim *a = kiosk_anim_new();
	struct renderer_stats before, after;
	struct scene_dir t;
	struct content s;
	struct options o;
	struct view v;
	uint64_t next;
	uint8_t px[3];

	assert_non_null(r);
	scene_dir_make(&t, gltf_write_variants_skinned, VARIANTS_OK);
	option_defaults(&o);
	o.content.model = t.model;
	o.content.matcap = t.white;
	o.content.anim_live = true;
	o.content.anim_time = -1;
	o.content.lod_pixels = 0;
	renderer_set_bone_limit(r, bones);
	assert_int_equal(content_load(&s, &o.content, true), 0);
	assert_int_equal(content_prepare(&s, &o.content, W, W), 0);
	assert_int_equal(content_upload(&s, r), 0);
	assert_non_null(s.play);
	assert_ptr_equal(s.play_ops, &content_deform_gpu);
	assert_true(split ? s.play_split && s.play_split->range_count == 2 : !s.play_split);
	assert_int_equal(renderer_set_mode(r, o.content.mode, false), 0);
	struct kiosk_anim_input in = {.running = true, .config = &o.content};
	assert_true(kiosk_anim_step(a, &s, r, &in, 1000000000ull, &next));
	assert_int_equal(renderer_variant_count(r), 2);
	v = content_view(&o.content);
	centre(d, r, &v, px);
	assert_true(px[0] > 200 && px[1] < 40 && px[2] < 40);
	renderer_get_stats(r, &before);
	assert_true(renderer_show_variant(r, content_variant_find(&s, "blue")));
	centre(d, r, &v, px);
	assert_true(px[2] > 200 && px[0] < 40 && px[1] < 40);
	renderer_get_stats(r, &after);
	assert_int_equal(after.vertex_bytes, before.vertex_bytes);
	assert_true(renderer_show_variant(r, -1));
	centre(d, r, &v, px);
	assert_true(px[0] > 200 && px[2] < 40);
	kiosk_anim_free(a);
	content_release(&s);
	renderer_free(r);
	scene_dir_remove(&t);
}

static void test_skinned_switch(void **state)
{
	(void)state;
	skinned_switch(UINT32_MAX, false);
}

static void test_split_skinned_switch(void **state)
{
	(void)state;
	skinned_switch(1, true);
}

/* A split's draws each carry, per variant, the material of the range
 * they were cut from: "blue" maps the second primitive alone, so only
 * the draws cut from it change. */
static void test_split_draws_keep_their_range(void **state)
{
	struct mesh m;
	struct anim_play_split *sp;
	struct scene_dir t;
	struct content s;
	struct options o;
	struct renderer *r;
	struct display *d = offscreen_open(W, W);

	(void)state;
	r = d ? renderer_new(&d->gl, NULL) : NULL;
	assert_non_null(r);
	scene_dir_make(&t, gltf_write_variants_skinned, VARIANTS_SPLIT);
	option_defaults(&o);
	o.content.model = t.model;
	o.content.anim_live = true;
	o.content.anim_time = -1;
	o.content.lod_pixels = 0;
	renderer_set_bone_limit(r, 1);
	assert_int_equal(content_load(&s, &o.content, true), 0);
	assert_int_equal(content_prepare(&s, &o.content, W, W), 0);
	assert_int_equal(content_upload(&s, r), 0);
	sp = s.play_split;
	assert_non_null(sp);
	assert_non_null(sp->variant_materials);
	m = s.mesh;
	assert_int_equal(m.range_count, 2);
	for (uint32_t k = 0; k < sp->range_count; k++) {
		uint32_t from = sp->origin[k];

		assert_true(from < m.range_count);
		assert_int_equal(sp->ranges[k].material, m.ranges[from].material);
		for (int var = 0; var < 2; var++)
			assert_int_equal(sp->variant_materials[(size_t)var * sp->range_count + k],
					 mesh_range_material(&m, var, from));
	}
	assert_int_not_equal(mesh_range_material(&m, 1, 1), m.ranges[1].material);
	assert_int_equal(renderer_variant_count(r), 2);
	content_release(&s);
	renderer_free(r);
	scene_dir_remove(&t);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_names_and_mapping),
	    cmocka_unit_test(test_per_primitive),
	    cmocka_unit_test(test_missing_material_refused),
	    cmocka_unit_test(test_missing_variant_refused),
	    cmocka_unit_test(test_too_many_refused),
	    cmocka_unit_test(test_draw_list_switch),
	    cmocka_unit_test(test_switch_draws_the_variant),
	    cmocka_unit_test(test_skinned_switch),
	    cmocka_unit_test(test_split_skinned_switch),
	    cmocka_unit_test(test_split_draws_keep_their_range),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
