/* The glTF loader on what exporters write beyond plain float triangles:
 * skins and morph targets posed at load, quantized and meshopt-compressed
 * attributes, sparse accessors and accessors without a bufferView, the
 * scene choice, deep hierarchies; and refusals that name the JSON path. */
#include "scene/gltf/gltf.h"
#include "scene/mesh/mesh.h"

#include <math.h>
#include <meshoptimizer.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

/* One buffer (box.bin) holds every block the test files point into. */
enum {
	POS = 0,	  /* 8 x float vec3: a 2 x 1 x 1 box */
	IDX = 96,	  /* 36 x uint16 */
	QPOS = 168,	  /* 8 x int16 vec3 normalized, stride 8: the box halved */
	DELTA = 232,	  /* 8 x float vec3: +2 in x where x > 0 */
	JOINTS = 328,	  /* 8 x uint8 vec4: joint 0 */
	WEIGHTS = 360,	  /* 8 x float vec4: 1, 0, 0, 0 */
	IBM = 488,	  /* 1 x mat4: identity */
	SPARSE_IDX = 552, /* 8 x uint8: 0..7 */
	MESHOPT = 560,	  /* encoded positions, then encoded indices */
	BIN_SIZE = 4096,
};

struct fixture {
	char dir[64];
	size_t mo_vertex_len, mo_index_len, bin_len;
};

static const float box[8][3] = {{-1, -.5f, -.5f}, {1, -.5f, -.5f}, {1, .5f, -.5f}, {-1, .5f, -.5f},
				{-1, -.5f, .5f},  {1, -.5f, .5f},  {1, .5f, .5f},  {-1, .5f, .5f}};
static const uint16_t box_idx[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
				     2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};

static void fill_bin(struct fixture *f, unsigned char *bin)
{
	memcpy(bin + POS, box, sizeof(box));
	memcpy(bin + IDX, box_idx, sizeof(box_idx));
	for (int v = 0; v < 8; v++) {
		int16_t q[4] = {0};
		float d[3] = {box[v][0] > 0 ? 2.0f : 0.0f, 0, 0}, w[4] = {1, 0, 0, 0};

		for (int k = 0; k < 3; k++)
			q[k] = (int16_t)lrintf(box[v][k] * 0.5f * 32767.0f);
		memcpy(bin + QPOS + v * 8, q, 8);
		memcpy(bin + DELTA + v * 12, d, 12);
		memset(bin + JOINTS + v * 4, 0, 4);
		memcpy(bin + WEIGHTS + v * 16, w, 16);
		bin[SPARSE_IDX + v] = (unsigned char)v;
	}
	float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
	memcpy(bin + IBM, id, sizeof(id));
	f->mo_vertex_len = meshopt_encodeVertexBuffer(bin + MESHOPT, 1024, box, 8, 12);
	unsigned idx32[36];
	for (int i = 0; i < 36; i++)
		idx32[i] = box_idx[i];
	f->mo_index_len =
	    meshopt_encodeIndexBuffer(bin + MESHOPT + f->mo_vertex_len, 1024, idx32, 36);
	f->bin_len = MESHOPT + f->mo_vertex_len + f->mo_index_len;
}

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));
	unsigned char *bin = calloc(1, BIN_SIZE);
	char path[128];
	FILE *fp;

	strcpy(f->dir, "/tmp/mk-gltf-ext-XXXXXX");
	if (!f || !bin || !mkdtemp(f->dir))
		return -1;
	fill_bin(f, bin);
	snprintf(path, sizeof(path), "%s/box.bin", f->dir);
	fp = fopen(path, "wb");
	if (!fp || fwrite(bin, 1, BIN_SIZE, fp) != BIN_SIZE || fclose(fp))
		return -1;
	free(bin);
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

/* The accessors every file shares: 0 POSITION, 1 indices, 2 quantized
 * POSITION, 3 morph delta, 4 JOINTS_0, 5 WEIGHTS_0, 6 inverse binds. */
