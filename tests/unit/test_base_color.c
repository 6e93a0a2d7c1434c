/* The glTF base colour: baseColorFactor x COLOR_0 per vertex, the
 * baseColorTexture and its KHR_texture_transform, [scene] base_color =
 * off, and what a model without colour costs (nothing). The colours on
 * screen: tests/oracle/base_color_check.c and the golden images. */
#include "scene/gltf/gltf.h"
#include "gltf_parts.h"
#include "gltf_write.h"
#include "render/draw_list.h"
#include "scene/mesh/lod.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/mesh_pack.h"
#include "util/image.h"

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
	char png[128];	    /* a 6 x 3 base map */
	struct mesh sphere; /* with colours (0.2 + 0.6 (p + 1) / 2) and UVs */
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));
	struct image img;

	strcpy(f->dir, "/tmp/mk-base-color-XXXXXX");
	if (!f || !mkdtemp(f->dir) || mesh_uv_sphere(&f->sphere, 12, 8) ||
	    mesh_alloc_colors(&f->sphere) || image_alloc(&img, 6, 3))
		return -1;
	for (uint32_t v = 0; v < f->sphere.vertex_count; v++) {
		for (int k = 0; k < 3; k++)
			f->sphere.colors[v * 4 + k] =
			    0.2f + 0.6f * (f->sphere.positions[v * 3 + k] + 1.0f) / 2.0f;
		f->sphere.colors[v * 4 + 3] = 0.5f;
	}
	for (int i = 0; i < 6 * 3 * 4; i++)
		img.rgba[i] = (uint8_t)(i * 3);
	snprintf(f->png, sizeof(f->png), "%s/base.png", f->dir);
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

static void write_model(const struct fixture *f, const char *name, struct gltf_write_opts o,
			char *path, size_t n)
{
	snprintf(path, n, "%s/%s", f->dir, name);
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
}

static struct gltf_write_opts plain(void)
{
	return (struct gltf_write_opts){
	    .index_bytes = 2, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
}

/* Factor x COLOR_0 per vertex, the map and its transform, and the
 * features material.c makes of them. */
static void factor_colour_map_and_transform(void **state)
{
	static const double factor[4] = {0.5, 1.0, 0.25, 1.0};
	struct fixture *f = *state;
	struct gltf_write_opts o = plain();
	struct material_config cfg;
	struct material mat;
	char path[256];
	struct mesh m;
	double c = cos(0.5), s = sin(0.5);
	const double want[6] = {c * 2, -s * 2, s * 3, c * 3, 0.25, -0.5};

	o.color_type = 5126;
	o.color_components = 3;
	o.base_color_png = f->png;
	o.embed_images = 1;
	o.base_factor = factor;
	o.texture_transform = "\"offset\":[0.25,-0.5],\"rotation\":0.5,\"scale\":[2,3]";
	write_model(f, "all.glb", o, path, sizeof(path));
	material_config_defaults(&cfg);
	assert_int_equal(gltf_load_textures(path, material_gltf_textures(&cfg), &m), 0);
	assert_non_null(m.colors);
	assert_true(m.has_colors && m.materials[0].has_base_map);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		for (int k = 0; k < 3; k++)
			assert_true(fabs(m.colors[v * 4 + k] -
					 factor[k] * f->sphere.colors[v * 4 + k]) < 1e-6);
		assert_true(m.colors[v * 4 + 3] == 1.0f); /* COLOR_0 of three has no alpha */
	}
	/* The map is its range's material's (one here). */
	assert_int_equal(m.range_count, 1);
	assert_int_equal(m.material_count, 1);
	assert_int_equal(m.materials[0].base_map.width, 6);
	for (int k = 0; k < 6; k++)
		assert_true(fabs(m.materials[0].base_transform[k] - want[k]) < 1e-6);
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.features, MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP);
	assert_int_equal(mat.surface_count, 1);
	assert_int_equal(mat.surfaces[0].base_map.width, 8); /* power-of-two sides, to repeat */
	assert_int_equal(mat.surfaces[0].base_map.height, 4);
	assert_true(mat.surfaces[0].base_transform[4] == 0.25f &&
		    mat.surfaces[0].base_transform[5] == -0.5f);
	material_release(&mat);
	mesh_release(&m);
	/* Off: neither the colours nor the map are read, nothing is on. */
	cfg.base_color = MATERIAL_OFF;
	assert_int_equal(material_gltf_textures(&cfg) & GLTF_TEXTURE_BASE_COLOR, 0);
	assert_int_equal(gltf_load_textures(path, material_gltf_textures(&cfg), &m), 0);
	assert_null(m.colors);
	assert_true(m.materials[0].has_base_map && !m.materials[0].base_map.width);
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.features, 0);
	material_release(&mat);
	mesh_release(&m);
}

