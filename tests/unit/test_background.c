/* [display] background: the parser (each mistake named, with the key and
 * what is accepted, from the config file and the command line), and the
 * drawing on a real GL (OSMesa, or EGL where Mesa has no OSMesa): a
 * colour is the clear alone, a gradient runs top to bottom of the panel
 * as the viewer sees it, an image covers the screen and keeps its shape. */
#include "config/options.h"
#include "config/settings.h"
#include "display/display.h"
#include "render/background.h"
#include "render/poster.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "offscreen.h"

#define W 96
#define H 64

static void parses(const char *text, enum background_kind kind, const float top[3],
		   const float bottom[3])
{
	struct background_spec s;
	char err[200] = "";

	assert_int_equal(background_parse(text, &s, err, sizeof(err)), 0);
	assert_int_equal(s.kind, kind);
	for (int i = 0; i < 3; i++) {
		assert_float_equal(s.top[i], top[i], 1e-6);
		assert_float_equal(s.bottom[i], bottom[i], 1e-6);
	}
}

static void good(void **state)
{
	const float grey[3] = {0.06f, 0.06f, 0.07f}, orange[3] = {1, 128 / 255.0f, 0};
	const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0};
	struct background_spec s;
	char err[200];

	(void)state;
	parses(NULL, BACKGROUND_COLOR, grey, grey);
	parses("", BACKGROUND_COLOR, grey, grey);
	parses("#ff8000", BACKGROUND_COLOR, orange, orange);
	parses("#FF8000", BACKGROUND_COLOR, orange, orange);
	parses("#ffffff, #000000", BACKGROUND_GRADIENT, white, black);
	parses("  #ffffff ,#000000  ", BACKGROUND_GRADIENT, white, black);
	assert_int_equal(background_parse("/srv/kiosk/Shop.JPG", &s, err, sizeof(err)), 0);
	assert_int_equal(s.kind, BACKGROUND_IMAGE);
	assert_string_equal(s.path, "/srv/kiosk/Shop.JPG");
	assert_int_equal(background_parse("shop.png", &s, err, sizeof(err)), 0);
	assert_int_equal(background_parse("shop.jpeg", &s, err, sizeof(err)), 0);
}

/* Each mistake, and the reason the parser gives for it. */
static const struct {
	const char *text, *reason;
} bad[] = {
    {"#12345", "'#12345' is not a colour; expected #rrggbb (six hex digits)"},
    {"#1234567", "'#1234567' is not a colour; expected #rrggbb"},
    {"#12345g", "'#12345g' has a digit that is not hex; expected #rrggbb"},
    {"#111111,", "'' is not a colour; expected #rrggbb"},
    {"#111111, 222222", "'222222' is not a colour; expected #rrggbb"},
    {"#111111, #222222, #333333", "a gradient has two colours, top and bottom, not more"},
    {"red", "'red' is neither a colour nor a .png/.jpg/.jpeg/.webp file"},
    {"shop.gif", "'shop.gif' is neither a colour nor a .png/.jpg/.jpeg/.webp file"},
};

static void reasons(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		struct background_spec s;
		char err[200] = "";

		assert_int_equal(background_parse(bad[i].text, &s, err, sizeof(err)), -EINVAL);
		if (!strstr(err, bad[i].reason))
			fail_msg("%s: '%s', expected '%s'", bad[i].text, err, bad[i].reason);
	}
}

/* What the journal says, from fd 2, while fn runs. */
static void captured(void (*fn)(const char *), const char *arg, char *out, size_t n)
{
	char path[] = "/tmp/mk-bg-log-XXXXXX";
	int fd = mkstemp(path), saved = dup(2);
	ssize_t got;

	assert_true(fd >= 0 && saved >= 0);
	fflush(stderr);
	dup2(fd, 2);
	fn(arg);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	got = pread(fd, out, n - 1, 0);
	out[got > 0 ? got : 0] = '\0';
	close(fd);
	unlink(path);
}

