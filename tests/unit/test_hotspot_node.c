/* A hotspot given by a node (node = NAME) is drawn at the node's world
 * origin and follows it when the model plays. The model: an ellipsoid
 * (radii 8, 2, 2 about (10, -3, 1), as test_hotspot_place.c's) whose node
 * has a child "pivot" at the ellipsoid's centre turned by the clip about
 * z (0 at 0 s, 45 degrees at 1 s), and under it "tip" 4 along x and 2.5
 * in front. The tip's origin is worked out here from those numbers, and
 * projected by a reference of the documented camera (none of the
 * renderer's matrices): the green dot's pixel centre is within 2 pixels
 * of it at --time 0 and at --time 1, where it has moved. At rest the node
 * hotspot lands exactly where a point = hotspot at the same place does;
 * from the prepared-mesh cache too. A node the model lacks is said
 * (file, line, name) and only that hotspot is dropped. */
#include "offscreen.h"
#include "config/settings.h"
#include "content/content.h"
#include "gltf_write.h"
#include "hotspot_fixture.h"
#include "render/render.h"
#include "scene/mesh/mesh.h"
#include "util/image.h"
#include "util/log.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#define W 640
#define H 480

static const double centre[3] = {10, -3, 1}, radii[3] = {8, 2, 2};
/* The tip under the pivot, in the pivot's frame. */
static const double tip[3] = {4, 0, 2.5};

static void write_model(const char *path)
{
	struct gltf_write_opts o = {.index_bytes = 4, .with_normals = 1, .bad_index = -1};
	struct mesh s;

	o.node = "\"name\":\"body\",\"children\":[1]";
	o.extra_nodes = "{\"name\":\"pivot\",\"translation\":[10,-3,1],\"children\":[2]},"
			"{\"name\":\"tip\",\"translation\":[4,0,2.5]}";
	o.with_anim = 1;
	o.anim_node = 1;
	assert_int_equal(mesh_uv_sphere(&s, 96, 48), 0);
	for (uint32_t i = 0; i < s.vertex_count * 3; i++)
		s.positions[i] = (float)(centre[i % 3] + radii[i % 3] * s.positions[i]);
	assert_int_equal(gltf_write(path, &s, &o), 0);
	mesh_release(&s);
}

/* The tip's world origin at t seconds (0 to 1: the clip turns the pivot
 * linearly, in its quaternion, from 0 to 45 degrees about z). */
static void tip_at(double t, double out[3])
{
	double a = t * M_PI / 4;

	out[0] = centre[0] + tip[0] * cos(a) - tip[1] * sin(a);
	out[1] = centre[1] + tip[0] * sin(a) + tip[1] * cos(a);
	out[2] = centre[2] + tip[2];
}

/* File coordinates to pixels from the documented camera (the loader's
 * fit: the box's centre, the farthest vertex 8 away; a 30 degree
 * vertical field of view at the distance where the unit sphere with a
 * margin of 1.08 fills the height), at yaw 0. */
static void reference(const double p[3], double out[2])
{
	double half_fov = 15 * M_PI / 180, dist = 1.08 / sin(half_fov), f = 1 / tan(half_fov);
	double q[3], depth;

	for (int k = 0; k < 3; k++)
		q[k] = (p[k] - centre[k]) / 8.0;
	depth = dist - q[2];
	out[0] = W / 2.0 + f * q[0] / depth * H / 2.0;
	out[1] = H / 2.0 - f * q[1] / depth * H / 2.0;
}

static void add_hotspot(struct options *o, const char *name, const char *node, const double *p)
{
	struct hotspot *h = &o->content.hotspots.items[o->content.hotspots.count++];

	hotspot_init(h, name, 10 + o->content.hotspots.count);
	snprintf(h->file, sizeof(h->file), "/m/ellipsoid.ini");
	if (node)
		snprintf(h->node, sizeof(h->node), "%s", node);
	if (p) {
		h->has_point = true;
		memcpy(h->point, p, sizeof(h->point));
	}
	h->color[0] = 0, h->color[1] = 1, h->color[2] = 0, h->color[3] = 1;
}

struct rig {
	char dir[32], model[96], grey[96];
	struct display *d;
	struct renderer *r;
	struct options o;
};

static void rig_open(struct rig *g)
{
	struct image img;

	snprintf(g->dir, sizeof(g->dir), "/tmp/mk-hotspot-node-XXXXXX");
	assert_non_null(mkdtemp(g->dir));
	snprintf(g->model, sizeof(g->model), "%s/ellipsoid.gltf", g->dir);
	snprintf(g->grey, sizeof(g->grey), "%s/grey.png", g->dir);
	write_model(g->model);
	assert_int_equal(image_alloc(&img, 4, 4), 0);
	memset(img.rgba, 90, 64);
	assert_int_equal(image_write_png(g->grey, &img), 0);
	image_release(&img);
	setenv("XDG_CACHE_HOME", g->dir, 1);
	g->d = offscreen_open(W, H);
	g->r = g->d ? renderer_new(&g->d->gl, NULL) : NULL;
	assert_non_null(g->r);
	option_defaults(&g->o);
	g->o.content.model = g->model;
	g->o.content.matcap = g->grey;
	g->o.content.zoom = 1; /* the camera alone: no fit's zoom */
	g->o.content.pitch = 0;
	g->o.content.yaw = 0;
}

