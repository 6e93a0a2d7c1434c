#include "camera/camera_math.h"

#include <drm_fourcc.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Larger frames are refused: a matcap needs few pixels, and the sizes
 * below keep every product of them far from overflowing. */
#define MAX_SIDE 16384

/* 4-byte RGB first: GPUs import it as it is (few take 24-bit RGB), and it
 * uploads in aligned rows. */
const uint32_t camera_formats[] = {DRM_FORMAT_XBGR8888,
				   DRM_FORMAT_XRGB8888,
				   DRM_FORMAT_ABGR8888,
				   DRM_FORMAT_ARGB8888,
				   DRM_FORMAT_BGR888,
				   DRM_FORMAT_RGB888,
				   DRM_FORMAT_NV12,
				   DRM_FORMAT_NV21,
				   DRM_FORMAT_YUV420,
				   DRM_FORMAT_YVU420,
				   DRM_FORMAT_YUYV,
				   DRM_FORMAT_UYVY,
				   0};

struct format_desc {
	uint32_t fourcc;
	enum camera_kind kind;
	int bytes; /* per texel of plane 0 */
	int order[4];
};

/* DRM names formats by a little-endian word: BGR888 is the bytes R, G, B
 * in memory, XRGB8888 the bytes B, G, R, X. */
static const struct format_desc formats[] = {
    {DRM_FORMAT_BGR888, CAMERA_KIND_RGB, 3, {0, 1, 2, 0}},
    {DRM_FORMAT_RGB888, CAMERA_KIND_RGB, 3, {2, 1, 0, 0}},
    {DRM_FORMAT_XBGR8888, CAMERA_KIND_RGB, 4, {0, 1, 2, 0}},
    {DRM_FORMAT_ABGR8888, CAMERA_KIND_RGB, 4, {0, 1, 2, 0}},
    {DRM_FORMAT_XRGB8888, CAMERA_KIND_RGB, 4, {2, 1, 0, 0}},
    {DRM_FORMAT_ARGB8888, CAMERA_KIND_RGB, 4, {2, 1, 0, 0}},
    {DRM_FORMAT_NV12, CAMERA_KIND_SEMI, 1, {0, 1, 0, 0}},
    {DRM_FORMAT_NV21, CAMERA_KIND_SEMI, 1, {1, 0, 0, 0}},
    {DRM_FORMAT_YUV420, CAMERA_KIND_PLANAR, 1, {1, 2, 0, 0}},
    {DRM_FORMAT_YVU420, CAMERA_KIND_PLANAR, 1, {2, 1, 0, 0}},
    {DRM_FORMAT_YUYV, CAMERA_KIND_PACKED, 4, {0, 1, 2, 3}},
    {DRM_FORMAT_UYVY, CAMERA_KIND_PACKED, 4, {1, 0, 3, 2}},
};

static const struct format_desc *find_format(uint32_t fourcc)
{
	for (size_t i = 0; i < sizeof(formats) / sizeof(formats[0]); i++)
		if (formats[i].fourcc == fourcc)
			return &formats[i];
	return NULL;
}

bool camera_format_supported(uint32_t fourcc)
{
	return find_format(fourcc) != NULL;
}

static void set_plane(struct camera_plane_layout *p, int w, int h, int bytes, unsigned stride,
		      unsigned offset)
{
	*p = (struct camera_plane_layout){w, h, bytes, stride, offset};
}

int camera_layout_make(uint32_t fourcc, int width, int height, unsigned stride,
		       struct camera_layout *out)
{
	const struct format_desc *f = find_format(fourcc);
	int cw = (width + 1) / 2, ch = (height + 1) / 2;
	unsigned luma;

	memset(out, 0, sizeof(*out));
	if (!f)
		return -ENOTSUP;
	if (width < 2 || height < 2 || width > MAX_SIDE || height > MAX_SIDE)
		return -EINVAL;
	out->fourcc = fourcc;
	out->width = width;
	out->height = height;
	out->kind = f->kind;
	memcpy(out->order, f->order, sizeof(out->order));
	switch (f->kind) {
	case CAMERA_KIND_RGB:
		out->planes = 1;
		set_plane(&out->plane[0], width, height, f->bytes, stride, 0);
		break;
	case CAMERA_KIND_PACKED:
		out->planes = 1;
		set_plane(&out->plane[0], cw, height, 4, stride, 0);
		break;
	case CAMERA_KIND_SEMI:
		out->planes = 2;
		luma = stride * (unsigned)height;
		set_plane(&out->plane[0], width, height, 1, stride, 0);
		set_plane(&out->plane[1], cw, ch, 2, stride, luma);
		break;
	case CAMERA_KIND_PLANAR:
		out->planes = 3;
		luma = stride * (unsigned)height;
		set_plane(&out->plane[0], width, height, 1, stride, 0);
		set_plane(&out->plane[1], cw, ch, 1, stride / 2, luma);
		set_plane(&out->plane[2], cw, ch, 1, stride / 2, luma + stride / 2 * (unsigned)ch);
		break;
	}
	for (int i = 0; i < out->planes; i++) {
		const struct camera_plane_layout *p = &out->plane[i];

		if (p->stride < (unsigned)(p->width * p->bytes_per_texel) ||
		    p->stride > 8u * MAX_SIDE)
			return -EINVAL;
	}
	return 0;
}