/* COLOR_0 as normalized bytes (vec4) and shorts (vec3), its alpha kept
 * (1 for a vec3), and without a material the factor is 1. */
static void colour_types(void **state)
{
	static const int types[2] = {5121, 5123};
	static const double step[2] = {1.0 / 255, 1.0 / 65535};
	struct fixture *f = *state;
	struct gltf_write_opts o = plain();
	char path[256];
	struct mesh m;

	for (int t = 0; t < 2; t++) {
		o.color_type = types[t];
		o.color_components = t ? 3 : 4;
		write_model(f, t ? "ushort.glb" : "ubyte.glb", o, path, sizeof(path));
		assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), 0);
		assert_non_null(m.colors);
		for (uint32_t v = 0; v < m.vertex_count; v++) {
			for (int k = 0; k < 3; k++)
				assert_true(fabs(m.colors[v * 4 + k] -
						 f->sphere.colors[v * 4 + k]) <= step[t]);
			/* COLOR_0's own alpha (0.5 in the VEC4 one), else 1:
			 * no flag of whether the vertex reads a base map. */
			assert_true(fabs(m.colors[v * 4 + 3] - (t ? 1.0f : 0.5f)) <= step[t]);
		}
		mesh_release(&m);
	}
	/* Two components are no colour: refused. */
	o.color_components = 2;
	write_model(f, "vec2.glb", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), -EINVAL);
	/* ... but only read when the base colour is asked for. */
	assert_int_equal(gltf_load_textures(path, 0, &m), 0);
	mesh_release(&m);
}

/* A model with no colour costs nothing: no array, no feature. */
static void no_colour_no_cost(void **state)
{
	static const double white[4] = {1, 1, 1, 1};
	struct fixture *f = *state;
	struct gltf_write_opts o = plain();
	struct material_config cfg;
	struct material mat;
	char path[256];
	struct mesh m;

	material_config_defaults(&cfg);
	write_model(f, "plain.glb", o, path, sizeof(path));
	for (int i = 0; i < 2; i++) {
		assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), 0);
		assert_null(m.colors);
		assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
		assert_int_equal(mat.features, 0);
		material_release(&mat);
		mesh_release(&m);
		/* A white factor is no colour either. */
		o.base_factor = white;
		write_model(f, "white.glb", o, path, sizeof(path));
	}
	/* Nor is a white base map with no UVs to place it. */
	o.base_color_png = f->png;
	o.embed_images = 1;
	o.with_uvs = 0;
	write_model(f, "white-nouv.glb", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), 0);
	assert_null(m.colors);
	assert_false(m.has_colors);
	mesh_release(&m);
}

/* The base map's texCoord (here the transform's, which overrides it)
 * picks the UV set loaded; a set the model lacks places no map. */
static void tex_coord_picks_the_uv_set(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = plain();
	char path[256];
	struct mesh m;

	o.base_color_png = f->png;
	o.embed_images = 1;
	o.texture_transform = "\"texCoord\":1";
	o.uv_set = 1;
	write_model(f, "uv1.glb", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), 0);
	assert_non_null(m.uvs);
	assert_memory_equal(m.uvs, f->sphere.uvs, (size_t)m.vertex_count * 8);
	assert_int_equal(m.materials[0].base_map.width, 6);
	mesh_release(&m);
	/* Without the base colour, TEXCOORD_0 is what is read: none here. */
	assert_int_equal(gltf_load_textures(path, 0, &m), 0);
	assert_null(m.uvs);
	mesh_release(&m);
	o.uv_set = 0;
	write_model(f, "uv1-missing.glb", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), 0);
	assert_null(m.colors); /* one colour, the default factor 0.8 0.7 0.6: a constant */
	assert_true(m.has_colors);
	assert_true(fabsf(m.vertex_color[0] - 0.8f) < 1e-6f);
	assert_null(m.uvs);
	assert_int_equal(m.materials[0].base_map.width, 0);
	mesh_release(&m);
	/* A normal map asked for needs TEXCOORD_0: it wins, the base map on
	 * TEXCOORD_1 is left out (a warning). */
	o.normal_png = f->png;
	write_model(f, "uv1-normal.glb", o, path, sizeof(path));
	assert_int_equal(
	    gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR | GLTF_TEXTURE_NORMAL, &m), 0);
	assert_non_null(m.uvs);
	assert_int_equal(m.materials[0].normal_map.width, 6);
	assert_int_equal(m.materials[0].base_map.width, 0);
	mesh_release(&m);
}