static void read_ini(const char *value)
{
	char text[200], path[] = "/tmp/mk-bg-ini-XXXXXX";
	int fd = mkstemp(path);
	struct options o;

	snprintf(text, sizeof(text), "[display]\nsize = 320x240\nbackground = %s\n", value);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
	close(fd);
	option_defaults(&o);
	assert_int_equal(options_read_file(&o, path), OPTIONS_CONFIG);
	options_release(&o);
	unlink(path);
}

static void command_line(const char *value)
{
	const char *argv[] = {"mk", "--background", value};
	struct options o;

	assert_int_equal(options_parse(&o, 3, (char **)argv), OPTIONS_USAGE);
	options_release(&o);
}

/* Every message names the file and line (or the option), the key, the
 * value, the reason and what is accepted. */
static void messages(void **state)
{
	(void)state;
	log_set_level(LOG_ERR);
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		char log[1024], want[400];

		captured(read_ini, bad[i].text, log, sizeof(log));
		snprintf(want, sizeof(want),
			 ":3: [display] background = '%s' is not valid: ", bad[i].text);
		if (!strstr(log, want) || !strstr(log, bad[i].reason) ||
		    !strstr(log, "; expected " BACKGROUND_EXPECTED))
			fail_msg("file, %s: %s", bad[i].text, log);
		captured(command_line, bad[i].text, log, sizeof(log));
		snprintf(want, sizeof(want), "--background: '%s' is not valid: ", bad[i].text);
		if (!strstr(log, want) || !strstr(log, bad[i].reason) ||
		    !strstr(log, "; expected " BACKGROUND_EXPECTED))
			fail_msg("command line, %s: %s", bad[i].text, log);
	}
}

/* A good value is kept as written, for the scene to load. */
static void kept(void **state)
{
	const char *argv[] = {"mk", "--background", "#000000, #ffffff"};
	struct options o;

	(void)state;
	assert_int_equal(options_parse(&o, 3, (char **)argv), OPTIONS_OK);
	assert_string_equal(o.content.background, "#000000, #ffffff");
	options_release(&o);
}

/* In a file, an image's relative path is taken from the file's folder,
 * as every path; colours are left as written. */
static void relative(void **state)
{
	const char *values[][2] = {{"shop.jpg", "/tmp/shop.jpg"},
				   {"#101010, #202020", "#101010, #202020"}};

	(void)state;
	for (int i = 0; i < 2; i++) {
		char text[200], path[] = "/tmp/mk-bg-ini-XXXXXX";
		int fd = mkstemp(path);
		struct options o;

		snprintf(text, sizeof(text), "[display]\nbackground = %s\n", values[i][0]);
		assert_true(fd >= 0);
		assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
		close(fd);
		option_defaults(&o);
		assert_int_equal(options_read_file(&o, path), OPTIONS_OK);
		assert_string_equal(o.content.background, values[i][1]);
		options_release(&o);
		unlink(path);
	}
}

/* The drawing. */
static int setup(void **state)
{
	log_set_level(LOG_ERR);
	*state = offscreen_open(W, H);
	return *state ? 0 : -1;
}

static void draw(struct display *d, const char *text, const struct image *img, int rotation,
		 struct image *frame)
{
	struct background_spec s;
	struct background *b;
	char err[200];

	assert_int_equal(background_parse(text, &s, err, sizeof(err)), 0);
	b = background_new(&d->gl, &s, img);
	assert_non_null(b);
	assert_int_equal(d->begin_frame(d), 0);
	background_draw(b, W, H, rotation);
	assert_int_equal(d->gl.GetError(), GL_NO_ERROR);
	assert_int_equal(d->present(d), 0);
	assert_int_equal(d->read_frame(d, frame), 0);
	background_free(b);
}

static const uint8_t *pixel(const struct image *f, int x, int y)
{
	return f->rgba + ((size_t)y * (size_t)f->width + (size_t)x) * 4;
}

static void near(const uint8_t *p, int r, int g, int b, int tol)
{
	if (abs(p[0] - r) > tol || abs(p[1] - g) > tol || abs(p[2] - b) > tol)
		fail_msg("%d %d %d, expected %d %d %d", p[0], p[1], p[2], r, g, b);
}

