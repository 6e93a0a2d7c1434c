/* glTF animation's pure maths (src/scene/anim/anim.h): the samplers against
 * values worked by hand, slerp the shorter way, the loop modes, a clock
 * run forward by a year, and node evaluation parents first without
 * recursion; and a glTF file's animations read into that model, a
 * malformed one refused with a warning while the still model loads. */
#include "scene/anim/anim.h"
#include "scene/gltf/gltf.h"

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

#define NEAR(a, b) assert_true(fabs((double)(a) - (double)(b)) < 1e-5)

static double at(struct anim_sampler *s, double t)
{
	float v;

	anim_sampler_eval(s, false, t, &v);
	return v;
}

static void step_and_linear(void **state)
{
	(void)state;
	float in[] = {0, 1, 2}, out[] = {0, 10, 20};
	struct anim_sampler s = {in, out, 3, 1, ANIM_STEP};

	assert_null(anim_sampler_check(&s));
	NEAR(at(&s, -1), 0); // before the first key: the first value
	NEAR(at(&s, 0.5), 0);
	NEAR(at(&s, 1.0), 10);
	NEAR(at(&s, 1.99), 10);
	NEAR(at(&s, 5), 20); // after the last: the last
	s.interp = ANIM_LINEAR;
	NEAR(at(&s, 0.25), 2.5);
	NEAR(at(&s, 1.5), 15);
	NEAR(at(&s, 2.0), 20);
	struct anim_sampler one = {in, out, 1, 1, ANIM_LINEAR};
	NEAR(at(&one, 7), 0);
}

static void cubicspline_by_hand(void **state)
{
	(void)state;
	// Keys at 0 and 2: (in-tangent, value, out-tangent) each.
	float in[] = {0, 2}, out[] = {99, 1, 3, -2, 5, 99};
	struct anim_sampler s = {in, out, 2, 1, ANIM_CUBICSPLINE};

	// p(u) = h00 v0 + td h10 b0 + h01 v1 + td h11 a1, td = 2:
	// u = 0.5: 0.5*1 + 2*0.125*3 + 0.5*5 + 2*(-0.125)*(-2) = 4.25
	NEAR(at(&s, 1.0), 4.25);
	// u = 0.25: 0.84375*1 + 0.28125*3 + 0.15625*5 + (-0.09375)*(-2) = 2.65625
	NEAR(at(&s, 0.5), 2.65625);
	NEAR(at(&s, 0), 1);
	NEAR(at(&s, 2), 5);
	NEAR(at(&s, 3), 5);
}

static void slerp_the_shorter_way(void **state)
{
	(void)state;
	double h = sqrt(0.5);
	// Identity to a quarter turn about z, the second key given as its
	// negative: the same rotation, and the long way would spin 270 degrees.
	float in[] = {0, 1}, out[] = {0, 0, 0, 1, 0, 0, (float)-h, (float)-h};
	struct anim_sampler s = {in, out, 2, 4, ANIM_LINEAR};
	float q[4];

	anim_sampler_eval(&s, true, 0.5, q); // 45 degrees about z
	NEAR(q[0], 0);
	NEAR(q[1], 0);
	NEAR(q[2], sin(M_PI / 8));
	NEAR(q[3], cos(M_PI / 8));
	anim_sampler_eval(&s, true, 0.25, q); // constant speed: 22.5 degrees
	NEAR(q[2], sin(M_PI / 16));
	NEAR(q[3], cos(M_PI / 16));
	// A CUBICSPLINE rotation comes out of unit length.
	float cin[] = {0, 1},
	      cout[] = {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
	struct anim_sampler c = {cin, cout, 2, 4, ANIM_CUBICSPLINE};
	anim_sampler_eval(&c, true, 0.5, q);
	NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1);
	NEAR(q[2], q[3]); // halfway to a half turn: a quarter turn about z
}

