#include "util/image.h"

#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <turbojpeg.h>
#include <webp/encode.h>
#include <unistd.h>
#include <zlib.h>

static const uint8_t png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

static void put_be32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)(v >> 24);
	p[1] = (uint8_t)(v >> 16);
	p[2] = (uint8_t)(v >> 8);
	p[3] = (uint8_t)v;
}

/* A PNG whose header is valid, CRC included, and declares w x h. */
static size_t png_header_only(uint8_t *buf, uint32_t w, uint32_t h)
{
	memcpy(buf, png_sig, 8);
	put_be32(buf + 8, 13);
	memcpy(buf + 12, "IHDR", 4);
	put_be32(buf + 16, w);
	put_be32(buf + 20, h);
	buf[24] = 8; /* bit depth */
	buf[25] = 6; /* RGBA */
	buf[26] = buf[27] = buf[28] = 0;
	put_be32(buf + 29, (uint32_t)crc32(0, buf + 12, 17));
	return 33;
}

static uint8_t *read_all(const char *path, size_t *size)
{
	FILE *f = fopen(path, "rb");
	uint8_t *data = malloc(1 << 20);

	*size = fread(data, 1, 1 << 20, f);
	fclose(f);
	return data;
}

static void png_round_trip(void **state)
{
	struct image a, b;
	char path[] = "/tmp/mk-image-XXXXXX";
	int fd = mkstemp(path);

	(void)state;
	close(fd);
	assert_int_equal(image_alloc(&a, 7, 5), 0);
	for (int i = 0; i < 7 * 5 * 4; i++)
		a.rgba[i] = (uint8_t)(i * 37);
	assert_int_equal(image_write_png(path, &a), 0);
	assert_int_equal(image_load(path, &b), 0);
	assert_int_equal(b.width, 7);
	assert_int_equal(b.height, 5);
	assert_memory_equal(a.rgba, b.rgba, 7 * 5 * 4);
	image_release(&a);
	image_release(&b);
	unlink(path);
}

static void rejects_empty_and_unknown(void **state)
{
	struct image img;
	uint8_t text[] = "hello, not an image";

	(void)state;
	assert_int_equal(image_decode("empty.png", text, 0, &img), -EINVAL);
	assert_null(img.rgba);
	assert_int_equal(image_decode("text.png", text, sizeof(text), &img), -EINVAL);
	assert_int_equal(image_load("/nonexistent/matcap.png", &img), -ENOENT);
}

static void rejects_huge_declared_png(void **state)
{
	uint8_t buf[64];
	struct image img;
	size_t n = png_header_only(buf, 100000, 100000);

	(void)state;
	/* Refused from the header alone, before any allocation. */
	assert_int_equal(image_decode("huge.png", buf, n, &img), -EINVAL);
	assert_null(img.rgba);
	n = png_header_only(buf, 0x7fffffff, 1);
	assert_int_equal(image_decode("wide.png", buf, n, &img), -EINVAL);
}

static void rejects_truncated_png(void **state)
{
	struct image a, img;
	size_t size;
	uint8_t *data;
	char path[] = "/tmp/mk-image-XXXXXX";
	int fd = mkstemp(path);

	(void)state;
	close(fd);
	assert_int_equal(image_alloc(&a, 64, 64), 0);
	for (int i = 0; i < 64 * 64 * 4; i++)
		a.rgba[i] = (uint8_t)rand();
	assert_int_equal(image_write_png(path, &a), 0);
	data = read_all(path, &size);
	for (size_t cut = 1; cut < size; cut += size / 17 + 1) {
		assert_int_equal(image_decode("cut.png", data, cut, &img), -EINVAL);
		assert_null(img.rgba);
	}
	/* A flipped byte in the pixel data breaks a CRC or the zlib stream. */
	data[size / 2] ^= 0x55;
	assert_int_equal(image_decode("flipped.png", data, size, &img), -EINVAL);
	free(data);
	image_release(&a);
	unlink(path);
}

static void jpeg_round_trip_and_truncation(void **state)
{
	tjhandle tj = tjInitCompress();
	unsigned char *jpg = NULL;
	unsigned long jsize = 0;
	uint8_t rgba[16 * 8 * 4];
	struct image img;

	(void)state;
	for (int i = 0; i < 16 * 8 * 4; i++)
		rgba[i] = (i % 4 == 0) ? 200 : 40;
	assert_int_equal(
	    tjCompress2(tj, rgba, 16, 0, 8, TJPF_RGBA, &jpg, &jsize, TJSAMP_444, 95, 0), 0);
	assert_int_equal(image_decode("ok.jpg", jpg, jsize, &img), 0);
	assert_int_equal(img.width, 16);
	assert_true(abs(img.rgba[0] - 200) < 8 && abs(img.rgba[1] - 40) < 8);
	image_release(&img);
	assert_int_equal(image_decode("cut.jpg", jpg, 20, &img), -EINVAL);
	assert_null(img.rgba);
	tjFree(jpg);
	tjDestroy(tj);
}

/* The halvings: an axis while its half still reaches the side, then
 * both while over the bytes; none for a small image. */
