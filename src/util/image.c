#include "util/image.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <turbojpeg.h>

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

static int png_decode(const char *name, const uint8_t *data, size_t size, struct image *out)
{
	struct png_source src = {name, data, size, 0};
	png_structp png;
	png_infop info = NULL;
	png_bytep *volatile rows = NULL;
	volatile int ret = -EINVAL;

	png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &src, png_log_error, png_log_warning);
	if (!png)
		return -ENOMEM;
	info = png_create_info_struct(png);
	if (!info)
		goto out;
	if (setjmp(png_jmpbuf(png))) {
		image_release(out);
		goto out;
	}
	png_set_user_limits(png, IMAGE_MAX_SIDE, IMAGE_MAX_SIDE);
	png_set_read_fn(png, &src, png_read_mem);
	png_read_info(png, info);
	/* Whatever the file holds, hand back 8-bit RGBA. */
	png_set_expand(png);
	png_set_strip_16(png);
	png_set_gray_to_rgb(png);
	png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
	png_set_interlace_handling(png);
	png_read_update_info(png, info);
	int w = (int)png_get_image_width(png, info);
	int h = (int)png_get_image_height(png, info);
	if (png_get_rowbytes(png, info) != (size_t)w * 4) {
		log_err("%s: unsupported PNG pixel layout", name);
		goto out;
	}
	ret = image_alloc(out, w, h);
	if (ret)
		goto out;
	ret = -EINVAL;
	rows = malloc(sizeof(*rows) * (size_t)h);
	if (!rows) {
		ret = -ENOMEM;
		image_release(out);
		goto out;
	}
	for (int y = 0; y < h; y++)
		rows[y] = out->rgba + (size_t)y * (size_t)w * 4;
	png_read_image(png, rows);
	png_read_end(png, NULL);
	ret = 0;
out:
	free(rows);
	png_destroy_read_struct(&png, info ? &info : NULL, NULL);
	return ret;
}

static int jpeg_decode(const char *name, const uint8_t *data, size_t size, struct image *out)
{
	tjhandle tj = tjInitDecompress();
	int w, h, subsamp, colorspace;
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
	ret = image_alloc(out, w, h);
	if (ret)
		goto out;
	/* A warning means corrupt or truncated data (libjpeg pads it with
	 * grey): a file cut short by an interrupted copy is refused, not
	 * shown half grey. */
	if (tjDecompress2(tj, data, (unsigned long)size, out->rgba, w, 0, h, TJPF_RGBA,
			  TJFLAG_ACCURATEDCT | TJFLAG_STOPONWARNING)) {
		log_err("%s: not a valid JPEG: %s", name, tjGetErrorStr2(tj));
		image_release(out);
		ret = -EINVAL;
	}
out:
	tjDestroy(tj);
	return ret;
}

int image_decode(const char *name, const uint8_t *data, size_t size, struct image *out)
{
	static const uint8_t png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

	out->width = 0;
	out->height = 0;
	out->rgba = NULL;
	if (size >= 8 && memcmp(data, png_sig, 8) == 0)
		return png_decode(name, data, size, out);
	if (size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff)
		return jpeg_decode(name, data, size, out);
	if (size == 0)
		log_err("%s: file is empty, expected a PNG or JPEG image", name);
	else
		log_err("%s: not a PNG or JPEG image (unknown signature)", name);
	return -EINVAL;
}

int image_load(const char *path, struct image *out)
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
		ret = image_decode(path, data, size, out);
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