static void bad_samplers(void **state)
{
	(void)state;
	float in[] = {0, 1, 1}, out[] = {0, 1, 2};
	struct anim_sampler s = {in, out, 3, 1, ANIM_LINEAR};

	assert_non_null(anim_sampler_check(&s)); // not strictly increasing
	in[2] = -1;
	assert_non_null(anim_sampler_check(&s));
	in[2] = 2;
	out[1] = NAN;
	assert_non_null(anim_sampler_check(&s));
	s.count = 0;
	assert_non_null(anim_sampler_check(&s));
}

static double seek(enum anim_loop loop, double speed, double seconds)
{
	struct anim_clock c;

	anim_clock_init(&c, 2.0, loop, speed);
	anim_clock_seek(&c, seconds);
	return anim_clock_time(&c);
}

static void loop_modes(void **state)
{
	(void)state;
	NEAR(seek(ANIM_REPEAT, 1, 0.5), 0.5);
	NEAR(seek(ANIM_REPEAT, 1, 5), 1.0);
	NEAR(seek(ANIM_REPEAT, 2, 1.25), 0.5);
	NEAR(seek(ANIM_ONCE, 1, 1.5), 1.5);
	NEAR(seek(ANIM_ONCE, 1, 5), 2.0); // holds the last frame
	NEAR(seek(ANIM_PINGPONG, 1, 2.5), 1.5);
	NEAR(seek(ANIM_PINGPONG, 1, 3), 1.0);
	NEAR(seek(ANIM_PINGPONG, 1, 4.5), 0.5);

	struct anim_clock c;
	anim_clock_init(&c, 2.0, ANIM_ONCE, 1);
	assert_true(anim_clock_moving(&c));
	anim_clock_advance(&c, 1900000000ull);
	assert_true(anim_clock_moving(&c));
	anim_clock_advance(&c, 200000000ull);
	assert_false(anim_clock_moving(&c));
	NEAR(anim_clock_time(&c), 2.0);
	anim_clock_init(&c, 0, ANIM_REPEAT, 1); // one key: a still
	anim_clock_advance(&c, 5000000000ull);
	assert_false(anim_clock_moving(&c));
	NEAR(anim_clock_time(&c), 0);
}

/* STEP keys alone hold the pose between keys: the kiosk draws no frame
 * meanwhile; anything that interpolates moves every frame. */
static void step_clips_hold(void **state)
{
	(void)state;
	float in[] = {0, 1, 2.5f}, out[] = {0, 1, 2}, lin_in[] = {0, 2}, lin_out[] = {0, 1};
	float one_in[] = {0}, one_out[] = {5};
	struct anim_sampler s[3] = {{in, out, 3, 1, ANIM_STEP},
				    {one_in, one_out, 1, 1, ANIM_LINEAR},
				    {lin_in, lin_out, 2, 1, ANIM_LINEAR}};
	struct anim_clip c = {.samplers = s, .sampler_count = 2, .duration = 2.5};

	NEAR(anim_clip_hold(&c, 0.2, false), 0.8);
	NEAR(anim_clip_hold(&c, 1.0, false), 1.5); /* the next key is the end */
	NEAR(anim_clip_hold(&c, 2.0, true), 1.0);  /* back below the key at 1 */
	NEAR(anim_clip_hold(&c, 0.5, true), 0.5);  /* before the key at 1: the start */
	NEAR(anim_clip_hold(&c, 2.5, false), 0.0);
	c.sampler_count = 3; /* one that interpolates: every frame */
	NEAR(anim_clip_hold(&c, 0.2, false), 0.0);
}