static void fit_shifts(void **state)
{
	struct image_fit side = {2048, 0}, budget = {2048, (size_t)4 << 20}, none = {0, 0};
	int sx, sy, w, h;

	(void)state;
	image_fit_shifts(8192, 8192, &side, &sx, &sy, &w, &h);
	assert_true(sx == 2 && sy == 2 && w == 2048 && h == 2048);
	image_fit_shifts(3000, 64, &side, &sx, &sy, &w, &h);
	assert_true(sx == 0 && sy == 0 && w == 3000 && h == 64);
	image_fit_shifts(8192, 64, &side, &sx, &sy, &w, &h);
	assert_true(sx == 2 && sy == 0 && w == 2048 && h == 64);
	image_fit_shifts(8192, 8192, &budget, &sx, &sy, &w, &h);
	assert_true(w == 1024 && h == 1024);
	assert_true((size_t)w * (size_t)h * 4 <= budget.bytes);
	image_fit_shifts(256, 256, &budget, &sx, &sy, &w, &h);
	assert_true(sx == 0 && sy == 0 && w == 256 && h == 256);
	image_fit_shifts(8192, 1, &(struct image_fit){0, 16}, &sx, &sy, &w, &h);
	assert_true(w == 4 && h == 1);
	image_fit_shifts(8192, 8192, &none, &sx, &sy, &w, &h);
	assert_true(w == 8192 && h == 8192);
}

static uint8_t *png_bytes(const struct image *img, size_t *size)
{
	char path[] = "/tmp/mk-image-XXXXXX";
	int fd = mkstemp(path);
	uint8_t *data;

	close(fd);
	assert_int_equal(image_write_png(path, img), 0);
	data = read_all(path, size);
	unlink(path);
	return data;
}

/* A PNG made smaller as it is read is the box filter's mean of each block
 * (odd sides: the edge blocks are smaller); one that needs no halving is
 * the file's pixels exactly. */
static void png_fit_box_filter(void **state)
{
	struct image a, b;
	struct image_fit fit = {4, 0};
	size_t size;
	uint8_t *data;
	int fw, fh;

	(void)state;
	assert_int_equal(image_alloc(&a, 9, 8), 0);
	for (int y = 0; y < 8; y++)
		for (int x = 0; x < 9; x++)
			for (int c = 0; c < 4; c++)
				a.rgba[(y * 9 + x) * 4 + c] = (uint8_t)((x + y) % 2 ? 200 : 100);
	data = png_bytes(&a, &size);
	assert_int_equal(image_decode_fit("a.png", data, size, &fit, &b, &fw, &fh), 0);
	assert_true(fw == 9 && fh == 8 && b.width == 5 && b.height == 4);
	assert_int_equal(b.rgba[0], 150);	/* 2x2: two of each */
	assert_int_equal(b.rgba[(4) * 4], 150); /* the last column: 1x2 */
	image_release(&b);
	fit.side = 16;
	assert_int_equal(image_decode_fit("a.png", data, size, &fit, &b, NULL, NULL), 0);
	assert_true(b.width == 9 && memcmp(a.rgba, b.rgba, 9 * 8 * 4) == 0);
	image_release(&b);
	free(data);
	image_release(&a);
}

/* The attack: a large PNG of one colour (a zlib bomb) decodes to its share
 * of the budget, never its full size, and keeps its colour. */
static void png_fit_bomb(void **state)
{
	struct image a, b;
	struct image_fit fit = {0, 64 * 64 * 4};
	size_t size;
	uint8_t *data;

	(void)state;
	assert_int_equal(image_alloc(&a, 2048, 1024), 0);
	for (size_t i = 0; i < 2048 * 1024; i++)
		memcpy(a.rgba + i * 4, (uint8_t[]){10, 20, 30, 255}, 4);
	data = png_bytes(&a, &size);
	image_release(&a);
	assert_int_equal(image_decode_fit("bomb.png", data, size, &fit, &b, NULL, NULL), 0);
	assert_true((size_t)b.width * (size_t)b.height * 4 <= fit.bytes);
	assert_true(b.width == 2 * b.height);
	assert_memory_equal(b.rgba + ((size_t)b.width * b.height - 1) * 4,
			    ((uint8_t[]){10, 20, 30, 255}), 4);
	image_release(&b);
	free(data);
}

/* A JPEG is scaled by libjpeg-turbo (1/8 here), then by the box filter. */
static void jpeg_fit(void **state)
{
	tjhandle tj = tjInitCompress();
	unsigned char *jpg = NULL;
	unsigned long jsize = 0;
	static uint8_t rgba[512 * 64 * 4];
	struct image_fit fit = {4, 0};
	struct image img;

	(void)state;
	for (size_t i = 0; i < sizeof(rgba); i++)
		rgba[i] = (i % 4 == 0) ? 200 : 40;
	assert_int_equal(
	    tjCompress2(tj, rgba, 512, 0, 64, TJPF_RGBA, &jpg, &jsize, TJSAMP_444, 95, 0), 0);
	assert_int_equal(image_decode_fit("a.jpg", jpg, jsize, &fit, &img, NULL, NULL), 0);
	assert_true(img.width == 4 && img.height == 4);
	assert_true(abs(img.rgba[0] - 200) < 8 && abs(img.rgba[1] - 40) < 8);
	image_release(&img);
	tjFree(jpg);
	tjDestroy(tj);
}

