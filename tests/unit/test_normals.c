/* [scene] normals (issue 37, point 1): glTF says a primitive without
 * NORMAL is drawn with flat normals. A cube whose 8 corners its triangles
 * share, as an STL conversion writes it, loads as 36 vertices with each
 * side's normal exactly +-x, +-y or +-z (it was a pillow: the normals
 * averaged across its edges); normals = smooth keeps that old averaging,
 * normals = flat flattens a model that gives normals too, and the default
 * leaves a model's own normals as they were. The level of detail keeps a
 * flat mesh flat where it simplifies; live playback of a skinned model
 * without normals poses the split vertices as the still is baked; and a
 * second start from the prepared-mesh cache draws the same flat frame. */
#include "scene/gltf/gltf.h"
#include "scene/mesh/lod.h"
#include "scene/anim/anim_play.h"
#include "gltf_write.h"
#include "anim_fixture.h"

#include <math.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/mk-normals-XXXXXX";

static const char *model_path(const char *name)
{
	static char path[128];

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	return path;
}

static const char *write_cube(void)
{
	struct gltf_write_opts o = {.index_bytes = 2, .bad_index = -1};
	struct mesh c;

	assert_int_equal(gltf_test_cube(&c), 0);
	assert_int_equal(gltf_write(model_path("cube.glb"), &c, &o), 0);
	mesh_release(&c);
	return model_path("cube.glb");
}

static void load(const char *path, int normals, struct mesh *m)
{
	struct gltf_options o = {.normals = normals};

	assert_int_equal(gltf_load_options(path, &o, m), 0);
}

/* Every triangle's three corners carry its face normal, bit for bit. */
static void assert_flat(const struct mesh *m)
{
	for (uint32_t t = 0; t < m->index_count; t += 3) {
		const uint32_t *c = m->indices + t;
		float f[3];

		mesh_face_normal(m->positions + c[0] * 3, m->positions + c[1] * 3,
				 m->positions + c[2] * 3, f);
		for (int k = 0; k < 3; k++)
			assert_memory_equal(m->normals + c[k] * 3, f, sizeof(f));
	}
}

static void cube_without_normals_is_flat(void **state)
{
	struct mesh m;

	(void)state;
	load(write_cube(), MESH_NORMALS_FILE, &m);
	assert_int_equal(m.vertex_count, 36);
	assert_int_equal(m.index_count, 36);
	assert_flat(&m);
	/* Each normal one axis exactly, pointing out of the side. */
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *n = m.normals + v * 3, *p = m.positions + v * 3;
		int axes = 0;

		for (int k = 0; k < 3; k++) {
			assert_true(n[k] == 0.0f || n[k] == 1.0f || n[k] == -1.0f);
			axes += n[k] != 0.0f;
			if (n[k] != 0.0f)
				assert_true(n[k] * p[k] > 0.0f);
		}
		assert_int_equal(axes, 1);
	}
	mesh_release(&m);
}

static void smooth_keeps_the_old_average(void **state)
{
	struct mesh m;

	(void)state;
	load(write_cube(), MESH_NORMALS_SMOOTH, &m);
	assert_int_equal(m.vertex_count, 8);
	/* A corner's normal is the (area-weighted) average of its three
	 * sides': into its octant, near the diagonal, never along an axis. */
	for (uint32_t v = 0; v < m.vertex_count; v++) {
		const float *n = m.normals + v * 3, *p = m.positions + v * 3;
		double along = 0.0;

		for (int k = 0; k < 3; k++) {
			assert_true(n[k] * p[k] > 0.1f);
			along += n[k] * copysign(1.0 / sqrt(3.0), p[k]);
		}
		assert_true(along > 0.9);
	}
	mesh_release(&m);
}

static void given_normals_stay_unless_flat(void **state)
{
	struct gltf_write_opts o = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	struct mesh sphere, file, flat;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&sphere, 16, 8), 0);
	assert_int_equal(gltf_write(model_path("sphere.glb"), &sphere, &o), 0);
	load(model_path("sphere.glb"), MESH_NORMALS_FILE, &file);
	assert_int_equal(file.vertex_count, sphere.vertex_count);
	for (uint32_t i = 0; i < sphere.vertex_count * 3; i++)
		assert_float_equal(file.normals[i], sphere.normals[i], 1e-6);
	load(model_path("sphere.glb"), MESH_NORMALS_FLAT, &flat);
	assert_int_equal(flat.vertex_count, sphere.index_count);
	assert_int_equal(flat.index_count, sphere.index_count);
	assert_flat(&flat);
	mesh_release(&sphere);
	mesh_release(&file);
	mesh_release(&flat);
}

/* A faceted sphere simplified by the level of detail: its bigger
 * triangles are flat again (the welded pass gave each corner one of the
 * old faces' normals: shaded as a blend). */
