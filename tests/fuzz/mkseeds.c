/* Writes the fuzzers' seed corpora (`make fuzz-seeds`): small valid files
 * in each variant the parsers take, so that the fuzzer starts deep inside
 * them rather than at the magic bytes.
 *   mkseeds DIR   writes DIR/gltf/ and DIR/image/ (DIR/config/ is written
 *                 by hand: a copy of config/kiosk.ini and a few variants)
 * Every file stays under 4 KiB but the material ones, which embed a
 * 4x4 PNG. */
#include "gltf_write.h"
#include "scene/gltf/gltf_json_depth.h"
#include "util/image.h"
#include "scene/mesh/mesh.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <turbojpeg.h>
#include <webp/encode.h>

static int put_model(const char *dir, const char *name, const struct mesh *m,
		     struct gltf_write_opts o)
{
	char path[4096];

	snprintf(path, sizeof(path), "%s/gltf/%s", dir, name);
	if (gltf_write(path, m, &o)) {
		fprintf(stderr, "mkseeds: cannot write %s\n", path);
		return 1;
	}
	return 0;
}

/* Node extras nested to the JSON bound (gltf_json_depth.h), and one level
 * past it: the fuzzer starts on both sides of the line. (The attack itself,
 * 30,000 levels, is past -max_len: tests/fuzz/run.sh replays it whole.) */
static int write_deep(const char *dir, const struct mesh *s, struct gltf_write_opts o)
{
	/* The node lies 3 deep (file, "nodes", the node). */
	int arrays = GLTF_JSON_MAX_DEPTH - 3, n = snprintf(NULL, 0, "\"extras\":"), bad;
	char node[256];

	snprintf(node, sizeof(node), "\"extras\":");
	memset(node + n, '[', (size_t)arrays + 1);
	memset(node + n + arrays + 1, ']', (size_t)arrays + 1);
	node[n + 2 * arrays + 2] = '\0';
	o.node = node;
	o.container = GLTF_DATA_URI;
	bad = put_model(dir, "sphere-extras-past-bound.gltf", s, o);
	memmove(node + n, node + n + 1, strlen(node + n + 1));
	node[n + 2 * arrays] = '\0';
	o.container = GLTF_GLB;
	return bad | put_model(dir, "sphere-extras-at-bound.glb", s, o);
}

static int write_models(const char *dir)
{
	struct gltf_write_opts ok = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	struct gltf_write_opts o;
	struct mesh s;
	char png[4096];
	int bad = 0;

	if (mesh_uv_sphere(&s, 6, 4))
		return 1;
	bad |= put_model(dir, "sphere.glb", &s, ok);
	o = ok;
	o.index_bytes = 1;
	o.with_normals = 0;
	bad |= put_model(dir, "sphere-u8-nonormals.glb", &s, o);
	o = ok;
	o.index_bytes = 4;
	o.byte_stride = 16;
	bad |= put_model(dir, "sphere-u32-stride.glb", &s, o);
	o = ok;
	o.index_bytes = 0;
	o.node = "\"scale\":[-1,2,1],\"rotation\":[0,0.7071,0,0.7071],\"translation\":[5,0,0]";
	bad |= put_model(dir, "sphere-noindex-trs.glb", &s, o);
	o = ok;
	o.parent = "\"matrix\":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,3,1]";
	o.container = GLTF_DATA_URI;
	bad |= put_model(dir, "sphere-parent-datauri.gltf", &s, o);
	o = ok;
	o.container = GLTF_EXTERNAL_BIN;
	bad |= put_model(dir, "sphere-external.gltf", &s, o);
	snprintf(png, sizeof(png), "%s/image/rgba.png", dir);
	o = ok;
	o.with_uvs = 1;
	o.normal_png = png;
	o.embed_images = 1;
	o.iridescence_factor = 1;
	o.thickness_range[0] = 100;
	o.thickness_range[1] = 400;
	bad |= put_model(dir, "sphere-material.glb", &s, o);
	bad |= write_deep(dir, &s, ok);
	mesh_release(&s);
	return bad;
}

