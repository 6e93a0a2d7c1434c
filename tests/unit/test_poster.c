/* The poster on a real GL (OSMesa, or EGL where Mesa has no OSMesa): the
 * picture fitted inside the screen with the background beside it, and
 * turned for a portrait panel the way the renderer turns the model
 * (mat4_rotate_z), so its top-left lands where the model's would. */
#include "display/display.h"
#include "render/background.h"
#include "render/poster.h"
#include "util/log.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "offscreen.h"

#define W 96
#define H 64

static const struct background_spec green = {BACKGROUND_COLOR, {0, 1, 0}, {0, 1, 0}, NULL};

static int setup(void **state)
{
	log_set_level(LOG_ERR);
	*state = offscreen_open(W, H);
	return *state ? 0 : -1;
}

/* A picture w x h, blue but for its top-left quarter, red. */
static void make_picture(struct image *img, int w, int h)
{
	assert_int_equal(image_alloc(img, w, h), 0);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			uint8_t *p = img->rgba + ((size_t)y * (size_t)w + (size_t)x) * 4;
			bool red = x < w / 2 && y < h / 2;

			p[0] = red ? 255 : 0;
			p[1] = 0;
			p[2] = red ? 0 : 255;
			p[3] = 255;
		}
}

/* 'r', 'b' or 'g' (background) for the pixel at x, y, rows top first. */
static char colour_at(const struct image *frame, int x, int y)
{
	const uint8_t *p = frame->rgba + ((size_t)y * (size_t)frame->width + (size_t)x) * 4;

	if (p[0] > 200 && p[1] < 50 && p[2] < 50)
		return 'r';
	if (p[2] > 200 && p[0] < 50 && p[1] < 50)
		return 'b';
	if (p[1] > 200 && p[0] < 50 && p[2] < 50)
		return 'g';
	return '?';
}

static void draw(struct display *d, int w, int h, int rotation, struct image *frame)
{
	struct background *bg;
	struct image img;

	make_picture(&img, w, h);
	assert_int_equal(d->begin_frame(d), 0);
	bg = background_new(&d->gl, &green, NULL);
	assert_non_null(bg);
	assert_int_equal(poster_draw(&d->gl, &img, W, H, rotation, bg), 0);
	background_free(bg);
	assert_int_equal(d->present(d), 0);
	assert_int_equal(d->read_frame(d, frame), 0);
	image_release(&img);
}

/* A 4:3 picture on a 3:2 screen fills the height, with the background
 * left and right of it. */
static void fitted(void **state)
{
	struct image frame;

	draw(*state, 40, 30, 0, &frame);
	assert_int_equal(colour_at(&frame, 2, H / 2), 'g');
	assert_int_equal(colour_at(&frame, W - 3, H / 2), 'g');
	assert_int_equal(colour_at(&frame, W / 2 - 10, 3), 'r');
	assert_int_equal(colour_at(&frame, W / 2 + 10, 3), 'b');
	assert_int_equal(colour_at(&frame, W / 2 - 10, H - 4), 'b');
	image_release(&frame);
}

/* A portrait picture for a panel turned 90 or 270 degrees fills the
 * screen; its top-left goes where the renderer puts the model's. */
static void turned(void **state)
{
	struct image frame;

	draw(*state, H, W, 90, &frame); /* (-1, 1) -> (-1, -1): bottom-left */
	assert_int_equal(colour_at(&frame, 3, H - 4), 'r');
	assert_int_equal(colour_at(&frame, 3, 3), 'b');
	assert_int_equal(colour_at(&frame, W - 4, H - 4), 'b');
	image_release(&frame);
	draw(*state, H, W, 270, &frame); /* (-1, 1) -> (1, 1): top-right */
	assert_int_equal(colour_at(&frame, W - 4, 3), 'r');
	assert_int_equal(colour_at(&frame, 3, 3), 'b');
	image_release(&frame);
	draw(*state, W, H, 180, &frame); /* bottom-right */
	assert_int_equal(colour_at(&frame, W - 4, H - 4), 'r');
	assert_int_equal(colour_at(&frame, 3, 3), 'b');
	image_release(&frame);
}

static void background_only(void **state)
{
	struct display *d = *state;
	struct background *bg = background_new(&d->gl, &green, NULL);
	struct image frame;

	assert_non_null(bg);
	assert_int_equal(d->begin_frame(d), 0);
	assert_int_equal(poster_draw(&d->gl, NULL, W, H, 0, bg), 0);
	background_free(bg);
	assert_int_equal(d->present(d), 0);
	assert_int_equal(d->read_frame(d, &frame), 0);
	assert_int_equal(colour_at(&frame, W / 2, H / 2), 'g');
	image_release(&frame);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(fitted),
	    cmocka_unit_test(turned),
	    cmocka_unit_test(background_only),
	};

	return cmocka_run_group_tests_name("poster", tests, setup, NULL);
}
