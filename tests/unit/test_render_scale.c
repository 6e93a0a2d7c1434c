/* [display] render_scale (render/render_scale.h): the key as the config
 * file and the command line take it, auto's choice for a panel's size,
 * and the GL pass on a real context: the scene drawn at the scaled size,
 * then over the whole frame, upright, filtered, with the display's
 * framebuffer and viewport back for the full-resolution overlays. */
#include "config/options.h"
#include "config/settings.h"
#include "display/display.h"
#include "render/background.h"
#include "render/render_scale.h"
#include "util/log.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "offscreen.h"

#define W 64
#define H 48

static enum options_status read_ini(struct options *o, const char *text)
{
	char path[] = "/tmp/mk-scale-XXXXXX";
	int fd = mkstemp(path);
	enum options_status st;

	assert_true(fd >= 0);
	assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
	close(fd);
	option_defaults(o);
	st = options_read_file(o, path);
	unlink(path);
	return st;
}

/* 1 when left out; auto is 0; 0.5 to 1 taken; the rest refused. */
static void key(void **state)
{
	static const char *const bad[] = {"0.4", "1.5", "0", "half", "", "auto1"};
	const char *argv[] = {"mk", "--render-scale", "0.75"};
	struct options o;
	char text[80];

	(void)state;
	assert_int_equal(read_ini(&o, "[display]\nsize = 320x240\n"), OPTIONS_OK);
	assert_float_equal(o.display.render_scale, 1, 0);
	options_release(&o);
	assert_int_equal(read_ini(&o, "[display]\nrender_scale = auto\n"), OPTIONS_OK);
	assert_float_equal(o.display.render_scale, 0, 0);
	options_release(&o);
	assert_int_equal(read_ini(&o, "[display]\nrender_scale = 0.5\n"), OPTIONS_OK);
	assert_float_equal(o.display.render_scale, 0.5, 0);
	options_release(&o);
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		snprintf(text, sizeof(text), "[display]\nrender_scale = %s\n", bad[i]);
		assert_int_not_equal(read_ini(&o, text), OPTIONS_OK);
		options_release(&o);
	}
	assert_int_equal(options_parse(&o, 3, (char **)argv), OPTIONS_OK);
	assert_float_equal(o.display.render_scale, 0.75, 0);
	options_release(&o);
}

/* A number is kept; auto: 1 up to 1080p (1440p on a GPU), then the
 * largest step of 0.05 within the budget, never under 0.5; on a software
 * rasteriser only where the plane scales (the GL pass costs it more than it
 * saves). */
static void pick(void **state)
{
	(void)state;
	assert_float_equal(render_scale_pick(0.6, 3840, 2160, true, false), 0.6, 0);
	assert_float_equal(render_scale_pick(1, 3840, 2160, true, true), 1, 0);
	assert_float_equal(render_scale_pick(0, 1280, 720, true, true), 1, 0);
	assert_float_equal(render_scale_pick(0, 1920, 1080, true, true), 1, 0);
	assert_float_equal(render_scale_pick(0, 1080, 1920, true, true), 1, 0);
	assert_float_equal(render_scale_pick(0, 2560, 1440, true, true), 0.75, 1e-12);
	assert_float_equal(render_scale_pick(0, 3840, 2160, true, true), 0.5, 1e-12);
	assert_float_equal(render_scale_pick(0, 7680, 4320, true, true), 0.5, 1e-12);
	assert_float_equal(render_scale_pick(0, 3840, 2160, true, false), 1, 0);
	assert_float_equal(render_scale_pick(0, 2560, 1440, false, false), 1, 0);
	assert_float_equal(render_scale_pick(0, 3840, 2160, false, false), 0.65, 1e-12);
	assert_float_equal(render_scale_pick(0, 3840, 2160, false, true), 0.65, 1e-12);
}

/* Within the budget, or at the floor; never larger for a larger panel. */
static void pick_within_budget(void **state)
{
	(void)state;
	for (int soft = 0; soft < 2; soft++) {
		double budget = soft ? 1920.0 * 1080 : 2560.0 * 1440, last = 1;

		for (int w = 640; w <= 7680; w += 160) {
			int h = w * 9 / 16, sw, sh;
			double s = render_scale_pick(0, w, h, soft, true);

			render_scale_size(s, w, h, &sw, &sh);
			assert_true(s >= RENDER_SCALE_MIN && s <= 1);
			assert_true(s <= last);
			assert_true(s == RENDER_SCALE_MIN || (double)sw * sh <= budget * 1.001);
			last = s;
		}
	}
}

static void size(void **state)
{
	int w, h;

	(void)state;
	render_scale_size(0.5, 1920, 1080, &w, &h);
	assert_int_equal(w, 960);
	assert_int_equal(h, 540);
	render_scale_size(0.75, 1366, 768, &w, &h);
	assert_int_equal(w, 1025);
	assert_int_equal(h, 576);
	render_scale_size(0.5, 1, 1, &w, &h);
	assert_int_equal(w, 1);
	assert_int_equal(h, 1);
}

/* The drawing, on the offscreen backend the goldens use. */
static int setup(void **state)
{
	log_set_level(LOG_ERR);
	*state = offscreen_open(W, H);
	return *state ? 0 : -1;
}