/* Packed as normalized bytes in the compact format, floats otherwise; and
 * simplification keeps them. */
static void packed_and_simplified(void **state)
{
	struct fixture *f = *state;
	struct mesh_packed p;
	struct mesh m;

	assert_int_equal(mesh_array_stride(VERTEX_COMPACT, MESH_COLORS), 4);
	assert_int_equal(mesh_array_stride(VERTEX_FLOAT32, MESH_COLORS), 16);
	assert_int_equal(mesh_array_component(VERTEX_COMPACT, MESH_COLORS), MESH_UNORM8);
	assert_int_equal(mesh_pack(&f->sphere, VERTEX_COMPACT, &p), 0);
	assert_non_null(p.arrays[MESH_COLORS]);
	for (uint32_t i = 0; i < f->sphere.vertex_count * 4; i++)
		assert_int_equal(((const uint8_t *)p.arrays[MESH_COLORS])[i],
				 (uint8_t)lrintf(f->sphere.colors[i] * 255.0f));
	mesh_packed_release(&p);
	assert_int_equal(mesh_uv_sphere(&m, 64, 32), 0);
	assert_int_equal(mesh_alloc_colors(&m), 0);
	for (uint32_t i = 0; i < m.vertex_count * 4; i++)
		m.colors[i] = 0.25f;
	assert_int_equal(lod_prepare_mesh(&m, 8.0, 320, 240, NULL), 0);
	assert_non_null(m.colors);
	for (uint32_t i = 0; i < m.vertex_count * 4; i++)
		assert_true(m.colors[i] == 0.25f);
	mesh_release(&m);
}

/* Only the images a scene uses and can place are decoded: counted by the
 * loader, not timed. */
static void decodes_only_what_is_used(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = plain();
	struct material_config cfg;
	char path[256];
	struct mesh m;
	struct {
		unsigned textures;
		unsigned decoded;
	} cases[] = {
	    {0, 0}, {GLTF_TEXTURE_BASE_COLOR, 1}, {GLTF_TEXTURE_NORMAL | GLTF_TEXTURE_OCCLUSION, 2},
	    {0, 3}, /* the defaults: every one */
	    {0, 0}, /* detail and base colour off */
	};

	material_config_defaults(&cfg);
	cases[3].textures = material_gltf_textures(&cfg);
	cfg.detail = cfg.base_color = MATERIAL_OFF;
	cases[4].textures = material_gltf_textures(&cfg);
	o.normal_png = o.occlusion_png = o.base_color_png = f->png;
	o.embed_images = 1;
	write_model(f, "maps.glb", o, path, sizeof(path));
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		assert_int_equal(gltf_load_textures(path, cases[i].textures, &m), 0);
		assert_int_equal(mesh_images_decoded(&m), cases[i].decoded);
		assert_true(m.materials[0].has_normal_map && m.materials[0].has_base_map);
		mesh_release(&m);
	}
	/* No TEXCOORD_0: no texture can be placed, none is decoded. */
	o.with_uvs = 0;
	write_model(f, "maps-nouv.glb", o, path, sizeof(path));
	assert_int_equal(gltf_load_textures(path, cases[3].textures, &m), 0);
	assert_int_equal(mesh_images_decoded(&m), 0);
	mesh_release(&m);
}

