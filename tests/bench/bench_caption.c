/* What the caption's quad costs a frame on the GL path, alone: frames of
 * the same size cleared, every other one with the caption blended over
 * it, each finished (glFinish) and timed, the two kinds taken in turn so
 * that a busy machine slows both alike; the medians and their
 * difference. Its picture (FreeType, HarfBuzz, FriBidi) is drawn once, as
 * the kiosk draws it on the content worker, and timed apart; then the
 * pictures of a German, a Japanese (its glyphs from the fallback font
 * fontconfig finds: the first draw asks fontconfig, later ones too, each
 * drawing has a set of fonts of its own) and a long wrapped caption,
 * their medians, on the worker's side: none is drawn a frame.
 *   bench_caption BACKEND WxH LOGO [FRAMES]   (BACKEND: osmesa or egl-headless) */
#include "display/display.h"
#include "render/caption.h"
#include "scene/text/caption.h"
#include "util/log.h"

#include "bench_clock.h"
#include "bench_display.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The median of a picture's drawings (the first, fontconfig's start
 * included, said apart in *first). */
static double picture_ms(const char *text, double *first)
{
	struct caption_config c = {.text = (char *)text, .size = 32, .padding = 12};
	double t[15];
	struct image img;

	for (int i = 0; i < 15; i++) {
		t[i] = bench_now_ms();
		if (caption_render_fit(&c, NULL, &(struct caption_fit){640, 480, "bench", true},
				       &img, NULL))
			return -1;
		t[i] = bench_now_ms() - t[i];
		image_release(&img);
	}
	*first = t[0];
	return bench_median(t + 1, 14);
}

static void pictures(void)
{
	static const char *const texts[][2] = {
	    {"German", "Vase mit gemalter Signatur\\nLeihgabe des Stadtmuseums Köln"},
	    {"Japanese (fallback)", "江戸時代の伊万里焼の花瓶。\\n有田で焼かれ、長崎から渡った。"},
	    {"150 characters wrapped",
	     "A vase with a painted signature under its foot, made in Arita in the 1690s and "
	     "shipped from Nagasaki to Amsterdam; lent by the city museum for this show."},
	};

	for (size_t i = 0; i < sizeof(texts) / sizeof(texts[0]); i++) {
		double first = 0, median = picture_ms(texts[i][1], &first);

		printf("picture at 640x480, size 32, %s: %.2f ms (the first %.2f ms)\n",
		       texts[i][0], median, first);
	}
}

static double frame(struct display *d, const struct caption_gl *cap)
{
	double t = bench_now_ms();

	d->gl.ClearColor(0.1f, 0.1f, 0.1f, 1);
	d->gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	if (cap)
		caption_gl_draw(cap, 0, d->width, d->height, 0);
	d->gl.Finish();
	return bench_now_ms() - t;
}

int main(int argc, char **argv)
{
	struct display_config cfg = {0};
	struct caption_config c = {.text = "Amphora, Attic, 5th c. BC\\nLent by the city museum",
				   .size = 32,
				   .padding = 12};
	struct display *d = NULL;
	struct caption_gl *cap;
	struct image img;
	int n = argc > 4 ? atoi(argv[4]) : 400;
	double *off, *on, t;

	if (argc < 4 || sscanf(argv[2], "%dx%d", &cfg.width, &cfg.height) != 2 || n < 2) {
		fprintf(stderr, "usage: bench_caption osmesa|egl-headless WxH LOGO [FRAMES]\n");
		return 2;
	}
	log_set_level(LOG_WARN);
	c.logo = argv[3];
	d = bench_display_open(argv[1], &cfg);
	if (!d || d->begin_frame(d))
		return 1;
	t = bench_now_ms();
	if (caption_render(&c, NULL, &img))
		return 1;
	t = bench_now_ms() - t;
	cap = caption_gl_new(&d->gl, &img, &c);
	off = calloc((size_t)n, sizeof(*off));
	on = calloc((size_t)n, sizeof(*on));
	if (!cap || !off || !on)
		return 1;
	frame(d, cap); /* the first draw compiles and uploads */
	for (int i = 0; i < n; i++) {
		off[i] = frame(d, NULL);
		on[i] = frame(d, cap);
	}
	printf("%s %dx%d caption %dx%d: picture %.1f ms once; frame %.3f ms, with caption %.3f "
	       "ms: %.3f ms a frame\n",
	       argv[1], cfg.width, cfg.height, img.width, img.height, t, bench_median(off, n),
	       bench_median(on, n), bench_median(on, n) - bench_median(off, n));
	pictures();
	free(off);
	free(on);
	image_release(&img);
	caption_gl_free(cap);
	return 0;
}
