/* Live playback's CPU pose (src/scene/anim/anim_play.h) against the still the
 * loader bakes (--time): for Khronos and assimp models that skin, morph
 * and move nodes, the positions and normals anim_play_pose writes at a
 * clip time equal the mesh loaded posed at that time, with the same fit;
 * so do the GPU path's (its bones and morph targets through the vertex
 * shader's maths in C, tests/oracle/anim_mirror.c). A capsule whose
 * vertices weigh 5 to 8 joints over JOINTS_0 and JOINTS_1 blends all
 * eight as the bake does, and the GPU path refuses it (the shader blends
 * four) with a reason for the journal.
 * A model without animation keeps nothing for playback and loads as it
 * did. */
#include "scene/anim/anim_play.h"
#include "scene/gltf/gltf.h"
#include "oracle/anim_mirror.h"
#include "gltf_joints.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#define ASSIMP	   "/usr/share/assimp/models/glTF2/"
#define MORPH_CUBE ASSIMP "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"
/* More attributes than any model here needs. */
#define SHADER_ROOM 16

static double max_diff(const float *a, const float *b, size_t n)
{
	double d = 0;

	for (size_t i = 0; i < n; i++)
		d = fmax(d, fabs((double)a[i] - b[i]));
	return d;
}

/* The still at t, and the live pose at t from what the same load kept. */
static void pose_equals_still(const char *path, double t)
{
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .time = t, .speed = 1, .play = &play};
	struct mesh still;
	struct anim_pose *pose;
	struct anim_clock c;
	float *pos, *nrm;

	assert_int_equal(gltf_load_options(path, &o, &still), 0);
	assert_non_null(play);
	assert_int_equal(play->vertex_count, still.vertex_count);
	pose = anim_pose_new(play->anim);
	assert_non_null(pose);
	anim_pose_rest(play->anim, pose);
	anim_clock_init(&c, play->anim->clips[0].duration, ANIM_REPEAT, 1.0);
	anim_clock_seek(&c, t);
	anim_pose_apply(play->anim, &play->anim->clips[0], anim_clock_time(&c), pose);
	pos = calloc((size_t)still.vertex_count * 3, sizeof(float));
	nrm = calloc((size_t)still.vertex_count * 3, sizeof(float));
	assert_non_null(pos);
	assert_non_null(nrm);
	anim_play_pose(play, pose, pos, nrm);
	double dp = max_diff(pos, still.positions, (size_t)still.vertex_count * 3);
	double dn = max_diff(nrm, still.normals, (size_t)still.vertex_count * 3);

	if (dp >= 1e-5 || dn >= 1e-4)
		print_message("%s at %.2f s: positions differ by %g, normals by %g\n", path, t, dp,
			      dn);
	assert_true(dp < 1e-5);
	assert_true(dn < 1e-4);
	free(pos);
	free(nrm);
	anim_pose_free(pose);
	anim_play_free(play);
	mesh_release(&still);
}

static void each_time(const char *path)
{
	static const double times[] = {0.0, 0.35, 1.0, 1.7, 2.9};

	if (access(path, R_OK)) {
		print_message("%s: not installed, left out\n", path);
		return;
	}
	for (size_t i = 0; i < sizeof(times) / sizeof(*times); i++)
		pose_equals_still(path, times[i]);
}

