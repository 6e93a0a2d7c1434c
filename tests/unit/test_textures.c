/* The textures people ship (issue 37): EXT_texture_webp preferred over
 * the texture's PNG/JPEG source, that source the fallback when the WebP
 * cannot be decoded, and KHR_texture_basisu (KTX2) refused by name: Debian
 * 12 and 13 ship no KTX2 transcoder. */
#include "scene/gltf/gltf.h"
#include "scene/mesh/mesh.h"
#include "util/image.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>
#include <webp/encode.h>

static char dir[64];

static int make_dir(void **state)
{
	(void)state;
	strcpy(dir, "/tmp/mk-textures-XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void write_file(const char *name, const void *data, size_t size)
{
	char path[128];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(data, 1, size, f), size);
	fclose(f);
}

/* A w x h image of one colour: name.png, or name.webp (lossless; cut to
 * half its bytes when truncated, as an interrupted copy leaves it). */
static void flat_image(const char *name, int w, int h, const uint8_t rgb[3], bool webp,
		       bool truncated)
{
	struct image img;
	char path[128];

	assert_int_equal(image_alloc(&img, w, h), 0);
	for (int i = 0; i < w * h; i++) {
		memcpy(img.rgba + i * 4, rgb, 3);
		img.rgba[i * 4 + 3] = 255;
	}
	if (webp) {
		uint8_t *out = NULL;
		size_t size = WebPEncodeLosslessRGBA(img.rgba, w, h, w * 4, &out);

		assert_true(size > 12);
		write_file(name, out, truncated ? size / 2 : size);
		WebPFree(out);
	} else {
		snprintf(path, sizeof(path), "%s/%s", dir, name);
		assert_int_equal(image_write_png(path, &img), 0);
	}
	image_release(&img);
}

/* One triangle with TEXCOORD_0 whose base colour texture is `texture`
 * (its JSON), with `images` and the file's extension lists `exts`. */
static void write_model(const char *name, const char *texture, const char *images, const char *exts)
{
	char json[2048];
	int n = snprintf(
	    json, sizeof(json),
	    "{\"asset\":{\"version\":\"2.0\"},%s\"buffers\":[{\"byteLength\":60,\"uri\":"
	    "\"data:application/octet-stream;base64,"
	    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"
	    "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,"
	    "\"byteOffset\":36,\"byteLength\":24}],\"accessors\":[{\"bufferView\":0,"
	    "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":"
	    "[1,1,0]},{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC2\"}],"
	    "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
	    "\"textures\":[%s],\"images\":[%s],\"meshes\":[{\"primitives\":[{\"attributes\":"
	    "{\"POSITION\":0,\"TEXCOORD_0\":1},\"material\":0}]}],\"nodes\":[{\"mesh\":0}],"
	    "\"scenes\":[{\"nodes\":[0]}],\"scene\":0}",
	    exts, texture, images);

	assert_true(n > 0 && (size_t)n < sizeof(json));
	write_file(name, json, (size_t)n);
}

/* The base map the loader decoded for the model's one material (materials[0]). */
static const struct image *base_map(const struct mesh *m)
{
	return &m->materials[0].base_map;
}

/* Load dir/name with its base colour map, the journal's lines into log. */
static int load_log(const char *name, struct mesh *m, char *log, size_t n)
{
	char path[128], log_path[128];
	int saved, ret;
	size_t got;
	FILE *fp;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	snprintf(log_path, sizeof(log_path), "%s/%s.log", dir, name);
	fflush(stderr);
	saved = dup(2);
	fp = fopen(log_path, "w+");
	assert_non_null(fp);
	dup2(fileno(fp), 2);
	ret = gltf_load_textures(path, GLTF_TEXTURE_BASE_COLOR, m);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	rewind(fp);
	got = fread(log, 1, n - 1, fp);
	log[got] = '\0';
	fclose(fp);
	return ret;
}

static void load(const char *name, struct mesh *m)
{
	char log[2048];

	assert_int_equal(load_log(name, m, log, sizeof(log)), 0);
}

static const uint8_t red[3] = {220, 20, 30}, blue[3] = {20, 40, 230};
static const char *const webp_texture =
    "{\"source\":1,\"extensions\":{\"EXT_texture_webp\":{\"source\":0}}}";
static const char *const webp_images = "{\"uri\":\"red.webp\"},{\"uri\":\"blue.png\"}";
static const char *const webp_exts =
    "\"extensionsUsed\":[\"EXT_texture_webp\"],\"extensionsRequired\":[\"EXT_texture_webp\"],";

/* A texture with EXT_texture_webp and a PNG source shows the WebP (the
 * file's choice); a required EXT_texture_webp no longer refuses the file. */
static void webp_preferred(void **state)
{
	struct mesh m;

	(void)state;
	flat_image("red.webp", 4, 2, red, true, false);
	flat_image("blue.png", 2, 2, blue, false, false);
	write_model("webp.gltf", webp_texture, webp_images, webp_exts);
	load("webp.gltf", &m);
	assert_int_equal(base_map(&m)->width, 4);
	assert_memory_equal(base_map(&m)->rgba, red, 3);
	mesh_release(&m);
	/* WebP alone (no source). */
	write_model("webp-only.gltf", "{\"extensions\":{\"EXT_texture_webp\":{\"source\":0}}}",
		    webp_images, webp_exts);
	load("webp-only.gltf", &m);
	assert_int_equal(base_map(&m)->width, 4);
	mesh_release(&m);
}

/* A WebP that cannot be decoded (cut short): the texture's source
 * instead, not an untextured model. */
static void webp_falls_back_to_source(void **state)
{
	char log[2048];
	struct mesh m;

	(void)state;

	flat_image("red.webp", 64, 64, red, true, true);
	flat_image("blue.png", 2, 2, blue, false, false);
	write_model("cut.gltf", webp_texture, webp_images, webp_exts);
	assert_int_equal(load_log("cut.gltf", &m, log, sizeof(log)), 0);
	assert_non_null(strstr(log, "not a valid WebP"));
	assert_non_null(strstr(log, "image 1 instead (the texture's source)"));
	assert_int_equal(base_map(&m)->width, 2);
	assert_memory_equal(base_map(&m)->rgba, blue, 3);
	mesh_release(&m);
}

/* KTX2: required, the file is refused naming KHR_texture_basisu; used
 * with a PNG source, the source is shown; KTX2 alone, no map. */
static void basisu_refused_by_name(void **state)
{
	static const char *basisu =
	    "{\"source\":1,\"extensions\":{\"KHR_texture_basisu\":{\"source\":0}}}";
	static const char *images = "{\"uri\":\"a.ktx2\"},{\"uri\":\"blue.png\"}";
	static const uint8_t ktx2[16] = {0xab, 'K',  'T',  'X',	 ' ', '2', '0', 0xbb,
					 '\r', '\n', 0x1a, '\n', 0,   0,   0,	0};
	char log[2048];
	struct mesh m;

	(void)state;
	write_file("a.ktx2", ktx2, sizeof(ktx2));
	flat_image("blue.png", 2, 2, blue, false, false);
	write_model("required.gltf", basisu, images,
		    "\"extensionsUsed\":[\"KHR_texture_basisu\"],"
		    "\"extensionsRequired\":[\"KHR_texture_basisu\"],");
	assert_int_not_equal(load_log("required.gltf", &m, log, sizeof(log)), 0);
	assert_non_null(strstr(log, "required.gltf: extensionsRequired: KHR_texture_basisu"));
	assert_non_null(strstr(log, "no KTX2 transcoder in Debian 12/13"));
	write_model("used.gltf", basisu, images, "\"extensionsUsed\":[\"KHR_texture_basisu\"],");
	load("used.gltf", &m);
	assert_int_equal(base_map(&m)->width, 2);
	mesh_release(&m);
	write_model("ktx2-only.gltf", "{\"extensions\":{\"KHR_texture_basisu\":{\"source\":0}}}",
		    images, "\"extensionsUsed\":[\"KHR_texture_basisu\"],");
	assert_int_equal(load_log("ktx2-only.gltf", &m, log, sizeof(log)), 0);
	assert_int_equal(base_map(&m)->width, 0);
	assert_non_null(strstr(log, "texture 0 is KTX2 only (KHR_texture_basisu): no KTX2 "
				    "transcoder in Debian 12/13"));
	mesh_release(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test_setup_teardown(webp_preferred, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(webp_falls_back_to_source, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(basisu_refused_by_name, make_dir, remove_dir),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