static void a_year_keeps_its_nanoseconds(void **state)
{
	(void)state;
	const uint64_t hour = 3600000000000ull, year = 365ull * 24 * hour;
	const uint64_t frame = 16666667ull; // 60 Hz
	struct anim_clock c;

	// A clip of 1.7 s, speed 1: the phase after a year is the exact
	// remainder, and a frame then still moves it by exactly one frame.
	anim_clock_init(&c, 1.7, ANIM_REPEAT, 1.0);
	for (uint64_t t = 0; t < year; t += hour)
		anim_clock_advance(&c, hour);
	assert_int_equal(c.phase_ns, year % 1700000000ull);
	uint64_t before = c.phase_ns;
	anim_clock_advance(&c, frame);
	assert_int_equal((c.phase_ns + 1700000000ull - before) % 1700000000ull, frame);

	// Pingpong at speed 0.7: each step's fraction of a nanosecond is
	// carried, so a year of hours lands within a few nanoseconds of the
	// exact phase (the double product itself rounds 1 in 2^52).
	anim_clock_init(&c, 1.7, ANIM_PINGPONG, 0.7);
	for (uint64_t t = 0; t < year; t += hour)
		anim_clock_advance(&c, hour);
	uint64_t want = (year / 10 * 7) % 3400000000ull;
	assert_true(llabs((long long)c.phase_ns - (long long)want) < 16);

	// A day of 60 Hz frames at speed 0.7 (5 million steps): the same.
	anim_clock_init(&c, 1.7, ANIM_REPEAT, 0.7);
	uint64_t frames = 24 * 3600 * 60ull;
	for (uint64_t i = 0; i < frames; i++)
		anim_clock_advance(&c, frame);
	want = (uint64_t)((frames * frame) / 10 * 7) % 1700000000ull;
	assert_true(llabs((long long)c.phase_ns - (long long)want) < 16);

	// --time of a year gives the phase a year of frames gives.
	anim_clock_init(&c, 1.7, ANIM_REPEAT, 1.0);
	anim_clock_seek(&c, 365.0 * 24 * 3600 + 0.25);
	assert_int_equal(c.phase_ns, (year + 250000000ull) % 1700000000ull);
}

static struct anim_node node(int parent)
{
	struct anim_node n = {.parent = parent};

	n.rest.r[3] = 1;
	n.rest.s[0] = n.rest.s[1] = n.rest.s[2] = 1;
	return n;
}

static void nodes_parents_first(void **state)
{
	(void)state;
	// Node 0 is the child of 1, which is the child of 2: listed children
	// first, as glTF allows.
	struct anim_node nodes[3] = {node(1), node(2), node(-1)};
	int order[3];
	struct mesh_anim a = {.nodes = nodes, .node_count = 3, .order = order};

	nodes[2].rest.t[0] = 1;
	nodes[1].rest.r[2] = (float)sqrt(0.5); // a quarter turn about z
	nodes[1].rest.r[3] = (float)sqrt(0.5);
	nodes[0].rest.t[1] = 1;
	assert_true(anim_order(nodes, 3, order));
	assert_int_equal(order[0], 2);
	assert_int_equal(order[1], 1);
	assert_int_equal(order[2], 0);
	struct anim_pose *p = anim_pose_new(&a);
	float world[3][16];
	anim_pose_world(&a, p, world);
	// T(1,0,0) Rz(90) T(0,1,0): (0,1,0) turns to (-1,0,0), then + (1,0,0).
	NEAR(world[0][12], 0);
	NEAR(world[0][13], 0);
	NEAR(world[0][0], 0); // x axis turned onto y
	NEAR(world[0][1], 1);
	anim_pose_free(p);

	nodes[2].parent = 0; // a cycle
	assert_false(anim_order(nodes, 3, order));
	nodes[2].parent = 7; // no such node
	assert_false(anim_order(nodes, 3, order));
}

