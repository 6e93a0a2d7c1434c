/* The pure parts of the camera matcap: plane layouts and strides, the
 * upload plan GLES2 can follow, the crop circle, and YCbCr to RGB against
 * values worked out by hand from BT.601 and BT.709. */
#include "camera/camera_math.h"

#include <drm_fourcc.h>
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

static void rgb_formats_are_one_plane(void **state)
{
	struct camera_layout l;

	(void)state;
	/* vimc's Sensor B: BGR888 is the bytes R, G, B. */
	assert_int_equal(camera_layout_make(DRM_FORMAT_BGR888, 1920, 1080, 5760, &l), 0);
	assert_int_equal(l.kind, CAMERA_KIND_RGB);
	assert_int_equal(l.planes, 1);
	assert_int_equal(l.plane[0].width, 1920);
	assert_int_equal(l.plane[0].bytes_per_texel, 3);
	assert_int_equal(l.order[0], 0);
	assert_int_equal(l.order[2], 2);
	/* XRGB8888 is the bytes B, G, R, X: red is byte 2. */
	assert_int_equal(camera_layout_make(DRM_FORMAT_XRGB8888, 640, 480, 2560, &l), 0);
	assert_int_equal(l.plane[0].bytes_per_texel, 4);
	assert_int_equal(l.order[0], 2);
	assert_int_equal(l.order[2], 0);
}

static void nv12_chroma_follows_the_luma_stride(void **state)
{
	struct camera_layout l;

	(void)state;
	assert_int_equal(camera_layout_make(DRM_FORMAT_NV12, 636, 480, 640, &l), 0);
	assert_int_equal(l.kind, CAMERA_KIND_SEMI);
	assert_int_equal(l.planes, 2);
	assert_int_equal(l.plane[0].stride, 640);
	assert_int_equal(l.plane[1].stride, 640);
	assert_int_equal(l.plane[1].width, 318);
	assert_int_equal(l.plane[1].height, 240);
	assert_int_equal(l.plane[1].bytes_per_texel, 2);
	assert_int_equal(l.plane[1].offset, 640 * 480);
	/* NV21 swaps Cb and Cr in the chroma texel. */
	assert_int_equal(camera_layout_make(DRM_FORMAT_NV21, 636, 480, 640, &l), 0);
	assert_int_equal(l.order[0], 1);
	assert_int_equal(l.order[1], 0);
}

static void yuv420_odd_sizes_round_chroma_up(void **state)
{
	struct camera_layout l;

	(void)state;
	assert_int_equal(camera_layout_make(DRM_FORMAT_YUV420, 635, 479, 640, &l), 0);
	assert_int_equal(l.planes, 3);
	assert_int_equal(l.plane[1].width, 318);
	assert_int_equal(l.plane[1].height, 240);
	assert_int_equal(l.plane[1].stride, 320);
	assert_int_equal(l.plane[2].stride, 320);
	assert_int_equal(l.plane[1].offset, 640 * 479);
	assert_int_equal(l.plane[2].offset, 640 * 479 + 320 * 240);
	assert_int_equal(l.order[0], 1); /* Cb is plane 1 */
	assert_int_equal(camera_layout_make(DRM_FORMAT_YVU420, 635, 479, 640, &l), 0);
	assert_int_equal(l.order[0], 2); /* YV12: Cr first */
}

static void packed_formats_hold_pixel_pairs(void **state)
{
	struct camera_layout l;

	(void)state;
	assert_int_equal(camera_layout_make(DRM_FORMAT_YUYV, 641, 480, 1284, &l), 0);
	assert_int_equal(l.kind, CAMERA_KIND_PACKED);
	assert_int_equal(l.width, 641);
	assert_int_equal(l.plane[0].width, 321);
	assert_int_equal(l.plane[0].bytes_per_texel, 4);
	assert_int_equal(camera_layout_make(DRM_FORMAT_UYVY, 640, 480, 1280, &l), 0);
	assert_int_equal(l.order[0], 1); /* Y0 is byte 1 */
	assert_int_equal(l.order[1], 0); /* Cb byte 0 */
}

