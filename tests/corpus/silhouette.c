/* Is a rendered model plausibly shown? The corpus test's check on files
 * nobody on the project wrote, where no reference image exists:
 *   silhouette FILE.png
 * The background is the corner pixel's colour. The model must cover at
 * least 1% of the frame, be fitted (its silhouette spans at least 40% of
 * the frame's width or height, centred within a quarter of it), and be
 * shaded (its pixels neither all black nor all one tone). Prints the
 * figures; exits 0 when all hold.
 *   silhouette FILE.png Y0 Y1 SHARE
 * The fit's centring (issue 33): the model in the rows Y0 to Y1 alone (the
 * room a caption leaves), its silhouette's box centred within SHARE of the
 * frame's width and height of that room's centre. */
#include "util/image.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

struct figures {
	long count;
	int x0, y0, x1, y1;
	double mean, spread; /* luma of the model's pixels, 0..255 */
};

static int luma(const uint8_t *p)
{
	return (p[0] * 299 + p[1] * 587 + p[2] * 114) / 1000;
}

static int is_model(const uint8_t *p, const uint8_t *bg)
{
	for (int k = 0; k < 3; k++)
		if (abs(p[k] - bg[k]) > 12)
			return 1;
	return 0;
}

static struct figures measure(const struct image *img, int y0, int y1)
{
	const uint8_t *bg = img->rgba;
	struct figures f = {0, img->width, img->height, -1, -1, 0, 0};
	double sum = 0, sum2 = 0;

	for (int y = y0; y < y1; y++)
		for (int x = 0; x < img->width; x++) {
			const uint8_t *p = img->rgba + ((size_t)y * img->width + x) * 4;
			int l = luma(p);

			if (!is_model(p, bg))
				continue;
			f.count++;
			f.x0 = x < f.x0 ? x : f.x0, f.x1 = x > f.x1 ? x : f.x1;
			f.y0 = y < f.y0 ? y : f.y0, f.y1 = y > f.y1 ? y : f.y1;
			sum += l, sum2 += (double)l * l;
		}
	if (f.count) {
		f.mean = sum / f.count;
		f.spread = sqrt(fmax(sum2 / f.count - f.mean * f.mean, 0));
	}
	return f;
}

/* The silhouette's box centre against the room's (rows y0 to y1). */
static int centred(const struct image *img, int y0, int y1, double share)
{
	struct figures f = measure(img, y0, y1);
	double w = img->width, h = img->height;
	double cx = (f.x0 + f.x1 + 1) / 2.0 / w - 0.5,
	       cy = ((f.y0 + f.y1 + 1) / 2.0 - (y0 + y1) / 2.0) / h;
	int ok = f.count > 0 && fabs(cx) <= share && fabs(cy) <= share;

	printf("%s: %dx%d, its box's centre (%+.4f, %+.4f) of the frame from the room's (rows %d "
	       "to %d)\n",
	       ok ? "centred" : "not centred", f.x1 - f.x0 + 1, f.y1 - f.y0 + 1, cx, cy, y0, y1);
	return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
	struct image img;
	struct figures f;
	double w, h, cx, cy;
	int ok;

	if (argc != 2 && argc != 5) {
		fprintf(stderr, "usage: silhouette FILE.png [Y0 Y1 SHARE]\n");
		return 2;
	}
	if (image_load(argv[1], &img))
		return 2;
	if (argc == 5) {
		int y0 = atoi(argv[2]), y1 = atoi(argv[3]);

		ok = y0 >= 0 && y1 <= img.height && y0 < y1 ? !centred(&img, y0, y1, atof(argv[4]))
							    : 0;
		image_release(&img);
		return ok ? 0 : 1;
	}
	f = measure(&img, 0, img.height);
	w = img.width, h = img.height;
	cx = (f.x0 + f.x1 + 1) / 2.0 / w - 0.5, cy = (f.y0 + f.y1 + 1) / 2.0 / h - 0.5;
	ok = f.count >= 0.01 * w * h && fmax((f.x1 - f.x0 + 1) / w, (f.y1 - f.y0 + 1) / h) >= 0.4 &&
	     fabs(cx) <= 0.25 && fabs(cy) <= 0.25 && f.mean >= 8 && f.spread >= 2;
	printf("%s: %.1f%% of the frame, %dx%d at (%+.2f, %+.2f), luma %.0f +- %.0f\n",
	       ok ? "shown" : "not shown", 100.0 * f.count / (w * h), f.x1 - f.x0 + 1,
	       f.y1 - f.y0 + 1, cx, cy, f.mean, f.spread);
	image_release(&img);
	return ok ? 0 : 1;
}
