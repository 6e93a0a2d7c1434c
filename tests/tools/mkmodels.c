/* Writes the test and bench models into a folder:
 *   mkmodels DIR          sphere, loader variants, the malformed set, the
 *                         corpus test's torus knots, and the material maps
 *                         and models
 *   mkmodels DIR --bench  also torus knots of about 10k, 100k and 1M triangles,
 *                         and the 100k one textured, skinned (still and turning), morphing
 *                         and flat-shaded, and the 10k and 100k ones without normals
 *   mkmodels DIR --bomb SIDE  only bomb.gltf: four SIDE x SIDE PNGs of one
 *                         colour as its base colour, normal, occlusion and
 *                         film thickness textures (tests/suite.sh)
 *   mkmodels DIR --scan   only knot-1m.glb, the bench's 1M-triangle knot
 *                         (tests/e2e/limits.sh: a scan's cold start's memory) */
#include "gltf_morph.h"
#include "gltf_variants.h"
#include "gltf_write.h"
#include "maps.h"
#include "parts_models.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/tangent.h"
#include "util/image.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int put(const char *dir, const char *name, const struct mesh *m, struct gltf_write_opts o)
{
	char path[4096];

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	if (gltf_write(path, m, &o)) {
		fprintf(stderr, "mkmodels: cannot write %s\n", path);
		return 1;
	}
	return 0;
}

/* Base colour: COLOR_0 as normalized bytes, no material; and a base map
 * with a factor and KHR_texture_transform. */