static void bad_layouts_are_refused(void **state)
{
	struct camera_layout l;

	(void)state;
	assert_int_equal(camera_layout_make(DRM_FORMAT_BGR888, 640, 480, 1919, &l), -EINVAL);
	assert_int_equal(camera_layout_make(DRM_FORMAT_NV12, 640, 480, 639, &l), -EINVAL);
	assert_int_equal(camera_layout_make(DRM_FORMAT_BGR888, 0, 480, 1920, &l), -EINVAL);
	assert_int_equal(camera_layout_make(DRM_FORMAT_BGR888, 100000, 4, 300000, &l), -EINVAL);
	assert_int_equal(camera_layout_make(fourcc_code('M', 'J', 'P', 'G'), 640, 480, 0, &l),
			 -ENOTSUP);
	assert_false(camera_format_supported(fourcc_code('M', 'J', 'P', 'G')));
	for (const uint32_t *f = camera_formats; *f; f++)
		assert_true(camera_format_supported(*f));
}

static void the_last_row_needs_no_padding(void **state)
{
	struct camera_layout l;

	(void)state;
	assert_int_equal(camera_layout_make(DRM_FORMAT_BGR888, 636, 480, 1920, &l), 0);
	assert_int_equal(camera_plane_span(&l.plane[0]), 1920u * 479u + 636u * 3u);
	assert_int_equal(camera_layout_make(DRM_FORMAT_NV12, 636, 480, 640, &l), 0);
	assert_int_equal(camera_plane_span(&l.plane[1]), 640u * 239u + 318u * 2u);
}

static void upload_plans_cover_every_stride(void **state)
{
	struct camera_plane_layout p = {636, 480, 3, 1908, 0};
	struct camera_upload up;

	(void)state;
	/* Tight rows: the largest alignment that describes them. */
	camera_upload_plan(&p, &up);
	assert_int_equal(up.mode, CAMERA_UPLOAD_ALIGNED);
	assert_int_equal(up.alignment, 4);
	/* Rows padded to 8 bytes. */
	p.width = 635;
	p.stride = 1912;
	camera_upload_plan(&p, &up);
	assert_int_equal(up.mode, CAMERA_UPLOAD_ALIGNED);
	assert_int_equal(up.alignment, 8);
	assert_int_equal(up.texture_width, 635);
	/* Padded to 64 bytes: a wider texture, read in part. */
	p.width = 636;
	p.stride = 1920;
	camera_upload_plan(&p, &up);
	assert_int_equal(up.mode, CAMERA_UPLOAD_WIDE);
	assert_int_equal(up.texture_width, 640);
	assert_true(fabs(up.u_scale - 636.0 / 640.0) < 1e-12);
	/* Neither: row by row. */
	p.stride = 1910;
	camera_upload_plan(&p, &up);
	assert_int_equal(up.mode, CAMERA_UPLOAD_ROWS);
	assert_int_equal(up.texture_width, 636);
	/* An NV12 chroma plane with its luma stride: 636 bytes padded to 8. */
	p = (struct camera_plane_layout){318, 240, 2, 640, 0};
	camera_upload_plan(&p, &up);
	assert_int_equal(up.mode, CAMERA_UPLOAD_ALIGNED);
	assert_int_equal(up.alignment, 8);
	assert_int_equal(up.texture_width, 318);
	/* 600 bytes padded to 640: wide. */
	p.width = 300;
	camera_upload_plan(&p, &up);
	assert_int_equal(up.mode, CAMERA_UPLOAD_WIDE);
	assert_int_equal(up.texture_width, 320);
}

