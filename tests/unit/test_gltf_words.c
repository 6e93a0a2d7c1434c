/* The loader's words for the files users bring: ours first (an empty file,
 * a GLB cut short with its declared and real lengths, glTF 1.0, a JSON
 * syntax error with line and column), and the files a model names in
 * subfolders of its folder (textures/, as Blender and Sketchfab write
 * them), with the real reason when one cannot be used. */
#include "scene/gltf/gltf.h"
#include "scene/mesh/mesh.h"
#include "../tools/gltf_write.h"
#include "util/image.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

struct fixture {
	char dir[64];
	char log[8192]; /* what the last load printed */
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	if (!f)
		return -1;
	strcpy(f->dir, "/tmp/mk-gltf-words-XXXXXX");
	if (!mkdtemp(f->dir))
		return -1;
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fixture *f = *state;
	char cmd[128];

	snprintf(cmd, sizeof(cmd), "rm -rf %s", f->dir);
	free(f);
	return system(cmd);
}

static void path_in(const struct fixture *f, const char *name, char *out, size_t n)
{
	snprintf(out, n, "%s/%s", f->dir, name);
}

static void write_bytes(const struct fixture *f, const char *name, const void *data, size_t n)
{
	char path[256];
	FILE *fp;

	path_in(f, name, path, sizeof(path));
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(fwrite(data, 1, n, fp), n);
	assert_int_equal(fclose(fp), 0);
}

/* Loads name (textures: enum gltf_texture bits) with stderr in f->log. */
static int load(struct fixture *f, const char *name, unsigned textures)
{
	char path[256], log[256];
	struct mesh m;
	FILE *fp;
	size_t n;
	int saved, ret;

	path_in(f, name, path, sizeof(path));
	path_in(f, "load.log", log, sizeof(log));
	fflush(stderr);
	saved = dup(2);
	fp = fopen(log, "w");
	assert_non_null(fp);
	dup2(fileno(fp), 2);
	ret = gltf_load_textures(path, textures, &m);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	fclose(fp);
	if (ret == 0)
		mesh_release(&m);
	fp = fopen(log, "r");
	n = fread(f->log, 1, sizeof(f->log) - 1, fp);
	f->log[n] = 0;
	fclose(fp);
	fprintf(stderr, "%s", f->log);
	return ret;
}

/* Refused, with exactly one error line, which names the file and says
 * words (ours, at the start of the reason). */
static void assert_refused(struct fixture *f, const char *name, const char *words)
{
	char head[512];
	const char *err;

	assert_int_not_equal(load(f, name, 0), 0);
	err = strstr(f->log, "error: ");
	assert_non_null(err);
	assert_null(strstr(err + 1, "error: "));
	snprintf(head, sizeof(head), "error: %s/%s: %s", f->dir, name, words);
	assert_non_null(strstr(f->log, head));
}

static void empty_file(void **state)
{
	write_bytes(*state, "empty.glb", "", 0);
	assert_refused(*state, "empty.glb",
		       "the file is empty (0 bytes), expected a glTF 2.0 model (.gltf or .glb)");
	write_bytes(*state, "empty.gltf", "", 0);
	assert_refused(*state, "empty.gltf", "the file is empty (0 bytes)");
}

static void gltf_1_0(void **state)
{
	static const char v1[] = "{\"asset\":{\"version\":\"1.0\"},\"meshes\":{\"box\":{}}}";
	static const char keyed[] = "{\"meshes\":{\"box\":{\"primitives\":[]}},\"nodes\":{}}";
	static const unsigned char glb1[20] = {'g', 'l', 'T', 'F', 1, 0, 0, 0, 20, 0, 0, 0};

	write_bytes(*state, "v1.gltf", v1, sizeof(v1) - 1);
	assert_refused(
	    *state, "v1.gltf",
	    "glTF 1.0 is not supported; re-export it as glTF 2.0 (asset.version \"1.0\")");
	/* Early 1.0 exports have no asset at all: the lists keyed by name say it. */
	write_bytes(*state, "keyed.gltf", keyed, sizeof(keyed) - 1);
	assert_refused(*state, "keyed.gltf", "glTF 1.0 is not supported; re-export it as glTF 2.0");
	write_bytes(*state, "v1.glb", glb1, sizeof(glb1));
	assert_refused(*state, "v1.glb",
		       "glTF 1.0 is not supported; re-export it as glTF 2.0 (a GLB of version 1)");
}

/* A whole GLB (from gltf_write) cut at several places: each names the
 * length declared and the length there is. */
