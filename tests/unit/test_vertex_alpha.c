/* COLOR_0's alpha is the vertex's own, and whether a draw reads a base
 * map is its range's material's: a model whose blended primitive has
 * COLOR_0 alpha 0.5 and no map, beside an opaque one with a green map,
 * draws the first half red over black and the second green. (The mesh's colour alpha once meant
 * "reads the base map": COLOR_0's alpha was dropped, the blended part
 * drawn opaque.) */
#include "offscreen.h"
#include "config/settings.h"
#include "content/content.h"
#include "render/render.h"
#include "scene/gltf/gltf.h"
#include "scene/mesh/mesh.h"
#include "util/image.h"
#include "util/log.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#define W 64

/* Two quads facing +z: A (x -1 .. -0.2) with COLOR_0 (1, 0, 0, 0.5) and a
 * blended material without a map; B (x 0.2 .. 1) with TEXCOORD_0 and an
 * opaque material whose base map is green.png. */
static const float quad_a[12] = {-1, -0.5f, 0, -0.2f, -0.5f, 0, -0.2f, 0.5f, 0, -1, 0.5f, 0};
static const float quad_b[12] = {0.2f, -0.5f, 0, 1, -0.5f, 0, 1, 0.5f, 0, 0.2f, 0.5f, 0};
static const float red_half[16] = {1, 0, 0, 0.5f, 1, 0, 0, 0.5f, 1, 0, 0, 0.5f, 1, 0, 0, 0.5f};
static const float uvs[8] = {0, 0, 1, 0, 1, 1, 0, 1};
static const uint16_t quad[6] = {0, 1, 2, 0, 2, 3};

static void base64(const uint8_t *in, size_t n, char *out)
{
	static const char t[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

	for (size_t i = 0; i < n; i += 3) {
		uint32_t v = (uint32_t)in[i] << 16 | (i + 1 < n ? (uint32_t)in[i + 1] << 8 : 0) |
			     (i + 2 < n ? in[i + 2] : 0);

		*out++ = t[v >> 18 & 63];
		*out++ = t[v >> 12 & 63];
		*out++ = i + 1 < n ? t[v >> 6 & 63] : '=';
		*out++ = i + 2 < n ? t[v & 63] : '=';
	}
	*out = '\0';
}

static const char gltf_json[] =
    "{\"asset\":{\"version\":\"2.0\"},"
    "\"buffers\":[{\"byteLength\":204,\"uri\":\"data:application/octet-stream;base64,%s\"}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteLength\":96},"
    "{\"buffer\":0,\"byteOffset\":96,\"byteLength\":64},"
    "{\"buffer\":0,\"byteOffset\":160,\"byteLength\":32},"
    "{\"buffer\":0,\"byteOffset\":192,\"byteLength\":12}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\","
    "\"min\":[-1,-0.5,0],\"max\":[-0.2,0.5,0]},"
    "{\"bufferView\":0,\"byteOffset\":48,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\","
    "\"min\":[0.2,-0.5,0],\"max\":[1,0.5,0]},"
    "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC4\"},"
    "{\"bufferView\":2,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
    "{\"bufferView\":3,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],"
    "\"materials\":[{\"alphaMode\":\"BLEND\",\"doubleSided\":true},"
    "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},\"doubleSided\":true}],"
    "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"green.png\"}],"
    "\"meshes\":[{\"primitives\":["
    "{\"attributes\":{\"POSITION\":0,\"COLOR_0\":2},\"indices\":4,\"material\":0},"
    "{\"attributes\":{\"POSITION\":1,\"TEXCOORD_0\":3},\"indices\":4,\"material\":1}]}],"
    "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0}";

static void write_png(const char *path, uint8_t r, uint8_t g, uint8_t b)
{
	struct image img;

	assert_int_equal(image_alloc(&img, 4, 4), 0);
	for (int i = 0; i < 16; i++) {
		img.rgba[i * 4] = r, img.rgba[i * 4 + 1] = g, img.rgba[i * 4 + 2] = b;
		img.rgba[i * 4 + 3] = 255;
	}
	assert_int_equal(image_write_png(path, &img), 0);
	image_release(&img);
}

static void write_model(const char *path)
{
	uint8_t data[204];
	char b64[300], json[4096];
	FILE *f;

	memcpy(data, quad_a, 48);
	memcpy(data + 48, quad_b, 48);
	memcpy(data + 96, red_half, 64);
	memcpy(data + 160, uvs, 32);
	memcpy(data + 192, quad, 12);
	base64(data, sizeof(data), b64);
	assert_true(snprintf(json, sizeof(json), gltf_json, b64) < (int)sizeof(json));
	f = fopen(path, "w");
	assert_non_null(f);
	assert_true(fputs(json, f) >= 0);
	assert_int_equal(fclose(f), 0);
}

/* The loader keeps COLOR_0's alpha in the colours, and the map is the
 * second range's material's alone. */
static void loaded(const char *path)
{
	struct mesh m;

	assert_int_equal(gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, &m), 0);
	assert_non_null(m.colors);
	assert_int_equal(m.range_count, 2);
	for (uint32_t i = 0; i < m.ranges[0].index_count; i++)
		assert_true(m.colors[m.indices[m.ranges[0].first_index + i] * 4 + 3] == 0.5f);
	assert_false(m.materials[m.ranges[0].material].has_base_map);
	assert_true(m.materials[m.ranges[1].material].base_map.width > 0);
	mesh_release(&m);
}