static void morph(void **state)
{
	(void)state;
	each_time("tests/corpus/khronos/SimpleMorph.gltf");
	each_time(ASSIMP "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
}

static void skin(void **state)
{
	(void)state;
	each_time("tests/corpus/khronos/RiggedSimple.gltf");
	each_time(ASSIMP "simple_skin/simple_skin.gltf");
}

static void nodes(void **state)
{
	(void)state;
	each_time("tests/corpus/khronos/BoxAnimated.gltf");
	each_time("tests/corpus/khronos/AnimatedTriangle.gltf");
}

/* The GPU path's bones and morph targets, through the shader's maths
 * (tests/oracle/anim_mirror.c), pose the mesh as the CPU path does. */
static void gpu_mirror_at(const char *path, double t)
{
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .time = t, .speed = 1, .play = &play};
	struct mesh still;
	struct anim_pose *pose;
	float *rows, v[3], n[3], weights[ANIM_PLAY_MORPH_MAX];
	double dp = 0, dn = 0;
	const char *why;

	if (access(path, R_OK))
		return;
	assert_int_equal(gltf_load_options(path, &o, &still), 0);
	/* A part without normals of its own takes the CPU path. */
	if (anim_play_gpu_prepare(play, 1000) == -ENOTSUP) {
		print_message("%s: normals generated, the CPU path\n", path);
		anim_play_free(play);
		mesh_release(&still);
		return;
	}
	assert_int_equal(anim_play_gpu_prepare(play, 1), -E2BIG);
	assert_int_equal(anim_play_gpu_prepare(play, 1000), 0);
	assert_int_equal(anim_play_morph_prepare(play, SHADER_ROOM, &why), 0);
	assert_false(play->morphs); /* none left to the CPU */
	pose = anim_pose_new(play->anim);
	anim_pose_apply(play->anim, &play->anim->clips[0], t, pose);
	rows = calloc((size_t)play->bones * 12, sizeof(float));
	anim_play_bones(play, pose, rows);
	anim_play_morph_weights(play, pose, weights);
	for (uint32_t i = 0; i < still.vertex_count; i++) {
		anim_mirror_vertex(play, rows, weights, i, false, v, n);
		for (int k = 0; k < 3; k++) {
			dp = fmax(dp, fabs(v[k] - still.positions[i * 3 + k]));
			dn = fmax(dn, fabs(n[k] - still.normals[i * 3 + k]));
		}
	}
	print_message("%s at %.2f s on the GPU's maths: %u bones, %u morph targets, positions off "
		      "by %g, normals by %g\n",
		      path, t, play->bones, play->morph_targets, dp, dn);
	assert_true(dp < 1e-5 && dn < 1e-4);
	free(rows);
	anim_pose_free(pose);
	anim_play_free(play);
	mesh_release(&still);
}

static void gpu_mirror(void **state)
{
	(void)state;
	gpu_mirror_at("tests/corpus/khronos/RiggedSimple.gltf", 0.9);
	gpu_mirror_at(ASSIMP "simple_skin/simple_skin.gltf", 1.3);
	gpu_mirror_at("tests/corpus/khronos/BoxAnimated.gltf", 1.7);
	gpu_mirror_at(MORPH_CUBE, 1.3);
	gpu_mirror_at(MORPH_CUBE, 3.1);
}

/* Where the targets go: the GPU when their attributes fit the room, else
 * the CPU (morphs left set), said why; a model without targets needs none. */
static void morph_placement(void **state)
{
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .speed = 1, .play = &play};
	struct mesh m;
	const char *why;

	(void)state;
	if (access(MORPH_CUBE, R_OK))
		return;
	assert_int_equal(gltf_load_options(MORPH_CUBE, &o, &m), 0);
	assert_int_equal(anim_play_gpu_prepare(play, 1000), 0);
	assert_int_equal(anim_play_morph_attributes(play), 4); /* two, with normals */
	assert_int_equal(anim_play_morph_prepare(play, 3, &why), -ENOSPC);
	assert_non_null(why);
	assert_int_equal(play->morph_targets, 0);
	assert_true(play->morphs);
	assert_int_equal(anim_play_morph_prepare(play, 4, &why), 0);
	assert_int_equal(play->morph_targets, 2);
	assert_true(play->morph_normals);
	assert_false(play->morphs);
	/* Uploaded again to a smaller GPU: decided again. */
	assert_int_equal(anim_play_morph_prepare(play, 0, &why), -ENOSPC);
	assert_null(play->gpu_morph);
	assert_true(play->morphs);
	anim_play_free(play);
	mesh_release(&m);
	play = NULL;
	assert_int_equal(gltf_load_options("tests/corpus/khronos/RiggedSimple.gltf", &o, &m), 0);
	assert_int_equal(anim_play_gpu_prepare(play, 1000), 0);
	assert_int_equal(anim_play_morph_attributes(play), 0);
	assert_int_equal(anim_play_morph_prepare(play, 0, &why), 0);
	assert_null(why);
	assert_int_equal(play->morph_targets, 0);
	anim_play_free(play);
	mesh_release(&m);
}