static void base64(const uint8_t *in, size_t n, char *out)
{
	static const char abc[] =
	    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

	for (size_t i = 0; i < n; i += 3) {
		uint32_t v = (uint32_t)in[i] << 16 | (i + 1 < n ? (uint32_t)in[i + 1] << 8 : 0) |
			     (i + 2 < n ? in[i + 2] : 0);

		for (int k = 0; k < 4; k++)
			*out++ = (size_t)k <= n - i ? abc[(v >> (18 - 6 * k)) & 63] : '=';
	}
	*out = '\0';
}

/* Three triangles, a primitive each, of materials mat[i] (-1: none) from
 * the JSON array materials; the third with COLOR_0 (0.5, 0.25, 1) when
 * color_0. */
static void load_three(const char *materials, const int mat[3], bool color_0, struct mesh *m)
{
	float data[36] = {0};
	char b64[200], prim[3][96], json[4096];
	int n;

	for (int t = 0; t < 3; t++) {
		float *v = data + t * 9;
		v[0] = (float)t, v[3] = (float)t + 1, v[6] = (float)t, v[7] = 1, v[8] = 0.1f * t;
		char material[32] = "";

		if (mat[t] >= 0)
			snprintf(material, sizeof(material), ",\"material\":%d", mat[t]);
		snprintf(prim[t], sizeof(prim[t]), "{\"attributes\":{\"POSITION\":%d%s}%s}", t,
			 t == 2 && color_0 ? ",\"COLOR_0\":3" : "", material);
	}
	for (int k = 0; k < 3; k++)
		data[27 + k * 3] = 0.5f, data[28 + k * 3] = 0.25f, data[29 + k * 3] = 1.0f;
	base64((const uint8_t *)data, sizeof(data), b64);
	n = snprintf(
	    json, sizeof(json),
	    "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":144,\"uri\":"
	    "\"data:application/octet-stream;base64,%s\"}],\"bufferViews\":[{\"buffer\":0,"
	    "\"byteLength\":108},{\"buffer\":0,\"byteOffset\":108,\"byteLength\":36}],"
	    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":"
	    "\"VEC3\"},{\"bufferView\":0,\"byteOffset\":36,\"componentType\":5126,\"count\":3,"
	    "\"type\":\"VEC3\"},{\"bufferView\":0,\"byteOffset\":72,\"componentType\":5126,"
	    "\"count\":3,\"type\":\"VEC3\"},{\"bufferView\":1,\"componentType\":5126,\"count\":"
	    "3,\"type\":\"VEC3\"}],\"materials\":%s,\"meshes\":[{\"primitives\":[%s,%s,%s]}],"
	    "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0}",
	    b64, materials, prim[0], prim[1], prim[2]);
	assert_true(n > 0 && (size_t)n < sizeof(json));
	assert_int_equal(gltf_load_memory_textures("three.gltf", (const uint8_t *)json, (size_t)n,
						   NULL, GLTF_TEXTURE_BASE_COLOR, m),
			 0);
	assert_int_equal(m->vertex_count, 9);
}

static void assert_colour(const float *c, float r, float g, float b, float a)
{
	assert_true(c[0] == r && c[1] == g && c[2] == b && c[3] == a);
}

/* A model of one colour keeps it as a constant (mesh.vertex_color, a
 * constant vertex attribute): no colour per vertex to build, store or
 * upload. Colours that differ between primitives, or COLOR_0, are per
 * vertex, and the constant so far becomes the first vertices' colours. */
/* A base map's sampler: its wrap per axis, and a minFilter of NEAREST or
 * LINEAR reads one level (no mipmaps: what the spec and three.js draw);
 * a mipmapped minFilter, or no sampler, keeps the chain. */