static void lod_keeps_flat(void **state)
{
	struct gltf_write_opts o = {.index_bytes = 4, .bad_index = -1};
	struct mesh sphere, m;
	struct lod_result r;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&sphere, 96, 48), 0);
	assert_int_equal(gltf_write(model_path("facets.glb"), &sphere, &o), 0);
	load(model_path("facets.glb"), MESH_NORMALS_FILE, &m);
	assert_flat(&m);
	assert_int_equal(lod_prepare_mesh(&m, 8.0, 320, 240, &r), 0);
	print_message("lod of a flat sphere: %u -> %u triangles, %u -> %u vertices\n",
		      r.triangles_before, r.triangles_after, r.vertices_before, r.vertices_after);
	assert_true(r.triangles_after < r.triangles_before / 2);
	assert_flat(&m);
	mesh_release(&sphere);
	mesh_release(&m);
}

/* A skinned, animated sphere without normals: live playback's CPU pose
 * of the split vertices is the still baked at that time, flat. */
static void skinned_without_normals_plays_flat(void **state)
{
	struct gltf_write_opts o = {.index_bytes = 2, .bad_index = -1};
	struct anim_play *play = NULL;
	struct gltf_options g = {.pose = true, .time = 0.6, .speed = 1, .play = &play};
	struct mesh sphere, still;
	struct anim_pose *pose;
	float *pos, *nrm;

	(void)state;
	assert_int_equal(mesh_uv_sphere(&sphere, 16, 8), 0);
	o.node = "\"skin\":0";
	o.extra_nodes = "{\"children\":[2]},{\"rotation\":[0,0,0.2588,0.9659]}";
	o.scenes = "{\"nodes\":[0,1]}";
	o.skin_joints = "1,2";
	o.with_anim = 1;
	o.anim_node = 2;
	assert_int_equal(gltf_write(model_path("skinned.glb"), &sphere, &o), 0);
	assert_int_equal(gltf_load_options(model_path("skinned.glb"), &g, &still), 0);
	assert_non_null(play);
	assert_int_equal(still.vertex_count, sphere.index_count);
	assert_int_equal(play->vertex_count, still.vertex_count);
	assert_flat(&still);
	pose = anim_pose_new(play->anim);
	assert_non_null(pose);
	anim_pose_rest(play->anim, pose);
	anim_pose_apply(play->anim, &play->anim->clips[0], 0.6, pose);
	pos = calloc((size_t)still.vertex_count * 3, sizeof(float));
	nrm = calloc((size_t)still.vertex_count * 3, sizeof(float));
	assert_non_null(pos);
	assert_non_null(nrm);
	anim_play_pose(play, pose, pos, nrm);
	for (uint32_t i = 0; i < still.vertex_count * 3; i++) {
		assert_float_equal(pos[i], still.positions[i], 1e-5);
		assert_float_equal(nrm[i], still.normals[i], 1e-4);
	}
	free(pos);
	free(nrm);
	anim_pose_free(pose);
	anim_play_free(play);
	mesh_release(&sphere);
	mesh_release(&still);
}

static int differing(const struct image *a, const struct image *b)
{
	int n = 0;

	for (size_t i = 0; i < (size_t)a->width * a->height * 4; i += 4)
		n += memcmp(a->rgba + i, b->rgba + i, 4) != 0;
	return n;
}

/* The kiosk's load, prepare and draw; cached: whether the mesh must
 * come from the prepared-mesh cache. */
static void frame(const char *path, int normals, bool cached, struct image *out)
{
	struct content_config c = config(path, -1);
	struct content s;
	struct renderer *r;

	c.normals = normals;
	c.lod_pixels = 4;
	r = shown(&s, &c);
	assert_int_equal(s.cached != NULL, cached);
	draw(r, &s, &c, out);
	renderer_free(r);
	content_release(&s);
}

static void the_cache_keeps_them_flat(void **state)
{
	const char *cube = write_cube();
	struct image first, again, smooth;

	(void)state;
	frame(cube, MESH_NORMALS_FILE, false, &first);
	frame(cube, MESH_NORMALS_FILE, true, &again);
	assert_int_equal(differing(&first, &again), 0);
	/* Another setting, another entry: not the flat one. */
	frame(cube, MESH_NORMALS_SMOOTH, false, &smooth);
	print_message("flat against smooth: %d of %d pixels differ\n", differing(&first, &smooth),
		      SIZE * SIZE);
	assert_true(differing(&first, &smooth) > SIZE * SIZE / 20);
	image_release(&first);
	image_release(&again);
	image_release(&smooth);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(cube_without_normals_is_flat),
	    cmocka_unit_test(smooth_keeps_the_old_average),
	    cmocka_unit_test(given_normals_stay_unless_flat),
	    cmocka_unit_test(lod_keeps_flat),
	    cmocka_unit_test(skinned_without_normals_plays_flat),
	    cmocka_unit_test(the_cache_keeps_them_flat),
	};
	char cmd[64];
	int failed;

	if (!mkdtemp(dir))
		return 1;
	failed = anim_tests_run("normals", tests, sizeof(tests) / sizeof(tests[0]));
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	if (system(cmd) != 0)
		fprintf(stderr, "could not remove %s\n", dir);
	return failed;
}
