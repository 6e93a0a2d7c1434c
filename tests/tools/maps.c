#include "maps.h"
#include "util/image.h"

#include <math.h>
#include <png.h>
#include <zlib.h>
#include <stdlib.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

/* 16 x 8 cells of 32 texels, every other row shifted by half a cell: a
 * scaly relief that tiles, square on a UV sphere's equator (u runs 2 pi
 * round it, v pi from pole to pole). */
#define DETAIL_W 512
#define DETAIL_H 256
#define CELL	 32.0

static double wrap_delta(double d, double period)
{
	return d - period * floor(d / period + 0.5);
}

/* A dome per cell: 1 at its centre, 0 at its rim and between cells. */
static double scales(double x, double y)
{
	double best = 1e9;

	for (int dy = -1; dy <= 1; dy++) {
		double row = floor(y / CELL) + dy, cy = (row + 0.5) * CELL;
		double shift = fmod(row, 2.0) != 0.0 ? CELL / 2 : 0.0;
		double cx = (floor((x - shift) / CELL) + 0.5) * CELL + shift;

		for (int dx = -1; dx <= 1; dx++) {
			double ex = wrap_delta(x - (cx + dx * CELL), DETAIL_W);
			double ey = wrap_delta(y - cy, DETAIL_H);

			best = fmin(best, sqrt(ex * ex + ey * ey));
		}
	}
	best /= CELL * 0.62;
	return best < 1.0 ? pow(cos(best * M_PI / 2), 2.0) : 0.0;
}

struct texel {
	double n[3], ao, shift;
};

/* Tangent-space normal (x right = +u, y up = -v, as glTF), occlusion
 * darker between the scales, and hue-shift stripes along u. */
static void relief(int x, int y, struct texel *t)
{
	const double strength = 6.0;
	double hx = scales(x + 1, y) - scales(x - 1, y), hy = scales(x, y + 1) - scales(x, y - 1);
	double n[3] = {-strength * hx / 2, strength * hy / 2, 1.0};
	double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);

	for (int k = 0; k < 3; k++)
		t->n[k] = n[k] / len;
	t->ao = 0.35 + 0.65 * sqrt(scales(x, y));
	t->shift = 0.5 + 0.5 * cos(2 * M_PI * 3.0 * x / DETAIL_W);
}

static unsigned char byte(double v)
{
	return (unsigned char)lround(fmin(fmax(v, 0.0), 1.0) * 255.0);
}

static int save(const char *dir, const char *name, const struct image *img)
{
	char path[4096];

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	if (image_write_png(path, img)) {
		fprintf(stderr, "maps: cannot write %s\n", path);
		return 1;
	}
	return 0;
}

static int write_relief(const char *dir)
{
	struct image img[4];
	static const char *const names[4] = {"detail.png", "normal.png", "occlusion.png",
					     "thickness.png"};
	int bad = 0;

	for (int i = 0; i < 4; i++)
		if (image_alloc(&img[i], DETAIL_W, DETAIL_H))
			return 1;
	for (int y = 0; y < DETAIL_H; y++)
		for (int x = 0; x < DETAIL_W; x++) {
			struct texel t;
			size_t o = ((size_t)y * DETAIL_W + (size_t)x) * 4;
			unsigned char *d = img[0].rgba + o, *n = img[1].rgba + o;
			unsigned char *a = img[2].rgba + o, *th = img[3].rgba + o;

			relief(x, y, &t);
			d[0] = n[0] = byte(t.n[0] * 0.5 + 0.5);
			d[1] = n[1] = byte(t.n[1] * 0.5 + 0.5);
			n[2] = byte(t.n[2] * 0.5 + 0.5);
			d[2] = a[0] = a[1] = a[2] = byte(t.ao);
			d[3] = th[1] = byte(t.shift);
			n[3] = a[3] = th[3] = 255;
		}
	for (int i = 0; i < 4; i++) {
		bad |= save(dir, names[i], &img[i]);
		image_release(&img[i]);
	}
	return bad;
}

/* Egg crate: 8 bumps round, 4 from pole to pole, level at the poles so
 * the sphere's many pole vertices agree. */
static int write_height(const char *dir)
{
	struct image img;
	int bad;

	if (image_alloc(&img, 256, 128))
		return 1;
	for (int y = 0; y < 128; y++)
		for (int x = 0; x < 256; x++) {
			double u = (x + 0.5) / 256, v = (y + 0.5) / 128;
			unsigned char h =
			    byte(0.5 + 0.5 * sin(2 * M_PI * 8 * u) * sin(2 * M_PI * 2 * v));
			unsigned char *p = img.rgba + ((size_t)y * 256 + (size_t)x) * 4;

			p[0] = p[1] = p[2] = h;
			p[3] = 255;
		}
	bad = save(dir, "height.png", &img);
	image_release(&img);
	return bad;
}

