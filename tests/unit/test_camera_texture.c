/* The camera pass on a real GL (OSMesa, the upload path): synthetic frames
 * of each format family, with padded strides, go through the shader and
 * come back out of the matcap texture. Colours must match the reference
 * conversion of camera_math.c, and the picture's top-left must land at
 * the texture's first row, left (mirrored: right). */
#include "camera/camera_texture.h"
#include "display/display.h"

#include <drm_fourcc.h>
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "offscreen.h"

#define SIDE 64 /* the frame and the matcap: one texel per pixel */

struct fixture {
	struct display *d;
	struct camera_texture *t;
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	if (!f)
		return -1;
	f->d = offscreen_open(16, 16);
	if (!f->d)
		return -1;
	f->t = camera_texture_new(&f->d->gl, NULL, SIDE, false);
	if (!f->t)
		return -1;
	*state = f;
	return 0;
}

/* OSMesa leaks a fixed few hundred bytes per process; unloaded at exit it
 * leaves LeakSanitizer nothing to name them by (tests/e2e/live.sh turns leak
 * checks off for it). Kept loaded, they can be suppressed by library,
 * and everything of ours is still checked. */
static int teardown(void **state)
{
	struct fixture *f = *state;

	camera_texture_free(f->t);
	/* The display is left open: see offscreen.h. */
	free(f);
	return 0;
}

/* The quadrants of the test picture: top-left, top-right, bottom-left,
 * bottom-right. */
static const uint8_t quad_rgb[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
/* The same colours in BT.601 limited range. */
static const uint8_t quad_yuv[4][3] = {
    {81, 90, 240}, {145, 54, 34}, {41, 240, 110}, {235, 128, 128}};

static int quadrant(int x, int y)
{
	return (y >= SIDE / 2) * 2 + (x >= SIDE / 2);
}

static void check_quadrants(struct camera_texture *t, const uint8_t want[4][3], bool mirror,
			    int tolerance)
{
	struct image img;

	assert_int_equal(camera_texture_read(t, &img), 0);
	for (int y = 4; y < SIDE; y += 8)
		for (int x = 4; x < SIDE; x += 8) {
			const uint8_t *px = img.rgba + ((size_t)y * SIDE + (size_t)x) * 4;
			const uint8_t *w = want[quadrant(mirror ? SIDE - 1 - x : x, y)];

			for (int c = 0; c < 3; c++)
				if (abs(px[c] - w[c]) > tolerance)
					fail_msg("texel %d,%d channel %d is %d, expected %d", x, y,
						 c, px[c], w[c]);
		}
	image_release(&img);
}

static void frame_init(struct camera_frame *fr, uint32_t fourcc, unsigned stride)
{
	memset(fr, 0, sizeof(*fr));
	assert_int_equal(camera_layout_make(fourcc, SIDE, SIDE, stride, &fr->layout), 0);
	fr->encoding = CAMERA_ENC_REC601;
	fr->range = CAMERA_RANGE_LIMITED;
	for (int p = 0; p < CAMERA_MAX_PLANES; p++)
		fr->plane[p].fd = -1;
}

/* A packed RGB frame: the bytes of red, green and blue at order[]. */
static uint8_t *rgb_frame(struct camera_frame *fr, uint32_t fourcc, unsigned stride)
{
	uint8_t *buf;
	int bpp;

	frame_init(fr, fourcc, stride);
	bpp = fr->layout.plane[0].bytes_per_texel;
	buf = calloc(1, (size_t)stride * SIDE);
	assert_non_null(buf);
	memset(buf, 0xee, (size_t)stride * SIDE); /* padding that must not show */
	for (int y = 0; y < SIDE; y++)
		for (int x = 0; x < SIDE; x++)
			for (int c = 0; c < 3; c++)
				buf[(size_t)y * stride + (size_t)x * bpp +
				    (size_t)fr->layout.order[c]] = quad_rgb[quadrant(x, y)][c];
	fr->plane[0].data = buf;
	return buf;
}

static void rgb_formats_and_strides(void **state)
{
	struct fixture *f = *state;
	/* BGR888 tight (aligned), padded to a whole texel (wide), padded by
	 * 2 bytes (row by row); XRGB8888 with its own byte order. */
	const struct {
		uint32_t fourcc;
		unsigned stride;
	} cases[] = {{DRM_FORMAT_BGR888, SIDE * 3},
		     {DRM_FORMAT_BGR888, SIDE * 3 + 6},
		     {DRM_FORMAT_BGR888, SIDE * 3 + 2},
		     {DRM_FORMAT_RGB888, SIDE * 3 + 9},
		     {DRM_FORMAT_XRGB8888, SIDE * 4 + 64}};
	struct camera_frame fr;

	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		uint8_t *buf = rgb_frame(&fr, cases[i].fourcc, cases[i].stride);

		assert_int_equal(camera_texture_update(f->t, &fr), 0);
		assert_int_equal(camera_texture_path(f->t), CAMERA_PATH_UPLOAD);
		assert_int_not_equal(camera_texture_id(f->t), 0);
		check_quadrants(f->t, quad_rgb, false, 1);
		free(buf);
	}
}

static void mirror_flips_left_and_right(void **state)
{
	struct fixture *f = *state;
	struct camera_view v = {0.5, 0.5, 0.5, true};
	struct camera_frame fr;
	uint8_t *buf = rgb_frame(&fr, DRM_FORMAT_BGR888, SIDE * 3);

	camera_texture_set_view(f->t, &v);
	assert_int_equal(camera_texture_update(f->t, &fr), 0);
	check_quadrants(f->t, quad_rgb, true, 1);
	v.mirror = false;
	camera_texture_set_view(f->t, &v);
	free(buf);
}

