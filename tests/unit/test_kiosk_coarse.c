/* The live loop (kiosk_run) through OSMesa with a model prepared from
 * scratch over [kiosk] coarse_above (issue 34 part 2): its first frame is
 * the coarse picture, then the full level of detail is swapped in, and
 * that frame is the still's (the content --output prepares, drawn as
 * main.c's render_frames draws it: content_view at the fit's zoom), pixel
 * for pixel: the fit did not move. A next-model press while the full mesh
 * is being prepared: it is dropped, never shown, and the next model comes;
 * or, when the next one does not load, it is swapped in after all.
 *
 * The threshold is the setting itself ([kiosk] coarse_above = 1000, for
 * a knot of 16384 triangles); the full mesh's preparation is held by the
 * test hook MK_TEST_REFINE_GATE (src/content/content_coarse.c; built with
 * MK_TEST_HOOKS, as every sanitizer build is) until the coarse frame was
 * read, so that no machine is too fast or too slow for the window. */
#include "app/kiosk.h"
#include "app/signals.h"
#include "config/options.h"
#include "content/content.h"
#include "display/display.h"
#include "live_kiosk.h"
#include "render/render.h"
#include "scene/mesh/mesh.h"
#include "util/clock.h"
#include "util/log.h"

#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

/* OSMesa leaks a fixed few hundred bytes per process; kept loaded (the
 * display is never freed) they are suppressed by library: see
 * tests/unit/test_camera_texture.c. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
	return "leak:libOSMesa\nleak:libLLVM\nleak:display_osmesa_new\n";
}

#define SIZE   "64x64"
#define PIXELS 64
/* A hang guard (a swap that never comes), not a measure: a minute. */
#define GIVE_UP_NS (60ull * 1000000000ull)

enum step { WAIT_COARSE, WAIT_SWAP, WAIT_FULL, DONE };

struct script {
	struct input_source base; /* first: the loop hands this back */
	struct live_kiosk *lk;
	enum step step;
	bool press_next; /* next-model while the full mesh is prepared */
	bool comes_back; /* ... and no other model loads: the first one's full mesh comes */
	const char *gate;
	const char *first; /* the model shown coarse */
	uint64_t give_up_ns;
	long swap_frame;
	bool coarse_seen; /* the first frame drawn showed the coarse mesh */
	bool stale_full;  /* the first model shown whole after next-model */
	struct image coarse, full;
};

static void open_gate(const char *gate)
{
	FILE *g = fopen(gate, "w");

	if (g)
		fclose(g);
}

static void read_frame(struct script *s, struct image *out)
{
	if (s->lk->d->read_frame(s->lk->d, out))
		memset(out, 0, sizeof(*out));
}

static int press(struct script *s, uint64_t now, struct app_event *out)
{
	s->step = WAIT_SWAP;
	out[0] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_MODEL, .pressed = 1};
	out[1] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_MODEL};
	open_gate(s->gate);
	return 2;
}

/* The first frame: the coarse one, read before the gate opens. With
 * press_next, once the full mesh's job took it (refine NULL). */
static int wait_coarse(struct script *s, uint64_t now, struct app_event *out)
{
	const struct content *c = &s->lk->content;

	if (kiosk_frames_drawn(s->lk->k) < 1)
		return 0;
	if (!s->coarse.rgba) {
		s->coarse_seen = c->coarse;
		read_frame(s, &s->coarse);
	}
	if (s->press_next)
		return c->refine ? 0 : press(s, now, out);
	open_gate(s->gate);
	s->step = WAIT_SWAP;
	return 0;
}

/* True once the full mesh (or, with press_next, the next model) is
 * shown; the first model shown whole after next-model is noted. */
static bool swapped(struct script *s)
{
	const struct content *c = &s->lk->content;
	bool first = c->model_path && !strcmp(c->model_path, s->first);

	if (s->press_next && !s->comes_back && first && !c->coarse)
		s->stale_full = true;
	return !c->coarse && !(s->press_next && !s->comes_back && first);
}

static int script_read(struct input_source *src, uint64_t now, struct app_event *out, int max)
{
	struct script *s = (struct script *)src;

	if (max < 2)
		return 0;
	if (!s->give_up_ns)
		s->give_up_ns = monotonic_ns() + GIVE_UP_NS;
	if (s->step != DONE && monotonic_ns() > s->give_up_ns) {
		open_gate(s->gate);
		s->step = DONE;
		kill(getpid(), SIGTERM);
	}
	switch (s->step) {
	case WAIT_COARSE:
		return wait_coarse(s, now, out);
	case WAIT_SWAP:
		if (swapped(s)) {
			s->swap_frame = kiosk_frames_drawn(s->lk->k);
			s->step = WAIT_FULL;
		}
		break;
	case WAIT_FULL:
		swapped(s); /* a stale full mesh after the swap counts too */
		/* A frame drawn since, or none due: the last one drawn shows
		 * it (a swap without a job is drawn in the pass that made it). */
		if (kiosk_frames_drawn(s->lk->k) > s->swap_frame ||
		    !kiosk_app_state(s->lk->k)->dirty) {
			read_frame(s, &s->full);
			s->step = DONE;
			kill(getpid(), SIGTERM);
		}
		break;
	case DONE:
		break;
	}
	return 0;
}

