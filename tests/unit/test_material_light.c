/* Issue 37's materials resolved (scene/gltf_material.cc, scene/material.c):
 * KHR_materials_unlit per material, emissiveFactor x
 * KHR_materials_emissive_strength with its map on TEXCOORD_1 through its
 * own transform, and a spec-gloss material's diffuse as its base colour;
 * each range's draw adds them to its own program only. On the old code
 * the unlit flag and the emission were not read (the file with
 * KHR_materials_pbrSpecularGlossiness required was refused). */
#include "gltf_parts.h"
#include "render/draw_list.h"
#include "scene/gltf/gltf.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "util/image.h"
#include "util/log.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

struct fixture {
	char dir[64], png[128];
	struct mesh sphere;
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));
	struct image img;

	if (!f)
		return -1;
	strcpy(f->dir, "/tmp/mk-light-XXXXXX");
	if (!mkdtemp(f->dir) || mesh_uv_sphere(&f->sphere, 12, 8) || image_alloc(&img, 4, 4))
		return -1;
	memset(img.rgba, 200, 64);
	snprintf(f->png, sizeof(f->png), "%s/t.png", f->dir);
	if (image_write_png(f->png, &img))
		return -1;
	image_release(&img);
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fixture *f = *state;
	char cmd[128];

	snprintf(cmd, sizeof(cmd), "rm -rf %s", f->dir);
	mesh_release(&f->sphere);
	free(f);
	return system(cmd);
}

/* Loads parts into m and resolves them with cfg into mat. */
static void load(const struct fixture *f, const struct gltf_part *p,
		 const struct gltf_part_more *more, int n, const struct material_config *cfg,
		 struct mesh *m, struct material *mat)
{
	char path[256];

	snprintf(path, sizeof(path), "%s/m.glb", f->dir);
	assert_int_equal(gltf_write_parts_more(path, p, more, n), 0);
	assert_int_equal(gltf_load_textures(path, material_gltf_textures(cfg), m), 0);
	assert_int_equal(material_load(mat, cfg, m, true), 0);
}

/* One unlit part beside a shaded one: the flag is the part's own, and
 * [material] unlit = shade turns it off. */
static void unlit_per_material(void **state)
{
	static const char unlit[] = "\"extensions\":{\"KHR_materials_unlit\":{}}";
	struct fixture *f = *state;
	struct gltf_part p[2] = {{&f->sphere, {1, 1, 1, 1}, f->png, unlit, NULL, 1, NULL},
				 {&f->sphere, {0.5, 0.5, 1, 1}, NULL, NULL, NULL, 1, NULL}};
	struct material_config cfg;
	struct material mat;
	struct mesh m;

	material_config_defaults(&cfg);
	load(f, p, NULL, 2, &cfg, &m, &mat);
	assert_int_equal(mat.surface_count, 2);
	assert_true(m.materials[0].unlit && !m.materials[1].unlit);
	assert_true(mat.surfaces[0].features & MATERIAL_UNLIT);
	assert_false(mat.surfaces[1].features & MATERIAL_UNLIT);
	/* Only the unlit range's program variant adds it. */
	struct draw_list l;
	assert_int_equal(draw_list_build(&l, m.ranges, m.range_count, m.indices, m.index_count,
					 m.vertex_count, mat.surfaces, mat.surface_count, true),
			 0);
	for (uint32_t i = 0; i < l.count; i++)
		assert_int_equal(draw_variant_adds(draw_item_variant(&l.items[i])),
				 l.items[i].surface == 0 ? MATERIAL_UNLIT : 0u);
	draw_list_release(&l);
	material_release(&mat);
	cfg.unlit = UNLIT_SHADE;
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_false((mat.surfaces[0].features | mat.features) & MATERIAL_UNLIT);
	material_release(&mat);
	mesh_release(&m);
}

/* emissiveFactor x strength, its map on TEXCOORD_1 (the only set the part
 * has) with its own transform; a part without emission has none. */
static void emission_factor_strength_and_map(void **state)
{
	static const char glow[] = "\"emissiveFactor\":[1,0.5,0.25],\"extensions\":{"
				   "\"KHR_materials_emissive_strength\":{\"emissiveStrength\":2}}";
	static const char info[] = "\"texCoord\":1,\"extensions\":{\"KHR_texture_transform\":{"
				   "\"texCoord\":1,\"offset\":[0.5,0],\"scale\":[0.5,1]}}";
	struct fixture *f = *state;
	struct gltf_part p[2] = {{&f->sphere, {1, 1, 1, 1}, NULL, glow, NULL, 1, NULL},
				 {&f->sphere, {0.5, 0.5, 1, 1}, NULL, NULL, NULL, 1, NULL}};
	struct gltf_part_more more[2] = {{f->png, info, 1, 0, NULL, 0},
					 {NULL, NULL, 1, 0, NULL, 0}};
	static const float want[6] = {0.5f, 0, 0, 1, 0.5f, 0};
	struct material_config cfg;
	struct material mat;
	struct mesh m;

	material_config_defaults(&cfg);
	load(f, p, more, 2, &cfg, &m, &mat);
	assert_non_null(m.uvs);
	assert_true(mat.surfaces[0].emissive[0] == 2.0f && mat.surfaces[0].emissive[1] == 1.0f &&
		    mat.surfaces[0].emissive[2] == 0.5f);
	assert_int_equal(mat.surfaces[0].features & (MATERIAL_EMISSIVE | MATERIAL_EMISSIVE_MAP),
			 MATERIAL_EMISSIVE | MATERIAL_EMISSIVE_MAP);
	assert_int_equal(mat.surfaces[0].emissive_map.width, 4);
	for (int k = 0; k < 6; k++)
		assert_true(fabsf(mat.surfaces[0].emissive_transform[k] - want[k]) < 1e-6f);
	assert_false(mat.surfaces[1].features & MATERIAL_EMISSIVE);
	assert_true(material_needs_uvs(mat.features));
	/* One set in the file: no second one is carried, nor bound. */
	assert_null(m.uv1);
	assert_false(material_needs_uv1(mat.features));
	material_release(&mat);
	mesh_release(&m);
}

