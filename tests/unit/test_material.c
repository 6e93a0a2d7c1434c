#include "scene/gltf/gltf.h"
#include "gltf_write.h"
#include "util/image.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "oracle/oracle.h"
#include "scene/mesh/tangent.h"
#include "render/shader.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

struct fixture {
	char dir[64];
	char png[3][128]; /* a flat normal map, an occlusion map, a thickness map */
	struct mesh sphere;
};

static void path_in(const struct fixture *f, const char *name, char *out, size_t n)
{
	snprintf(out, n, "%s/%s", f->dir, name);
}

/* A w x h map with every texel r, g, b, a. */
static void write_png(const char *path, int w, int h, const uint8_t rgba[4])
{
	struct image img;

	assert_int_equal(image_alloc(&img, w, h), 0);
	for (int i = 0; i < w * h; i++)
		memcpy(img.rgba + i * 4, rgba, 4);
	assert_int_equal(image_write_png(path, &img), 0);
	image_release(&img);
}

static int setup(void **state)
{
	static const uint8_t colours[3][4] = {
	    {128, 128, 255, 255}, {64, 64, 64, 255}, {0, 51, 0, 255}};
	static const char *const names[3] = {"normal.png", "occlusion.png", "thickness.png"};
	struct fixture *f = calloc(1, sizeof(*f));

	strcpy(f->dir, "/tmp/mk-material-XXXXXX");
	if (!mkdtemp(f->dir) || mesh_uv_sphere(&f->sphere, 12, 8))
		return -1;
	char dir[sizeof(f->dir)];

	memcpy(dir, f->dir, sizeof(dir));
	for (int i = 0; i < 3; i++) {
		snprintf(f->png[i], sizeof(f->png[i]), "%s/%s", dir, names[i]);
		write_png(f->png[i], 6, 3 + i, colours[i]);
	}
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

static struct gltf_write_opts material_opts(const struct fixture *f)
{
	return (struct gltf_write_opts){.index_bytes = 2,
					.with_normals = 1,
					.bad_index = -1,
					.with_uvs = 1,
					.normal_png = f->png[0],
					.occlusion_png = f->png[1],
					.thickness_png = f->png[2],
					.embed_images = 1,
					.iridescence_factor = 0.5,
					.thickness_range = {200, 400}};
}

static void write_model(const struct fixture *f, const char *name, struct gltf_write_opts o,
			char *path, size_t n)
{
	path_in(f, name, path, n);
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
}

/* The matcap program's defines, space-separated, as the builder gets them. */
static const char *matcap_defines(unsigned features, enum shading_mode mode, bool ortho, bool lit,
				  bool highp)
{
	static char buf[512];
	struct shader_source src;
	size_t n = 0;

	buf[0] = '\0';
	assert_int_equal(shader_source_matcap(&src, NULL, features, mode, ortho, lit, highp), 0);
	for (int i = 0; i < src.define_count; i++)
		n += (size_t)snprintf(buf + n, sizeof(buf) - n, "%s%s", i ? " " : "",
				      src.defines[i]);
	return buf;
}

/* A feature that is off puts no line in the program: the defines are the
 * mapping mode's and nothing else. */
static void defines_hold_only_what_is_on(void **state)
{
	struct shader_source src = {0};

	(void)state;
	assert_string_equal(matcap_defines(0, SHADING_VIEW, false, false, false), "MODE_VIEW");
	assert_string_equal(
	    matcap_defines(MATERIAL_IRIDESCENCE | MATERIAL_RAMP, SHADING_VIEW, true, false, false),
	    "MODE_VIEW CAMERA_ORTHO IRIDESCENCE IRIDESCENCE_RAMP");
	/* Displacement is done on the CPU: it adds nothing to the program. */
	assert_string_equal(
	    matcap_defines(MATERIAL_DISPLACEMENT, SHADING_NORMAL, false, false, false),
	    "MODE_NORMAL");
	/* sem-vertex has no per-fragment normal for these to work on. */
	assert_string_equal(matcap_defines(MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL,
					   SHADING_SEM_VERTEX, false, true, false),
			    "MODE_SEM_FRAGMENT DETAIL_MAP DETAIL_NORMAL LIT");
	assert_string_equal(matcap_defines(MATERIAL_DETAIL, SHADING_SEM_VERTEX, false, false, true),
			    "MODE_SEM_VERTEX DETAIL_MAP PRECISION_HIGHP");
	for (int i = 0; i < SHADER_MAX_DEFINES; i++)
		assert_int_equal(shader_source_define(&src, "X"), 0);
	assert_int_equal(shader_source_define(&src, "X"), -ENOSPC);
	assert_false(material_needs_uvs(MATERIAL_IRIDESCENCE | MATERIAL_DISPLACEMENT));
	assert_true(material_needs_uvs(MATERIAL_DETAIL));
	assert_false(material_needs_tangents(MATERIAL_DETAIL));
	assert_true(material_needs_tangents(MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL));
}

/* With nothing asked for, nothing is decoded, however much the glTF
 * material names; what it says in numbers is still read. */
static void textures_decoded_only_when_asked(void **state)
{
	struct fixture *f = *state;
	struct material_config cfg;
	char path[256];
	struct mesh m;

	write_model(f, "all.glb", material_opts(f), path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, 0, &m), 0);
	assert_true(m.materials[0].present && m.materials[0].iridescence);
	assert_true(m.materials[0].has_normal_map && m.materials[0].has_occlusion_map &&
		    m.materials[0].has_thickness_map);
	assert_int_equal(m.materials[0].normal_map.width + m.materials[0].occlusion_map.width +
			     m.materials[0].thickness_map.width,
			 0);
	assert_true(fabs(m.materials[0].iridescence_factor - 0.5) < 1e-6);
	assert_true(m.materials[0].thickness_min == 200.0f &&
		    m.materials[0].thickness_max == 400.0f);
	assert_true(fabs(m.materials[0].base_color[0] - 0.8) < 1e-6);
	mesh_release(&m);
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_OCCLUSION, &m), 0);
	assert_int_equal(m.materials[0].normal_map.width, 0);
	assert_int_equal(m.materials[0].occlusion_map.width, 6);
	assert_int_equal(m.materials[0].occlusion_map.height, 4);
	mesh_release(&m);
	/* The settings decide what is asked. */
	material_config_defaults(&cfg);
	assert_int_equal(material_gltf_textures(&cfg),
			 GLTF_TEXTURE_NORMAL | GLTF_TEXTURE_OCCLUSION | GLTF_TEXTURE_THICKNESS |
			     GLTF_TEXTURE_BASE_COLOR);
	cfg.base_color = MATERIAL_OFF;
	assert_int_equal(material_gltf_textures(&cfg),
			 GLTF_TEXTURE_NORMAL | GLTF_TEXTURE_OCCLUSION | GLTF_TEXTURE_THICKNESS);
	cfg.iridescence = MATERIAL_OFF;
	assert_int_equal(material_gltf_textures(&cfg),
			 GLTF_TEXTURE_NORMAL | GLTF_TEXTURE_OCCLUSION);
	cfg.detail = MATERIAL_OFF;
	assert_int_equal(material_gltf_textures(&cfg), 0);
}

