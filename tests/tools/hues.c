/* Which of the six colour-bar hues (red, yellow, green, cyan, blue,
 * magenta) a picture shows: the check that a camera's test pattern is on
 * the model (tests/e2e/camera.sh). A hue counts when at least --share of
 * the picture's non-background pixels are of it, saturated and bright.
 *   hues [--share S] FILE MIN MAX   exit 0 when MIN <= hues shown <= MAX */
#include "util/image.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[6] = {"red", "yellow", "green", "cyan", "blue", "magenta"};

/* -1 for a pixel that is grey, dark or between two hues. */
static int hue_of(const uint8_t *p)
{
	double r = p[0] / 255.0, g = p[1] / 255.0, b = p[2] / 255.0;
	double mx = fmax(r, fmax(g, b)), mn = fmin(r, fmin(g, b)), d = mx - mn, h;
	int k;

	if (mx < 0.3 || d / mx < 0.5)
		return -1;
	if (mx == r)
		h = fmod((g - b) / d + 6.0, 6.0);
	else if (mx == g)
		h = (b - r) / d + 2.0;
	else
		h = (r - g) / d + 4.0;
	k = (int)lround(h) % 6;
	return fabs(h - lround(h)) < 0.34 ? k : -1;
}

int main(int argc, char **argv)
{
	struct image img;
	double share = 0.005;
	long count[6] = {0}, fg = 0;
	int a = 1, shown = 0, lo, hi;

	if (argc > 2 && !strcmp(argv[1], "--share")) {
		share = atof(argv[2]);
		a = 3;
	}
	if (argc - a != 3) {
		fprintf(stderr, "usage: hues [--share S] FILE MIN MAX\n");
		return 2;
	}
	lo = atoi(argv[a + 1]);
	hi = atoi(argv[a + 2]);
	if (image_load(argv[a], &img))
		return 2;
	for (long i = 0; i < (long)img.width * img.height; i++) {
		const uint8_t *p = img.rgba + i * 4;
		const uint8_t *bg = img.rgba; /* the top-left pixel is background */
		int k;

		if (abs(p[0] - bg[0]) + abs(p[1] - bg[1]) + abs(p[2] - bg[2]) < 12)
			continue;
		fg++;
		if ((k = hue_of(p)) >= 0)
			count[k]++;
	}
	for (int k = 0; k < 6; k++) {
		bool on = fg && count[k] >= share * fg;

		shown += on;
		printf("%s %.2f%%%s\n", names[k], fg ? 100.0 * count[k] / fg : 0.0,
		       on ? " shown" : "");
	}
	printf("%d hues in %ld model pixels of %s\n", shown, fg, argv[a]);
	image_release(&img);
	return shown >= lo && shown <= hi ? 0 : 1;
}
