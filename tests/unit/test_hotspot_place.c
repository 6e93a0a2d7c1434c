/* A hotspot is drawn where the camera puts its point: an ellipsoid (radii
 * 8, 2, 2 about (10, -3, 1), so the loader's centring and scale matter)
 * with a green dot on its surface, drawn at 640x480 at three yaws; the
 * centre of the dot's pixels read from the frame is within 2 pixels of a
 * reference projection written here from the documented camera (the
 * loader fits the model into the unit sphere by its box's centre and
 * farthest vertex; a 30 degree vertical field of view from the distance
 * at which the unit sphere with a margin of 1.08 fills the short side;
 * the view turns the model by yaw about y): none of the renderer's
 * matrices. A point turned behind the model is not drawn at all: the
 * depth hides it, it has no normal to fade it. */
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
/* The surface point in the direction u of the unit sphere. */
static const double dir[3] = {0.3, 0.25, 0.92};

static void surface_point(double out[3])
{
	double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);

	for (int k = 0; k < 3; k++)
		out[k] = centre[k] + radii[k] * dir[k] / len;
}

static void write_model(const char *path)
{
	struct gltf_write_opts o = {.index_bytes = 4, .with_normals = 1, .bad_index = -1};
	struct mesh s;

	assert_int_equal(mesh_uv_sphere(&s, 96, 48), 0);
	for (uint32_t i = 0; i < s.vertex_count * 3; i++)
		s.positions[i] = (float)(centre[i % 3] + radii[i % 3] * s.positions[i]);
	assert_int_equal(gltf_write(path, &s, &o), 0);
	mesh_release(&s);
}

/* The reference: file coordinates to pixels, from the documented camera
 * alone. The ellipsoid's box centre is `centre`, its farthest vertex 8
 * away (the x radius). */
static void reference(const double p[3], double yaw_deg, double out[2])
{
	double yaw = yaw_deg * M_PI / 180, half_fov = 15 * M_PI / 180;
	double dist = 1.08 / sin(half_fov); /* landscape: the short side is the height */
	double q[3], x, z, depth, f = 1 / tan(half_fov);

	for (int k = 0; k < 3; k++)
		q[k] = (p[k] - centre[k]) / 8.0;
	x = q[0] * cos(yaw) + q[2] * sin(yaw);
	z = -q[0] * sin(yaw) + q[2] * cos(yaw);
	depth = dist - z; /* the eye at +dist on z, looking down -z */
	out[0] = W / 2.0 + f * x / depth * H / 2.0;
	out[1] = H / 2.0 - f * q[1] / depth * H / 2.0;
}

/* The dot's drawn centre at yaw against the reference. */
static void at_yaw(struct display *d, struct renderer *r, struct content *s, struct options *o,
		   const double p[3], double yaw)
{
	double want[2], got[2] = {0, 0};
	struct image f;
	struct view v;

	o->content.yaw = yaw;
	v = content_view(&o->content);
	v.zoom = (float)s->zoom;
	assert_true(s->zoom == 1);
	renderer_draw(r, &v, W, H);
	assert_int_equal(d->read_frame(d, &f), 0);
	reference(p, yaw, want);
	assert_true(dot_centre(&f, got) > 20);
	image_release(&f);
	print_message("yaw %g: drawn (%.2f, %.2f), reference (%.2f, %.2f)\n", yaw, got[0], got[1],
		      want[0], want[1]);
	if (fabs(got[0] - want[0]) > 2 || fabs(got[1] - want[1]) > 2)
		fail_msg(
		    "yaw %g: the dot is drawn at (%.2f, %.2f), the reference projects its point "
		    "to (%.2f, %.2f)",
		    yaw, got[0], got[1], want[0], want[1]);
}

static void load(struct content *s, struct options *o, struct renderer *r)
{
	assert_int_equal(content_load(s, &o->content, true), 0);
	assert_int_equal(content_prepare(s, &o->content, W, H), 0);
	assert_int_equal(content_upload(s, r), 0);
	assert_int_equal(renderer_set_mode(r, o->content.mode, false), 0);
}

/* At next-hotspot's view of it (its picture shown), the hotspot's text
 * is placed beside the dot: right of it, centred on it, on screen. */
