/* The still the loader bakes (--time, [scene] time) and live playback's
 * engine are one: a tube that is skinned to a bending joint AND morphed
 * (a target that swells it along its normals and turns them), loaded
 * posed at a clip time t, has the positions and normals anim_play_pose
 * writes at t from what the same load kept for playback: the normals to
 * the bit, the positions within one float rounding (the still rounds the
 * world position once more before its fit). The clip's fit is one for
 * every still of the clip: the engine is fitted as the still is. */
#include "scene/anim/anim_play.h"
#include "scene/gltf/gltf.h"
#include "util/log.h"
#include "gltf_morph.h"

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#define RINGS	 6 /* along y, from -1 to 1 */
#define AROUND	 8
#define VERTICES (RINGS * AROUND)
#define INDICES	 ((RINGS - 1) * AROUND * 6)

/* The binary chunk's views, in order. */
struct tube {
	float pos[VERTICES][3], nrm[VERTICES][3];
	uint8_t joints[VERTICES][4];
	float weights[VERTICES][4];
	uint32_t idx[INDICES];
	float dpos[VERTICES][3], dnrm[VERTICES][3];
	float times[3];
	float rot[3][4]; /* the upper joint about z: 0, 40 degrees, 0 */
	float swell[3];	 /* the target's weight: 0.2, 1, 0 */
};

static void tube_vertex(struct tube *t, int r, int a)
{
	int v = r * AROUND + a;
	double y = -1.0 + 2.0 * r / (RINGS - 1), u = 2 * M_PI * a / AROUND;
	float up = (float)((y + 1) / 2);

	t->nrm[v][0] = (float)cos(u);
	t->nrm[v][2] = (float)sin(u);
	t->pos[v][0] = 0.3f * t->nrm[v][0];
	t->pos[v][1] = (float)y;
	t->pos[v][2] = 0.3f * t->nrm[v][2];
	t->joints[v][1] = 1;
	t->weights[v][0] = 1 - up;
	t->weights[v][1] = up;
	for (int k = 0; k < 3; k++)
		t->dpos[v][k] = 0.2f * t->nrm[v][k];
	t->dnrm[v][1] = 0.4f; /* turned toward +y, unnormalised: the engine normalises */
}

static void tube_fill(struct tube *t)
{
	static const float times[3] = {0, 1, 2}, swell[3] = {0.2f, 1, 0};
	float s = (float)sin(M_PI / 9), c = (float)cos(M_PI / 9);
	const float rot[3][4] = {{0, 0, 0, 1}, {0, 0, s, c}, {0, 0, 0, 1}};
	uint32_t *i = t->idx;

	memset(t, 0, sizeof(*t));
	for (int r = 0; r < RINGS; r++)
		for (int a = 0; a < AROUND; a++)
			tube_vertex(t, r, a);
	for (uint32_t r = 0; r + 1 < RINGS; r++)
		for (uint32_t a = 0; a < AROUND; a++) {
			uint32_t v = r * AROUND + a, w = r * AROUND + (a + 1) % AROUND;

			*i++ = v, *i++ = v + AROUND, *i++ = w;
			*i++ = w, *i++ = v + AROUND, *i++ = w + AROUND;
		}
	memcpy(t->times, times, sizeof(times));
	memcpy(t->rot, rot, sizeof(rot));
	memcpy(t->swell, swell, sizeof(swell));
}

/* Each view of the binary chunk: where it starts and how long it is. */
#define VIEW(field)                                                                                \
	{                                                                                          \
		offsetof(struct tube, field), sizeof(((struct tube *)0)->field)                    \
	}