/* Every pixel of A is red at half strength, nowhere green (it reads no
 * map); B's are green (its map); none is anything else. */
static void drawn_right(struct display *d, struct renderer *r, const struct view *v)
{
	unsigned half_red = 0, green = 0;
	struct image f;

	renderer_draw(r, v, W, W);
	assert_int_equal(d->read_frame(d, &f), 0);
	for (int i = 0; i < f.width * f.height; i++) {
		const uint8_t *p = f.rgba + (size_t)i * 4;

		if (p[0] > 20) {
			if (p[0] < 100 || p[0] > 160 || p[1] > 20)
				fail_msg("pixel %d: %u %u %u, expected half red (COLOR_0's alpha "
					 "0.5, no map)",
					 i, p[0], p[1], p[2]);
			half_red++;
		} else if (p[1] > 200 && p[2] < 20) {
			green++;
		}
	}
	image_release(&f);
	assert_true(half_red > 50 && green > 50);
}

static void colour_alpha_and_base_map_per_draw(void **state)
{
	char dir[] = "/tmp/mk-vertex-alpha-XXXXXX", model[96], white[96], map[96], cmd[96];
	struct display *d = offscreen_open(W, W);
	struct renderer *r = d ? renderer_new(&d->gl, NULL) : NULL;
	struct content s;
	struct options o;
	struct view v;

	(void)state;
	assert_non_null(r);
	assert_non_null(mkdtemp(dir));
	snprintf(model, sizeof(model), "%s/model.gltf", dir);
	snprintf(white, sizeof(white), "%s/white.png", dir);
	snprintf(map, sizeof(map), "%s/green.png", dir);
	write_model(model);
	write_png(white, 255, 255, 255);
	write_png(map, 0, 255, 0);
	loaded(model);
	setenv("XDG_CACHE_HOME", dir, 1);
	option_defaults(&o);
	o.content.model = model;
	o.content.matcap = white;
	/* Not cached: a model that decodes a map is prepared at each start. */
	assert_int_equal(content_load(&s, &o.content, true), 0);
	assert_int_equal(content_prepare(&s, &o.content, W, W), 0);
	assert_int_equal(content_upload(&s, r), 0);
	assert_int_equal(renderer_set_mode(r, o.content.mode, false), 0);
	v = content_view(&o.content);
	v.background[0] = v.background[1] = v.background[2] = 0.0f;
	drawn_right(d, r, &v);
	content_release(&s);
	renderer_free(r);
	unsetenv("XDG_CACHE_HOME");
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(colour_alpha_and_base_map_per_draw),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
