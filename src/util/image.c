#include "util/image.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <png.h>
#include <stdbool.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <turbojpeg.h>
#include <webp/decode.h>

/* Files larger than this are not matcaps or textures a kiosk can use. */
#define IMAGE_MAX_FILE (64u << 20)

int image_alloc(struct image *img, int width, int height)
{
	img->width = 0;
	img->height = 0;
	img->rgba = NULL;
	if (width <= 0 || height <= 0 || width > IMAGE_MAX_SIDE || height > IMAGE_MAX_SIDE)
		return -EINVAL;
	img->rgba = calloc((size_t)width * (size_t)height, 4);
	if (!img->rgba)
		return -ENOMEM;
	img->width = width;
	img->height = height;
	return 0;
}

void image_release(struct image *img)
{
	free(img->rgba);
	img->rgba = NULL;
	img->width = 0;
	img->height = 0;
}

struct png_source {
	const char *name;
	const uint8_t *data;
	size_t size;
	size_t pos;
};

static void png_read_mem(png_structp png, png_bytep out, png_size_t len)
{
	struct png_source *src = png_get_io_ptr(png);

	if (len > src->size - src->pos)
		png_error(png, "file ends early (truncated)");
	memcpy(out, src->data + src->pos, len);
	src->pos += len;
}

static void png_log_error(png_structp png, png_const_charp msg)
{
	struct png_source *src = png_get_error_ptr(png);

	log_err("%s: not a valid PNG: %s", src->name, msg);
	png_longjmp(png, 1);
}

static void png_log_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg; /* libpng warns about harmless things (sRGB profiles) */
}

/* An interlaced PNG is read whole (its rows come in seven passes): one to
 * be made smaller is refused over this. */
#define IMAGE_WHOLE_MAX (64u << 20)

static int fit_dim(int n, int shift)
{
	return (int)(((long)n + (1L << shift) - 1) >> shift);
}

void image_fit_shifts(int w, int h, const struct image_fit *fit, int *sx, int *sy, int *ow, int *oh)
{
	int x = 0, y = 0;

	while (fit && fit->side > 0 && (w >> (x + 1)) >= fit->side)
		x++;
	while (fit && fit->side > 0 && (h >> (y + 1)) >= fit->side)
		y++;
	while (fit && fit->bytes && w > 0 && h > 0 &&
	       (size_t)fit_dim(w, x) * (size_t)fit_dim(h, y) * 4 > fit->bytes &&
	       (fit_dim(w, x) > 1 || fit_dim(h, y) > 1)) {
		x += fit_dim(w, x) > 1;
		y += fit_dim(h, y) > 1;
	}
	if (sx)
		*sx = x;
	if (sy)
		*sy = y;
	if (ow)
		*ow = fit_dim(w, x);
	if (oh)
		*oh = fit_dim(h, y);
}

/* A box filter fed one row at a time: each output texel is the rounded
 * mean of its 2^sx x 2^sy block (fewer at the right and bottom edges). */
struct box {
	struct image *out;
	int w, h, sx, sy;
	int row;       /* rows added */
	uint64_t *sum; /* the output row being summed, RGBA */
};

static int box_start(struct box *b, int w, int h, int sx, int sy, struct image *out)
{
	int ret = image_alloc(out, fit_dim(w, sx), fit_dim(h, sy));

	*b = (struct box){out, w, h, sx, sy, 0, NULL};
	if (!ret && !(b->sum = calloc((size_t)out->width * 4, sizeof(*b->sum)))) {
		image_release(out);
		ret = -ENOMEM;
	}
	return ret;
}

static void box_add(struct box *b, const uint8_t *row)
{
	int oy, rows;
	uint8_t *dst;

	for (int x = 0; x < b->w; x++)
		for (int c = 0; c < 4; c++)
			b->sum[(size_t)(x >> b->sx) * 4 + c] += row[(size_t)x * 4 + c];
	b->row++;
	if ((b->row & ((1 << b->sy) - 1)) && b->row < b->h)
		return;
	oy = (b->row - 1) >> b->sy;
	rows = b->row - (oy << b->sy);
	dst = b->out->rgba + (size_t)oy * (size_t)b->out->width * 4;
	for (int ox = 0; ox < b->out->width; ox++) {
		int cols = b->w - (ox << b->sx) < (1 << b->sx) ? b->w - (ox << b->sx) : 1 << b->sx;
		uint64_t n = (uint64_t)rows * (uint64_t)cols;

		for (int c = 0; c < 4; c++) {
			uint64_t *s = &b->sum[(size_t)ox * 4 + c];

			dst[ox * 4 + c] = (uint8_t)((*s + n / 2) / n);
			*s = 0;
		}
	}
}