static void sampler_wrap_and_min_filter(void **state)
{
	static const char *materials =
	    "[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1],"
	    "\"baseColorTexture\":{\"index\":0}}},"
	    "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,1,0,1],"
	    "\"baseColorTexture\":{\"index\":1}}},"
	    "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,1,1],"
	    "\"baseColorTexture\":{\"index\":2}}}],"
	    "\"textures\":[{\"source\":0,\"sampler\":0},{\"source\":0,\"sampler\":1},"
	    "{\"source\":0}],\"images\":[{\"uri\":\"no-such-map.png\"}],"
	    "\"samplers\":[{\"minFilter\":9729,\"wrapS\":33071,\"wrapT\":33648},"
	    "{\"minFilter\":9987}]";
	int seen = 0;
	struct mesh m;

	(void)state;
	load_three(materials, (const int[3]){0, 1, 2}, false, &m);
	assert_int_equal(m.material_count, 3);
	for (uint32_t k = 0; k < m.material_count; k++) {
		const struct mesh_material *g = &m.materials[k];

		if (g->base_color[0] > 0.5f) { /* red: clamp, mirror, one level */
			assert_true(g->base_no_mipmaps);
			assert_int_equal(g->base_wrap[0], MESH_WRAP_CLAMP);
			assert_int_equal(g->base_wrap[1], MESH_WRAP_MIRROR);
		} else {
			assert_false(g->base_no_mipmaps);
			assert_int_equal(g->base_wrap[0], MESH_WRAP_REPEAT);
			assert_int_equal(g->base_wrap[1], MESH_WRAP_REPEAT);
		}
		seen |= (g->base_color[0] > 0.5f) | (g->base_color[1] > 0.5f) << 1 |
			(g->base_color[2] > 0.5f) << 2;
	}
	assert_int_equal(seen, 7);
	mesh_release(&m);
}

static void one_colour_is_a_constant(void **state)
{
	static const char *red = "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]}}";
	static const char *green = "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,1,0,1]}}";
	char two[256], one[128];
	struct material_config cfg;
	struct material mat;
	struct mesh m;

	(void)state;
	snprintf(one, sizeof(one), "[%s]", red);
	snprintf(two, sizeof(two), "[%s,%s]", red, green);
	material_config_defaults(&cfg);
	load_three(one, (const int[3]){0, 0, 0}, false, &m);
	assert_null(m.colors);
	assert_true(m.has_colors);
	assert_colour(m.vertex_color, 1, 0, 0, 1);
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.features, MATERIAL_BASE_COLOR);
	assert_colour(mat.vertex_color, 1, 0, 0, 1);
	material_release(&mat);
	mesh_release(&m);
	load_three(two, (const int[3]){0, 1, 0}, false, &m);
	assert_non_null(m.colors);
	for (int v = 0; v < 9; v++)
		assert_colour(m.colors + v * 4, v / 3 != 1, v / 3 == 1, 0, 1);
	mesh_release(&m);
	load_three(one, (const int[3]){0, 0, 0}, true, &m);
	assert_non_null(m.colors);
	for (int v = 0; v < 9; v++)
		assert_colour(m.colors + v * 4, v < 6 ? 1.0f : 0.5f, 0, 0, 1);
	mesh_release(&m);
	/* A primitive without a material is white. */
	load_three(one, (const int[3]){-1, 0, -1}, false, &m);
	assert_non_null(m.colors);
	for (int v = 0; v < 9; v++)
		assert_colour(m.colors + v * 4, 1, v / 3 != 1, v / 3 != 1, 1);
	mesh_release(&m);
}

/* Every primitive keeps its own material: its base map, factor and
 * alpha, its sides. Primitives of one opaque or masked material share one
 * range; a blended material's primitives stay ranges of their own (each
 * ordered by depth). */