/* More targets than the shader adds, or targets on parts of two nodes
 * (two sets of weights): the CPU's, whatever the room. */
static void morph_placement_refused(void **state)
{
	float deltas[3] = {0};
	struct anim_play_part parts[2] = {
	    {.node = 0, .skin = -1, .vertex_count = 1},
	    {.node = 1, .skin = -1, .first_vertex = 1, .vertex_count = 1}};
	struct anim_play p = {.vertex_count = 2, .part_count = 1, .parts = parts};
	const char *why;

	(void)state;
	parts[0].target_count = ANIM_PLAY_MORPH_MAX + 1;
	parts[0].target_positions = deltas;
	assert_int_equal(anim_play_morph_prepare(&p, 100, &why), -E2BIG);
	assert_non_null(why);
	assert_true(p.morphs);
	parts[0].target_count = parts[1].target_count = 1;
	parts[1].target_positions = deltas;
	p.part_count = 2;
	assert_int_equal(anim_play_morph_prepare(&p, 100, &why), -EXDEV);
	assert_non_null(strstr(why, "several nodes"));
	assert_int_equal(p.morph_targets, 0);
	assert_null(p.gpu_morph);
}

/* The CPU pose of the capsule of `sets` joint sets (tests/tools/
 * gltf_joints.c) at t against its still; positions and normals differ by
 * *dp, *dn at most. Also the pose with the last set's weights left out,
 * *dropped off the still: the test's own check that the set moves the
 * vertices. */
static void joints_at(const char *path, int sets, double t, double *dp, double *dn, double *dropped)
{
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .time = t, .speed = 1, .play = &play};
	struct mesh still;
	struct anim_pose *pose;
	float *pos, *nrm;
	size_t n;

	assert_int_equal(gltf_load_options(path, &o, &still), 0);
	assert_non_null(play);
	assert_int_equal(play->influences, 4 * sets);
	n = (size_t)still.vertex_count * 3;
	pose = anim_pose_new(play->anim);
	pos = calloc(n, sizeof(float));
	nrm = calloc(n, sizeof(float));
	assert_true(pose && pos && nrm);
	anim_pose_rest(play->anim, pose);
	anim_pose_apply(play->anim, &play->anim->clips[0], t, pose);
	anim_play_pose(play, pose, pos, nrm);
	*dp = max_diff(pos, still.positions, n);
	*dn = max_diff(nrm, still.normals, n);
	/* A few vertices, as the journal of a failure would want them. */
	for (uint32_t v = 0; v < still.vertex_count; v += still.vertex_count / 3)
		print_message("  vertex %u at %.2f s: live %.6f %.6f %.6f, still %.6f %.6f %.6f\n",
			      v, t, pos[v * 3], pos[v * 3 + 1], pos[v * 3 + 2],
			      still.positions[v * 3], still.positions[v * 3 + 1],
			      still.positions[v * 3 + 2]);
	for (uint32_t v = 0; v < play->vertex_count; v++)
		for (int k = 4 * (sets - 1); k < 4 * sets; k++)
			play->weights[(size_t)v * 4 * sets + k] = 0;
	anim_play_pose(play, pose, pos, nrm);
	*dropped = max_diff(pos, still.positions, n);
	free(pos);
	free(nrm);
	anim_pose_free(pose);
	anim_play_free(play);
	mesh_release(&still);
}

/* Eight joints a vertex (JOINTS_1) and twelve (JOINTS_2): the CPU
 * blends them all, as the bake; the GPU path says no, and why. */