static void box_end(struct box *b)
{
	free(b->sum);
	b->sum = NULL;
}

/* src made smaller into out, by the box filter. */
static int box_image(const struct image *src, int sx, int sy, struct image *out)
{
	struct box b;
	int ret = box_start(&b, src->width, src->height, sx, sy, out);

	for (int y = 0; !ret && y < src->height; y++)
		box_add(&b, src->rgba + (size_t)y * (size_t)src->width * 4);
	box_end(&b);
	return ret;
}

/* What a PNG decode holds, on the heap: libpng's errors longjmp, and what
 * changed after setjmp must be read back from memory. */
struct png_job {
	struct png_source src;
	int ret, w, h;
	png_bytep *rows;
	uint8_t *row;
	struct image whole;
	struct box box;
};

static void png_job_free(struct png_job *j)
{
	free(j->rows);
	free(j->row);
	image_release(&j->whole);
	box_end(&j->box);
	free(j);
}

static void png_read_whole(png_structp png, struct png_job *j, struct image *img)
{
	j->ret = image_alloc(img, j->w, j->h);
	if (!j->ret && !(j->rows = malloc(sizeof(*j->rows) * (size_t)j->h)))
		j->ret = -ENOMEM;
	if (j->ret)
		return;
	for (int y = 0; y < j->h; y++)
		j->rows[y] = img->rgba + (size_t)y * (size_t)j->w * 4;
	png_read_image(png, j->rows);
	png_read_end(png, NULL);
}

/* Row by row through the box filter: the full size is never held. */
static void png_read_boxed(png_structp png, struct png_job *j, int sx, int sy, struct image *out)
{
	j->ret = box_start(&j->box, j->w, j->h, sx, sy, out);
	if (!j->ret && !(j->row = malloc((size_t)j->w * 4)))
		j->ret = -ENOMEM;
	for (int y = 0; !j->ret && y < j->h; y++) {
		png_read_row(png, j->row, NULL);
		box_add(&j->box, j->row);
	}
	if (!j->ret)
		png_read_end(png, NULL);
}

static void png_read_pixels(png_structp png, png_infop info, struct png_job *j,
			    const struct image_fit *fit, struct image *out)
{
	bool interlaced = png_get_interlace_type(png, info) != PNG_INTERLACE_NONE;
	int sx, sy;

	image_fit_shifts(j->w, j->h, fit, &sx, &sy, NULL, NULL);
	if (!sx && !sy) {
		png_read_whole(png, j, out);
	} else if (!interlaced) {
		png_read_boxed(png, j, sx, sy, out);
	} else if ((size_t)j->w * (size_t)j->h * 4 > IMAGE_WHOLE_MAX) {
		log_err("%s: an interlaced PNG of %dx%d is read whole, over %u MiB: expected one "
			"not interlaced, or smaller",
			j->src.name, j->w, j->h, IMAGE_WHOLE_MAX >> 20);
		j->ret = -EFBIG;
	} else {
		png_read_whole(png, j, &j->whole);
		if (!j->ret)
			j->ret = box_image(&j->whole, sx, sy, out);
	}
}

static int png_decode(const char *name, const uint8_t *data, size_t size,
		      const struct image_fit *fit, struct image *out, int *full_w, int *full_h)
{
	struct png_job *j = calloc(1, sizeof(*j));
	png_structp png;
	png_infop info = NULL;
	int ret;

	if (!j)
		return -ENOMEM;
	j->src = (struct png_source){name, data, size, 0};
	j->ret = -EINVAL;
	png =
	    png_create_read_struct(PNG_LIBPNG_VER_STRING, &j->src, png_log_error, png_log_warning);
	if (!png) {
		j->ret = -ENOMEM;
		goto out;
	}
	info = png_create_info_struct(png);
	if (!info)
		goto out;
	if (setjmp(png_jmpbuf(png))) {
		j->ret = -EINVAL;
		image_release(out);
		goto out;
	}
	png_set_user_limits(png, IMAGE_MAX_SIDE, IMAGE_MAX_SIDE);
	png_set_read_fn(png, &j->src, png_read_mem);
	png_read_info(png, info);
	/* Whatever the file holds, hand back 8-bit RGBA. */
	png_set_expand(png);
	png_set_strip_16(png);
	png_set_gray_to_rgb(png);
	png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
	png_set_interlace_handling(png);
	png_read_update_info(png, info);
	j->w = (int)png_get_image_width(png, info);
	j->h = (int)png_get_image_height(png, info);
	if (png_get_rowbytes(png, info) != (size_t)j->w * 4) {
		log_err("%s: unsupported PNG pixel layout", name);
		goto out;
	}
	png_read_pixels(png, info, j, fit, out);
	if (j->ret)
		image_release(out);
out:
	if (full_w)
		*full_w = j->w;
	if (full_h)
		*full_h = j->h;
	ret = j->ret;
	png_destroy_read_struct(&png, info ? &info : NULL, NULL);
	png_job_free(j);
	return ret;
}