static int write_color_models(const char *dir, struct mesh *s)
{
	static const double factor[4] = {1.0, 0.9, 0.75, 1.0};
	struct gltf_write_opts o = {
	    .index_bytes = 2, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	char base[4096];
	int bad;

	if (mesh_alloc_colors(s))
		return 1;
	for (uint32_t v = 0; v < s->vertex_count; v++) {
		for (int k = 0; k < 3; k++)
			s->colors[v * 4 + k] = 0.55f + 0.4f * s->positions[v * 3 + k];
		s->colors[v * 4 + 3] = 1.0f;
	}
	o.color_type = 5121;
	o.color_components = 4;
	bad = put(dir, "sphere-vertex-color.glb", s, o);
	o.color_type = 0;
	snprintf(base, sizeof(base), "%s/base.png", dir);
	o.base_color_png = base;
	o.embed_images = 1;
	o.base_factor = factor;
	o.texture_transform = "\"offset\":[0.25,0.1],\"rotation\":0.3,\"scale\":[2,1.5]";
	bad |= put(dir, "sphere-base-map.glb", s, o);
	free(s->colors);
	s->colors = NULL;
	return bad;
}

static int write_material_models(const char *dir)
{
	struct gltf_write_opts base = {
	    .index_bytes = 2, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	struct gltf_write_opts o;
	char normal[4096], occlusion[4096], thickness[4096], corrupt[4096];
	struct mesh s, coarse;
	int bad = maps_write(dir);

	snprintf(normal, sizeof(normal), "%s/normal.png", dir);
	snprintf(occlusion, sizeof(occlusion), "%s/occlusion.png", dir);
	snprintf(thickness, sizeof(thickness), "%s/thickness.png", dir);
	snprintf(corrupt, sizeof(corrupt), "%s/corrupt.png", dir);
	if (mesh_uv_sphere(&s, 64, 32) || mesh_uv_sphere(&coarse, 24, 12))
		return 1;
	/* glTF normal and occlusion textures in the buffer; no TANGENT, so
	 * the loader's consumer makes them from the UVs. */
	o = base;
	o.normal_png = normal;
	o.occlusion_png = occlusion;
	o.embed_images = 1;
	bad |= put(dir, "sphere-detail.glb", &s, o);
	/* A beetle: TANGENT given, textures in files beside the model, and
	 * KHR_materials_iridescence with a thickness texture. */
	if (tangent_generate(&s))
		return 1;
	o = base;
	o.container = GLTF_EXTERNAL_BIN;
	o.with_tangents = 1;
	o.normal_png = normal;
	o.occlusion_png = occlusion;
	o.thickness_png = thickness;
	o.iridescence_factor = 1.0;
	o.thickness_range[0] = 250;
	o.thickness_range[1] = 450;
	bad |= put(dir, "sphere-beetle.gltf", &s, o);
	/* Textures that cannot be used: a warning each, the model loads. */
	o.image_uri = "../normal.png";
	bad |= put(dir, "warn-texture-outside.gltf", &s, o);
	o = base;
	o.normal_png = corrupt;
	o.embed_images = 1;
	bad |= put(dir, "warn-texture-corrupt.glb", &s, o);
	bad |= write_color_models(dir, &s);
	/* Coarse, for displacement: 576 triangles of 15 degrees. */
	bad |= put(dir, "sphere-coarse.glb", &coarse, base);
	mesh_release(&s);
	mesh_release(&coarse);
	return bad;
}

/* Every triangle with vertices of its own and its face's normal: split
 * normals everywhere, as a flat-shaded export has them. */
static int split_flat(const struct mesh *src, struct mesh *out)
{
	if (mesh_alloc(out, src->index_count, src->index_count, src->uvs != NULL))
		return -1;
	for (uint32_t i = 0; i < src->index_count; i++) {
		uint32_t v = src->indices[i], t = i - i % 3;
		const float *a = src->positions + src->indices[t] * 3;
		const float *b = src->positions + src->indices[t + 1] * 3;
		const float *c = src->positions + src->indices[t + 2] * 3;
		double e1[3], e2[3], n[3], len;

		for (int k = 0; k < 3; k++)
			e1[k] = b[k] - a[k], e2[k] = c[k] - a[k];
		n[0] = e1[1] * e2[2] - e1[2] * e2[1];
		n[1] = e1[2] * e2[0] - e1[0] * e2[2];
		n[2] = e1[0] * e2[1] - e1[1] * e2[0];
		len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		for (int k = 0; k < 3; k++) {
			out->positions[i * 3 + k] = src->positions[v * 3 + k];
			out->normals[i * 3 + k] = len > 0 ? (float)(n[k] / len) : (float)(k == 2);
		}
		if (src->uvs)
			memcpy(out->uvs + i * 2, src->uvs + v * 2, 8);
		out->indices[i] = i;
	}
	return 0;
}

/* The corpus test's sources (tests/corpus/run.sh turns them into
 * gltfpack and Draco files): a torus knot, smooth with a UV seam, and the
 * same flat-shaded, every edge a crease. */
static int write_corpus(const char *dir)
{
	struct mesh k, flat;
	struct gltf_write_opts o = {
	    .index_bytes = 4, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	int bad = 0;

	if (mesh_torus_knot(&k, 256, 16) || split_flat(&k, &flat))
		return 1;
	bad |= put(dir, "knot.glb", &k, o);
	bad |= put(dir, "knot-flat.glb", &flat, o);
	mesh_release(&k);
	mesh_release(&flat);
	return bad;
}

/* A texel's hash, for a little noise: real textures are photographs and
 * paintings, and their PNGs do not shrink to nothing. */
static double grain(int x, int y)
{
	uint32_t h = (uint32_t)x * 73856093u ^ (uint32_t)y * 19349663u;

	h ^= h >> 13;
	h *= 0x5bd1e995u;
	h ^= h >> 15;
	return (h & 255) / 255.0 - 0.5;
}

/* The textured bench model's maps, BENCH_MAP_SIDE square: base colour
 * waves, a normal map of ripples and an occlusion map, each with grain. */
#define BENCH_MAP_SIDE 2048
static int write_bench_maps(const char *dir)
{
	static const char *const names[3] = {"bench-base.png", "bench-normal.png",
					     "bench-occlusion.png"};
	struct image img[3];
	char path[4096];
	int bad = 0;

	for (int i = 0; i < 3; i++)
		if (image_alloc(&img[i], BENCH_MAP_SIDE, BENCH_MAP_SIDE))
			return 1;
	for (int y = 0; y < BENCH_MAP_SIDE; y++)
		for (int x = 0; x < BENCH_MAP_SIDE; x++) {
			size_t at = ((size_t)y * BENCH_MAP_SIDE + (size_t)x) * 4;
			double u = (x + 0.5) / BENCH_MAP_SIDE, v = (y + 0.5) / BENCH_MAP_SIDE;
			double g = grain(x, y) * 0.06, nx = 0.3 * cos(2 * M_PI * 24 * u);
			double ny = 0.3 * sin(2 * M_PI * 6 * v), nz = sqrt(1 - nx * nx - ny * ny);
			double c[3][3] = {{0.55 + 0.4 * cos(2 * M_PI * u),
					   0.55 + 0.4 * sin(2 * M_PI * (u + 2 * v)),
					   0.5 + 0.35 * cos(2 * M_PI * 3 * v)},
					  {nx * 0.5 + 0.5, ny * 0.5 + 0.5, nz * 0.5 + 0.5},
					  {0.7 + 0.3 * (nx / 0.3) * (ny / 0.3)}};

			c[2][1] = c[2][2] = c[2][0];
			for (int i = 0; i < 3; i++) {
				for (int k = 0; k < 3; k++) {
					double t = fmin(fmax(c[i][k] + g, 0.0), 1.0);

					img[i].rgba[at + (size_t)k] =
					    (unsigned char)lround(t * 255);
				}
				img[i].rgba[at + 3] = 255;
			}
		}
	for (int i = 0; i < 3; i++) {
		snprintf(path, sizeof(path), "%s/%s", dir, names[i]);
		if (image_write_png(path, &img[i]))
			bad = 1, fprintf(stderr, "mkmodels: cannot write %s\n", path);
		image_release(&img[i]);
	}
	return bad;
}

/* The 100k knot in the forms tests/bench/bench_gltf.sh compares: with
 * base colour, normal and occlusion maps of BENCH_MAP_SIDE in its
 * buffer; skinned, two joints bending it; flat-shaded, every edge a
 * seam, for the level of detail. */
static int write_bench_forms(const char *dir, const struct mesh *k)
{
	struct gltf_write_opts o = {
	    .index_bytes = 4, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	char base[4096], normal[4096], occlusion[4096];
	struct mesh flat;
	int bad = write_bench_maps(dir);

	snprintf(base, sizeof(base), "%s/bench-base.png", dir);
	snprintf(normal, sizeof(normal), "%s/bench-normal.png", dir);
	snprintf(occlusion, sizeof(occlusion), "%s/bench-occlusion.png", dir);
	o.base_color_png = base;
	o.normal_png = normal;
	o.occlusion_png = occlusion;
	o.embed_images = 1;
	bad |= put(dir, "knot-100k-textured.glb", k, o);
	o.base_color_png = o.normal_png = o.occlusion_png = NULL;
	o.embed_images = 0;
	o.node = "\"skin\":0";
	o.extra_nodes = "{\"children\":[2]},{\"rotation\":[0,0,0.2588,0.9659]}";
	o.scenes = "{\"nodes\":[0,1]}";
	o.skin_joints = "1,2";
	bad |= put(dir, "knot-100k-skinned.glb", k, o);
	/* The same bend turned by an animation: live playback's figures. */
	o.with_anim = 1;
	o.anim_node = 2;
	bad |= put(dir, "knot-100k-turning.glb", k, o);
	o.with_anim = 0;
	/* Two morph targets that move positions and normals, their weights
	 * keyed: live playback's morph figures. */
	snprintf(base, sizeof(base), "%s/knot-100k-morphing.glb", dir);
	if (gltf_write_morph(base, k, 1)) {
		fprintf(stderr, "mkmodels: cannot write %s\n", base);
		bad = 1;
	}
	if (split_flat(k, &flat))
		return 1;
	o = (struct gltf_write_opts){
	    .index_bytes = 4, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	bad |= put(dir, "knot-100k-flat.glb", &flat, o);
	mesh_release(&flat);
	return bad;
}

/* The bench's 1M-triangle knot, as write_bench writes it. */
static int write_scan(const char *dir)
{
	struct gltf_write_opts o = {
	    .index_bytes = 4, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	struct mesh k1m;
	int bad;

	if (mesh_torus_knot(&k1m, 4096, 122))
		return 1;
	bad = put(dir, "knot-1m.glb", &k1m, o);
	mesh_release(&k1m);
	return bad;
}

static int write_bench(const char *dir)
{
	struct mesh k10, k100, k1m;
	/* With UVs, for the material features' figures (a scene that does
	 * not use them never uploads them). */
	struct gltf_write_opts o = {
	    .index_bytes = 4, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	int bad = 0;

	if (mesh_torus_knot(&k10, 256, 20) || mesh_torus_knot(&k100, 1024, 49) ||
	    mesh_torus_knot(&k1m, 4096, 122))
		return 1;
	bad |= put(dir, "knot-10k.glb", &k10, o);
	bad |= put(dir, "knot-100k.glb", &k100, o);
	bad |= put(dir, "knot-1m.glb", &k1m, o);
	bad |= write_bench_forms(dir, &k100);
	/* Without normals, as a CAD or STL conversion: [scene] normals'
	 * figures, flat against smooth (tests/bench/bench_normals.sh). */
	o.with_normals = 0;
	bad |= put(dir, "knot-10k-nonormals.glb", &k10, o);
	bad |= put(dir, "knot-100k-nonormals.glb", &k100, o);
	printf("knot-100k.glb %u triangles, knot-1m.glb %u triangles\n", k100.index_count / 3,
	       k1m.index_count / 3);
	mesh_release(&k10);
	mesh_release(&k100);
	mesh_release(&k1m);
	return bad;
}

/* [scene] fit and [display] background: a long model (the sphere
 * stretched four times along x, its normals with it) and a backdrop
 * image, wider than the golden frame, in four coloured quarters with a
 * white border, so a crop shows. */
static int write_look(const char *dir, const struct mesh *sphere)
{
	struct gltf_write_opts o = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	struct mesh m = *sphere;
	struct image img;
	char path[4096];
	size_t n = (size_t)sphere->vertex_count * 3;
	int bad = 0;

	m.positions = malloc(n * sizeof(float));
	m.normals = malloc(n * sizeof(float));
	if (!m.positions || !m.normals || image_alloc(&img, 200, 80)) {
		free(m.positions);
		free(m.normals);
		return 1;
	}
	for (size_t i = 0; i < n; i += 3) {
		double nx = sphere->normals[i] / 4.0, ny = sphere->normals[i + 1],
		       nz = sphere->normals[i + 2], len = sqrt(nx * nx + ny * ny + nz * nz);

		m.positions[i] = sphere->positions[i] * 4.0f;
		m.positions[i + 1] = sphere->positions[i + 1];
		m.positions[i + 2] = sphere->positions[i + 2];
		m.normals[i] = (float)(nx / len);
		m.normals[i + 1] = (float)(ny / len);
		m.normals[i + 2] = (float)(nz / len);
	}
	bad |= put(dir, "long.glb", &m, o);
	for (int y = 0; y < img.height; y++)
		for (int x = 0; x < img.width; x++) {
			uint8_t *p = img.rgba + ((size_t)y * (size_t)img.width + (size_t)x) * 4;
			bool border = x < 4 || y < 4 || x >= img.width - 4 || y >= img.height - 4;
			int q = (x >= img.width / 2) + 2 * (y >= img.height / 2);
			static const uint8_t quarter[4][3] = {
			    {200, 60, 50}, {60, 150, 70}, {50, 80, 180}, {210, 180, 60}};

			for (int c = 0; c < 3; c++)
				p[c] = border ? 255 : quarter[q][c];
			p[3] = 255;
		}
	snprintf(path, sizeof(path), "%s/backdrop.png", dir);
	bad |= image_write_png(path, &img) != 0;
	image_release(&img);
	free(m.positions);
	free(m.normals);
	return bad;
}

/* Every texture slot the kiosk decodes, each its own large image. */
static int write_bomb(const char *dir, int side)
{
	static const char *const names[4] = {"bomb-base.png", "bomb-normal.png",
					     "bomb-occlusion.png", "bomb-thickness.png"};
	static const unsigned char colour[4][4] = {
	    {200, 120, 60, 255}, {128, 128, 255, 255}, {230, 230, 230, 255}, {0, 160, 0, 255}};
	struct gltf_write_opts o = {
	    .index_bytes = 2, .with_normals = 1, .bad_index = -1, .with_uvs = 1};
	char path[4][4096];
	struct mesh s;
	int bad = 0;

	for (int k = 0; k < 4; k++) {
		snprintf(path[k], sizeof(path[k]), "%s/%s", dir, names[k]);
		bad |= maps_write_flat(path[k], side, colour[k]);
	}
	if (bad || mesh_uv_sphere(&s, 64, 32))
		return 1;
	o.container = GLTF_EXTERNAL_BIN;
	o.base_color_png = path[0];
	o.normal_png = path[1];
	o.occlusion_png = path[2];
	o.thickness_png = path[3];
	o.iridescence_factor = 1.0;
	o.thickness_range[0] = 250;
	o.thickness_range[1] = 450;
	bad |= put(dir, "bomb.gltf", &s, o);
	mesh_release(&s);
	return bad;
}

/* KHR_materials_variants: the cube of "red" and "blue" (gltf_variants.h). */
static int write_variants(const char *dir)
{
	char path[512];

	snprintf(path, sizeof(path), "%s/variants.gltf", dir);
	return gltf_write_variants(path, VARIANTS_OK) ? 1 : 0;
}

/* A cube without normals, its corners shared: flat sides by default,
 * a pillow with --normals smooth (golden normals-flat, normals-smooth). */
static int write_cube(const char *dir)
{
	struct gltf_write_opts o = {.index_bytes = 2, .bad_index = -1};
	struct mesh c;
	int bad;

	if (gltf_test_cube(&c))
		return 1;
	bad = put(dir, "cube-nonormals.glb", &c, o);
	mesh_release(&c);
	return bad;
}

/* The fit's centring (issue 33): a lopsided model, as a plane seen from
 * its side: a long body and, at one end, a tall thin fin. Its box's and
 * sphere's centres are far from its outline's at the start view. */
static int write_lopsided(const char *dir)
{
	static const float boxes[2][6] = {{-2, -0.3f, -0.3f, 2, 0.3f, 0.3f},
					  {1.3f, 0.3f, -0.08f, 2, 1.8f, 0.08f}};
	struct gltf_write_opts o = {.index_bytes = 2, .bad_index = -1};
	struct mesh cube, m;
	int bad = 1;

	if (gltf_test_cube(&cube))
		return 1;
	if (!mesh_alloc(&m, 16, 72, false)) {
		for (uint32_t b = 0; b < 2; b++) {
			for (uint32_t v = 0; v < 8; v++)
				for (int k = 0; k < 3; k++)
					m.positions[(b * 8 + v) * 3 + k] =
					    cube.positions[v * 3 + k] > 0 ? boxes[b][3 + k]
									  : boxes[b][k];
			for (uint32_t i = 0; i < 36; i++)
				m.indices[b * 36 + i] = cube.indices[i] + b * 8;
		}
		bad = put(dir, "lopsided.glb", &m, o);
		mesh_release(&m);
	}
	mesh_release(&cube);
	return bad;
}

int main(int argc, char **argv)
{
	struct mesh s;
	struct gltf_write_opts ok = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	struct gltf_write_opts o;
	int bad = 0;

	if (argc < 2) {
		fprintf(stderr, "usage: mkmodels DIR [--bench]\n");
		return 2;
	}
	if (argc > 3 && strcmp(argv[2], "--bomb") == 0)
		return write_bomb(argv[1], atoi(argv[3]));
	if (argc > 2 && strcmp(argv[2], "--scan") == 0)
		return write_scan(argv[1]);
	if (mesh_uv_sphere(&s, 128, 64))
		return 1;
	bad |= put(argv[1], "sphere.glb", &s, ok);
	o = ok;
	o.container = GLTF_EXTERNAL_BIN;
	o.with_normals = 0;
	bad |= put(argv[1], "sphere-nonormals.gltf", &s, o);
	bad |= write_cube(argv[1]);
	o = ok;
	o.container = GLTF_DATA_URI;
	bad |= put(argv[1], "sphere-datauri.gltf", &s, o);
	/* The broken ones: each must give one clear line and exit 1. */
	o = ok;
	o.truncate_to = 2000;
	bad |= put(argv[1], "bad-truncated.glb", &s, o);
	o = ok;
	o.container = GLTF_EXTERNAL_BIN;
	o.position_count = (long)s.vertex_count + 100;
	bad |= put(argv[1], "bad-past-end.gltf", &s, o);
	o = ok;
	o.bad_index = 9000; /* the sphere has 8385 vertices */
	bad |= put(argv[1], "bad-index.glb", &s, o);
	o = ok;
	o.container = GLTF_EXTERNAL_BIN;
	o.bin_uri = "missing.bin";
	bad |= put(argv[1], "bad-missing-buffer.gltf", &s, o);
	o.bin_uri = "/etc/passwd";
	bad |= put(argv[1], "bad-absolute-uri.gltf", &s, o);
	o.bin_uri = "../sphere.bin";
	bad |= put(argv[1], "bad-dotdot-uri.gltf", &s, o);
	/* Two scenes: "one" (the file's default) and "pair", the sphere twice. */
	o = ok;
	o.extra_nodes = "{\"mesh\":0,\"translation\":[2.5,0,0]}";
	o.scenes = "{\"name\":\"one\",\"nodes\":[0]},{\"name\":\"pair\",\"nodes\":[0,1]}";
	bad |= put(argv[1], "scenes.glb", &s, o);
	bad |= write_look(argv[1], &s);
	bad |= write_lopsided(argv[1]);
	mesh_release(&s);
	bad |= write_material_models(argv[1]);
	bad |= parts_models_write(argv[1]);
	bad |= write_corpus(argv[1]);
	bad |= write_variants(argv[1]);
	if (argc > 2 && strcmp(argv[2], "--bench") == 0)
		bad |= write_bench(argv[1]) | parts_models_write_bench(argv[1]);
	return bad;
}
