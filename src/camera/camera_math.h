/* The pure parts of the live camera matcap: how a frame's planes lie in
 * memory, how a plane of any stride gets into a GLES2 texture, where the
 * ball is in the frame, and YCbCr to RGB. No libcamera, no GL: the unit
 * tests check these against known values, and the GPU pass takes its
 * numbers from here. Formats are DRM fourccs, which is what libcamera's
 * PixelFormat holds. */
#ifndef MK_CAMERA_MATH_H
#define MK_CAMERA_MATH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CAMERA_MAX_PLANES 3

/* How the shader reads a format. */
enum camera_kind {
	CAMERA_KIND_RGB,    /* one plane of 3- or 4-byte pixels */
	CAMERA_KIND_SEMI,   /* Y plane + interleaved CbCr plane (NV12, NV21) */
	CAMERA_KIND_PLANAR, /* Y, Cb and Cr planes (YUV420, YVU420) */
	CAMERA_KIND_PACKED, /* Y0 Cb Y1 Cr in 4 bytes for 2 pixels (YUYV, UYVY) */
};

struct camera_plane_layout {
	int width; /* in texels: pixels, chroma samples, or pixel pairs */
	int height;
	int bytes_per_texel; /* 1, 2, 3 or 4 */
	unsigned stride;     /* bytes from one row to the next */
	unsigned offset;     /* from plane 0, when the planes are contiguous */
};

struct camera_layout {
	uint32_t fourcc;
	int width, height; /* in pixels */
	enum camera_kind kind;
	int planes;
	struct camera_plane_layout plane[CAMERA_MAX_PLANES];
	/* Byte order within a texel, as indexes into the texel's bytes:
	 * RGB: the bytes of red, green, blue; SEMI: of Cb, Cr in the chroma
	 * texel; PLANAR: the planes of Cb, Cr; PACKED: the bytes of Y0, Cb,
	 * Y1, Cr. */
	int order[4];
};

/* Preferred first: formats that upload as they are, then the YCbCr ones
 * the shader converts. Ends with 0. */
extern const uint32_t camera_formats[];
bool camera_format_supported(uint32_t fourcc);

/* The layout of a width x height frame whose first plane has the given
 * stride (libcamera reports that one only: the others follow V4L2's
 * rules, chroma rows of NV12 as long as luma rows, of YUV420 half).
 * Returns 0, -ENOTSUP for a format not handled, -EINVAL for a stride
 * shorter than a row or a size out of range. */
int camera_layout_make(uint32_t fourcc, int width, int height, unsigned stride,
		       struct camera_layout *out);

/* Bytes a plane spans from its offset: the last row is only as long as
 * its pixels, so a tightly allocated buffer is not refused. */
size_t camera_plane_span(const struct camera_plane_layout *p);

/* How one plane goes into a texture with GLES2, which has no row length
 * for unpacking: rows padded to 2, 4 or 8 bytes are a stated unpack
 * alignment; a stride that is a whole number of texels is a wider
 * texture of which the shader reads the left part; anything else is
 * uploaded row by row. */
enum camera_upload_mode { CAMERA_UPLOAD_ALIGNED, CAMERA_UPLOAD_WIDE, CAMERA_UPLOAD_ROWS };
struct camera_upload {
	enum camera_upload_mode mode;
	int alignment;	   /* GL_UNPACK_ALIGNMENT: 1, 2, 4 or 8 */
	int texture_width; /* texels */
	double u_scale;	   /* the image's share of the texture's width */
};
void camera_upload_plan(const struct camera_plane_layout *p, struct camera_upload *out);

/* The circle the ball fills: centre as shares of the frame's width and
 * height from its top-left corner, radius as a share of its shorter
 * side (0.5, 0.5, 0.5: the largest centred square). A circle that does
 * not fit is made smaller about the same centre. */
struct camera_crop {
	double u0, v0; /* the square's top-left corner, 0..1 of the frame */
	double du, dv; /* its width and height, 0..1; du < 0 when mirrored */
	bool shrunk;   /* the radius was made smaller to fit */
};
int camera_crop_make(int width, int height, double cx, double cy, double radius, bool mirror,
		     struct camera_crop *out);

/* YCbCr encodings and ranges, as libcamera's ColorSpace names them. */
enum camera_encoding { CAMERA_ENC_REC601, CAMERA_ENC_REC709, CAMERA_ENC_REC2020 };
enum camera_range { CAMERA_RANGE_LIMITED, CAMERA_RANGE_FULL };

/* rgb = m * (y, cb, cr) + offset, each input the byte / 255 (what a
 * shader samples from an 8-bit texture), rgb in 0..1 before clamping.
 * m is row-major. */
struct camera_yuv_matrix {
	float m[3][3];
	float offset[3];
};
void camera_yuv_matrix_make(enum camera_encoding enc, enum camera_range range,
			    struct camera_yuv_matrix *out);
/* The reference conversion of one 8-bit sample, rounded and clamped. */
void camera_yuv_to_rgb(const struct camera_yuv_matrix *mat, uint8_t y, uint8_t cb, uint8_t cr,
		       uint8_t rgb[3]);
/* What to assume when the camera does not say: BT.601 for SD frames
 * (576 lines or fewer), BT.709 for HD, both limited range (what V4L2's
 * default colour spaces are for YCbCr). */
enum camera_encoding camera_default_encoding(int height);

/* Percentiles of a window of samples (frame latencies, CPU times). */
#define CAMERA_STATS_MAX 4096
struct camera_stats {
	double v[CAMERA_STATS_MAX];
	int n;	    /* samples held, at most CAMERA_STATS_MAX */
	long total; /* samples ever added */
};
void camera_stats_add(struct camera_stats *s, double v);
/* p in 0..1; 0 when empty. Sorts a copy. */
double camera_stats_percentile(const struct camera_stats *s, double p);

#ifdef __cplusplus
}
#endif

#endif