/* External images follow the buffers' rule: beside the model only. A
 * texture that cannot be used is a warning; the model still loads. */
static void unusable_textures_leave_the_model(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = material_opts(f);
	char path[256], text[256];
	struct mesh m;

	o.embed_images = 0;
	o.container = GLTF_EXTERNAL_BIN;
	write_model(f, "beside.gltf", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_NORMAL, &m), 0);
	assert_int_equal(m.materials[0].normal_map.width, 6);
	mesh_release(&m);
	o.image_uri = "../normal.png";
	write_model(f, "outside.gltf", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_NORMAL, &m), 0);
	assert_int_equal(m.materials[0].normal_map.width, 0);
	mesh_release(&m);
	o.image_uri = "/etc/passwd";
	write_model(f, "absolute.gltf", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_NORMAL, &m), 0);
	assert_int_equal(m.materials[0].normal_map.width, 0);
	mesh_release(&m);
	path_in(f, "text.png", text, sizeof(text));
	FILE *t = fopen(text, "w");
	fputs("not a picture", t);
	fclose(t);
	o = material_opts(f);
	o.normal_png = text;
	write_model(f, "corrupt.glb", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_NORMAL, &m), 0);
	assert_int_equal(m.materials[0].normal_map.width, 0);
	mesh_release(&m);
}

/* TANGENT is read, turned with the node, and its w flips under a mirror. */
static void tangents_follow_the_node(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = material_opts(f);
	struct mesh src, m;
	char path[256];

	assert_int_equal(mesh_uv_sphere(&src, 12, 8), 0);
	assert_int_equal(tangent_generate(&src), 0);
	o.with_tangents = 1;
	for (int mirror = 0; mirror < 2; mirror++) {
		o.node = mirror ? "\"scale\":[-1,1,1]" : NULL;
		path_in(f, "tangents.glb", path, sizeof(path));
		assert_int_equal(gltf_write(path, &src, &o), 0);
		assert_int_equal(gltf_load(path, &m), 0);
		assert_non_null(m.tangents);
		for (uint32_t v = 0; v < m.vertex_count; v++) {
			assert_true(m.tangents[v * 4 + 3] == (mirror ? -1.0f : 1.0f));
			assert_true(fabs(m.tangents[v * 4] -
					 src.tangents[v * 4] * (mirror ? -1 : 1)) < 1e-6);
		}
		mesh_release(&m);
	}
	mesh_release(&src);
}