static void colour(void **state)
{
	struct image f;

	draw(*state, "#ff8000", NULL, 0, &f);
	near(pixel(&f, 0, 0), 255, 128, 0, 1);
	near(pixel(&f, W - 1, H - 1), 255, 128, 0, 1);
	image_release(&f);
}

/* White at the top, black at the bottom: of the picture as the viewer
 * sees it, so on a panel turned a quarter it runs across the frame. */
static void gradient(void **state)
{
	struct image f;

	draw(*state, "#ffffff, #000000", NULL, 0, &f);
	near(pixel(&f, W / 2, 0), 255, 255, 255, 6);
	near(pixel(&f, W / 2, H - 1), 0, 0, 0, 6);
	near(pixel(&f, 3, H / 2), 128, 128, 128, 6);
	image_release(&f);
	/* 90: the picture's top is the frame's left (render.c turns the
	 * model the same way: the picture's (-1, 1) lands at (-1, -1)). */
	draw(*state, "#ffffff, #000000", NULL, 90, &f);
	near(pixel(&f, 0, H / 2), 255, 255, 255, 6);
	near(pixel(&f, W - 1, H / 2), 0, 0, 0, 6);
	image_release(&f);
}

/* A square image, left half red and right half blue, with a green
 * column at each edge: covering a 3:2 screen, it fills the width and
 * its top and bottom are cropped (the green columns show at the edges);
 * a tall image keeps its left and right, loses its top and bottom. */
static void image(void **state)
{
	struct image img, f;

	assert_int_equal(image_alloc(&img, 32, 32), 0);
	for (int y = 0; y < 32; y++)
		for (int x = 0; x < 32; x++) {
			uint8_t *p = img.rgba + ((size_t)y * 32 + (size_t)x) * 4;
			bool edge = x < 2 || x > 29, top = y < 4;

			p[0] = !edge && x < 16 ? 255 : 0;
			p[1] = edge ? 255 : 0;
			p[2] = !edge && x >= 16 ? 255 : 0;
			p[2] = top && !edge ? 255 : p[2];
			p[3] = 255;
		}
	draw(*state, "cover.png", &img, 0, &f);
	near(pixel(&f, 0, H / 2), 0, 255, 0, 8);
	near(pixel(&f, W - 1, H / 2), 0, 255, 0, 8);
	near(pixel(&f, W / 4, H / 2), 255, 0, 0, 8);
	near(pixel(&f, 3 * W / 4, H / 2), 0, 0, 255, 8);
	/* The top rows (blue-topped) are cropped: the frame's top is red. */
	near(pixel(&f, W / 4, 0), 255, 0, 0, 8);
	image_release(&f);
	image_release(&img);
}

/* The poster is drawn over the same background. */
static void poster(void **state)
{
	struct display *d = *state;
	struct background_spec s;
	struct background *b;
	struct image f;
	char err[200];

	assert_int_equal(background_parse("#ffffff, #000000", &s, err, sizeof(err)), 0);
	b = background_new(&d->gl, &s, NULL);
	assert_non_null(b);
	assert_int_equal(d->begin_frame(d), 0);
	assert_int_equal(poster_draw(&d->gl, NULL, W, H, 0, b), 0);
	assert_int_equal(d->read_frame(d, &f), 0);
	near(pixel(&f, W / 2, 0), 255, 255, 255, 6);
	near(pixel(&f, W / 2, H - 1), 0, 0, 0, 6);
	image_release(&f);
	background_free(b);
}

int main(void)
{
	const struct CMUnitTest pure[] = {
	    cmocka_unit_test(good), cmocka_unit_test(reasons),	cmocka_unit_test(messages),
	    cmocka_unit_test(kept), cmocka_unit_test(relative),
	};
	const struct CMUnitTest gl[] = {
	    cmocka_unit_test(colour),
	    cmocka_unit_test(gradient),
	    cmocka_unit_test(image),
	    cmocka_unit_test(poster),
	};
	int failed = cmocka_run_group_tests_name("background parser", pure, NULL, NULL);

	return failed + cmocka_run_group_tests_name("background drawn", gl, setup, NULL);
}