/* A w x h WebP of rgba from libwebp's encoder (the tests may encode; the
 * program only decodes); lossless keeps every byte. */
static uint8_t *webp_of(const uint8_t *rgba, int w, int h, bool lossless, size_t *size)
{
	uint8_t *out = NULL;

	*size = lossless ? WebPEncodeLosslessRGBA(rgba, w, h, w * 4, &out)
			 : WebPEncodeRGBA(rgba, w, h, w * 4, 90, &out);
	assert_true(*size > 12);
	return out;
}

/* EXT_texture_webp's images: found by their RIFF/WEBP signature, decoded
 * to the same RGBA as a PNG (lossless: byte for byte, alpha kept). */
static void webp_round_trip(void **state)
{
	uint8_t rgba[8 * 4 * 4];
	struct image img;
	size_t size;
	uint8_t *webp;

	(void)state;
	for (size_t i = 0; i < sizeof(rgba); i++)
		rgba[i] = (uint8_t)(i * 37 + 11);
	webp = webp_of(rgba, 8, 4, true, &size);
	assert_int_equal(image_decode("a.webp", webp, size, &img), 0);
	assert_true(img.width == 8 && img.height == 4);
	assert_memory_equal(img.rgba, rgba, sizeof(rgba));
	image_release(&img);
	WebPFree(webp);
}

/* A truncated or corrupt WebP is refused (never shown half decoded), and
 * so is one whose header declares more than IMAGE_MAX_SIDE. */
static void webp_truncated_and_huge(void **state)
{
	static uint8_t rgba[64 * 64 * 4];
	struct image img;
	size_t size;
	uint8_t *webp;

	(void)state;
	for (size_t i = 0; i < sizeof(rgba); i++)
		rgba[i] = (uint8_t)rand();
	webp = webp_of(rgba, 64, 64, false, &size);
	for (size_t cut = 12; cut < size; cut += size / 13 + 1) {
		assert_int_equal(image_decode("cut.webp", webp, cut, &img), -EINVAL);
		assert_null(img.rgba);
	}
	WebPFree(webp);
	/* One side over IMAGE_MAX_SIDE: refused from the header. */
	static uint8_t row[(IMAGE_MAX_SIDE + 1) * 4];
	webp = webp_of(row, IMAGE_MAX_SIDE + 1, 1, true, &size);
	assert_int_equal(image_decode("wide.webp", webp, size, &img), -EINVAL);
	WebPFree(webp);
	assert_null(img.rgba);
}

/* A WebP over its fit is scaled by libwebp as it decodes: the fit's size
 * comes back, and the full size is reported. */
static void webp_fit(void **state)
{
	static uint8_t rgba[512 * 64 * 4];
	struct image_fit fit = {4, 0};
	struct image img;
	size_t size;
	int fw, fh;
	uint8_t *webp;

	(void)state;
	for (size_t i = 0; i < sizeof(rgba); i++)
		rgba[i] = (i % 4 == 0) ? 200 : (i % 4 == 3) ? 255 : 40;
	webp = webp_of(rgba, 512, 64, true, &size);
	assert_int_equal(image_decode_fit("a.webp", webp, size, &fit, &img, &fw, &fh), 0);
	assert_true(fw == 512 && fh == 64);
	assert_true(img.width == 4 && img.height == 4);
	assert_true(abs(img.rgba[0] - 200) < 8 && abs(img.rgba[1] - 40) < 8);
	image_release(&img);
	WebPFree(webp);
}

/* KTX2 (KHR_texture_basisu) is refused by name: Debian 12 and 13 ship no
 * transcoder. */
static void ktx2_refused(void **state)
{
	static const uint8_t ktx2[16] = {0xab, 'K',  'T',  'X',	 ' ', '2', '0', 0xbb,
					 '\r', '\n', 0x1a, '\n', 0,   0,   0,	0};
	struct image img;

	(void)state;
	assert_int_equal(image_decode("a.ktx2", ktx2, sizeof(ktx2), &img), -EINVAL);
	assert_null(img.rgba);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(png_round_trip),
	    cmocka_unit_test(rejects_empty_and_unknown),
	    cmocka_unit_test(rejects_huge_declared_png),
	    cmocka_unit_test(rejects_truncated_png),
	    cmocka_unit_test(jpeg_round_trip_and_truncation),
	    cmocka_unit_test(fit_shifts),
	    cmocka_unit_test(png_fit_box_filter),
	    cmocka_unit_test(png_fit_bomb),
	    cmocka_unit_test(jpeg_fit),
	    cmocka_unit_test(webp_round_trip),
	    cmocka_unit_test(webp_truncated_and_huge),
	    cmocka_unit_test(webp_fit),
	    cmocka_unit_test(ktx2_refused),
	};
	return cmocka_run_group_tests_name("image", tests, NULL, NULL);
}