static void glb_cut_short(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	char path[256], words[256];
	unsigned char *data;
	struct mesh s;
	size_t size;
	FILE *fp;

	assert_int_equal(mesh_uv_sphere(&s, 8, 4), 0);
	path_in(f, "whole.glb", path, sizeof(path));
	assert_int_equal(gltf_write(path, &s, &o), 0);
	mesh_release(&s);
	assert_int_equal(load(f, "whole.glb", 0), 0);
	fp = fopen(path, "rb");
	assert_non_null(fp);
	fseek(fp, 0, SEEK_END);
	size = (size_t)ftell(fp);
	rewind(fp);
	data = malloc(size);
	assert_int_equal(fread(data, 1, size, fp), size);
	fclose(fp);

	write_bytes(f, "cut.glb", data, size - 100);
	snprintf(words, sizeof(words),
		 "GLB cut short: its header declares %zu bytes, the file has %zu", size,
		 size - 100);
	assert_refused(f, "cut.glb", words);
	write_bytes(f, "cut10.glb", data, 10);
	assert_refused(f, "cut10.glb", "GLB cut short: 10 bytes, less than its 12-byte header");
	/* The header's length mended, the chunks still cut: the binary
	 * chunk's own length is named. */
	data[8] = (unsigned char)((size - 100) & 0xff);
	data[9] = (unsigned char)((size - 100) >> 8 & 0xff);
	data[10] = (unsigned char)((size - 100) >> 16 & 0xff);
	data[11] = 0;
	write_bytes(f, "cut-bin.glb", data, size - 100);
	assert_refused(f, "cut-bin.glb", "GLB cut short: its binary chunk declares ");
	free(data);
}

static void json_syntax_error(void **state)
{
	static const char text[] = "{\n  \"asset\": {\"version\": \"2.0\"},\n"
				   "  \"nodes\": [ {\"mesh\": 0,} ]\n}\n";
	static const char open[] = "{\"asset\": {\"version\": \"2.0\"},\n\"nodes\": [";

	write_bytes(*state, "syntax.gltf", text, sizeof(text) - 1);
	/* Ours, then the parser's words for it. */
	assert_refused(*state, "syntax.gltf",
		       "JSON syntax error at line 3, column 25: syntax error while parsing "
		       "object key - unexpected '}'");
	write_bytes(*state, "open.gltf", open, sizeof(open) - 1);
	assert_refused(*state, "open.gltf", "JSON syntax error at line 2, column 11: ");
}

/* A model whose buffer and textures lie in subfolders of its folder loads
 * them; a texture not there is named with that reason, and one outside the
 * folder with its own. */
static void files_in_subfolders(void **state)
{
	static const uint8_t blue[4] = {128, 128, 255, 255};
	struct fixture *f = *state;
	struct gltf_write_opts o = {.index_bytes = 2,
				    .with_normals = 1,
				    .bad_index = -1,
				    .with_uvs = 1,
				    .container = GLTF_EXTERNAL_BIN,
				    .bin_uri = "buffers/scene.bin",
				    .image_uri = "textures/normal%20map.png"};
	char path[256], bin[256], moved[256], png[256];
	struct image img;
	struct mesh s;

	path_in(f, "textures", path, sizeof(path));
	assert_int_equal(mkdir(path, 0755), 0);
	path_in(f, "buffers", path, sizeof(path));
	assert_int_equal(mkdir(path, 0755), 0);
	path_in(f, "textures/normal map.png", png, sizeof(png));
	assert_int_equal(image_alloc(&img, 4, 4), 0);
	for (int i = 0; i < 16; i++)
		memcpy(img.rgba + i * 4, blue, 4);
	assert_int_equal(image_write_png(png, &img), 0);
	image_release(&img);
	o.normal_png = png;
	assert_int_equal(mesh_uv_sphere(&s, 8, 4), 0);
	path_in(f, "scene.gltf", path, sizeof(path));
	assert_int_equal(gltf_write(path, &s, &o), 0);
	path_in(f, "scene.bin", bin, sizeof(bin));
	path_in(f, "buffers/scene.bin", moved, sizeof(moved));
	assert_int_equal(rename(bin, moved), 0);
	assert_int_equal(load(f, "scene.gltf", GLTF_TEXTURE_NORMAL), 0);
	assert_null(strstr(f->log, "warning"));

	assert_int_equal(unlink(png), 0);
	assert_int_equal(load(f, "scene.gltf", GLTF_TEXTURE_NORMAL), 0);
	assert_non_null(strstr(f->log, "normalTexture: image 0 \"textures/normal%20map.png\" is "
				       "not in the model's folder (no such file): not used"));

	o.image_uri = "../normal.png";
	path_in(f, "outside.gltf", path, sizeof(path));
	assert_int_equal(gltf_write(path, &s, &o), 0);
	assert_int_equal(load(f, "outside.gltf", GLTF_TEXTURE_NORMAL), 0);
	assert_non_null(strstr(f->log, "\"../normal.png\" lies outside the model's folder "
				       "(absolute paths and \"..\" are refused): not used"));
	mesh_release(&s);

	/* A buffer missing from its subfolder: named as written. */
	assert_int_equal(unlink(moved), 0);
	assert_refused(f, "scene.gltf",
		       "buffers[0].uri \"buffers/scene.bin\": no such file in the model's folder");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(empty_file),	   cmocka_unit_test(gltf_1_0),
	    cmocka_unit_test(glb_cut_short),	   cmocka_unit_test(json_syntax_error),
	    cmocka_unit_test(files_in_subfolders),
	};
	return cmocka_run_group_tests_name("gltf words", tests, setup, teardown);
}