static void label_beside(struct renderer *r, struct content *s, struct options *o,
			 const double p[3])
{
	const struct image *pic = content_caption(s, CONTENT_HOTSPOT_CAPTION);
	double want[2];
	struct view v;
	int at[2];

	o->content.yaw = 0;
	v = content_view(&o->content);
	v.zoom = (float)s->zoom;
	reference(p, 0, want);
	assert_non_null(pic->rgba);
	renderer_show_stop(r, CONTENT_HOTSPOT_CAPTION);
	assert_true(renderer_caption_at(r, &v, 0, W, H, at));
	print_message("label at (%d, %d), %dx%d, the dot at (%.1f, %.1f)\n", at[0], at[1],
		      pic->width, pic->height, want[0], want[1]);
	assert_true(at[0] > want[0] + 5 && at[0] < want[0] + 30);
	assert_true(fabs(at[1] + pic->height / 2.0 - want[1]) < 2);
	assert_true(at[0] + pic->width <= W);
	renderer_show_stop(r, -1);
	/* A tap on the dot (fractions of the screen) is on hotspot 1; one a
	 * fingertip away from it too; one across the screen on none. */
	assert_int_equal(content_hotspot_tapped(s, r, &v, W, H, want[0] / W, want[1] / H), 1);
	assert_int_equal(
	    content_hotspot_tapped(s, r, &v, W, H, (want[0] + 15) / W, (want[1] - 10) / H), 1);
	assert_int_equal(content_hotspot_tapped(s, r, &v, W, H, 0.1, 0.9), 0);
}

static void drawn_at_its_projection(void **state)
{
	static const double yaws[] = {0, 25, -30};
	char dir_path[] = "/tmp/mk-hotspot-place-XXXXXX", model[96], grey[96], cmd[96];
	struct display *d = offscreen_open(W, H);
	struct renderer *r = d ? renderer_new(&d->gl, NULL) : NULL;
	struct hotspot *h;
	struct image img;
	struct content s;
	struct options o;
	double p[3];

	(void)state;
	assert_non_null(r);
	assert_non_null(mkdtemp(dir_path));
	snprintf(model, sizeof(model), "%s/egg.glb", dir_path);
	snprintf(grey, sizeof(grey), "%s/grey.png", dir_path);
	write_model(model);
	assert_int_equal(image_alloc(&img, 4, 4), 0);
	memset(img.rgba, 90, 64);
	assert_int_equal(image_write_png(grey, &img), 0);
	image_release(&img);
	setenv("XDG_CACHE_HOME", dir_path, 1);
	option_defaults(&o);
	o.content.model = model;
	o.content.matcap = grey;
	o.content.zoom = 1; /* the camera alone: no fit's zoom */
	o.content.pitch = 0;
	surface_point(p);
	h = &o.content.hotspots.items[0];
	hotspot_init(h, "dot", 1);
	h->has_point = true;
	memcpy(h->point, p, sizeof(p));
	h->color[0] = 0, h->color[1] = 1, h->color[2] = 0, h->color[3] = 1;
	strcpy(h->text, "A dot");
	o.content.hotspots.count = 1;
	load(&s, &o, r);
	for (size_t i = 0; i < sizeof(yaws) / sizeof(yaws[0]); i++)
		at_yaw(d, r, &s, &o, p, yaws[i]);
	label_beside(r, &s, &o, p);
	/* Again from the prepared-mesh cache: the fit is kept in its entry. */
	content_release(&s);
	load(&s, &o, r);
	assert_non_null(s.cached);
	at_yaw(d, r, &s, &o, p, yaws[1]);
	/* Turned away: the model's own depth hides it. */
	{
		struct image f;
		struct view v;
		double got[2] = {0, 0};

		o.content.yaw = 180;
		v = content_view(&o.content);
		v.zoom = (float)s.zoom;
		renderer_draw(r, &v, W, H);
		assert_int_equal(d->read_frame(d, &f), 0);
		assert_int_equal(dot_centre(&f, got), 0);
		image_release(&f);
	}
	content_release(&s);
	renderer_free(r);
	unsetenv("XDG_CACHE_HOME");
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir_path);
	assert_int_equal(system(cmd), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(drawn_at_its_projection),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