static void a_deep_chain_costs_a_loop(void **state)
{
	(void)state;
	size_t n = 200000;
	struct anim_node *nodes = calloc(n, sizeof(*nodes));
	int *order = calloc(n, sizeof(*order));

	assert_non_null(nodes);
	assert_non_null(order);
	for (size_t i = 0; i < n; i++) // node i's parent is i + 1: reversed
		nodes[i] = node(i + 1 < n ? (int)i + 1 : -1);
	for (size_t i = 0; i < n; i++)
		nodes[i].rest.t[0] = 1;
	assert_true(anim_order(nodes, n, order));
	for (size_t k = 0; k < n; k++)
		assert_int_equal(order[k], (int)(n - 1 - k));
	struct mesh_anim a = {.nodes = nodes, .node_count = n, .order = order};
	struct anim_pose *p = anim_pose_new(&a);
	float(*world)[16] = calloc(n, sizeof(*world));
	assert_non_null(world);
	anim_pose_world(&a, p, world);
	NEAR(world[0][12], (double)n);
	anim_pose_free(p);
	free(world);
	free(nodes);
	free(order);
}

static void clips_over_the_rest_pose(void **state)
{
	(void)state;
	struct anim_node nodes[2] = {node(-1), node(0)};
	int order[2];
	float rest_w[2] = {0.5f, 0.25f};
	nodes[1].weight_offset = 0;
	nodes[1].weight_count = 2;
	float tin[] = {0, 2}, tout[] = {0, 0, 0, 4, 0, 0};
	float win[] = {0, 1}, wout[] = {0, 0, 1, 1};
	struct anim_sampler samplers[2] = {{tin, tout, 2, 3, ANIM_LINEAR},
					   {win, wout, 2, 2, ANIM_STEP}};
	struct anim_channel channels[2] = {{0, ANIM_TRANSLATION, 0}, {1, ANIM_WEIGHTS, 1}};
	char name[] = "Walk";
	struct anim_clip clip = {name, samplers, 2, channels, 2, 2.0};
	struct mesh_anim a = {.nodes = nodes,
			      .node_count = 2,
			      .order = order,
			      .rest_weights = rest_w,
			      .weight_total = 2,
			      .clips = &clip,
			      .clip_count = 1};

	assert_true(anim_order(nodes, 2, order));
	struct anim_pose *p = anim_pose_new(&a), *q = anim_pose_new(&a);
	NEAR(p->weights[0], 0.5); // the rest pose's weights
	anim_pose_apply(&a, &clip, 1.0, p);
	NEAR(p->local[0].t[0], 2);
	NEAR(p->weights[0], 1);
	NEAR(p->weights[1], 1);
	// The crossfade halfway from the rest pose to that.
	anim_pose_blend(&a, q, p, 0.5);
	NEAR(q->local[0].t[0], 1);
	NEAR(q->weights[0], 0.75);
	NEAR(q->weights[1], 0.625);
	float world[2][16];
	anim_pose_world(&a, p, world);
	NEAR(world[1][12], 2); // the child follows its parent
	anim_pose_free(p);
	anim_pose_free(q);

	assert_int_equal(anim_clip_find(&a, "auto"), 0);
	assert_int_equal(anim_clip_find(&a, "Walk"), 0);
	assert_int_equal(anim_clip_find(&a, "0"), 0);
	assert_int_equal(anim_clip_find(&a, "off"), -1);
	assert_int_equal(anim_clip_find(&a, "1"), -2);
	assert_int_equal(anim_clip_find(&a, "Run"), -2);
}

/* A small animated glTF, written here: a root node moved by a LINEAR
 * translation, its child (a morphing triangle) turned by a STEP rotation
 * and its two morph weights animated; a second, unnamed clip. `extra`
 * replaces the first sampler's interpolation, `rot_sampler` the rotation
 * channel's sampler, to make broken files. */