/* KHR_materials_iridescence into the shader's numbers (see material.c):
 * average 2 eta dmax / 550, range -dmax / (eta 550), shift 2 eta (dmax -
 * dmin) / 550, opacity 0.6 x factor; a setting overrides each. */
static void iridescence_from_gltf_and_settings(void **state)
{
	struct fixture *f = *state;
	struct material_config cfg;
	struct material mat;
	char path[256];
	struct mesh m;

	write_model(f, "irid.glb", material_opts(f), path, sizeof(path));
	material_config_defaults(&cfg);
	cfg.base_color = MATERIAL_OFF; /* its baseColorFactor: test_base_color.c */
	assert_int_equal(gltf_load_textures(path, material_gltf_textures(&cfg), &m), 0);
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_true(mat.features & MATERIAL_IRIDESCENCE);
	assert_true(mat.features & MATERIAL_DETAIL);
	assert_true(mat.features & MATERIAL_DETAIL_NORMAL);
	assert_true(fabs(mat.hue_average - 2 * 1.3 * 400 / 550.0) < 1e-5);
	assert_true(fabs(mat.hue_range + 400 / (1.3 * 550.0)) < 1e-5);
	assert_true(fabs(mat.hue_shift - 2 * 1.3 * 200 / 550.0) < 1e-5);
	assert_true(fabs(mat.opacity - 0.3) < 1e-6);
	/* The material's own map, on its surface (none for the whole
	 * model): packed at the largest map's size, a power of two: 8 x 4
	 * (from 6 x 5). Flat normal, occlusion 64 in blue, thickness 51 in
	 * alpha. Its iridescence is its surface's too. */
	assert_int_equal(mat.surface_count, 1);
	assert_int_equal(mat.detail.width, 0);
	assert_int_equal(mat.surfaces[0].features,
			 MATERIAL_IRIDESCENCE | MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL);
	assert_true(mat.surfaces[0].hue_average == mat.hue_average &&
		    mat.surfaces[0].hue_range == mat.hue_range &&
		    mat.surfaces[0].hue_shift == mat.hue_shift &&
		    mat.surfaces[0].opacity == mat.opacity);
	assert_int_equal(mat.surfaces[0].detail.width, 8);
	assert_int_equal(mat.surfaces[0].detail.height, 4);
	for (int i = 0; i < 32; i++) {
		const uint8_t *p = mat.surfaces[0].detail.rgba + i * 4;

		assert_true(abs(p[0] - 128) <= 1 && abs(p[1] - 128) <= 1);
		assert_int_equal(p[2], 64);
		assert_int_equal(p[3], 51);
	}
	material_release(&mat);
	cfg.hue_range = 0.25;
	cfg.opacity = 1.0;
	cfg.detail = MATERIAL_OFF;
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_true(mat.hue_range == 0.25f && mat.opacity == 1.0f);
	assert_int_equal(mat.features, MATERIAL_IRIDESCENCE);
	material_release(&mat);
	cfg.iridescence = MATERIAL_OFF;
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.features, 0);
	material_release(&mat);
	mesh_release(&m);
}

/* A file the settings name: strict (a one-shot render) fails with it;
 * the kiosk turns the feature off and goes on. */
static void named_files_strict_or_not(void **state)
{
	struct fixture *f = *state;
	struct material_config cfg;
	struct material mat;
	struct mesh nouv;

	material_config_defaults(&cfg);
	cfg.detail_map = "/nonexistent/detail.png";
	assert_int_equal(material_load(&mat, &cfg, &f->sphere, true), -ENOENT);
	assert_int_equal(material_load(&mat, &cfg, &f->sphere, false), 0);
	assert_int_equal(mat.features, 0);
	material_release(&mat);
	cfg.detail_map = f->png[1]; /* 6 x 3: brought to 8 x 4 */
	cfg.height_map = f->png[1];
	assert_int_equal(material_load(&mat, &cfg, &f->sphere, true), 0);
	assert_int_equal(mat.features,
			 MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL | MATERIAL_DISPLACEMENT);
	assert_int_equal(mat.detail.width, 8);
	assert_int_equal(mat.detail.height, 4);
	material_release(&mat);
	/* No UVs: nothing to place a map with. */
	assert_int_equal(mesh_uv_sphere(&nouv, 6, 4), 0);
	free(nouv.uvs);
	nouv.uvs = NULL;
	assert_int_equal(material_load(&mat, &cfg, &nouv, true), -EINVAL);
	assert_int_equal(material_load(&mat, &cfg, &nouv, false), 0);
	assert_int_equal(mat.features, 0);
	material_release(&mat);
	mesh_release(&nouv);
}