static void crop_default_is_the_largest_centred_square(void **state)
{
	struct camera_crop c;

	(void)state;
	assert_int_equal(camera_crop_make(1920, 1080, 0.5, 0.5, 0.5, false, &c), 0);
	assert_false(c.shrunk);
	assert_true(fabs(c.u0 - 420.0 / 1920) < 1e-12 && fabs(c.du - 1080.0 / 1920) < 1e-12);
	assert_true(fabs(c.v0) < 1e-12 && fabs(c.dv - 1.0) < 1e-12);
	/* Mirrored: from the right edge of the square, leftwards. */
	assert_int_equal(camera_crop_make(1920, 1080, 0.5, 0.5, 0.5, true, &c), 0);
	assert_true(fabs(c.u0 - 1500.0 / 1920) < 1e-12 && fabs(c.du + 1080.0 / 1920) < 1e-12);
	/* Portrait: the width is the short side. */
	assert_int_equal(camera_crop_make(480, 640, 0.5, 0.5, 0.5, false, &c), 0);
	assert_true(fabs(c.u0) < 1e-12 && fabs(c.du - 1.0) < 1e-12);
	assert_true(fabs(c.v0 - 80.0 / 640) < 1e-12 && fabs(c.dv - 0.75) < 1e-12);
}

static void crop_off_centre_shrinks_to_fit(void **state)
{
	struct camera_crop c;

	(void)state;
	/* A ball at (0.25, 0.4) with radius 0.2 of 1080 = 216 px fits. */
	assert_int_equal(camera_crop_make(1920, 1080, 0.25, 0.4, 0.2, false, &c), 0);
	assert_false(c.shrunk);
	assert_true(fabs(c.u0 - (480.0 - 216) / 1920) < 1e-12);
	assert_true(fabs(c.v0 - (432.0 - 216) / 1080) < 1e-12);
	/* Near the right edge: 192 px is all there is. */
	assert_int_equal(camera_crop_make(1920, 1080, 0.9, 0.5, 0.5, false, &c), 0);
	assert_true(c.shrunk);
	assert_true(fabs(c.du - 384.0 / 1920) < 1e-9 && fabs(c.dv - 384.0 / 1080) < 1e-9);
	/* On the edge there is no circle; nonsense is refused. */
	assert_int_equal(camera_crop_make(1920, 1080, 1.0, 0.5, 0.5, false, &c), -EINVAL);
	assert_int_equal(camera_crop_make(1920, 1080, 0.5, 0.5, 0.0, false, &c), -EINVAL);
	assert_int_equal(camera_crop_make(1920, 1080, NAN, 0.5, 0.5, false, &c), -EINVAL);
	assert_int_equal(camera_crop_make(1920, 1080, 1.5, 0.5, 0.5, false, &c), -EINVAL);
}

static void assert_rgb(enum camera_encoding e, enum camera_range r, int y, int cb, int cr, int er,
		       int eg, int eb)
{
	struct camera_yuv_matrix m;
	uint8_t rgb[3];

	camera_yuv_matrix_make(e, r, &m);
	camera_yuv_to_rgb(&m, (uint8_t)y, (uint8_t)cb, (uint8_t)cr, rgb);
	if (abs(rgb[0] - er) > 2 || abs(rgb[1] - eg) > 2 || abs(rgb[2] - eb) > 2)
		fail_msg("YCbCr %d %d %d gave %d %d %d, expected %d %d %d", y, cb, cr, rgb[0],
			 rgb[1], rgb[2], er, eg, eb);
}

/* Each value from Y = 16 + 219 (Kr R + Kg G + Kb B), Cb = 128 + 224 (B - Y)
 * / (2 (1 - Kb)), Cr = 128 + 224 (R - Y) / (2 (1 - Kr)), rounded. */
static void bt601_limited_known_colours(void **state)
{
	enum camera_encoding e = CAMERA_ENC_REC601;
	enum camera_range r = CAMERA_RANGE_LIMITED;

	(void)state;
	assert_rgb(e, r, 16, 128, 128, 0, 0, 0);
	assert_rgb(e, r, 235, 128, 128, 255, 255, 255);
	assert_rgb(e, r, 126, 128, 128, 128, 128, 128);
	assert_rgb(e, r, 81, 90, 240, 255, 0, 0);
	assert_rgb(e, r, 145, 54, 34, 0, 255, 0);
	assert_rgb(e, r, 41, 240, 110, 0, 0, 255);
	assert_rgb(e, r, 210, 16, 146, 255, 255, 0); /* yellow */
	/* Footroom and headroom clamp. */
	assert_rgb(e, r, 0, 128, 128, 0, 0, 0);
	assert_rgb(e, r, 255, 128, 128, 255, 255, 255);
}