static void b64(FILE *f, const unsigned char *p, size_t n)
{
	static const char t[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

	for (size_t i = 0; i < n; i += 3) {
		unsigned v = (unsigned)p[i] << 16 | (i + 1 < n ? (unsigned)p[i + 1] << 8 : 0) |
			     (i + 2 < n ? p[i + 2] : 0);

		fputc(t[v >> 18 & 63], f);
		fputc(t[v >> 12 & 63], f);
		fputc(i + 1 < n ? t[v >> 6 & 63] : '=', f);
		fputc(i + 2 < n ? t[v & 63] : '=', f);
	}
}

static void write_animated(const char *path, const char *interp, int rot_sampler)
{
	double h = sqrt(0.5);
	float data[] = {0, 0, 0, 1, 0, 0, 0,	    1,	      0,	  /* 0: positions */
			0, 1, 2,					  /* 36: times */
			0, 0, 0, 1, 0, 0, 2,	    0,	      0,	  /* 48: translations */
			0, 0, 0, 1, 0, 0, (float)h, (float)h, 0, 0, 1, 0, /* 84: rotations */
			0, 0, 1, 0, 1, 1,				  /* 132: weights */
			0, 0, 1, 0, 0, 1, 0,	    0,	      1, 1, 0, 0,
			1, 0, 0, 1, 0, 0}; /* 156: targets */
	FILE *f = fopen(path, "w");

	assert_non_null(f);
	fprintf(f,
		"{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
		"\"nodes\":[{\"children\":[1],\"translation\":[0,0,5]},{\"mesh\":0}],"
		"\"meshes\":[{\"weights\":[0.5,0],\"primitives\":[{\"attributes\":"
		"{\"POSITION\":0},\"targets\":[{\"POSITION\":5},{\"POSITION\":6}]}]}],"
		"\"buffers\":[{\"byteLength\":%zu,\"uri\":\"data:application/"
		"octet-stream;base64,",
		sizeof(data));
	b64(f, (const unsigned char *)data, sizeof(data));
	fprintf(f, "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":%zu}],", sizeof(data));
	fprintf(f, "\"accessors\":["
		   "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
		   "\"min\":[0,0,0],\"max\":[1,1,0]},"
		   "{\"bufferView\":0,\"byteOffset\":36,\"componentType\":5126,\"count\":3,"
		   "\"type\":\"SCALAR\",\"min\":[0],\"max\":[2]},"
		   "{\"bufferView\":0,\"byteOffset\":48,\"componentType\":5126,\"count\":3,"
		   "\"type\":\"VEC3\"},"
		   "{\"bufferView\":0,\"byteOffset\":84,\"componentType\":5126,\"count\":3,"
		   "\"type\":\"VEC4\"},"
		   "{\"bufferView\":0,\"byteOffset\":132,\"componentType\":5126,\"count\":6,"
		   "\"type\":\"SCALAR\"},"
		   "{\"bufferView\":0,\"byteOffset\":156,\"componentType\":5126,\"count\":3,"
		   "\"type\":\"VEC3\"},"
		   "{\"bufferView\":0,\"byteOffset\":192,\"componentType\":5126,\"count\":3,"
		   "\"type\":\"VEC3\"}],");
	fprintf(f,
		"\"animations\":[{\"name\":\"Move\",\"samplers\":["
		"{\"input\":1,\"output\":2,\"interpolation\":\"%s\"},"
		"{\"input\":1,\"output\":3,\"interpolation\":\"STEP\"},"
		"{\"input\":1,\"output\":4}],\"channels\":["
		"{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"translation\"}},"
		"{\"sampler\":%d,\"target\":{\"node\":1,\"path\":\"rotation\"}},"
		"{\"sampler\":2,\"target\":{\"node\":1,\"path\":\"weights\"}}]},"
		"{\"samplers\":[{\"input\":1,\"output\":2}],\"channels\":["
		"{\"sampler\":0,\"target\":{\"node\":1,\"path\":\"translation\"}}]}]}",
		interp, rot_sampler);
	fclose(f);
}

static struct mesh_anim *load_anim(const char *path, int *ret)
{
	struct mesh mesh;
	struct mesh_anim *a = (struct mesh_anim *)1; // the loader must clear it
	struct gltf_options o = {.anim = &a};

