#include "scene/gltf/gltf.h"
#include "gltf_write.h"
#include "scene/mesh/mesh.h"

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
	struct mesh sphere; /* small enough for 8-bit indices */
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	strcpy(f->dir, "/tmp/mk-gltf-XXXXXX");
	if (!mkdtemp(f->dir) || mesh_uv_sphere(&f->sphere, 12, 8))
		return -1;
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

static int write_and_load(struct fixture *f, const char *name, struct gltf_write_opts o,
			  struct mesh *out)
{
	char path[256];

	snprintf(path, sizeof(path), "%s/%s", f->dir, name);
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
	return gltf_load(path, out);
}

static struct gltf_write_opts ok_opts(void)
{
	return (struct gltf_write_opts){.index_bytes = 2, .with_normals = 1, .bad_index = -1};
}

/* Every triangle wound CCW seen from outside and every normal pointing out. */
static void assert_outward(const struct mesh *m)
{
	for (uint32_t t = 0; t < m->index_count; t += 3) {
		const float *a = m->positions + m->indices[t] * 3;
		const float *b = m->positions + m->indices[t + 1] * 3;
		const float *c = m->positions + m->indices[t + 2] * 3;
		double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
		double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
		double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
			       e1[0] * e2[1] - e1[1] * e2[0]};
		double centre[3] = {a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]};

		if (n[0] * n[0] + n[1] * n[1] + n[2] * n[2] < 1e-12)
			continue;
		assert_true(n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] > 0);
	}
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		const float *p = m->positions + v * 3, *n = m->normals + v * 3;
		assert_true(p[0] * n[0] + p[1] * n[1] + p[2] * n[2] > 0);
		assert_true(fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1) < 1e-5);
	}
}

static void loads_every_container(void **state)
{
	struct fixture *f = *state;
	static const enum gltf_container c[] = {GLTF_GLB, GLTF_EXTERNAL_BIN, GLTF_DATA_URI};
	static const char *names[] = {"a.glb", "b.gltf", "c.gltf"};
	struct mesh m;

	for (int i = 0; i < 3; i++) {
		struct gltf_write_opts o = ok_opts();

		o.container = c[i];
		assert_int_equal(write_and_load(f, names[i], o, &m), 0);
		assert_int_equal(m.vertex_count, f->sphere.vertex_count);
		assert_int_equal(m.index_count, f->sphere.index_count);
		assert_outward(&m);
		mesh_release(&m);
	}
}

static void loads_every_index_size(void **state)
{
	struct fixture *f = *state;
	struct mesh m;

	for (int bytes = 1; bytes <= 4; bytes *= 2) {
		struct gltf_write_opts o = ok_opts();

		o.index_bytes = bytes;
		assert_int_equal(write_and_load(f, "idx.glb", o, &m), 0);
		assert_memory_equal(m.indices, f->sphere.indices, f->sphere.index_count * 4);
		mesh_release(&m);
	}
}

static void generates_missing_normals(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = ok_opts();
	struct gltf_options smooth = {.normals = MESH_NORMALS_SMOOTH};
	struct mesh m;
	char path[256];

	o.with_normals = 0;
	snprintf(path, sizeof(path), "%s/nn.glb", f->dir);
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
	/* [scene] normals = smooth (the default is flat: test_normals.c):
	 * area-weighted and welded across the UV seam, close to the analytic
	 * normal of the sphere even at this coarse tessellation. */
	assert_int_equal(gltf_load_options(path, &smooth, &m), 0);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *p = m.positions + v * 3, *n = m.normals + v * 3;
		double pl = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
		assert_true((p[0] * n[0] + p[1] * n[1] + p[2] * n[2]) / pl > 0.98);
	}
	mesh_release(&m);
}

static void mirrored_transforms_keep_winding(void **state)
{
	struct fixture *f = *state;
	static const char *nodes[] = {"\"scale\":[-1,1,1]", "\"scale\":[-1,-1,-1]",
				      "\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,-1,0, 5,0,0,1]"};
	struct mesh m;

	for (int i = 0; i < 3; i++) {
		struct gltf_write_opts o = ok_opts();

		o.node = nodes[i];
		assert_int_equal(write_and_load(f, "mirror.glb", o, &m), 0);
		assert_outward(&m);
		mesh_release(&m);
	}
}

static void hierarchy_and_non_uniform_scale(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = ok_opts();
	struct mesh m;

	/* A mirroring, stretching parent over a rotated child: the normals
	 * must follow the inverse transpose, i.e. the ellipsoid's normals. */
	o.parent = "\"scale\":[-2,1,1],\"translation\":[100000,0,0]";
	o.node = "\"rotation\":[0,0,0.70710678,0.70710678]";
	assert_int_equal(write_and_load(f, "tree.glb", o, &m), 0);
	assert_outward(&m);
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *p = m.positions + v * 3, *n = m.normals + v * 3;
		/* Fitted: x spans [-1,1] (a = 2 before fitting), y and z [-.5,.5]. */
		double g[3] = {p[0] / 4.0, p[1], p[2]};
		double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
		assert_true((g[0] * n[0] + g[1] * n[1] + g[2] * n[2]) / gl > 0.999);
	}
	mesh_release(&m);
}

