/* What the animation player's tests share (test_kiosk_anim.c, the player;
 * test_anim_frames.c, its frames against the stills): an offscreen
 * display, a model's settings, the content loaded, prepared and uploaded
 * as the kiosk does, its frame drawn, and a prepared-mesh cache of their
 * own. Each unit test is a program of its own: this header defines what
 * it needs once per test. */
#ifndef MK_TEST_ANIM_FIXTURE_H
#define MK_TEST_ANIM_FIXTURE_H

#include "app/kiosk_anim.h"
#include "config/settings.h"
#include "content/content.h"
#include "display/display.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <cmocka.h>

#include "offscreen.h"

#define SIZE	96
#define KHRONOS "tests/corpus/khronos/"
#define T0	1000000000ull

static struct display *d;
/* The vertex attributes the next renderer may use (0: the GPU's). */
static uint32_t attribute_limit;

static inline int open_display(void **state)
{
	(void)state;
	d = offscreen_open(SIZE, SIZE);
	return d ? 0 : -1;
}

static inline struct content_config config(const char *model, double time)
{
	struct options o;

	option_defaults(&o);
	o.content.model = (char *)model;
	o.content.anim_time = time;
	o.content.anim_live = time < 0;
	o.content.lod_pixels = 0;
	/* The [scene] fit frames the mesh as loaded (the live one at 0 s):
	 * one zoom for both. */
	o.content.zoom = 1.0;
	return o.content;
}

/* The content's frame drawn by r (the kiosk's draw: the view and the fit). */
static inline void draw(struct renderer *r, const struct content *s, const struct content_config *c,
			struct image *out)
{
	struct view v = content_view(c);

	v.zoom = (float)s->zoom;
	assert_int_equal(d->begin_frame(d), 0);
	renderer_draw(r, &v, SIZE, SIZE);
	assert_int_equal(display_read_rgba(d, out), 0);
}

/* The live mesh's arrays are float32: the still is drawn from float32
 * arrays too, so that only the poses are compared. bones: the palette at
 * most (0: every model posed on the CPU). */
static inline struct renderer *shown_with(struct content *s, const struct content_config *c,
					  uint32_t bones)
{
	struct renderer *r = renderer_new(&d->gl, NULL);

	assert_non_null(r);
	renderer_set_vertex_format(r, VERTEX_FLOAT32);
	renderer_set_bone_limit(r, bones);
	renderer_set_attribute_limit(r, attribute_limit);
	assert_int_equal(content_load(s, c, true), 0);
	assert_int_equal(content_prepare(s, c, SIZE, SIZE), 0);
	assert_int_equal(content_upload(s, r), 0);
	assert_int_equal(renderer_set_mode(r, c->mode, c->ortho), 0);
	return r;
}

static inline struct renderer *shown(struct content *s, const struct content_config *c)
{
	return shown_with(s, c, UINT32_MAX);
}

/* The tests run with a cache of their own, empty: a model's first load
 * is parsed (the next of the same settings come from the cache), and
 * nothing is written where a user's or another test's cache is. */
static inline int anim_tests_run(const char *name, const struct CMUnitTest *tests, size_t count)
{
	char cache[] = "/tmp/mk-anim-cache-XXXXXX", cmd[64];
	int failed;

	if (!mkdtemp(cache))
		return 1;
	setenv("XDG_CACHE_HOME", cache, 1);
	failed = _cmocka_run_group_tests(name, tests, count, open_display, NULL);
	snprintf(cmd, sizeof(cmd), "rm -rf %s", cache);
	if (system(cmd) != 0)
		fprintf(stderr, "could not remove %s\n", cache);
	return failed;
}

#endif