static void rig_close(struct rig *g)
{
	char cmd[64];

	renderer_free(g->r);
	unsetenv("XDG_CACHE_HOME");
	snprintf(cmd, sizeof(cmd), "rm -rf %s", g->dir);
	assert_int_equal(system(cmd), 0);
}

static void load(struct rig *g, struct content *s)
{
	assert_int_equal(content_load(s, &g->o.content, true), 0);
	assert_int_equal(content_prepare(s, &g->o.content, W, H), 0);
	assert_int_equal(content_upload(s, g->r), 0);
	assert_int_equal(renderer_set_mode(g->r, g->o.content.mode, false), 0);
}

/* The dot drawn from s against the reference of p. */
static void drawn_at(struct rig *g, const struct content *s, const double p[3], const char *what)
{
	struct view v = content_view(&g->o.content);
	double want[2], got[2] = {0, 0};
	struct image f;

	v.zoom = (float)s->zoom;
	renderer_draw(g->r, &v, W, H);
	assert_int_equal(g->d->read_frame(g->d, &f), 0);
	reference(p, want);
	assert_true(dot_centre(&f, got) > 20);
	image_release(&f);
	print_message("%s: drawn (%.2f, %.2f), reference (%.2f, %.2f)\n", what, got[0], got[1],
		      want[0], want[1]);
	if (fabs(got[0] - want[0]) > 2 || fabs(got[1] - want[1]) > 2)
		fail_msg("%s: the node's dot is drawn at (%.2f, %.2f), the reference projects "
			 "the node's origin to (%.2f, %.2f)",
			 what, got[0], got[1], want[0], want[1]);
}

static void follows_its_node(void **state)
{
	struct rig g;
	struct content s;
	double p0[3], p1[3];

	(void)state;
	rig_open(&g);
	tip_at(0, p0);
	tip_at(1, p1);
	add_hotspot(&g.o, "tip", "tip", NULL);
	add_hotspot(&g.o, "same", NULL, p0);
	g.o.content.anim_time = 0;
	load(&g, &s);
	assert_int_equal(s.hotspot_count, 2);
	for (int k = 0; k < 3; k++)
		assert_true(fabsf(s.hotspots[0].point[k] - s.hotspots[1].point[k]) < 1e-5f);
	drawn_at(&g, &s, p0, "--time 0");
	/* From the cache's entry: the node's name and origin are kept. */
	content_release(&s);
	load(&g, &s);
	assert_non_null(s.cached);
	assert_int_equal(s.hotspot_count, 2);
	drawn_at(&g, &s, p0, "--time 0, cached");
	content_release(&s);
	/* A second into the clip the pivot has turned 45 degrees: the dot
	 * moved with the tip, by far more than the 2 pixels allowed. */
	g.o.content.hotspots.count = 1;
	g.o.content.anim_time = 1;
	load(&g, &s);
	assert_int_equal(s.hotspot_count, 1);
	drawn_at(&g, &s, p1, "--time 1");
	content_release(&s);
	rig_close(&g);
}

/* The live kiosk: the model plays, and each frame's pose (kiosk_anim.c:
 * play_ops->pose, then content_hotspots_follow) moves the dot with the
 * tip, to where the --time still of the same moment has it. */
static void follows_its_node_while_playing(void **state)
{
	struct rig g;
	struct content s;
	struct anim_pose *pose;
	double p[3];

	(void)state;
	rig_open(&g);
	add_hotspot(&g.o, "tip", "tip", NULL);
	g.o.content.anim_live = true;
	g.o.content.anim_time = -1;
	load(&g, &s);
	assert_non_null(s.play);
	assert_non_null(s.play_ops);
	assert_int_equal(s.hotspot_count, 1);
	pose = anim_pose_new(s.play->anim);
	assert_non_null(pose);
	for (int i = 0; i <= 4; i++) {
		double t = i / 4.0;
		char what[32];

		anim_pose_rest(s.play->anim, pose);
		anim_pose_apply(s.play->anim, &s.play->anim->clips[0], t, pose);
		s.play_ops->pose(&s, g.r, pose);
		content_hotspots_follow(&s, g.r);
		tip_at(t, p);
		snprintf(what, sizeof(what), "playing, %.2f s", t);
		drawn_at(&g, &s, p, what);
	}
	anim_pose_free(pose);
	content_release(&s);
	rig_close(&g);
}

static void unknown_node_is_said(void **state)
{
	struct rig g;
	struct content s;
	double p0[3];
	char err[300];

	(void)state;
	rig_open(&g);
	tip_at(0, p0);
	add_hotspot(&g.o, "gone", "no_such_node", NULL);
	add_hotspot(&g.o, "same", NULL, p0);
	g.o.content.anim_time = 0;
	log_clear_last_error();
	load(&g, &s);
	/* Only the one naming no node is dropped; the point is drawn. */
	assert_int_equal(s.hotspot_count, 1);
	assert_int_equal(s.hotspot_source[0], 1);
	log_last_error(err, sizeof(err));
	print_message("%s\n", err);
	assert_non_null(strstr(err, "/m/ellipsoid.ini:11: [hotspot.gone] node = no_such_node"));
	assert_non_null(strstr(err, "no node of that name"));
	drawn_at(&g, &s, p0, "the point beside it");
	content_release(&s);
	rig_close(&g);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(follows_its_node),
	    cmocka_unit_test(follows_its_node_while_playing),
	    cmocka_unit_test(unknown_node_is_said),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