/* A 4x4 gradient in the given libpng format. */
static int put_png(const char *dir, const char *name, int color, int depth, int interlace)
{
	char path[4096];
	FILE *f;
	png_structp png;
	png_infop info;
	png_color palette[4] = {{0, 0, 0}, {255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
	uint8_t row[4 * 4 * 2]; /* the widest: 16-bit RGBA */

	snprintf(path, sizeof(path), "%s/image/%s", dir, name);
	f = fopen(path, "wb");
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	info = png ? png_create_info_struct(png) : NULL;
	if (!f || !info || setjmp(png_jmpbuf(png))) {
		fprintf(stderr, "mkseeds: cannot write %s\n", path);
		return 1;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, 4, 4, depth, color, interlace, PNG_COMPRESSION_TYPE_DEFAULT,
		     PNG_FILTER_TYPE_DEFAULT);
	if (color == PNG_COLOR_TYPE_PALETTE)
		png_set_PLTE(png, info, palette, 4);
	png_write_info(png, info);
	for (int pass = png_set_interlace_handling(png); pass > 0; pass--)
		for (int y = 0; y < 4; y++) {
			for (size_t i = 0; i < sizeof(row); i++)
				row[i] = color == PNG_COLOR_TYPE_PALETTE
					     ? (uint8_t)((i + (size_t)y) % 4)
					     : (uint8_t)(i * 16 + (size_t)y * 60);
			png_write_row(png, row);
		}
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	fclose(f);
	return 0;
}

static int put_jpeg(const char *dir, const char *name, int pixel_format, int subsamp, int flags)
{
	uint8_t px[8 * 8 * 4];
	unsigned char *jpeg = NULL;
	unsigned long size = 0;
	char path[4096];
	tjhandle tj = tjInitCompress();
	FILE *f;
	int ret = 1;

	for (size_t i = 0; i < sizeof(px); i++)
		px[i] = (uint8_t)(i * 7);
	snprintf(path, sizeof(path), "%s/image/%s", dir, name);
	if (tj &&
	    tjCompress2(tj, px, 8, 0, 8, pixel_format, &jpeg, &size, subsamp, 75, flags) == 0 &&
	    (f = fopen(path, "wb"))) {
		ret = fwrite(jpeg, 1, size, f) != size;
		fclose(f);
	}
	if (ret)
		fprintf(stderr, "mkseeds: cannot write %s\n", path);
	tjFree(jpeg);
	if (tj)
		tjDestroy(tj);
	return ret;
}

/* A WebP (EXT_texture_webp): lossless (VP8L) or lossy with alpha (VP8X,
 * VP8 and ALPH chunks), from libwebp's encoder; the program only decodes. */
static int put_webp(const char *dir, const char *name, bool lossless)
{
	uint8_t px[8 * 8 * 4];
	uint8_t *webp = NULL;
	char path[4096];
	size_t size;
	FILE *f;
	int ret = 1;

	for (size_t i = 0; i < sizeof(px); i++)
		px[i] = (uint8_t)(i % 4 == 3 ? 128 + i : i * 7);
	size = lossless ? WebPEncodeLosslessRGBA(px, 8, 8, 8 * 4, &webp)
			: WebPEncodeRGBA(px, 8, 8, 8 * 4, 75, &webp);
	snprintf(path, sizeof(path), "%s/image/%s", dir, name);
	if (size && (f = fopen(path, "wb"))) {
		ret = fwrite(webp, 1, size, f) != size;
		fclose(f);
	}
	if (ret)
		fprintf(stderr, "mkseeds: cannot write %s\n", path);
	WebPFree(webp);
	return ret;
}

static int write_images(const char *dir)
{
	int bad = 0;

	bad |= put_png(dir, "rgba.png", PNG_COLOR_TYPE_RGB_ALPHA, 8, PNG_INTERLACE_NONE);
	bad |= put_png(dir, "rgb16.png", PNG_COLOR_TYPE_RGB, 16, PNG_INTERLACE_NONE);
	bad |= put_png(dir, "gray-interlaced.png", PNG_COLOR_TYPE_GRAY, 8, PNG_INTERLACE_ADAM7);
	bad |= put_png(dir, "gray-alpha.png", PNG_COLOR_TYPE_GA, 8, PNG_INTERLACE_NONE);
	bad |= put_png(dir, "palette.png", PNG_COLOR_TYPE_PALETTE, 2, PNG_INTERLACE_NONE);
	bad |= put_jpeg(dir, "rgb420.jpg", TJPF_RGBX, TJSAMP_420, 0);
	bad |= put_jpeg(dir, "gray.jpg", TJPF_GRAY, TJSAMP_GRAY, 0);
	bad |= put_jpeg(dir, "rgb444-progressive.jpg", TJPF_RGBX, TJSAMP_444, TJFLAG_PROGRESSIVE);
	bad |= put_webp(dir, "lossless.webp", true);
	bad |= put_webp(dir, "lossy-alpha.webp", false);
	return bad;
}

int main(int argc, char **argv)
{
	if (argc != 2) {
		fprintf(stderr, "usage: mkseeds DIR\n");
		return 2;
	}
	/* Images first: the material model embeds rgba.png. */
	return write_images(argv[1]) || write_models(argv[1]);
}