/* Prepared for the screen: subdivided and displaced, refitted, and with
 * tangents for the detail normal. */
static void prepare_gives_what_features_need(void **state)
{
	struct fixture *f = *state;
	struct material_config cfg;
	struct material mat;
	struct mesh m;
	double r2 = 0;

	(void)f;
	char height[256];
	static const uint8_t grey[4] = {100, 100, 100, 255};

	path_in(f, "height64.png", height, sizeof(height));
	write_png(height, 64, 64, grey);
	material_config_defaults(&cfg);
	cfg.detail_map = f->png[0];
	cfg.height_map = height;
	cfg.displacement_pixels = 4;
	assert_int_equal(mesh_uv_sphere(&m, 12, 8), 0);
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(material_prepare_mesh(&mat, &m, 640, 480), 0);
	/* A 64-texel map over 12 x 8 quads: edges span 5 to 10 texels. */
	assert_true(m.index_count >= 12 * 8 * 6 * 25 && m.index_count <= 12 * 8 * 6 * 100);
	assert_non_null(m.tangents);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *p = m.positions + v * 3;

		r2 = fmax(r2, p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
	}
	assert_true(fabs(sqrt(r2) - 1.0) < 1e-5);
	material_release(&mat);
	mesh_release(&m);
}

static void mirrors_of_the_shader_math(void **state)
{
	double rgb[3], n[3] = {0, 0, 1}, out[3];
	double tangent[4] = {1, 0, 0, 1}, flat[2] = {0.5, 0.5}, up[2] = {0.5, 1.0};
	double e[3] = {0, 0, -1}, l[3] = {0, 0, 1}, base[3] = {1, 0.5, 0.25};

	(void)state;
	shading_hsv_to_rgb(0.0, 1.0, 1.0, rgb);
	assert_true(rgb[0] == 1.0 && rgb[1] == 0.0 && rgb[2] == 0.0);
	shading_hsv_to_rgb(1.0 / 3.0, 1.0, 1.0, rgb);
	assert_true(fabs(rgb[0]) < 1e-12 && fabs(rgb[1] - 1) < 1e-12 && fabs(rgb[2]) < 1e-12);
	shading_hsv_to_rgb(2.0 / 3.0 + 3.0, 0.5, 0.8, rgb); /* whole turns do not matter */
	assert_true(fabs(rgb[0] - 0.4) < 1e-12 && fabs(rgb[1] - 0.4) < 1e-12 &&
		    fabs(rgb[2] - 0.8) < 1e-12);
	/* (n.e)^2: the same for a face seen from either side; no pow(). */
	assert_true(shading_iridescence_hue(-0.6, 0.5, 0.1, 0.2, 1.0) ==
		    shading_iridescence_hue(0.6, 0.5, 0.1, 0.2, 1.0));
	assert_true(fabs(shading_iridescence_hue(-1.0, 0.5, 0.1, 0.2, 0.0) - (0.1 - 0.2)) < 1e-15);
	assert_true(fabs(shading_iridescence_hue(0.0, 0.5, 0.1, 0.2, 1.0) - 0.6) < 1e-15);
	shading_detail_normal(n, tangent, flat, out);
	assert_true(fabs(out[2] - 1.0) < 1e-12);
	/* Green up is the bitangent, cross(n, t) w = +y; mirrored, -y. */
	shading_detail_normal(n, tangent, up, out);
	assert_true(fabs(out[1] - 1.0) < 1e-12);
	tangent[3] = -1;
	shading_detail_normal(n, tangent, up, out);
	assert_true(fabs(out[1] + 1.0) < 1e-12);
	/* Facing the light: full diffuse plus the full highlight. */
	shading_blinn_phong(n, e, l, base, 48, rgb);
	assert_true(fabs(rgb[0] - 1.5) < 1e-12 && fabs(rgb[2] - 0.75) < 1e-12);
	l[2] = -1; /* behind: ambient only */
	shading_blinn_phong(n, e, l, base, 48, rgb);
	assert_true(fabs(rgb[0] - 0.15) < 1e-12);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(defines_hold_only_what_is_on),
	    cmocka_unit_test(textures_decoded_only_when_asked),
	    cmocka_unit_test(unusable_textures_leave_the_model),
	    cmocka_unit_test(tangents_follow_the_node),
	    cmocka_unit_test(iridescence_from_gltf_and_settings),
	    cmocka_unit_test(named_files_strict_or_not),
	    cmocka_unit_test(prepare_gives_what_features_need),
	    cmocka_unit_test(mirrors_of_the_shader_math),
	};
	return cmocka_run_group_tests_name("material", tests, setup, teardown);
}