/* Y, then the chroma of each 2x2 block: interleaved (NV12/NV21) or in
 * two planes (YUV420/YVU420), with padded strides. */
static uint8_t *yuv_frame(struct camera_frame *fr, uint32_t fourcc, unsigned stride)
{
	const struct camera_layout *l;
	uint8_t *buf;
	size_t size;

	frame_init(fr, fourcc, stride);
	l = &fr->layout;
	size = l->plane[l->planes - 1].offset + (size_t)l->plane[l->planes - 1].stride * SIDE / 2;
	buf = malloc(size);
	assert_non_null(buf);
	memset(buf, 0x80, size);
	for (int y = 0; y < SIDE; y++)
		for (int x = 0; x < SIDE; x++) {
			const uint8_t *v = quad_yuv[quadrant(x, y)];
			size_t cy = (size_t)y / 2, cx = (size_t)x / 2;

			buf[(size_t)y * stride + (size_t)x] = v[0];
			if (l->kind == CAMERA_KIND_SEMI) {
				uint8_t *c =
				    buf + l->plane[1].offset + cy * l->plane[1].stride + cx * 2;

				c[l->order[0]] = v[1];
				c[l->order[1]] = v[2];
			} else {
				buf[l->plane[l->order[0]].offset + cy * l->plane[1].stride + cx] =
				    v[1];
				buf[l->plane[l->order[1]].offset + cy * l->plane[1].stride + cx] =
				    v[2];
			}
		}
	for (int p = 0; p < l->planes; p++)
		fr->plane[p].data = buf + l->plane[p].offset;
	return buf;
}

static void expected_rgb(enum camera_encoding e, enum camera_range r, uint8_t out[4][3])
{
	struct camera_yuv_matrix m;

	camera_yuv_matrix_make(e, r, &m);
	for (int q = 0; q < 4; q++)
		camera_yuv_to_rgb(&m, quad_yuv[q][0], quad_yuv[q][1], quad_yuv[q][2], out[q]);
}

static void yuv_formats_match_the_reference(void **state)
{
	struct fixture *f = *state;
	const struct {
		uint32_t fourcc;
		unsigned stride;
	} cases[] = {{DRM_FORMAT_NV12, SIDE},	     {DRM_FORMAT_NV12, SIDE + 16},
		     {DRM_FORMAT_NV21, SIDE + 2},    {DRM_FORMAT_YUV420, SIDE},
		     {DRM_FORMAT_YVU420, SIDE + 32}, {DRM_FORMAT_YUV420, SIDE + 6}};
	struct camera_frame fr;
	uint8_t want[4][3];

	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		for (int enc = 0; enc < 3; enc++) {
			uint8_t *buf = yuv_frame(&fr, cases[i].fourcc, cases[i].stride);

			fr.encoding = (enum camera_encoding)enc;
			fr.range = enc == 2 ? CAMERA_RANGE_FULL : CAMERA_RANGE_LIMITED;
			expected_rgb(fr.encoding, fr.range, want);
			assert_int_equal(camera_texture_update(f->t, &fr), 0);
			check_quadrants(f->t, want, false, 3);
			free(buf);
		}
	}
}

/* YUYV: alternate columns black and white with neutral chroma; the
 * shader must pick each pixel's own luma out of the pair. */
static void packed_yuv_keeps_every_column(void **state)
{
	struct fixture *f = *state;
	const uint32_t fourccs[2] = {DRM_FORMAT_YUYV, DRM_FORMAT_UYVY};
	struct camera_frame fr;
	struct image img;

	for (int i = 0; i < 2; i++) {
		unsigned stride = SIDE * 2 + 8;
		uint8_t *buf = malloc((size_t)stride * SIDE);

		assert_non_null(buf);
		frame_init(&fr, fourccs[i], stride);
		for (int y = 0; y < SIDE; y++)
			for (int pair = 0; pair < SIDE / 2; pair++) {
				uint8_t *t = buf + (size_t)y * stride + (size_t)pair * 4;

				t[fr.layout.order[0]] = 16;  /* Y0: black */
				t[fr.layout.order[1]] = 128; /* Cb */
				t[fr.layout.order[2]] = 235; /* Y1: white */
				t[fr.layout.order[3]] = 128; /* Cr */
			}
		fr.plane[0].data = buf;
		assert_int_equal(camera_texture_update(f->t, &fr), 0);
		assert_int_equal(camera_texture_read(f->t, &img), 0);
		for (int x = 0; x < SIDE; x++) {
			int v = img.rgba[((size_t)(SIDE / 2) * SIDE + (size_t)x) * 4 + 1];

			if (abs(v - (x % 2 ? 255 : 0)) > 2)
				fail_msg("column %d is %d", x, v);
		}
		image_release(&img);
		free(buf);
	}
}

static void a_crop_outside_the_frame_is_an_error(void **state)
{
	struct fixture *f = *state;
	struct camera_view v = {1.0, 0.5, 0.5, false};
	struct camera_frame fr;
	uint8_t *buf = rgb_frame(&fr, DRM_FORMAT_BGR888, SIDE * 3);

	camera_texture_set_view(f->t, &v);
	assert_int_equal(camera_texture_update(f->t, &fr), -EINVAL);
	v.cx = 0.5;
	camera_texture_set_view(f->t, &v);
	free(buf);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(rgb_formats_and_strides),
	    cmocka_unit_test(mirror_flips_left_and_right),
	    cmocka_unit_test(yuv_formats_match_the_reference),
	    cmocka_unit_test(packed_yuv_keeps_every_column),
	    cmocka_unit_test(a_crop_outside_the_frame_is_an_error),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