	*ret = gltf_load_options(path, &o, &mesh);
	if (*ret == 0)
		mesh_release(&mesh);
	return a;
}

static void reads_a_files_animations(void **state)
{
	(void)state;
	char path[] = "/tmp/mk-anim-XXXXXX.gltf";
	int fd = mkstemps(path, 5), ret;

	assert_true(fd >= 0);
	close(fd);
	write_animated(path, "LINEAR", 1);
	struct mesh_anim *a = load_anim(path, &ret);
	assert_int_equal(ret, 0);
	assert_non_null(a);
	assert_int_equal(a->node_count, 2);
	assert_int_equal(a->nodes[1].parent, 0);
	assert_int_equal(a->nodes[1].weight_count, 2);
	NEAR(a->rest_weights[0], 0.5); // the mesh's default weights
	NEAR(a->nodes[0].rest.t[2], 5);
	assert_int_equal(a->clip_count, 2);
	assert_string_equal(a->clips[0].name, "Move");
	assert_null(a->clips[1].name);
	NEAR(a->clips[0].duration, 2);
	assert_int_equal(a->clips[0].channel_count, 3);
	assert_int_equal(anim_clip_find(a, "Move"), 0);
	assert_int_equal(anim_clip_find(a, "1"), 1);

	struct anim_pose *p = anim_pose_new(a);
	assert_non_null(p);
	anim_pose_apply(a, &a->clips[0], 1.5, p);
	NEAR(p->local[0].t[0], 1.5);	   // LINEAR between (1,0,0) and (2,0,0)
	NEAR(p->local[0].t[2], 0);	   // the channel replaces the rest translation
	NEAR(p->local[1].r[2], sqrt(0.5)); // STEP: the key at 1 s holds
	NEAR(p->weights[0], 1);		   // (1,0) to (1,1), halfway
	NEAR(p->weights[1], 0.5);
	anim_pose_free(p);
	mesh_anim_free(a);

	// Posed at 1.5 s, fitted to the box of the whole clip: inside the
	// unit sphere, the clips kept.
	struct mesh posed;
	struct gltf_options po = {.anim = &a, .pose = true, .time = 1.5, .speed = 1};
	assert_int_equal(gltf_load_options(path, &po, &posed), 0);
	assert_non_null(a);
	for (uint32_t i = 0; i < posed.vertex_count; i++) {
		const float *v = posed.positions + i * 3;
		assert_true(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= 1.0001f);
	}
	mesh_release(&posed);
	mesh_anim_free(a);
	po.animation = "Run"; // a clip the file lacks: an error
	assert_int_equal(gltf_load_options(path, &po, &posed), -EINVAL);
	assert_null(a);

	// A malformed animation is a warning: the still model loads.
	write_animated(path, "SMOOTH", 1);
	a = load_anim(path, &ret);
	assert_int_equal(ret, 0);
	assert_null(a);
	write_animated(path, "LINEAR", 0); // rotation from a VEC3 sampler
	a = load_anim(path, &ret);
	assert_int_equal(ret, 0);
	assert_null(a);
	write_animated(path, "CUBICSPLINE", 1); // 3 values a key, not 9
	a = load_anim(path, &ret);
	assert_int_equal(ret, 0);
	assert_null(a);
	unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(step_and_linear),
	    cmocka_unit_test(cubicspline_by_hand),
	    cmocka_unit_test(slerp_the_shorter_way),
	    cmocka_unit_test(bad_samplers),
	    cmocka_unit_test(loop_modes),
	    cmocka_unit_test(step_clips_hold),
	    cmocka_unit_test(a_year_keeps_its_nanoseconds),
	    cmocka_unit_test(nodes_parents_first),
	    cmocka_unit_test(a_deep_chain_costs_a_loop),
	    cmocka_unit_test(clips_over_the_rest_pose),
	    cmocka_unit_test(reads_a_files_animations),
	};
	return cmocka_run_group_tests_name("anim", tests, NULL, NULL);
}