static void refuses_malformed(void **state)
{
	struct fixture *f = *state;
	struct mesh m;
	struct {
		const char *name;
		struct gltf_write_opts o;
	} cases[8];
	int n = 0;

	for (int i = 0; i < 8; i++)
		cases[i].o = ok_opts();
	cases[n].name = "truncated.glb", cases[n++].o.truncate_to = 300;
	cases[n].name = "past-end.glb", cases[n++].o.position_count = 1000;
	cases[n].name = "huge-count.glb", cases[n++].o.position_count = 0xffffffffL;
	cases[n].name = "bad-index.glb", cases[n++].o.bad_index = 117;
	cases[n].name = "stride.glb", cases[n++].o.byte_stride = 8;
	cases[n].name = "cycle.glb", cases[n++].o.node = "\"children\":[0]";
	cases[n].name = "missing.gltf", cases[n].o.container = GLTF_EXTERNAL_BIN;
	cases[n++].o.bin_uri = "nothere.bin";
	cases[n].name = "escape.gltf", cases[n].o.container = GLTF_EXTERNAL_BIN;
	cases[n++].o.bin_uri = "../escape.bin";
	for (int i = 0; i < n; i++) {
		int ret = write_and_load(f, cases[i].name, cases[i].o, &m);

		if (ret == 0)
			fail_msg("%s was accepted", cases[i].name);
		assert_null(m.positions);
		assert_int_equal(m.vertex_count, 0);
	}
}

static void refuses_absolute_uri(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = ok_opts();
	char bin[128];
	struct mesh m;

	/* The file exists, so only the path rule can refuse it. */
	o.container = GLTF_EXTERNAL_BIN;
	assert_int_equal(write_and_load(f, "abs.gltf", o, &m), 0);
	mesh_release(&m);
	snprintf(bin, sizeof(bin), "%s/abs.bin", f->dir);
	o.bin_uri = bin;
	assert_int_not_equal(write_and_load(f, "abs2.gltf", o, &m), 0);
}

static void refuses_garbage_in_memory(void **state)
{
	static const char *texts[] = {"", "{", "[]", "{\"asset\":{\"version\":\"2.0\"}}",
				      "glTF\x02\0\0\0\xff\xff\xff\xff"};
	struct mesh m;

	(void)state;
	for (int i = 0; i < 5; i++)
		assert_int_not_equal(gltf_load_memory("mem", (const uint8_t *)texts[i],
						      strlen(texts[i]) + (i == 4 ? 4 : 0), "", &m),
				     0);
}

/* Memory (issue 34): gltf_load_bytes_owned frees the file's bytes once
 * parsed, before the mesh is built (a 1M-triangle scan's 28 MB are not
 * held beside its parsed buffers and its mesh), and builds the same mesh
 * as gltf_load_bytes; a file the parser refuses leaves its bytes to the
 * caller, who frees them (ASan says if either frees twice or never). */
static void owned_bytes_go_once_parsed(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = ok_opts();
	struct gltf_options g = {0};
	struct mesh kept, owned;
	char path[256];
	uint8_t *data;
	size_t size;

	snprintf(path, sizeof(path), "%s/owned.glb", f->dir);
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
	assert_int_equal(gltf_read(path, &data, &size), 0);
	assert_int_equal(gltf_load_bytes(path, data, size, &g, &kept), 0);
	assert_int_equal(gltf_load_bytes_owned(path, &data, size, &g, &owned), 0);
	assert_null(data);
	assert_int_equal(owned.index_count, kept.index_count);
	assert_int_equal(owned.vertex_count, kept.vertex_count);
	assert_memory_equal(owned.indices, kept.indices, kept.index_count * 4);
	assert_memory_equal(owned.positions, kept.positions, kept.vertex_count * 12);
	mesh_release(&owned);
	mesh_release(&kept);
	o.truncate_to = 300;
	assert_int_equal(gltf_write(path, &f->sphere, &o), 0);
	assert_int_equal(gltf_read(path, &data, &size), 0);
	assert_int_not_equal(gltf_load_bytes_owned(path, &data, size, &g, &owned), 0);
	assert_non_null(data);
	free(data);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(loads_every_container),
	    cmocka_unit_test(loads_every_index_size),
	    cmocka_unit_test(generates_missing_normals),
	    cmocka_unit_test(mirrored_transforms_keep_winding),
	    cmocka_unit_test(hierarchy_and_non_uniform_scale),
	    cmocka_unit_test(refuses_malformed),
	    cmocka_unit_test(refuses_absolute_uri),
	    cmocka_unit_test(refuses_garbage_in_memory),
	    cmocka_unit_test(owned_bytes_go_once_parsed),
	};
	return cmocka_run_group_tests_name("gltf", tests, setup, teardown);
}