/* libjpeg-turbo scales by 1/2, 1/4 and 1/8 as it decodes (the same on
 * both axes); a further halving of one axis is the box filter's. */
static int jpeg_read(tjhandle tj, const char *name, const uint8_t *data, size_t size, int w, int h,
		     const struct image_fit *fit, struct image *out)
{
	int sx, sy, k;
	struct image scaled = {0};
	int ret;

	image_fit_shifts(w, h, fit, &sx, &sy, NULL, NULL);
	k = sx < sy ? sx : sy;
	k = k > 3 ? 3 : k;
	ret = image_alloc(sx == k && sy == k ? out : &scaled, fit_dim(w, k), fit_dim(h, k));
	if (ret)
		return ret;
	struct image *dst = sx == k && sy == k ? out : &scaled;
	/* A warning means corrupt or truncated data (libjpeg pads it with
	 * grey): a file cut short by an interrupted copy is refused, not
	 * shown half grey. */
	if (tjDecompress2(tj, data, (unsigned long)size, dst->rgba, dst->width, 0, dst->height,
			  TJPF_RGBA, TJFLAG_ACCURATEDCT | TJFLAG_STOPONWARNING)) {
		log_err("%s: not a valid JPEG: %s", name, tjGetErrorStr2(tj));
		image_release(dst);
		return -EINVAL;
	}
	if (dst == &scaled) {
		ret = box_image(&scaled, sx - k, sy - k, out);
		image_release(&scaled);
	}
	return ret;
}

static int jpeg_decode(const char *name, const uint8_t *data, size_t size,
		       const struct image_fit *fit, struct image *out, int *full_w, int *full_h)
{
	tjhandle tj = tjInitDecompress();
	int w = 0, h = 0, subsamp, colorspace;
	int ret = -EINVAL;

	if (!tj)
		return -ENOMEM;
	if (tjDecompressHeader3(tj, data, (unsigned long)size, &w, &h, &subsamp, &colorspace)) {
		log_err("%s: not a valid JPEG: %s", name, tjGetErrorStr2(tj));
		goto out;
	}
	if (w <= 0 || h <= 0 || w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE) {
		log_err("%s: JPEG is %dx%d, expected at most %dx%d", name, w, h, IMAGE_MAX_SIDE,
			IMAGE_MAX_SIDE);
		goto out;
	}
	ret = jpeg_read(tj, name, data, size, w, h, fit, out);
out:
	if (full_w)
		*full_w = w;
	if (full_h)
		*full_h = h;
	tjDestroy(tj);
	return ret;
}

/* libwebp scales as it decodes (into the size the fit gives, any ratio):
 * the full size of a large WebP is never held. */
static int webp_decode(const char *name, const uint8_t *data, size_t size,
		       const struct image_fit *fit, struct image *out, int *full_w, int *full_h)
{
	WebPDecoderConfig cfg;
	int ret = -EINVAL, w = 0, h = 0;

	if (!WebPInitDecoderConfig(&cfg))
		return -EINVAL; /* a libwebp of another ABI than the headers */
	if (WebPGetFeatures(data, size, &cfg.input) != VP8_STATUS_OK) {
		log_err("%s: not a valid WebP: its header cannot be read", name);
		goto out;
	}
	w = cfg.input.width;
	h = cfg.input.height;
	if (w <= 0 || h <= 0 || w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE) {
		log_err("%s: WebP is %dx%d, expected at most %dx%d", name, w, h, IMAGE_MAX_SIDE,
			IMAGE_MAX_SIDE);
		goto out;
	}
	image_fit_shifts(w, h, fit, NULL, NULL, &cfg.options.scaled_width,
			 &cfg.options.scaled_height);
	cfg.options.use_scaling = cfg.options.scaled_width != w || cfg.options.scaled_height != h;
	ret = image_alloc(out, cfg.options.scaled_width, cfg.options.scaled_height);
	if (ret)
		goto out;
	cfg.output.colorspace = MODE_RGBA;
	cfg.output.is_external_memory = 1;
	cfg.output.u.RGBA.rgba = out->rgba;
	cfg.output.u.RGBA.stride = out->width * 4;
	cfg.output.u.RGBA.size = (size_t)out->width * (size_t)out->height * 4;
	if (WebPDecode(data, size, &cfg) != VP8_STATUS_OK) {
		/* A truncated file is refused, not shown half decoded. */
		log_err("%s: not a valid WebP: its %dx%d picture cannot be decoded (truncated or "
			"corrupt)",
			name, w, h);
		image_release(out);
		ret = -EINVAL;
	}
	WebPFreeDecBuffer(&cfg.output);
out:
	if (full_w)
		*full_w = w;
	if (full_h)
		*full_h = h;
	return ret;
}

