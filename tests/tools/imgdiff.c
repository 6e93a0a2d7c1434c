/* Compares two images with a stated per-pixel tolerance, not exact bytes:
 * a pixel differs when any channel is off by more than --tol (of 255);
 * the images agree when at most --share of the compared pixels differ.
 * --disk compares only the inscribed disk less a rim of --rim pixels (the
 * orthographic-sphere check). Prints max difference, PSNR and the share. */
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
};

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

	printf("max_diff %d psnr_db %.2f share_over_tol %.5f (tol %d, allowed %.5f, %ld px)\n",
	       maxd, psnr, share, o->tol, o->share, n);
	return share <= o->share ? 0 : 1;
}

int main(int argc, char **argv)
{
	struct diff_opts o = {.tol = 8, .share = 0.005, .disk = 0, .rim = 3};
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
	}
	if (argc - i != 2) {
		fprintf(stderr, "usage: imgdiff [--tol N] [--share F] [--disk] [--rim PX] A B\n");
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