static uint64_t script_deadline(struct input_source *src)
{
	(void)src;
	return 0; /* always: the loop never sleeps */
}

static void script_destroy(struct input_source *src)
{
	(void)src; /* on the test's stack */
}

/* The still of c's model, from a cache of its own (cold): prepared as
 * --output prepares it (coarse_first off) and drawn as render_frames
 * draws it, on the live kiosk's display and renderer. */
static void draw_still(struct live_kiosk *lk, const char *cache, struct image *out)
{
	struct content_config *c = &lk->o.content;
	struct content s;
	struct view v;

	setenv("XDG_CACHE_HOME", cache, 1);
	c->coarse_first = false;
	assert_int_equal(content_load(&s, c, true), 0);
	assert_int_equal(content_prepare(&s, c, PIXELS, PIXELS), 0);
	assert_false(s.coarse);
	assert_int_equal(content_upload_model(&s, lk->r), 0);
	v = content_view(content_settings(&s, c));
	v.zoom = (float)s.zoom;
	content_place_view(&s, &v);
	assert_int_equal(lk->d->begin_frame(lk->d), 0);
	renderer_draw(lk->r, &v, PIXELS, PIXELS);
	assert_int_equal(lk->d->present(lk->d), 0);
	assert_int_equal(lk->d->read_frame(lk->d, out), 0);
	content_release(&s);
}

static long pixels_apart(const struct image *a, const struct image *b)
{
	long n = 0;

	assert_int_equal(a->width, b->width);
	assert_int_equal(a->height, b->height);
	for (long i = 0; i < (long)a->width * a->height; i++)
		n += memcmp(a->rgba + 4 * i, b->rgba + 4 * i, 4) != 0;
	return n;
}

/* A knot of 16384 triangles, over the ini's coarse_above of 1000. */
static void write_knot(const char *path)
{
	struct gltf_write_opts w = {.index_bytes = 4, .with_normals = 1, .bad_index = -1};
	struct mesh m;

	assert_int_equal(mesh_torus_knot(&m, 256, 32), 0);
	assert_int_equal(gltf_write(path, &m, &w), 0);
	mesh_release(&m);
}

struct fixture {
	char dir[32], ini[64], gate[64], cache[64], still_cache[64], model[64];
};

/* file NULL: the folder of models. */
static void fixture_make(struct fixture *f, const char *file)
{
	FILE *ini;

	strcpy(f->dir, "/tmp/mk-coarse-XXXXXX");
	assert_non_null(mkdtemp(f->dir));
	snprintf(f->ini, sizeof(f->ini), "%s/kiosk.ini", f->dir);
	snprintf(f->gate, sizeof(f->gate), "%s/gate", f->dir);
	snprintf(f->cache, sizeof(f->cache), "%s/cache", f->dir);
	snprintf(f->still_cache, sizeof(f->still_cache), "%s/still-cache", f->dir);
	snprintf(f->model, sizeof(f->model), "%s/models", f->dir);
	assert_int_equal(mkdir(f->model, 0755), 0);
	ini = fopen(f->ini, "w");
	assert_non_null(ini);
	fprintf(ini,
		"[kiosk]\ncoarse_above = 1000\nattract_after = 0\n[scene]\nmode = view\n"
		"model = %s%s%s\n",
		f->model, file ? "/" : "", file ? file : "");
	fclose(ini);
	setenv("XDG_CACHE_HOME", f->cache, 1);
	setenv("MK_TEST_REFINE_GATE", f->gate, 1);
}

static void fixture_done(void)
{
	unsetenv("MK_TEST_REFINE_GATE");
	unsetenv("XDG_CACHE_HOME");
}