#define BUFFER_VIEWS                                                                               \
	"\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":96},"                      \
	"{\"buffer\":0,\"byteOffset\":96,\"byteLength\":72},"                                      \
	"{\"buffer\":0,\"byteOffset\":168,\"byteLength\":64,\"byteStride\":8},"                    \
	"{\"buffer\":0,\"byteOffset\":232,\"byteLength\":96},"                                     \
	"{\"buffer\":0,\"byteOffset\":328,\"byteLength\":32},"                                     \
	"{\"buffer\":0,\"byteOffset\":360,\"byteLength\":128},"                                    \
	"{\"buffer\":0,\"byteOffset\":488,\"byteLength\":64},"                                     \
	"{\"buffer\":0,\"byteOffset\":552,\"byteLength\":8}]"
#define ACCESSORS                                                                                  \
	"{\"bufferView\":0,\"componentType\":5126,\"count\":8,\"type\":\"VEC3\"},"                 \
	"{\"bufferView\":1,\"componentType\":5123,\"count\":36,\"type\":\"SCALAR\"},"              \
	"{\"bufferView\":2,\"componentType\":5122,\"normalized\":true,\"count\":8,"                \
	"\"type\":\"VEC3\"},"                                                                      \
	"{\"bufferView\":3,\"componentType\":5126,\"count\":8,\"type\":\"VEC3\"},"                 \
	"{\"bufferView\":4,\"componentType\":5121,\"count\":8,\"type\":\"VEC4\"},"                 \
	"{\"bufferView\":5,\"componentType\":5126,\"count\":8,\"type\":\"VEC4\"},"                 \
	"{\"bufferView\":6,\"componentType\":5126,\"count\":1,\"type\":\"MAT4\"}"
#define HEAD                                                                                       \
	"{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":\"box.bin\",\"byteLength\":4096}]" \
	","
#define BOX_MESH "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}"

/* Writes NAME.gltf from the format and loads it with `scene`; the error
 * line (if any) lands in err. */
static int load_text(struct fixture *f, const char *name, const char *scene, char *err,
		     size_t err_size, struct mesh *out, const char *fmt, ...)
{
	char path[128], log[128];
	/* The boxes here carry no normals: smooth ones keep their 8 vertices
	 * and the indices the codecs' checks compare (a flat split would
	 * give each corner of each face its own). */
	struct gltf_options o = {.scene = scene, .normals = MESH_NORMALS_SMOOTH};
	va_list ap;
	FILE *fp;
	int saved, ret;

	snprintf(path, sizeof(path), "%s/%s.gltf", f->dir, name);
	snprintf(log, sizeof(log), "%s/%s.log", f->dir, name);
	fp = fopen(path, "w");
	assert_non_null(fp);
	va_start(ap, fmt);
	vfprintf(fp, fmt, ap);
	va_end(ap);
	assert_int_equal(fclose(fp), 0);
	fflush(stderr);
	saved = dup(2);
	fp = fopen(log, "w");
	assert_non_null(fp);
	dup2(fileno(fp), 2);
	ret = gltf_load_options(path, &o, out);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	fclose(fp);
	fp = fopen(log, "r");
	err[0] = 0;
	while (fgets(err, (int)err_size, fp) && !strstr(err, "error"))
		err[0] = 0;
	fclose(fp);
	if (err[0])
		fprintf(stderr, "%s", err);
	return ret;
}

static void extent(const struct mesh *m, double e[3])
{
	for (int k = 0; k < 3; k++) {
		double lo = INFINITY, hi = -INFINITY;

		for (uint32_t v = 0; v < m->vertex_count; v++) {
			lo = fmin(lo, m->positions[v * 3 + k]);
			hi = fmax(hi, m->positions[v * 3 + k]);
		}
		e[k] = hi - lo;
	}
}

/* The loaded box's proportions, x : y : z over y. */
static void assert_box(const struct mesh *m, double x, double y, double z)
{
	double e[3];

	extent(m, e);
	assert_true(fabs(e[0] / e[1] - x / y) < 1e-3);
	assert_true(fabs(e[2] / e[1] - z / y) < 1e-3);
	assert_int_equal(m->index_count, 36);
}

static void plain_box(void **state)
{
	char err[512];
	struct mesh m;

	assert_int_equal(load_text(*state, "plain", NULL, err, sizeof(err), &m,
				   HEAD BUFFER_VIEWS ",\"accessors\":[" ACCESSORS "],"
						     "\"meshes\":[" BOX_MESH
						     "],\"nodes\":[{\"mesh\":0}],"
						     "\"scenes\":[{\"nodes\":[0]}]}"),
			 0);
	assert_box(&m, 2, 1, 1);
	mesh_release(&m);
}

/* The mesh node's own scale is ignored; the joint's turn about z shows. */
static void skin_poses_at_load(void **state)
{
	char err[512];
	struct mesh m;

	assert_int_equal(load_text(*state, "skin", NULL, err, sizeof(err), &m,
				   HEAD BUFFER_VIEWS
				   ",\"accessors\":[" ACCESSORS "],"
				   "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
				   "\"JOINTS_0\":4,\"WEIGHTS_0\":5},\"indices\":1}]}],"
				   "\"skins\":[{\"joints\":[1],\"inverseBindMatrices\":6}],"
				   "\"nodes\":[{\"mesh\":0,\"skin\":0,\"scale\":[1,10,1]},"
				   "{\"rotation\":[0,0,0.70710678,0.70710678]}],"
				   "\"scenes\":[{\"nodes\":[0,1]}]}"),
			 0);
	assert_box(&m, 1, 2, 1);
	mesh_release(&m);
}

/* Default weights: 0.5 of a target that adds 2 to x on one side. A
 * target without a bufferView is all zeros and changes nothing. */
static void morph_weights_apply(void **state)
{
	char err[512];
	struct mesh m;

	assert_int_equal(
	    load_text(*state, "morph", NULL, err, sizeof(err), &m,
		      HEAD BUFFER_VIEWS
		      ",\"accessors\":[" ACCESSORS ","
		      "{\"componentType\":5126,\"count\":8,\"type\":\"VEC3\"}],"
		      "\"meshes\":[{\"weights\":[0.5,1],\"primitives\":[{\"attributes\":"
		      "{\"POSITION\":0},\"indices\":1,\"targets\":[{\"POSITION\":3},"
		      "{\"POSITION\":7}]}]}],\"nodes\":[{\"mesh\":0}],"
		      "\"scenes\":[{\"nodes\":[0]}]}"),
	    0);
	assert_box(&m, 3, 1, 1);
	mesh_release(&m);
}

static void quantized_positions(void **state)
{
	char err[512];
	struct mesh m;

	assert_int_equal(
	    load_text(*state, "quant", NULL, err, sizeof(err), &m,
		      HEAD "\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
			   "\"extensionsRequired\":[\"KHR_mesh_quantization\"]," BUFFER_VIEWS
			   ",\"accessors\":[" ACCESSORS "],\"meshes\":[{\"primitives\":"
			   "[{\"attributes\":{\"POSITION\":2},\"indices\":1}]}],"
			   "\"nodes\":[{\"mesh\":0,\"scale\":[2,2,2]}],"
			   "\"scenes\":[{\"nodes\":[0]}]}"),
	    0);
	assert_box(&m, 2, 1, 1);
	mesh_release(&m);
}

/* All eight positions from a sparse accessor without a bufferView. */
static void sparse_positions(void **state)
{
	char err[512];
	struct mesh m;

	assert_int_equal(
	    load_text(*state, "sparse", NULL, err, sizeof(err), &m,
		      HEAD BUFFER_VIEWS
		      ",\"accessors\":[" ACCESSORS ","
		      "{\"componentType\":5126,\"count\":8,\"type\":\"VEC3\",\"sparse\":"
		      "{\"count\":8,\"indices\":{\"bufferView\":7,\"componentType\":5121},"
		      "\"values\":{\"bufferView\":0}}}],\"meshes\":[{\"primitives\":[{"
		      "\"attributes\":{\"POSITION\":7},\"indices\":1}]}],"
		      "\"nodes\":[{\"mesh\":0}]}"),
	    0);
	assert_box(&m, 2, 1, 1); /* and no `scenes`: every tree shows */
	mesh_release(&m);
}

static void meshopt_compressed(void **state)
{
	struct fixture *f = *state;
	char err[512];
	struct mesh m;

	assert_int_equal(
	    load_text(f, "meshopt", NULL, err, sizeof(err), &m,
		      "{\"asset\":{\"version\":\"2.0\"},\"extensionsUsed\":"
		      "[\"EXT_meshopt_compression\"],\"extensionsRequired\":"
		      "[\"EXT_meshopt_compression\"],\"buffers\":[{\"uri\":\"box.bin\","
		      "\"byteLength\":4096},{\"byteLength\":168,\"extensions\":"
		      "{\"EXT_meshopt_compression\":{\"fallback\":true}}}],\"bufferViews\":["
		      "{\"buffer\":1,\"byteLength\":96,\"byteStride\":12,\"extensions\":"
		      "{\"EXT_meshopt_compression\":{\"buffer\":0,\"byteOffset\":%d,"
		      "\"byteLength\":%zu,\"byteStride\":12,\"count\":8,\"mode\":\"ATTRIBUTES\"}}},"
		      "{\"buffer\":1,\"byteOffset\":96,\"byteLength\":144,\"extensions\":"
		      "{\"EXT_meshopt_compression\":{\"buffer\":0,\"byteOffset\":%zu,"
		      "\"byteLength\":%zu,\"byteStride\":4,\"count\":36,\"mode\":\"TRIANGLES\"}}}],"
		      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":8,"
		      "\"type\":\"VEC3\"},{\"bufferView\":1,\"componentType\":5125,\"count\":36,"
		      "\"type\":\"SCALAR\"}],\"meshes\":[" BOX_MESH "],\"nodes\":[{\"mesh\":0}],"
		      "\"scenes\":[{\"nodes\":[0]}]}",
		      MESHOPT, f->mo_vertex_len, MESHOPT + f->mo_vertex_len, f->mo_index_len),
	    0);
	assert_box(&m, 2, 1, 1);
	/* The index codec may rotate a triangle, never change its winding. */
	for (int t = 0; t < 12; t++) {
		const uint32_t *got = m.indices + t * 3;
		int r = got[0] == box_idx[t * 3] ? 0 : got[1] == box_idx[t * 3] ? 1 : 2;

		for (int k = 0; k < 3; k++)
			assert_int_equal(got[(k + r) % 3], box_idx[t * 3 + k]);
	}
	mesh_release(&m);
}

/* Scene 1 by index and by name; the file's default is scene 0. */
static void picks_a_scene(void **state)
{
	static const char *picks[] = {NULL, "1", "tall", "2"};
	static const double ratio[] = {2, 0.5, 0.5, 0};

	for (int i = 0; i < 4; i++) {
		char err[512];
		struct mesh m;
		int ret = load_text(*state, "scenes", picks[i], err, sizeof(err), &m,
				    HEAD BUFFER_VIEWS
				    ",\"accessors\":[" ACCESSORS "],"
				    "\"meshes\":[" BOX_MESH "],\"nodes\":[{\"mesh\":0},"
				    "{\"mesh\":0,\"scale\":[1,4,1]}],\"scenes\":["
				    "{\"nodes\":[0]},{\"name\":\"tall\",\"nodes\":[1]}]}");
		double e[3];

		if (ratio[i] == 0) {
			assert_int_not_equal(ret, 0);
			assert_non_null(strstr(err, "no scene \"2\""));
			continue;
		}
		assert_int_equal(ret, 0);
		extent(&m, e);
		assert_true(fabs(e[0] / e[1] - ratio[i]) < 1e-3);
		mesh_release(&m);
	}
}

/* A chain of 100,000 nodes loads (no recursion over the file's data). */
static void deep_hierarchy(void **state)
{
	struct fixture *f = *state;
	enum { DEPTH = 100000 };
	size_t cap = (size_t)DEPTH * 24 + 4096, len = 0;
	char *json = malloc(cap), err[512];
	struct mesh m;

	assert_non_null(json);
	len += (size_t)snprintf(json + len, cap - len,
				HEAD BUFFER_VIEWS ",\"accessors\":[" ACCESSORS "],"
						  "\"meshes\":[" BOX_MESH "],\"nodes\":[");
	for (int i = 0; i < DEPTH - 1; i++)
		len += (size_t)snprintf(json + len, cap - len, "{\"children\":[%d]},", i + 1);
	snprintf(json + len, cap - len, "{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}");
	assert_int_equal(load_text(f, "deep", NULL, err, sizeof(err), &m, "%s", json), 0);
	assert_box(&m, 2, 1, 1);
	mesh_release(&m);
	free(json);
}

struct refusal {
	const char *name, *body, *words;
};

/* Each refused with one line that names the JSON path and what was
 * expected; bytes from the file are escaped. */
static void refusals_name_the_path(void **state)
{
	static const struct refusal r[] = {
	    {"two-parents",
	     "\"nodes\":[{\"children\":[2]},{\"children\":[2]},{\"mesh\":0}],"
	     "\"scenes\":[{\"nodes\":[0,1]}]}",
	     "nodes[1].children[0]: nodes[2] has two parents, nodes[0] and nodes[1]"},
	    {"cycle",
	     "\"nodes\":[{\"mesh\":0},{\"children\":[2]},{\"children\":[1]}],"
	     "\"scenes\":[{\"nodes\":[0]}]}",
	     "is its own ancestor"},
	    {"required",
	     "\"extensionsRequired\":[\"KHR_mesh_quantization\",\"EXT_future\"],"
	     "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}",
	     "extensionsRequired: EXT_future not supported"},
	    {"no-extent", "\"nodes\":[{\"mesh\":1}],\"scenes\":[{\"nodes\":[0]}]}",
	     "every POSITION is the same point"},
	    {"int-position", "\"nodes\":[{\"mesh\":2}],\"scenes\":[{\"nodes\":[0]}]}",
	     "meshes[2].primitives[0].attributes.POSITION (accessors[1]): type SCALAR, "
	     "expected VEC3"},
	};
	for (size_t i = 0; i < sizeof(r) / sizeof(r[0]); i++) {
		char err[512];
		struct mesh m;

		assert_int_not_equal(
		    load_text(*state, r[i].name, NULL, err, sizeof(err), &m,
			      HEAD BUFFER_VIEWS
			      ",\"accessors\":[" ACCESSORS ","
			      "{\"componentType\":5126,\"count\":8,\"type\":\"VEC3\"}],"
			      "\"meshes\":[" BOX_MESH ",{\"primitives\":[{\"attributes\":"
			      "{\"POSITION\":7},\"indices\":1}]},{\"primitives\":[{\"attributes\":"
			      "{\"POSITION\":1}}]}],%s",
			      r[i].body),
		    0);
		assert_non_null(strstr(err, r[i].name));
		assert_non_null(strstr(err, r[i].words));
	}
}

static void missing_buffer_named_as_written(void **state)
{
	char err[512];
	struct mesh m;

	assert_int_not_equal(load_text(*state, "missing", NULL, err, sizeof(err), &m,
				       "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"uri\":"
				       "\"sub/\\u0001gone.bin\",\"byteLength\":4}]}"),
			     0);
	assert_non_null(strstr(err, "buffers[0].uri \"sub/\\x01gone.bin\": no such file"));
	for (const char *c = err; *c; c++)
		assert_true(*c == '\n' || (unsigned char)*c >= 0x20);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(plain_box),
	    cmocka_unit_test(skin_poses_at_load),
	    cmocka_unit_test(morph_weights_apply),
	    cmocka_unit_test(quantized_positions),
	    cmocka_unit_test(sparse_positions),
	    cmocka_unit_test(meshopt_compressed),
	    cmocka_unit_test(picks_a_scene),
	    cmocka_unit_test(deep_hierarchy),
	    cmocka_unit_test(refusals_name_the_path),
	    cmocka_unit_test(missing_buffer_named_as_written),
	};
	return cmocka_run_group_tests_name("gltf extensions", tests, setup, teardown);
}