static const uint8_t *pixel(const struct image *f, int x, int y)
{
	return f->rgba + ((size_t)y * (size_t)f->width + (size_t)x) * 4;
}

static void near(const uint8_t *p, int r, int g, int b, int tol)
{
	if (abs(p[0] - r) > tol || abs(p[1] - g) > tol || abs(p[2] - b) > tol)
		fail_msg("%d %d %d, expected %d %d %d", p[0], p[1], p[2], r, g, b);
}

/* W/2 x H/2: the left half red, the right half blue, the top 4 rows green. */
static void pattern(struct image *img)
{
	assert_int_equal(image_alloc(img, W / 2, H / 2), 0);
	for (int y = 0; y < H / 2; y++)
		for (int x = 0; x < W / 2; x++) {
			uint8_t *p = img->rgba + ((size_t)y * (W / 2) + (size_t)x) * 4;

			p[0] = y >= 4 && x < W / 4 ? 255 : 0;
			p[1] = y < 4 ? 255 : 0;
			p[2] = y >= 4 && x >= W / 4 ? 255 : 0;
			p[3] = 255;
		}
}

/* The pattern drawn as the scene at half size comes out over the whole
 * frame, upright (green on top), the halves where they were and the seam
 * between them filtered; afterwards the display's framebuffer and a full
 * viewport are bound again. samples: the display's, as the scaled buffer
 * takes them (multisampled renderbuffers resolved by a blit on OSMesa:
 * the same picture, its edges being the texels'). */
static void draw_pattern(struct display *d, int samples)
{
	struct render_scale *s = render_scale_new(&d->gl, 0.5, samples, NULL);
	struct background_spec spec;
	struct background *b;
	struct image img, f;
	GLint target = -1, fbo = -1, vp[4];
	char err[160];
	int w, h;

	assert_non_null(s);
	pattern(&img);
	assert_int_equal(background_parse("pattern.png", &spec, err, sizeof(err)), 0);
	b = background_new(&d->gl, &spec, &img);
	assert_non_null(b);
	assert_int_equal(d->begin_frame(d), 0);
	d->gl.GetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
	render_scale_begin(s, false, W, H, &w, &h);
	assert_int_equal(w, W / 2);
	assert_int_equal(h, H / 2);
	d->gl.GetIntegerv(GL_VIEWPORT, vp);
	assert_int_equal(vp[2], W / 2);
	assert_int_equal(vp[3], H / 2);
	d->gl.GetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
	assert_int_not_equal(fbo, target);
	background_draw(b, w, h, 0);
	render_scale_end(s);
	d->gl.GetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
	assert_int_equal(fbo, target);
	d->gl.GetIntegerv(GL_VIEWPORT, vp);
	assert_int_equal(vp[2], W);
	assert_int_equal(vp[3], H);
	assert_int_equal(d->gl.GetError(), GL_NO_ERROR);
	assert_int_equal(d->present(d), 0);
	assert_int_equal(d->read_frame(d, &f), 0);
	near(pixel(&f, W / 2, 0), 0, 255, 0, 2);
	near(pixel(&f, 2, H / 2), 255, 0, 0, 2);
	near(pixel(&f, W - 3, H - 1), 0, 0, 255, 2);
	/* Linear filtering: the two pixels either side of the seam mix. */
	assert_true(pixel(&f, W / 2, H / 2)[0] > 40 && pixel(&f, W / 2, H / 2)[2] > 40);
	image_release(&f);
	image_release(&img);
	background_free(b);
	render_scale_free(s);
}

static void gl_pass(void **state)
{
	draw_pattern(*state, 0);
}

static void gl_pass_multisampled(void **state)
{
	draw_pattern(*state, 4);
}

/* At 1, or where the plane scales, the scene draws straight into the
 * display's framebuffer at full size. */
static void full_size(void **state)
{
	struct display *d = *state;
	struct render_scale *s = render_scale_new(&d->gl, 0.5, 0, NULL);
	struct render_scale *one = render_scale_new(&d->gl, 1, 0, NULL);
	GLint target = -1, fbo = -1;
	int w, h;

	assert_int_equal(d->begin_frame(d), 0);
	d->gl.GetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
	render_scale_begin(s, true, W, H, &w, &h);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
	render_scale_end(s);
	render_scale_begin(one, false, W, H, &w, &h);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
	d->gl.GetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
	assert_int_equal(fbo, target);
	render_scale_end(one);
	render_scale_free(s);
	render_scale_free(one);
}

int main(void)
{
	const struct CMUnitTest pure[] = {
	    cmocka_unit_test(key),
	    cmocka_unit_test(pick),
	    cmocka_unit_test(pick_within_budget),
	    cmocka_unit_test(size),
	};
	const struct CMUnitTest drawn[] = {
	    cmocka_unit_test(gl_pass),
	    cmocka_unit_test(gl_pass_multisampled),
	    cmocka_unit_test(full_size),
	};
	int failed = cmocka_run_group_tests(pure, NULL, NULL);

	return failed + cmocka_run_group_tests(drawn, setup, NULL);
}