/* The base map on TEXCOORD_0 and the emissive map on TEXCOORD_1: the
 * second set is carried as the mesh's uv1 (the part's own, zeros for the
 * part without one) and the map drawn by it, with no warning; before, the
 * emissive factor was drawn alone and the journal said so. */
static void emission_on_its_own_uv_set(void **state)
{
	static const char glow[] = "\"emissiveFactor\":[1,0.5,0.25]";
	static const char info[] = "\"texCoord\":1,\"extensions\":{\"KHR_texture_transform\":{"
				   "\"offset\":[0.25,0],\"scale\":[0.5,1]}}";
	struct fixture *f = *state;
	uint32_t nv = f->sphere.vertex_count;
	float *uv1 = malloc((size_t)nv * 8);
	struct gltf_part p[2] = {{&f->sphere, {1, 1, 1, 1}, f->png, glow, NULL, 1, NULL},
				 {&f->sphere, {0.5, 0.5, 1, 1}, NULL, NULL, NULL, 1, NULL}};
	struct gltf_part_more more[2] = {{f->png, info, 0, 0, NULL, 1},
					 {NULL, NULL, 0, 0, NULL, 0}};
	struct material_config cfg;
	struct material mat;
	struct mesh m;
	unsigned warned;

	assert_non_null(uv1);
	/* Another mapping than TEXCOORD_0's: u and v swapped. */
	for (uint32_t i = 0; i < nv; i++) {
		uv1[i * 2] = f->sphere.uvs[i * 2 + 1];
		uv1[i * 2 + 1] = f->sphere.uvs[i * 2];
	}
	more[0].uv1 = uv1;
	material_config_defaults(&cfg);
	warned = log_warnings();
	load(f, p, more, 2, &cfg, &m, &mat);
	assert_int_equal(log_warnings(), warned);
	assert_non_null(m.uvs);
	assert_non_null(m.uv1);
	assert_int_equal(m.vertex_count, 2 * nv);
	for (uint32_t i = 0; i < nv * 2; i++) {
		assert_true(m.uv1[i] == uv1[i]);
		assert_true(m.uv1[nv * 2 + i] == 0.0f);
	}
	assert_true(m.materials[0].emissive_uv1 && !m.materials[1].emissive_uv1);
	assert_int_equal(mat.surfaces[0].features &
			     (MATERIAL_EMISSIVE_MAP | MATERIAL_EMISSIVE_UV1 | MATERIAL_BASE_MAP),
			 MATERIAL_EMISSIVE_MAP | MATERIAL_EMISSIVE_UV1);
	assert_int_equal(mat.surfaces[0].emissive_map.width, 4);
	assert_true(mat.features & MATERIAL_BASE_MAP);
	assert_false(mat.surfaces[1].features & MATERIAL_EMISSIVE_UV1);
	assert_true(material_needs_uv1(mat.features) && material_needs_uvs(mat.features));
	/* The part's program variant reads the second set; the other's none. */
	struct draw_list l;
	assert_int_equal(draw_list_build(&l, m.ranges, m.range_count, m.indices, m.index_count,
					 m.vertex_count, mat.surfaces, mat.surface_count, true),
			 0);
	for (uint32_t i = 0; i < l.count; i++)
		assert_int_equal(draw_variant_adds(draw_item_variant(&l.items[i])) &
				     MATERIAL_EMISSIVE_UV1,
				 l.items[i].surface == 0 ? MATERIAL_EMISSIVE_UV1 : 0u);
	draw_list_release(&l);
	material_release(&mat);
	mesh_release(&m);
	free(uv1);
}

/* A spec-gloss material: diffuseFactor (with its alpha) and diffuseTexture
 * are the base colour. */
static void spec_gloss_diffuse_is_the_base_colour(void **state)
{
	struct fixture *f = *state;
	struct gltf_part p[1] = {{&f->sphere, {0.25, 0.5, 0.75, 0.6}, f->png, NULL, NULL, 1, NULL}};
	struct gltf_part_more more[1] = {{NULL, NULL, 0, 1, NULL, 0}};
	struct material_config cfg;
	struct material mat;
	struct mesh m;

	material_config_defaults(&cfg);
	load(f, p, more, 1, &cfg, &m, &mat);
	assert_true(m.materials[0].base_color[0] == 0.25f && m.materials[0].base_color[1] == 0.5f &&
		    m.materials[0].base_color[2] == 0.75f);
	assert_true(fabsf(mat.surfaces[0].alpha - 0.6f) < 1e-6f);
	assert_int_equal(mat.surfaces[0].base_map.width, 4);
	assert_int_equal(mat.features & (MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP),
			 MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP);
	material_release(&mat);
	mesh_release(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(unlit_per_material),
	    cmocka_unit_test(emission_factor_strength_and_map),
	    cmocka_unit_test(emission_on_its_own_uv_set),
	    cmocka_unit_test(spec_gloss_diffuse_is_the_base_colour),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