/* KTX2 (KHR_texture_basisu): recognised to be refused by name. */
static const uint8_t ktx2_sig[12] = {0xab, 'K',	 'T',  'X',  ' ',  '2',
				     '0',  0xbb, '\r', '\n', 0x1a, '\n'};

int image_decode_fit(const char *name, const uint8_t *data, size_t size,
		     const struct image_fit *fit, struct image *out, int *full_w, int *full_h)
{
	static const uint8_t png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

	out->width = 0;
	out->height = 0;
	out->rgba = NULL;
	if (size >= 8 && memcmp(data, png_sig, 8) == 0)
		return png_decode(name, data, size, fit, out, full_w, full_h);
	if (size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff)
		return jpeg_decode(name, data, size, fit, out, full_w, full_h);
	if (size >= 12 && !memcmp(data, "RIFF", 4) && !memcmp(data + 8, "WEBP", 4))
		return webp_decode(name, data, size, fit, out, full_w, full_h);
	if (size >= sizeof(ktx2_sig) && !memcmp(data, ktx2_sig, sizeof(ktx2_sig)))
		log_err("%s: a KTX2 image (KHR_texture_basisu) is not supported: no KTX2 "
			"transcoder in Debian 12/13; expected a PNG, JPEG or WebP image",
			name);
	else if (size == 0)
		log_err("%s: file is empty, expected a PNG, JPEG or WebP image", name);
	else
		log_err("%s: not a PNG, JPEG or WebP image (unknown signature)", name);
	return -EINVAL;
}

int image_decode(const char *name, const uint8_t *data, size_t size, struct image *out)
{
	return image_decode_fit(name, data, size, NULL, out, NULL, NULL);
}

int image_load(const char *path, struct image *out)
{
	return image_load_fit(path, NULL, out);
}

int image_load_fit(const char *path, const struct image_fit *fit, struct image *out)
{
	unsigned char *data;
	size_t size;
	int ret = file_read_all(path, IMAGE_MAX_FILE, &data, &size);

	out->rgba = NULL;
	if (ret == -EFBIG)
		log_err("%s: file is larger than %u bytes, the most expected", path,
			IMAGE_MAX_FILE);
	else if (ret && file_refusal(ret))
		log_err("%s: %s", path, file_refusal(ret));
	else if (ret)
		log_err("%s: cannot open: %s", path, strerror(-ret));
	else
		ret = image_decode_fit(path, data, size, fit, out, NULL, NULL);
	free(data);
	return ret;
}

int image_write_png(const char *path, const struct image *img)
{
	FILE *f = fopen(path, "wb");
	png_structp png = NULL;
	png_infop info = NULL;
	int ret = -EIO;

	if (!f) {
		ret = -errno;
		log_err("%s: cannot write: %s", path, strerror(errno));
		return ret;
	}
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	if (!png)
		goto out;
	info = png_create_info_struct(png);
	if (!info)
		goto out;
	if (setjmp(png_jmpbuf(png))) {
		log_err("%s: PNG encoding failed", path);
		goto out;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8,
		     PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
		     PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (int y = 0; y < img->height; y++)
		png_write_row(png, img->rgba + (size_t)y * (size_t)img->width * 4);
	png_write_end(png, NULL);
	ret = 0;
out:
	png_destroy_write_struct(&png, &info);
	if (fclose(f) && !ret) {
		log_err("%s: write error", path);
		ret = -EIO;
	}
	return ret;
}