static void bt709_and_full_range_known_colours(void **state)
{
	(void)state;
	assert_rgb(CAMERA_ENC_REC709, CAMERA_RANGE_LIMITED, 63, 102, 240, 255, 0, 0);
	assert_rgb(CAMERA_ENC_REC709, CAMERA_RANGE_LIMITED, 173, 42, 26, 0, 255, 0);
	assert_rgb(CAMERA_ENC_REC709, CAMERA_RANGE_LIMITED, 32, 240, 118, 0, 0, 255);
	/* Full range (JPEG): Y 0..255, chroma / 255. */
	assert_rgb(CAMERA_ENC_REC601, CAMERA_RANGE_FULL, 0, 128, 128, 0, 0, 0);
	assert_rgb(CAMERA_ENC_REC601, CAMERA_RANGE_FULL, 255, 128, 128, 255, 255, 255);
	assert_rgb(CAMERA_ENC_REC601, CAMERA_RANGE_FULL, 76, 85, 255, 254, 0, 0);
	assert_rgb(CAMERA_ENC_REC2020, CAMERA_RANGE_LIMITED, 74, 97, 240, 255, 0, 0);
}

static void matrix_offsets_are_consistent(void **state)
{
	struct camera_yuv_matrix m;

	(void)state;
	/* Grey (any Y, Cb = Cr = 128) has equal channels in every encoding:
	 * the chroma columns of each row cancel at 128. */
	for (int e = 0; e < 3; e++) {
		camera_yuv_matrix_make((enum camera_encoding)e, CAMERA_RANGE_LIMITED, &m);
		for (int i = 0; i < 3; i++)
			assert_true(fabs(m.m[i][0] * 16.0f / 255 + m.m[i][1] * 128.0f / 255 +
					 m.m[i][2] * 128.0f / 255 + m.offset[i]) < 1e-6);
	}
	assert_int_equal(camera_default_encoding(480), CAMERA_ENC_REC601);
	assert_int_equal(camera_default_encoding(576), CAMERA_ENC_REC601);
	assert_int_equal(camera_default_encoding(720), CAMERA_ENC_REC709);
}

static void stats_percentiles(void **state)
{
	struct camera_stats *s = calloc(1, sizeof(*s));

	(void)state;
	assert_non_null(s);
	assert_true(camera_stats_percentile(s, 0.5) == 0.0);
	for (int i = 100; i >= 1; i--)
		camera_stats_add(s, i);
	assert_true(fabs(camera_stats_percentile(s, 0.5) - 51) <= 1);
	assert_true(fabs(camera_stats_percentile(s, 0.9) - 90) <= 1);
	/* The window keeps the newest samples. */
	for (int i = 0; i < CAMERA_STATS_MAX; i++)
		camera_stats_add(s, 7);
	assert_int_equal(s->n, CAMERA_STATS_MAX);
	assert_true(camera_stats_percentile(s, 0.99) == 7);
	free(s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(rgb_formats_are_one_plane),
	    cmocka_unit_test(nv12_chroma_follows_the_luma_stride),
	    cmocka_unit_test(yuv420_odd_sizes_round_chroma_up),
	    cmocka_unit_test(packed_formats_hold_pixel_pairs),
	    cmocka_unit_test(bad_layouts_are_refused),
	    cmocka_unit_test(the_last_row_needs_no_padding),
	    cmocka_unit_test(upload_plans_cover_every_stride),
	    cmocka_unit_test(crop_default_is_the_largest_centred_square),
	    cmocka_unit_test(crop_off_centre_shrinks_to_fit),
	    cmocka_unit_test(bt601_limited_known_colours),
	    cmocka_unit_test(bt709_and_full_range_known_colours),
	    cmocka_unit_test(matrix_offsets_are_consistent),
	    cmocka_unit_test(stats_percentiles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