/* Gold, teal, violet, rose and back: a ramp that wraps round. */
static int write_ramp(const char *dir)
{
	static const double stops[5][3] = {{1.0, 0.76, 0.2},
					   {0.1, 0.75, 0.7},
					   {0.45, 0.2, 0.9},
					   {0.9, 0.25, 0.5},
					   {1.0, 0.76, 0.2}};
	struct image img;
	int bad;

	if (image_alloc(&img, 256, 4))
		return 1;
	for (int x = 0; x < 256; x++) {
		double t = (x + 0.5) / 256 * 4;
		int i = (int)t;
		double f = t - i;

		for (int y = 0; y < 4; y++) {
			unsigned char *p = img.rgba + ((size_t)y * 256 + (size_t)x) * 4;

			for (int c = 0; c < 3; c++)
				p[c] = byte(stops[i][c] * (1 - f) + stops[i + 1][c] * f);
			p[3] = 255;
		}
	}
	bad = save(dir, "ramp.png", &img);
	image_release(&img);
	return bad;
}

/* A base colour map, sRGB: smooth waves that repeat on both axes (so
 * GL_REPEAT has no seam), with no axis symmetric, so that a texture
 * transform shows. */
static int write_base(const char *dir)
{
	struct image img;
	int bad;

	if (image_alloc(&img, BASE_SIDE, BASE_SIDE))
		return 1;
	for (int y = 0; y < BASE_SIDE; y++)
		for (int x = 0; x < BASE_SIDE; x++) {
			unsigned char *p = img.rgba + ((size_t)y * BASE_SIDE + (size_t)x) * 4;
			double u = (x + 0.5) / BASE_SIDE, v = (y + 0.5) / BASE_SIDE;

			p[0] = byte(0.55 + 0.4 * cos(2 * M_PI * u));
			p[1] = byte(0.55 + 0.4 * sin(2 * M_PI * (u + 2 * v)));
			p[2] = byte(0.5 + 0.35 * cos(2 * M_PI * 3 * v));
			p[3] = 255;
		}
	bad = save(dir, "base.png", &img);
	image_release(&img);
	return bad;
}

/* [caption] logo: a 40x40 orange ring on a blue disc, its edge and the
 * ring's hole see-through with soft edges, so the golden shows the logo
 * blended (premultiplied) over the caption's box. */
static int write_logo(const char *dir)
{
	struct image img;
	char path[4096];
	int ret;

	if (image_alloc(&img, 40, 40))
		return 1;
	for (int y = 0; y < 40; y++)
		for (int x = 0; x < 40; x++) {
			uint8_t *p = img.rgba + (y * 40 + x) * 4;
			double r = hypot(x + 0.5 - 20, y + 0.5 - 20);
			double a =
			    fmin(fmax(19.5 - r, 0), 1) * (r < 6 ? fmin(fmax(r - 5, 0), 1) : 1);
			bool ring = r > 11 && r < 16;

			p[0] = ring ? 240 : 40;
			p[1] = ring ? 140 : 90;
			p[2] = ring ? 30 : 200;
			p[3] = (uint8_t)lround(a * 255);
		}
	snprintf(path, sizeof(path), "%s/logo.png", dir);
	ret = image_write_png(path, &img) != 0;
	image_release(&img);
	return ret;
}

int maps_write(const char *dir)
{
	char path[4096];
	FILE *f;
	int bad = write_relief(dir) | write_height(dir) | write_ramp(dir) | write_base(dir) |
		  write_logo(dir);

	snprintf(path, sizeof(path), "%s/corrupt.png", dir);
	f = fopen(path, "wb");
	if (!f)
		return 1;
	fputs("\211PNG\r\n\032\n but nothing after the signature", f);
	fclose(f);
	return bad;
}

int maps_write_flat(const char *path, int side, const unsigned char rgba[4])
{
	FILE *f = fopen(path, "wb");
	png_structp png = NULL;
	png_infop info = NULL;
	unsigned char *row = malloc((size_t)side * 4);
	int bad = 1;

	if (!f || !row)
		goto out;
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	info = png ? png_create_info_struct(png) : NULL;
	if (!info || setjmp(png_jmpbuf(png)))
		goto out;
	for (int x = 0; x < side; x++)
		memcpy(row + (size_t)x * 4, rgba, 4);
	png_init_io(png, f);
	png_set_IHDR(png, info, (png_uint_32)side, (png_uint_32)side, 8, PNG_COLOR_TYPE_RGB_ALPHA,
		     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_set_compression_level(png, 9);
	png_set_compression_strategy(png, Z_RLE);
	png_set_filter(png, 0, PNG_FILTER_SUB);
	png_write_info(png, info);
	for (int y = 0; y < side; y++)
		png_write_row(png, row);
	png_write_end(png, NULL);
	bad = 0;
out:
	if (png)
		png_destroy_write_struct(&png, &info);
	free(row);
	if (f && fclose(f))
		bad = 1;
	if (bad)
		fprintf(stderr, "maps: cannot write %s\n", path);
	return bad;
}
