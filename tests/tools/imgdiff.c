/* Compares two images with a stated per-pixel tolerance, not exact bytes:
 * a pixel differs when any channel is off by more than --tol (of 255);
 * the images agree when at most --share of the compared pixels differ.
 * --disk compares only the inscribed disk less a rim of --rim pixels (the
 * orthographic-sphere check). Prints max difference, PSNR and the share;
 * --iou adds the silhouettes' intersection over union (a pixel is the
 * model's where it is off its own image's corner pixel, the background, by
 * more than 12 of 255, as tests/corpus/silhouette.c): a pose that is off
 * shows there before the shading does. */
#include "util/image.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct diff_opts {
	int tol;
	double share;
	int disk;
	double rim;
	int iou;
};

static int is_model(const struct image *a, const uint8_t *p)
{
	for (int c = 0; c < 3; c++)
		if (abs(p[c] - a->rgba[c]) > 12)
			return 1;
	return 0;
}

/* Intersection over union of the two silhouettes; 1 when both are empty. */
static double silhouette_iou(const struct image *a, const struct image *b)
{
	long both = 0, either = 0;

	for (size_t i = 0; i < (size_t)a->width * a->height; i++) {
		int in_a = is_model(a, a->rgba + i * 4), in_b = is_model(b, b->rgba + i * 4);

		both += in_a && in_b;
		either += in_a || in_b;
	}
	return either ? (double)both / (double)either : 1.0;
}

static int in_disk(const struct image *a, int x, int y, double rim)
{
	double cx = a->width / 2.0, cy = a->height / 2.0, r = fmin(cx, cy) - rim;
	double dx = x + 0.5 - cx, dy = y + 0.5 - cy;

	return dx * dx + dy * dy <= r * r;
}

static int compare(const struct image *a, const struct image *b, const struct diff_opts *o)
{
	long n = 0, off = 0;
	int maxd = 0;
	double se = 0;

	for (int y = 0; y < a->height; y++)
		for (int x = 0; x < a->width; x++) {
			const uint8_t *p = a->rgba + ((size_t)y * a->width + x) * 4;
			const uint8_t *q = b->rgba + ((size_t)y * b->width + x) * 4;
			int d = 0;

			if (o->disk && !in_disk(a, x, y, o->rim))
				continue;
			for (int c = 0; c < 3; c++) {
				int e = abs(p[c] - q[c]);

				d = e > d ? e : d;
				se += (double)e * e;
			}
			maxd = d > maxd ? d : maxd;
			off += d > o->tol;
			n++;
		}
	double mse = se / (3.0 * (double)(n ? n : 1));
	double psnr = mse > 0 ? 10 * log10(255.0 * 255.0 / mse) : INFINITY;
	double share = n ? (double)off / (double)n : 1.0;

	printf("max_diff %d psnr_db %.2f share_over_tol %.5f (tol %d, allowed %.5f, %ld px)", maxd,
	       psnr, share, o->tol, o->share, n);
	if (o->iou)
		printf(" iou %.4f", silhouette_iou(a, b));
	printf("\n");
	return share <= o->share ? 0 : 1;
}

int main(int argc, char **argv)
{
	struct diff_opts o = {.tol = 8, .share = 0.005, .disk = 0, .rim = 3, .iou = 0};
	struct image a, b;
	int i = 1, ret;

	for (; i < argc && strncmp(argv[i], "--", 2) == 0; i++) {
		if (!strcmp(argv[i], "--tol") && i + 1 < argc)
			o.tol = atoi(argv[++i]);
		else if (!strcmp(argv[i], "--share") && i + 1 < argc)
			o.share = atof(argv[++i]);
		else if (!strcmp(argv[i], "--rim") && i + 1 < argc)
			o.rim = atof(argv[++i]);
		else if (!strcmp(argv[i], "--disk"))
			o.disk = 1;
		else if (!strcmp(argv[i], "--iou"))
			o.iou = 1;
	}
	if (argc - i != 2) {
		fprintf(stderr,
			"usage: imgdiff [--tol N] [--share F] [--disk] [--rim PX] [--iou] A B\n");
		return 2;
	}
	if (image_load(argv[i], &a) || image_load(argv[i + 1], &b))
		return 2;
	if (a.width != b.width || a.height != b.height) {
		printf("sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width, b.height);
		ret = 1;
	} else {
		ret = compare(&a, &b, &o);
	}
	image_release(&a);
	image_release(&b);
	return ret;
}