static void each_primitive_keeps_its_material(void **state)
{
	struct fixture *f = *state;
	struct gltf_part p[4] = {
	    {&f->sphere,
	     {1, 0.5, 0.25, 1},
	     f->png,
	     "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,"
	     "\"doubleSided\":true",
	     NULL,
	     1,
	     NULL},
	    {&f->sphere, {0.2, 0.4, 1, 0.5}, NULL, "\"alphaMode\":\"BLEND\"", NULL, 1, NULL},
	    {&f->sphere, {0, 0, 0, 1}, NULL, NULL, NULL, 0, NULL}, /* the BLEND one again */
	    {&f->sphere,
	     {1, 1, 1, 1},
	     f->png,
	     NULL,
	     "\"extensions\":{\"KHR_texture_transform\":{\"offset\":[0.5,0]}}",
	     1,
	     NULL}};
	struct material_config cfg;
	struct material mat;
	char path[256];
	struct mesh m;
	uint32_t tris = f->sphere.index_count;

	snprintf(path, sizeof(path), "%s/parts.glb", f->dir);
	assert_int_equal(gltf_write_parts(path, p, 4), 0);
	material_config_defaults(&cfg);
	assert_int_equal(gltf_load_textures(path, material_gltf_textures(&cfg), &m), 0);
	assert_int_equal(m.material_count, 3);
	assert_int_equal(m.range_count, 4);
	/* Material 0: masked, double sided, its own map. */
	assert_int_equal(m.materials[0].alpha_mode, MESH_ALPHA_MASK);
	assert_true(fabsf(m.materials[0].alpha_cutoff - 0.3f) < 1e-6f);
	assert_true(m.materials[0].double_sided);
	assert_int_equal(m.materials[0].base_map.width, 6);
	assert_true(m.materials[0].base_color[1] == 0.5f);
	/* Material 1: blended, alpha 0.5, no map, two ranges. */
	assert_int_equal(m.materials[1].alpha_mode, MESH_ALPHA_BLEND);
	assert_true(m.materials[1].base_alpha == 0.5f && !m.materials[1].double_sided);
	assert_int_equal(m.materials[1].base_map.width, 0);
	/* Material 2: opaque, its own map with its own transform. */
	assert_int_equal(m.materials[2].alpha_mode, MESH_ALPHA_OPAQUE);
	assert_int_equal(m.materials[2].base_map.width, 6);
	assert_true(m.materials[2].base_transform[4] == 0.5f);
	assert_true(m.materials[0].base_transform[4] == 0.0f);
	for (uint32_t r = 0; r < 4; r++) {
		static const uint32_t material[4] = {0, 1, 1, 2};

		assert_int_equal(m.ranges[r].material, material[r]);
		assert_int_equal(m.ranges[r].first_index, r * tris);
		assert_int_equal(m.ranges[r].index_count, tris);
	}
	/* Whether a part reads a map is its range's material's; the
	 * colours' alpha is COLOR_0's (none here: 1). */
	assert_non_null(m.colors);
	assert_true(m.materials[m.ranges[0].material].has_base_map);
	assert_false(m.materials[m.ranges[1].material].has_base_map);
	assert_true(m.colors[m.indices[0] * 4 + 3] == 1.0f);
	assert_true(m.colors[m.indices[tris] * 4 + 3] == 1.0f);
	/* Resolved: one surface per material, its map and alpha. */
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.surface_count, 3);
	assert_int_equal(mat.surfaces[0].alpha_mode, MESH_ALPHA_MASK);
	assert_true(mat.surfaces[0].double_sided && mat.surfaces[0].base_map.width == 8);
	assert_true(mat.surfaces[1].alpha == 0.5f && !mat.surfaces[1].base_map.width);
	material_release(&mat);
	/* Base colour off: no alpha, the sides stay. */
	cfg.base_color = MATERIAL_OFF;
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.surfaces[1].alpha_mode, MESH_ALPHA_OPAQUE);
	assert_true(mat.surfaces[0].double_sided);
	material_release(&mat);
	mesh_release(&m);
}

/* A w x h normal map of one texel value. */
static void flat_png(const char *path, int w, int h, const uint8_t rgb[3])
{
	struct image img;

	assert_int_equal(image_alloc(&img, w, h), 0);
	for (int i = 0; i < w * h; i++) {
		memcpy(img.rgba + i * 4, rgb, 3);
		img.rgba[i * 4 + 3] = 255;
	}
	assert_int_equal(image_write_png(path, &img), 0);
	image_release(&img);
}

/* Each material's normal and occlusion maps and iridescence reach the
 * ranges drawn with it, and only those: material 0 a tilted normal map,
 * material 1 none, material 2 a flat one and a film. Each range's draw
 * leaves out of the model's program what its material lacks. */
