/* A live kiosk for a unit test (kiosk_run, as main() runs it): a config
 * file's options, its content loaded, prepared and uploaded on a 32x32
 * display (OSMesa, else EGL surfaceless), and the test's script its one
 * input source. Shared by test_kiosk_reload.c, test_kiosk_matcap.c and
 * test_kiosk_coarse.c (its own size, a coarse picture first). */
#ifndef MK_TEST_LIVE_KIOSK_H
#define MK_TEST_LIVE_KIOSK_H

#include "app/kiosk.h"
#include "config/options.h"
#include "content/content.h"
#include "display/display.h"
#include "gltf_write.h"
#include "render/render.h"
#include "scene/mesh/mesh.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

struct live_kiosk {
	char *argv[13]; /* kept: a reload parses them again */
	struct options o;
	struct content content;
	struct display *d;
	struct renderer *r;
	struct kiosk *k;
};

/* A UV sphere with normals, as a .glb at path. */
static inline void live_kiosk_sphere(const char *path)
{
	struct gltf_write_opts w = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	struct mesh m;

	assert_int_equal(mesh_uv_sphere(&m, 16, 8), 0);
	assert_int_equal(gltf_write(path, &m, &w), 0);
	mesh_release(&m);
}

/* The kiosk of the config file ini on a size ("WxH") display, ready to
 * run, src its input; coarse: a large model prepared from scratch is
 * shown coarse first, as main() sets it for the live kiosk
 * (content_config.coarse_first). */
static inline void live_kiosk_open(struct live_kiosk *lk, char *ini, struct input_source *src,
				   char *size, bool coarse)
{
	char *argv[] = {"matcap-kiosk", "--backend", "osmesa",	 "--size", size, "--config", ini,
			"--keyboard",	"none",	     "--camera", "off",	   "-q", NULL};
	struct display_config cfg = {0};
	struct kiosk_parts parts = {.content = &lk->content, .options = &lk->o, .argv = lk->argv};

	assert_int_equal(sscanf(size, "%dx%d", &cfg.width, &cfg.height), 2);
	memcpy(lk->argv, argv, sizeof(argv));
	assert_int_equal(options_parse(&lk->o, 12, lk->argv), OPTIONS_OK);
	lk->o.content.coarse_first = coarse;
	assert_int_equal(content_load(&lk->content, &lk->o.content, true), 0);
#ifdef MK_HAVE_OSMESA
	lk->d = display_osmesa_new(&cfg);
#else
	lk->d = display_egl_new(&cfg);
#endif
	assert_non_null(lk->d);
	lk->r = renderer_new(&lk->d->gl, NULL);
	assert_non_null(lk->r);
	assert_int_equal(content_prepare(&lk->content, &lk->o.content, lk->d->width, lk->d->height),
			 0);
	assert_int_equal(content_upload(&lk->content, lk->r), 0);
	assert_int_equal(renderer_set_mode(lk->r, lk->o.content.mode, lk->o.content.ortho), 0);
	parts.display = lk->d;
	parts.renderer = lk->r;
	lk->k = kiosk_new(&parts, 0);
	assert_non_null(lk->k);
	assert_int_equal(kiosk_add_input(lk->k, src), 0);
}

/* The same on a 32x32 display, each model prepared whole. */
static inline void live_kiosk_start(struct live_kiosk *lk, char *ini, struct input_source *src)
{
	live_kiosk_open(lk, ini, src, "32x32", false);
}

/* All but the display, left open: OSMesa leaks a fixed few hundred bytes
 * per process (the tests' __lsan_default_suppressions). */
static inline void live_kiosk_stop(struct live_kiosk *lk)
{
	kiosk_free(lk->k);
	renderer_free(lk->r);
	content_release(&lk->content);
	options_release(&lk->o);
}

#endif