/* Accessors 0 to 9, one a view: the view's type, component type, count. */
static const char *const accessors[] = {
    "5126,\"count\":%d,\"type\":\"VEC3\",\"min\":[-0.3,-1,-0.3],\"max\":[0.3,1,0.3]",
    "5126,\"count\":%d,\"type\":\"VEC3\"",
    "5121,\"count\":%d,\"type\":\"VEC4\"",
    "5126,\"count\":%d,\"type\":\"VEC4\"",
    "5125,\"count\":%d,\"type\":\"SCALAR\"",
    "5126,\"count\":%d,\"type\":\"VEC3\",\"min\":[-0.2,0,-0.2],\"max\":[0.2,0,0.2]",
    "5126,\"count\":%d,\"type\":\"VEC3\"",
    "5126,\"count\":%d,\"type\":\"SCALAR\",\"min\":[0],\"max\":[2]",
    "5126,\"count\":%d,\"type\":\"VEC4\"",
    "5126,\"count\":%d,\"type\":\"SCALAR\"",
};

/* The JSON: node 0 shows the mesh with skin 0 (joints: nodes 1 and 2, 2
 * the child of 1, tilted about x), the clip bends node 2 and weighs node
 * 0's target. */
static const char head[] =
    "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}],"
    "\"nodes\":[{\"mesh\":0,\"skin\":%d},{\"children\":[2],\"rotation\":[0.1305262,0,0,"
    "0.9914449],\"translation\":[0.5,0,0]},{\"translation\":[0,0.1,0]}],"
    "\"skins\":[{\"joints\":[1,2]}],"
    "\"meshes\":[{\"weights\":[0.5],\"primitives\":[{\"attributes\":{\"POSITION\":0,"
    "\"NORMAL\":1,\"JOINTS_0\":2,\"WEIGHTS_0\":3},\"indices\":4,\"targets\":[{"
    "\"POSITION\":5,\"NORMAL\":6}]}]}],"
    "\"animations\":[{\"samplers\":[{\"input\":7,\"output\":8},{\"input\":7,"
    "\"output\":9}],\"channels\":[{\"sampler\":0,\"target\":{\"node\":2,\"path\":"
    "\"rotation\"}},{\"sampler\":1,\"target\":{\"node\":0,\"path\":\"weights\"}}]}],";

/* The tube as a GLB at path, node 0 showing it with skin `skin` (0: the
 * file's one); bad: vertex AROUND + 3 weighs joint 5 of the skin's two.
 * 0 or -1. */