static void each_material_keeps_its_maps(void **state)
{
	static const uint8_t tilted[3] = {200, 128, 200}, flat[3] = {128, 128, 255};
	struct fixture *f = *state;
	char path[256], tilt_png[256], flat_png_path[256];
	struct gltf_part p[3] = {
	    {&f->sphere, {1, 1, 1, 1}, NULL, NULL, NULL, 1, tilt_png},
	    {&f->sphere, {1, 1, 1, 1}, NULL, NULL, NULL, 1, NULL},
	    {&f->sphere,
	     {1, 1, 1, 1},
	     NULL,
	     "\"extensions\":{\"KHR_materials_iridescence\":{\"iridescenceFactor\":1,"
	     "\"iridescenceThicknessMaximum\":300}}",
	     NULL,
	     1,
	     flat_png_path}};
	static const unsigned want[3] = {MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL, 0,
					 MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL |
					     MATERIAL_IRIDESCENCE};
	struct material_config cfg;
	struct material mat;
	struct draw_list l;
	struct mesh m;

	snprintf(tilt_png, sizeof(tilt_png), "%s/tilted.png", f->dir);
	snprintf(flat_png_path, sizeof(flat_png_path), "%s/flat.png", f->dir);
	snprintf(path, sizeof(path), "%s/maps.glb", f->dir);
	flat_png(tilt_png, 4, 4, tilted);
	flat_png(flat_png_path, 2, 2, flat);
	assert_int_equal(gltf_write_parts(path, p, 3), 0);
	material_config_defaults(&cfg);
	assert_int_equal(gltf_load_textures(path, material_gltf_textures(&cfg), &m), 0);
	assert_int_equal(m.material_count, 3);
	assert_int_equal(m.materials[0].normal_map.width, 4);
	assert_int_equal(m.materials[1].normal_map.width, 0);
	assert_int_equal(m.materials[2].normal_map.width, 2);
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.features &
			     (MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL | MATERIAL_IRIDESCENCE),
			 want[2]);
	assert_int_equal(mat.detail.width, 0); /* no map over the whole model */
	for (int k = 0; k < 3; k++)
		assert_int_equal(mat.surfaces[k].features, want[k]);
	/* Each its own map: tilted x (200 -> about 0.57 of the way, packed
	 * normalised), flat; material 1 none. */
	assert_int_equal(mat.surfaces[0].detail.width, 4);
	assert_true(mat.surfaces[0].detail.rgba[0] > 180);
	assert_int_equal(mat.surfaces[1].detail.width, 0);
	assert_int_equal(mat.surfaces[2].detail.width, 2);
	assert_true(abs(mat.surfaces[2].detail.rgba[0] - 128) <= 1);
	assert_true(fabsf(mat.surfaces[2].hue_average - (float)(2 * 1.3 * 300 / 550.0)) < 1e-5f);
	assert_true(mat.surfaces[2].opacity > 0.0f && mat.surfaces[0].opacity == 0.0f);
	/* Each range draws its material's surface with the program its
	 * features need. */
	assert_int_equal(draw_list_build(&l, m.ranges, m.range_count, m.indices, m.index_count,
					 m.vertex_count, mat.surfaces, mat.surface_count, true),
			 0);
	assert_int_equal(l.count, 3);
	for (uint32_t i = 0; i < l.count; i++) {
		const struct draw_item *it = &l.items[i];
		unsigned drawn = want[2] & ~draw_variant_missing(draw_item_variant(it));

		assert_int_equal(drawn, want[it->surface]);
		assert_int_equal(draw_item_variant(it) == 0, it->surface == 2);
	}
	draw_list_release(&l);
	material_release(&mat);
	/* A detail_map in the settings covers every part in their stead. */
	cfg.detail_map = tilt_png;
	assert_int_equal(material_load(&mat, &cfg, &m, true), 0);
	assert_int_equal(mat.detail.width, 4);
	for (int k = 0; k < 3; k++) {
		assert_true(mat.surfaces[k].features & MATERIAL_DETAIL_NORMAL);
		assert_int_equal(mat.surfaces[k].detail.width, 0);
	}
	material_release(&mat);
	mesh_release(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(factor_colour_map_and_transform),
	    cmocka_unit_test(colour_types),
	    cmocka_unit_test(no_colour_no_cost),
	    cmocka_unit_test(tex_coord_picks_the_uv_set),
	    cmocka_unit_test(packed_and_simplified),
	    cmocka_unit_test(decodes_only_what_is_used),
	    cmocka_unit_test(one_colour_is_a_constant),
	    cmocka_unit_test(sampler_wrap_and_min_filter),
	    cmocka_unit_test(each_primitive_keeps_its_material),
	    cmocka_unit_test(each_material_keeps_its_maps),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