static void coarse_then_the_still(void **state)
{
	struct script s = {.base = {.name = "coarse script",
				    .fd = -1,
				    .read = script_read,
				    .deadline = script_deadline,
				    .destroy = script_destroy}};
	struct live_kiosk lk;
	struct fixture f;
	struct image still;
	char path[96];

	(void)state;
	fixture_make(&f, "knot.glb");
	snprintf(path, sizeof(path), "%s/knot.glb", f.model);
	write_knot(path);
	live_kiosk_open(&lk, f.ini, &s.base, SIZE, true);
	/* Prepared coarse, its full mesh not yet. */
	assert_true(lk.content.coarse);
	assert_non_null(lk.content.refine);
	s.lk = &lk;
	s.gate = f.gate;
	s.first = path;
	assert_int_equal(kiosk_run(lk.k), 0);
	assert_int_equal(s.step, DONE);
	assert_true(s.coarse_seen);
	assert_false(lk.content.coarse);
	assert_null(lk.content.refine);
	assert_non_null(s.coarse.rgba);
	assert_non_null(s.full.rgba);
	draw_still(&lk, f.still_cache, &still);
	/* Two distinct frames, the second the still's. */
	assert_true(pixels_apart(&s.coarse, &s.full) > 0);
	assert_int_equal(pixels_apart(&s.full, &still), 0);
	image_release(&s.coarse);
	image_release(&s.full);
	image_release(&still);
	live_kiosk_stop(&lk);
	fixture_done();
}

/* A folder of the knot (first, shown coarse) and a sphere: next-model
 * while the knot's full mesh is prepared. */
static void next_model_while_coarse(void **state)
{
	struct script s = {.base = {.name = "coarse switch script",
				    .fd = -1,
				    .read = script_read,
				    .deadline = script_deadline,
				    .destroy = script_destroy},
			   .press_next = true};
	struct live_kiosk lk;
	struct fixture f;
	char knot[96], sphere[96];

	(void)state;
	fixture_make(&f, NULL);
	snprintf(knot, sizeof(knot), "%s/a-knot.glb", f.model);
	snprintf(sphere, sizeof(sphere), "%s/b-sphere.glb", f.model);
	write_knot(knot);
	live_kiosk_sphere(sphere);
	live_kiosk_open(&lk, f.ini, &s.base, SIZE, true);
	assert_string_equal(lk.content.model_path, knot);
	assert_true(lk.content.coarse);
	s.lk = &lk;
	s.gate = f.gate;
	s.first = knot;
	assert_int_equal(kiosk_run(lk.k), 0);
	assert_int_equal(s.step, DONE);
	assert_true(s.coarse_seen);
	/* The knot's full mesh never shown; the sphere is, whole. */
	assert_false(s.stale_full);
	assert_string_equal(lk.content.model_path, sphere);
	assert_false(lk.content.coarse);
	assert_true(pixels_apart(&s.coarse, &s.full) > 0);
	image_release(&s.coarse);
	image_release(&s.full);
	live_kiosk_stop(&lk);
	fixture_done();
}

/* A folder of the knot and a file that does not load: next-model while
 * the knot's full mesh is prepared finds no other model, and the knot's
 * full mesh, kept aside, comes after all (not the coarse one for good). */
static void next_model_that_fails(void **state)
{
	struct script s = {.base = {.name = "coarse failed switch script",
				    .fd = -1,
				    .read = script_read,
				    .deadline = script_deadline,
				    .destroy = script_destroy},
			   .press_next = true,
			   .comes_back = true};
	struct live_kiosk lk;
	struct fixture f;
	struct image still;
	char knot[96], broken[96];
	FILE *b;

	(void)state;
	fixture_make(&f, NULL);
	snprintf(knot, sizeof(knot), "%s/a-knot.glb", f.model);
	snprintf(broken, sizeof(broken), "%s/b-broken.glb", f.model);
	write_knot(knot);
	b = fopen(broken, "w");
	assert_non_null(b);
	fputs("not a glb", b);
	fclose(b);
	live_kiosk_open(&lk, f.ini, &s.base, SIZE, true);
	assert_true(lk.content.coarse);
	s.lk = &lk;
	s.gate = f.gate;
	s.first = knot;
	assert_int_equal(kiosk_run(lk.k), 0);
	assert_int_equal(s.step, DONE);
	assert_string_equal(lk.content.model_path, knot);
	assert_false(lk.content.coarse);
	assert_null(lk.content.refine);
	draw_still(&lk, f.still_cache, &still);
	assert_true(pixels_apart(&s.coarse, &s.full) > 0);
	assert_int_equal(pixels_apart(&s.full, &still), 0);
	image_release(&s.coarse);
	image_release(&s.full);
	image_release(&still);
	live_kiosk_stop(&lk);
	fixture_done();
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(coarse_then_the_still),
	    cmocka_unit_test(next_model_while_coarse),
	    cmocka_unit_test(next_model_that_fails),
	};

	/* Before the GL driver starts its threads, as main() does. */
	signals_block();
	log_set_level(LOG_WARN);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