static void joints8(void **state)
{
	static const double times[] = {0.3, 1.0, 1.45}; /* 0: the bind pose */
	char dir[] = "/tmp/mk-joints8-XXXXXX", path[64], path12[64];
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .speed = 1, .play = &play};
	struct mesh sphere, m;
	uint32_t spread = 0, all = 0;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/capsule.glb", dir);
	snprintf(path12, sizeof(path12), "%s/capsule12.glb", dir);
	assert_int_equal(mesh_uv_sphere(&sphere, 16, 12), 0);
	assert_int_equal(gltf_write_joints(path, &sphere, 2), 0);
	assert_int_equal(gltf_write_joints(path12, &sphere, 3), 0);
	for (int sets = 2; sets <= 3; sets++)
		for (size_t i = 0; i < sizeof(times) / sizeof(*times); i++) {
			double dp, dn, dropped;

			joints_at(sets == 2 ? path : path12, sets, times[i], &dp, &dn, &dropped);
			print_message(
			    "capsule of %d joints at %.2f s: positions off by %g, normals "
			    "by %g; without JOINTS_%d off by %g\n",
			    4 * sets, times[i], dp, dn, sets - 1, dropped);
			assert_true(dp < 1e-5);
			assert_true(dn < 1e-4);
			assert_true(dropped > 0.01);
		}
	assert_int_equal(gltf_load_options(path, &o, &m), 0);
	/* Most vertices weigh five joints or more (past 1%), some all eight. */
	for (uint32_t v = 0; v < play->vertex_count; v++) {
		uint32_t used = 0;

		for (int k = 0; k < 8; k++)
			used += play->weights[(size_t)v * 8 + k] > 0.01f;
		spread += used >= 5;
		all += used == 8;
	}
	print_message("capsule: %u of %u vertices weigh 5 joints or more, %u all 8\n", spread,
		      play->vertex_count, all);
	assert_true(spread > play->vertex_count / 2);
	assert_true(all > 0);
	assert_int_equal(anim_play_gpu_prepare(play, 1000), -ERANGE);
	assert_int_equal(play->bones, 0);
	assert_non_null(strstr(anim_play_gpu_why(-ERANGE), "JOINTS_1"));
	anim_play_free(play);
	mesh_release(&m);
	/* Twelve: the GPU path says no too. */
	play = NULL;
	assert_int_equal(gltf_load_options(path12, &o, &m), 0);
	assert_int_equal(play->influences, 12);
	assert_int_equal(anim_play_gpu_prepare(play, 1000), -ERANGE);
	anim_play_free(play);
	mesh_release(&m);
	/* JOINTS_0 alone: four a vertex, the arrays as they always were. */
	play = NULL;
	assert_int_equal(gltf_load_options("tests/corpus/khronos/RiggedSimple.gltf", &o, &m), 0);
	assert_int_equal(play->influences, 4);
	assert_int_equal(anim_play_gpu_prepare(play, 1000), 0);
	anim_play_free(play);
	mesh_release(&m);
	mesh_release(&sphere);
	unlink(path);
	unlink(path12);
	rmdir(dir);
}

/* No animation: nothing kept, and the very mesh a load without it gives. */
static void still_model_unchanged(void **state)
{
	(void)state;
	const char *path = "tests/corpus/khronos/MultipleScenes.gltf";
	struct anim_play *play = (struct anim_play *)1;
	struct gltf_options o = {.pose = true, .speed = 1, .play = &play}, plain = {0};
	struct mesh a, b;

	assert_int_equal(gltf_load_options(path, &o, &a), 0);
	assert_null(play);
	assert_int_equal(gltf_load_options(path, &plain, &b), 0);
	assert_int_equal(a.vertex_count, b.vertex_count);
	assert_memory_equal(a.positions, b.positions, (size_t)a.vertex_count * 3 * sizeof(float));
	assert_memory_equal(a.normals, b.normals, (size_t)a.vertex_count * 3 * sizeof(float));
	mesh_release(&a);
	mesh_release(&b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(morph),	       cmocka_unit_test(skin),
	    cmocka_unit_test(nodes),	       cmocka_unit_test(gpu_mirror),
	    cmocka_unit_test(morph_placement), cmocka_unit_test(morph_placement_refused),
	    cmocka_unit_test(joints8),	       cmocka_unit_test(still_model_unchanged),
	};
	return cmocka_run_group_tests_name("anim_play", tests, NULL, NULL);
}