static int tube_write(const char *path, int skin, bool bad)
{
	static const size_t views[][2] = {VIEW(pos), VIEW(nrm),	 VIEW(joints), VIEW(weights),
					  VIEW(idx), VIEW(dpos), VIEW(dnrm),   VIEW(times),
					  VIEW(rot), VIEW(swell)};
	static const int counts[] = {VERTICES, VERTICES, VERTICES, VERTICES, INDICES,
				     VERTICES, VERTICES, 3,	   3,	     3};
	static struct tube t;
	char json[4096];
	size_t n;

	tube_fill(&t);
	if (bad)
		t.joints[AROUND + 3][1] = 5;
	n = (size_t)snprintf(json, sizeof(json), head, skin);
	n += (size_t)snprintf(json + n, sizeof(json) - n,
			      "\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":[", sizeof(t));
	for (int v = 0; v < 10 && n < sizeof(json); v++)
		n += (size_t)snprintf(json + n, sizeof(json) - n,
				      "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}",
				      v ? "," : "", views[v][0], views[v][1]);
	for (int v = 0; v < 10 && n < sizeof(json); v++) {
		n += (size_t)snprintf(
		    json + n, sizeof(json) - n,
		    "%s{\"bufferView\":%d,\"componentType\":", v ? "," : "],\"accessors\":[", v);
		n += (size_t)snprintf(json + n, sizeof(json) - n, accessors[v], counts[v]);
		n += (size_t)snprintf(json + n, sizeof(json) - n, "}");
	}
	n += (size_t)snprintf(json + n, sizeof(json) - n, "]}");
	if (n >= sizeof(json))
		return -1;
	return gltf_write_glb(path, json, n, &t, sizeof(t));
}

static double max_diff(const float *a, const float *b, size_t n)
{
	double d = 0;

	for (size_t i = 0; i < n; i++)
		d = fmax(d, fabs((double)a[i] - b[i]));
	return d;
}

/* The still at t against anim_play_pose at t; *moved: how far the still's
 * vertices lie from `rest` (NULL: not measured). */
static void still_is_live(const char *path, double t, const float *rest, double *moved)
{
	struct anim_play *play = NULL;
	struct gltf_options o = {.pose = true, .time = t, .speed = 1, .play = &play};
	struct mesh still;
	struct anim_clock c;
	struct anim_pose *pose;
	float pos[VERTICES * 3], nrm[VERTICES * 3];

	assert_int_equal(gltf_load_options(path, &o, &still), 0);
	assert_non_null(play);
	assert_int_equal(still.vertex_count, VERTICES);
	assert_int_equal(play->vertex_count, VERTICES);
	pose = anim_pose_new(play->anim);
	assert_non_null(pose);
	anim_clock_init(&c, play->anim->clips[0].duration, ANIM_REPEAT, 1.0);
	anim_clock_seek(&c, t);
	anim_pose_apply(play->anim, &play->anim->clips[0], anim_clock_time(&c), pose);
	anim_play_pose(play, pose, pos, nrm);
	/* Fitted into the unit sphere: the still's world position is
	 * rounded to a float once before its fit, no more. The normals are
	 * the engine's own, to the bit (the bake's doubles of before were
	 * half a float's epsilon off). */
	assert_true(max_diff(pos, still.positions, VERTICES * 3) <= FLT_EPSILON);
	assert_memory_equal(nrm, still.normals, sizeof(nrm));
	if (moved)
		*moved = max_diff(rest, still.positions, VERTICES * 3);
	anim_pose_free(pose);
	anim_play_free(play);
	mesh_release(&still);
}

static void still_equals_live_pose(void **state)
{
	static const double times[] = {0.4, 1.0, 1.5, 2.7};
	char dir[] = "/tmp/mk-bake-XXXXXX", path[64];
	struct gltf_options o = {.pose = true, .speed = 1};
	struct mesh rest;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/tube.glb", dir);
	assert_int_equal(tube_write(path, 0, false), 0);
	assert_int_equal(gltf_load_options(path, &o, &rest), 0);
	still_is_live(path, 0.0, rest.positions, NULL);
	for (size_t i = 0; i < sizeof(times) / sizeof(*times); i++) {
		double moved;

		still_is_live(path, times[i], rest.positions, &moved);
		/* The pose is not the one at 0 s: the comparison is not of
		 * two rest poses. */
		assert_true(moved > 0.01);
	}
	mesh_release(&rest);
	unlink(path);
	rmdir(dir);
}

/* A skin the engine cannot pose refuses the model with one error that
 * names the file, the field and what was expected (the bake's doubles
 * refused these; the engine must, not read past its arrays). */
static void bad_skin_refused(void **state)
{
	static const struct {
		int skin;
		bool bad;
		const char *words;
	} cases[] = {
	    {7, false, "nodes[0].skin: skin 7 does not exist, expected below 1"},
	    {0, true, "JOINTS_0: vertex 11 names joint 5, expected one of the skin's 2"},
	};
	char dir[] = "/tmp/mk-bake-XXXXXX", path[64], err[512];

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/tube.glb", dir);
	for (size_t i = 0; i < sizeof(cases) / sizeof(*cases); i++) {
		struct gltf_options o = {.speed = 1};
		struct mesh m;

		assert_int_equal(tube_write(path, cases[i].skin, cases[i].bad), 0);
		log_clear_last_error();
		assert_int_not_equal(gltf_load_options(path, &o, &m), 0);
		log_last_error(err, sizeof(err));
		assert_non_null(strstr(err, path));
		assert_non_null(strstr(err, cases[i].words));
	}
	unlink(path);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(still_equals_live_pose),
	    cmocka_unit_test(bad_skin_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