size_t camera_plane_span(const struct camera_plane_layout *p)
{
	return (size_t)p->stride * (size_t)(p->height - 1) +
	       (size_t)p->width * (size_t)p->bytes_per_texel;
}

void camera_upload_plan(const struct camera_plane_layout *p, struct camera_upload *out)
{
	unsigned row = (unsigned)(p->width * p->bytes_per_texel);

	*out = (struct camera_upload){CAMERA_UPLOAD_ROWS, 1, p->width, 1.0};
	/* GL pads each row to the alignment: the stride must be exactly the
	 * padded row. The largest alignment that fits lets GL copy in the
	 * widest words. */
	for (int a = 8; a >= 1; a /= 2) {
		if (p->stride == (row + (unsigned)a - 1) / (unsigned)a * (unsigned)a) {
			out->mode = CAMERA_UPLOAD_ALIGNED;
			out->alignment = a;
			return;
		}
	}
	if (p->stride % (unsigned)p->bytes_per_texel == 0) {
		out->mode = CAMERA_UPLOAD_WIDE;
		out->texture_width = (int)(p->stride / (unsigned)p->bytes_per_texel);
		out->u_scale = (double)p->width / out->texture_width;
	}
}

int camera_crop_make(int width, int height, double cx, double cy, double radius, bool mirror,
		     struct camera_crop *out)
{
	double px = cx * width, py = cy * height;
	double r = radius * (width < height ? width : height);
	double fit = fmin(fmin(px, width - px), fmin(py, height - py));

	memset(out, 0, sizeof(*out));
	if (width < 1 || height < 1 || !(cx >= 0 && cx <= 1) || !(cy >= 0 && cy <= 1) ||
	    !(radius > 0))
		return -EINVAL;
	if (r > fit) {
		r = fit;
		out->shrunk = true;
	}
	/* Less than a pixel across: nothing to show. */
	if (r < 0.5)
		return -EINVAL;
	out->u0 = (px + (mirror ? r : -r)) / width;
	out->du = (mirror ? -2.0 : 2.0) * r / width;
	out->v0 = (py - r) / height;
	out->dv = 2.0 * r / height;
	return 0;
}

/* Kr and Kb of each encoding (ITU-R BT.601, BT.709, BT.2020). */
static const double luma_weights[3][2] = {{0.299, 0.114}, {0.2126, 0.0722}, {0.2627, 0.0593}};

void camera_yuv_matrix_make(enum camera_encoding enc, enum camera_range range,
			    struct camera_yuv_matrix *out)
{
	double kr = luma_weights[enc][0], kb = luma_weights[enc][1], kg = 1.0 - kr - kb;
	/* Limited range: Y 16..235, Cb and Cr 16..240 about 128. */
	double ys = range == CAMERA_RANGE_FULL ? 1.0 : 255.0 / 219.0;
	double cs = range == CAMERA_RANGE_FULL ? 1.0 : 255.0 / 224.0;
	double y0 = range == CAMERA_RANGE_FULL ? 0.0 : 16.0 / 255.0;
	double c0 = 128.0 / 255.0;
	double rows[3][3] = {
	    {1.0, 0.0, 2.0 * (1.0 - kr)},
	    {1.0, -2.0 * kb * (1.0 - kb) / kg, -2.0 * kr * (1.0 - kr) / kg},
	    {1.0, 2.0 * (1.0 - kb), 0.0},
	};

	for (int i = 0; i < 3; i++) {
		double m0 = rows[i][0] * ys, m1 = rows[i][1] * cs, m2 = rows[i][2] * cs;

		out->m[i][0] = (float)m0;
		out->m[i][1] = (float)m1;
		out->m[i][2] = (float)m2;
		out->offset[i] = (float)(-(m0 * y0 + m1 * c0 + m2 * c0));
	}
}

void camera_yuv_to_rgb(const struct camera_yuv_matrix *mat, uint8_t y, uint8_t cb, uint8_t cr,
		       uint8_t rgb[3])
{
	double in[3] = {y / 255.0, cb / 255.0, cr / 255.0};

	for (int i = 0; i < 3; i++) {
		double v = mat->offset[i];

		for (int j = 0; j < 3; j++)
			v += (double)mat->m[i][j] * in[j];
		v = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
		rgb[i] = (uint8_t)lround(v * 255.0);
	}
}

enum camera_encoding camera_default_encoding(int height)
{
	return height <= 576 ? CAMERA_ENC_REC601 : CAMERA_ENC_REC709;
}

void camera_stats_add(struct camera_stats *s, double v)
{
	s->v[s->total % CAMERA_STATS_MAX] = v;
	s->total++;
	if (s->n < CAMERA_STATS_MAX)
		s->n++;
}

static int compare_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

double camera_stats_percentile(const struct camera_stats *s, double p)
{
	double *copy;
	double v;
	int i;

	if (s->n == 0)
		return 0.0;
	copy = malloc(sizeof(double) * (size_t)s->n);
	if (!copy)
		return 0.0;
	memcpy(copy, s->v, sizeof(double) * (size_t)s->n);
	qsort(copy, (size_t)s->n, sizeof(double), compare_double);
	i = (int)(p * (s->n - 1) + 0.5);
	v = copy[i < 0 ? 0 : i >= s->n ? s->n - 1 : i];
	free(copy);
	return v;
}
