/* [caption]: the colours and the text's escapes, the placement in each
 * position and its drift (bounded, a pixel at a time, none when off), the
 * picture (kerning narrows "AV", a line break adds a line, the box and
 * the text's colour premultiplied, a bad font or logo named), and the
 * quad on a real GL (OSMesa, or EGL where Mesa has no OSMesa): pixel for
 * pixel where the viewer sees it, on an upright panel and one turned a
 * quarter. */
#include "display/display.h"
#include "render/caption.h"
#include "render/render.h"
#include "scene/text/caption.h"
#include "scene/text/caption_font.h"
#include "scene/gltf/gltf_name.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
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

static void colors(void **state)
{
	unsigned char c[4];

	(void)state;
	assert_true(caption_parse_color("#ff8000", c));
	assert_int_equal(c[0], 255);
	assert_int_equal(c[1], 128);
	assert_int_equal(c[2], 0);
	assert_int_equal(c[3], 255);
	assert_true(caption_parse_color("#00000080", c));
	assert_int_equal(c[3], 128);
	assert_false(caption_parse_color("ff8000", c));
	assert_false(caption_parse_color("#ff80", c));
	assert_false(caption_parse_color("#gg8000", c));
	assert_false(caption_parse_color(NULL, c));
}

static void texts(void **state)
{
	struct caption_config c = {.text = "Vase\\nLent by \\\\ us"};
	char *t = caption_text(&c, "knot");

	(void)state;
	assert_string_equal(t, "Vase\nLent by \\ us");
	free(t);
	c.text = "auto";
	t = caption_text(&c, "amphora");
	assert_string_equal(t, "amphora");
	free(t);
	assert_null(caption_text(&c, NULL));
	c.text = NULL;
	assert_null(caption_text(&c, "amphora"));
	assert_false(caption_wanted(&c));
	c.logo = "logo.png";
	assert_true(caption_wanted(&c));
}

static void placed(void **state)
{
	struct caption_config c = {.padding = 10};
	int at[2];

	(void)state;
	c.position = CAPTION_BOTTOM_LEFT;
	caption_place(&c, 100, 40, 800, 600, 0, at);
	assert_int_equal(at[0], 10);
	assert_int_equal(at[1], 550);
	c.position = CAPTION_TOP_RIGHT;
	caption_place(&c, 100, 40, 800, 600, 0, at);
	assert_int_equal(at[0], 690);
	assert_int_equal(at[1], 10);
	c.position = CAPTION_BOTTOM;
	caption_place(&c, 100, 40, 800, 600, 0, at);
	assert_int_equal(at[0], 350);
	assert_int_equal(at[1], 550);
	/* Off: the same place at any hour. */
	caption_place(&c, 100, 40, 800, 600, 12345.0, at);
	assert_int_equal(at[0], 350);
}

/* Over two days, minute by minute: within the bound, a pixel at a time,
 * and it does move on both axes. */
static void drifts(void **state)
{
	struct caption_config c = {.padding = 10, .drift = true};
	int at[2], before[2], lo[2] = {1 << 20, 1 << 20}, hi[2] = {-(1 << 20), -(1 << 20)};

	(void)state;
	caption_place(&c, 100, 40, 800, 600, 0, before);
	assert_int_equal(before[0], 10);
	for (int m = 1; m <= 48 * 60; m++) {
		caption_place(&c, 100, 40, 800, 600, m * 60.0, at);
		for (int k = 0; k < 2; k++) {
			assert_true(abs(at[k] - before[k]) <= 1);
			lo[k] = at[k] < lo[k] ? at[k] : lo[k];
			hi[k] = at[k] > hi[k] ? at[k] : hi[k];
			before[k] = at[k];
		}
	}
	assert_int_equal(lo[0], 10 - CAPTION_DRIFT_PX);
	assert_int_equal(hi[0], 10 + CAPTION_DRIFT_PX);
	assert_int_equal(lo[1], 550 - CAPTION_DRIFT_PX);
	assert_int_equal(hi[1], 550 + CAPTION_DRIFT_PX);
}

/* --status's frame with the plane's caption put in: premultiplied over,
 * clipped at the frame's edge. */
static void blended(void **state)
{
	struct image cap, frame;

	(void)state;
	assert_int_equal(image_alloc(&cap, 2, 1), 0);
	assert_int_equal(image_alloc(&frame, 2, 2), 0);
	memcpy(cap.rgba, (uint8_t[]){128, 0, 0, 128, 0, 0, 0, 0}, 8);
	memset(frame.rgba, 200, 16);
	caption_blend(&cap, 1, 1, &frame);
	assert_int_equal(frame.rgba[12], 128 + 200 * 127 / 255);
	assert_int_equal(frame.rgba[13], 200 * 127 / 255);
	assert_int_equal(frame.rgba[0], 200);
	assert_int_equal(frame.rgba[8], 200);
	image_release(&cap);
	image_release(&frame);
}

static int width_of(const char *text)
{
	struct caption_config c = {.text = (char *)text, .size = 40, .box = "none"};
	struct image img;
	int w;

	assert_int_equal(caption_render(&c, NULL, &img), 0);
	w = img.width;
	image_release(&img);
	return w;
}

/* HarfBuzz applies the font's kerning: "AV" is narrower than "A" and "V"
 * apart (each picture is one pixel wider than its text). */
static void kerned(void **state)
{
	(void)state;
	assert_true(width_of("AV") - 1 < width_of("A") - 1 + width_of("V") - 1 - 1);
}

static void pictured(void **state)
{
	struct caption_config c = {
	    .text = "Ag", .size = 20, .padding = 4, .color = "#ff0000", .box = "#0000ff80"};
	struct image one, two;
	const uint8_t *corner;

	(void)state;
	assert_int_equal(caption_render(&c, NULL, &one), 0);
	/* The box premultiplied: blue at half. */
	corner = one.rgba;
	assert_int_equal(corner[0], 0);
	assert_int_equal(corner[2], 128);
	assert_int_equal(corner[3], 128);
	c.text = "Ag\\nAg";
	assert_int_equal(caption_render(&c, NULL, &two), 0);
	assert_int_equal(two.width, one.width);
	assert_true(two.height > one.height + 15);
	/* Some pixel is the text's red, fully covered. */
	{
		bool red = false;

		for (long i = 0; i < (long)one.width * one.height && !red; i++)
			red = one.rgba[i * 4] == 255 && one.rgba[i * 4 + 3] == 255;
		assert_true(red);
	}
	image_release(&one);
	image_release(&two);
}

static void refused(void **state)
{
	struct caption_config c = {.text = "x", .size = 20};
	struct image img;

	(void)state;
	c.font = "/nonexistent/font.ttf";
	assert_int_equal(caption_render(&c, NULL, &img), -EINVAL);
	assert_null(img.rgba);
	c.font = NULL;
	c.logo = "/nonexistent/logo.png";
	assert_true(caption_render(&c, NULL, &img) < 0);
	assert_null(img.rgba);
	c.logo = NULL;
	c.color = "red";
	assert_int_equal(caption_render(&c, NULL, &img), -EINVAL);
	c.color = NULL;
	c.text = NULL;
	assert_int_equal(caption_render(&c, NULL, &img), -ENOENT);
}

static void write_file(const char *path, const void *data, size_t n)
{
	FILE *f = fopen(path, "wb");

	assert_non_null(f);
	assert_int_equal(fwrite(data, 1, n, f), n);
	fclose(f);
}

static void put_u32(unsigned char *p, uint32_t v)
{
	for (int k = 0; k < 4; k++)
		p[k] = (unsigned char)(v >> (8 * k));
}

/* [caption] text = auto: asset.extras.title first, else the scene shown
 * ([scene] model_scene by index or name, else "scene", else the first),
 * from a .gltf and from a GLB's JSON chunk; nothing from a file that names
 * none or is not glTF. */
static void named(void **state)
{
	static const char titled[] =
	    "{\"asset\":{\"version\":\"2.0\",\"extras\":{\"title\":\"Amphora \u05db\"}},"
	    "\"scenes\":[{\"name\":\"A\"}]}";
	static const char scenes[] = "{\"asset\":{\"version\":\"2.0\"},\"scene\":1,"
				     "\"scenes\":[{\"name\":\"First\"},{\"name\":\"Second\"}]}";
	static const char bare[] = "{\"asset\":{\"version\":\"2.0\"}}";
	char dir[] = "/tmp/test_caption.XXXXXX", path[64];
	unsigned char glb[20 + sizeof(scenes) + 3] = "glTF";
	size_t json = (sizeof(scenes) - 1 + 3) & ~(size_t)3;
	char *name;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/t.gltf", dir);
	write_file(path, titled, sizeof(titled) - 1);
	name = gltf_model_name(path, NULL);
	assert_string_equal(name, "Amphora \xd7\x9b");
	free(name);
	write_file(path, scenes, sizeof(scenes) - 1);
	name = gltf_model_name(path, NULL);
	assert_string_equal(name, "Second");
	free(name);
	name = gltf_model_name(path, "0");
	assert_string_equal(name, "First");
	free(name);
	assert_null(gltf_model_name(path, "7"));
	/* The same as a GLB: the JSON chunk, padded with spaces. */
	put_u32(glb + 4, 2);
	put_u32(glb + 8, (uint32_t)(20 + json));
	put_u32(glb + 12, (uint32_t)json);
	put_u32(glb + 16, 0x4E4F534Au);
	memset(glb + 20, ' ', json);
	memcpy(glb + 20, scenes, sizeof(scenes) - 1);
	snprintf(path, sizeof(path), "%s/t.glb", dir);
	write_file(path, glb, 20 + json);
	name = gltf_model_name(path, NULL);
	assert_string_equal(name, "Second");
	free(name);
	write_file(path, bare, sizeof(bare) - 1);
	assert_null(gltf_model_name(path, NULL));
	write_file(path, "not json", 8);
	assert_null(gltf_model_name(path, NULL));
	unlink(path);
	snprintf(path, sizeof(path), "%s/t.gltf", dir);
	unlink(path);
	rmdir(dir);
}

static int setup(void **state)
{
	log_set_level(LOG_ERR);
	*state = offscreen_open(W, H);
	return *state ? 0 : -1;
}

static const uint8_t *pixel(const struct image *f, int x, int y)
{
	return f->rgba + ((size_t)y * (size_t)f->width + (size_t)x) * 4;
}

/* A 4x2 picture, its top-left texel red, the rest green, top-left on a
 * panel cleared black: at (pad, pad) upright; turned a quarter, the
 * viewer's top-left is where rotation 90 puts the frame's pixel. */
static void drawn(struct display *d, int rotation, int x, int y)
{
	struct caption_config c = {.padding = 3, .position = CAPTION_TOP_LEFT};
	struct image img, f;
	struct caption_gl *cap;

	assert_int_equal(image_alloc(&img, 4, 2), 0);
	for (int i = 0; i < 8; i++) {
		uint8_t px[4] = {i ? 0 : 255, i ? 255 : 0, 0, 255};

		memcpy(img.rgba + i * 4, px, 4);
	}
	cap = caption_gl_new(&d->gl, &img, &c);
	assert_non_null(cap);
	assert_int_equal(d->begin_frame(d), 0);
	d->gl.ClearColor(0, 0, 0, 1);
	d->gl.Clear(GL_COLOR_BUFFER_BIT);
	caption_gl_draw(cap, 0, W, H, rotation);
	assert_int_equal(d->read_frame(d, &f), 0);
	assert_int_equal(pixel(&f, x, y)[0], 255);
	assert_int_equal(pixel(&f, x, y)[1], 0);
	assert_int_equal(pixel(&f, 0, 0)[1], 0);
	image_release(&f);
	image_release(&img);
	caption_gl_free(cap);
}

static void upright(void **state)
{
	drawn(*state, 0, 3, 3);
}

/* Turned 90 degrees as poster.c and the renderer turn theirs (the
 * turned screen's x runs up the frame, its y to the right): its top-left
 * corner is the frame's bottom-left. */
static void turned(void **state)
{
	drawn(*state, 90, 3, H - 1 - 3);
}

/* A 2x2 picture of one colour. */
static void solid(struct image *img, uint8_t r, uint8_t g)
{
	assert_int_equal(image_alloc(img, 2, 2), 0);
	for (int i = 0; i < 4; i++)
		memcpy(img->rgba + i * 4, (uint8_t[4]){r, g, 0, 255}, 4);
}

static uint8_t green_at(struct display *d, struct renderer *r)
{
	struct view v = {0};
	struct image f;
	uint8_t g;

	assert_int_equal(d->begin_frame(d), 0);
	d->gl.ClearColor(0, 0, 0, 1);
	d->gl.Clear(GL_COLOR_BUFFER_BIT);
	renderer_draw_caption(r, &v, 0, W, H);
	assert_int_equal(d->read_frame(d, &f), 0);
	g = pixel(&f, 3, 3)[1];
	assert_int_equal(pixel(&f, 3, 3)[0], 255 - g);
	image_release(&f);
	return g;
}

/* [frame] stops: the renderer shows the picture of the stop the app is
 * at (green) where it has one, else the caption (red), each picture with
 * its own serial (a new plane buffer for each). */
static void stop_picked(void **state)
{
	struct display *d = *state;
	struct caption_config c = {.padding = 3, .position = CAPTION_TOP_LEFT};
	struct image caption, stops[2] = {{0}};
	struct renderer *r = renderer_new(&d->gl, NULL);
	unsigned serial;

	assert_non_null(r);
	solid(&caption, 255, 0);
	solid(&stops[0], 0, 255);
	assert_int_equal(renderer_set_caption(r, &caption, &c), 0);
	assert_int_equal(renderer_set_stop_captions(r, stops, 2, &c), 0);
	serial = renderer_caption_serial(r);
	assert_int_not_equal(serial, 0);
	assert_int_equal(green_at(d, r), 0);
	renderer_show_stop(r, 0);
	assert_int_equal(green_at(d, r), 255);
	assert_int_not_equal(renderer_caption_serial(r), serial);
	assert_int_not_equal(renderer_caption_serial(r), 0);
	renderer_show_stop(r, 1); /* no text: the caption */
	assert_int_equal(green_at(d, r), 0);
	assert_int_equal(renderer_caption_serial(r), serial);
	renderer_show_stop(r, 0);
	assert_int_equal(green_at(d, r), 255);
	renderer_show_stop(r, -1);
	assert_int_equal(green_at(d, r), 0);
	assert_int_equal(renderer_caption_serial(r), serial);
	renderer_free(r);
	image_release(&caption);
	image_release(&stops[0]);
}

/* The attacks: a text far larger than the frame is laid out within it
 * (the picture and the margin round it fit 640x480), cut with an
 * ellipsis, never refused. */
static void fitted(const char *text, double size, struct caption_cut *cut)
{
	struct caption_config c = {.text = (char *)text, .size = size, .padding = 12};
	struct caption_fit fit = {640, 480, "test", false};
	struct image img;

	assert_int_equal(caption_render_fit(&c, NULL, &fit, &img, cut), 0);
	assert_true(img.width <= 640 - 2 * 12 && img.height <= 480 - 2 * 12);
	image_release(&img);
}

static char *repeated(const char *unit, int n)
{
	size_t len = strlen(unit);
	char *s = malloc(len * (size_t)n + 1);

	assert_non_null(s);
	for (int i = 0; i < n; i++)
		memcpy(s + len * (size_t)i, unit, len);
	s[len * (size_t)n] = '\0';
	return s;
}

static void twenty_thousand_lines_fit(void **state)
{
	char *text = repeated("line\\n", 20000);
	struct caption_cut cut;

	(void)state;
	fitted(text, 0, &cut);
	assert_int_equal(cut.lines, 20001);
	assert_true(cut.shown > 1 && cut.shown < 20);
	free(text);
}

static void hundred_thousand_chars_fit(void **state)
{
	char *text = repeated("x", 100000);
	struct caption_cut cut;

	(void)state;
	fitted(text, 0, &cut);
	/* A word of 100,000 letters wraps between its letters: the lines
	 * that fit are shown, the last with an ellipsis, none cut at the
	 * side. */
	assert_true(cut.shown > 1 && cut.shown < cut.lines && cut.cut == 0);
	free(text);
}

/* 100,000 words: every one measured (HarfBuzz shapes a long buffer only
 * so far; measured whole, the words past it measured nothing and all
 * fitted the last line), so thousands of lines are counted. */
static void hundred_thousand_words_measured(void **state)
{
	char *text = repeated("Wort ", 100000);
	struct caption_cut cut;

	(void)state;
	fitted(text, 0, &cut);
	assert_true(cut.lines > 10000 && cut.shown > 1 && cut.shown < 20 && cut.cut == 0);
	free(text);
}

/* Before the frame is known a long text is laid out in a large panel's
 * frame, not in IMAGE_MAX_SIDE's: its picture was 8192x8192 (256 MiB)
 * until it was fitted. */
static void no_frame_yet_a_panel_sized_picture(void **state)
{
	char *text = repeated("x", 100000);
	struct caption_config c = {.text = text, .padding = 12};
	struct caption_fit fit = {.quiet = true};
	struct image img;

	(void)state;
	assert_int_equal(caption_render_fit(&c, NULL, &fit, &img, NULL), 0);
	assert_true(img.width <= CAPTION_FRAME_GUESS_W && img.height <= CAPTION_FRAME_GUESS_H);
	image_release(&img);
	free(text);
}

static void a_size_too_large_fits(void **state)
{
	char *lines = repeated("A\\n", 90);
	struct caption_cut cut;

	(void)state;
	fitted(lines, 400, &cut);
	assert_true(cut.lines == 91 && cut.shown == 1);
	free(lines);
	/* A caption that fits is not touched. */
	fitted("Amphora", 0, &cut);
	assert_true(cut.lines == 1 && cut.shown == 1 && cut.cut == 0);
}

static void lines_that_fit(void **state)
{
	(void)state;
	assert_int_equal(caption_lines_fit(20000, 33, 432), 13);
	assert_int_equal(caption_lines_fit(3, 33, 432), 3);
	assert_int_equal(caption_lines_fit(90, 466, 432), 1);
}

/* The characters no installed font has, each once, in the order met:
 * Japanese is drawn from Noto CJK (make deps-test installs it), an emoji
 * DejaVu lacks and an Egyptian hieroglyph are not (no test package has
 * them); a variation selector needs no glyph. Each is named with the
 * package that has it. */
static void missing_characters(void **state)
{
	uint32_t c[4];

	(void)state;
	assert_int_equal(caption_missing(NULL, "ja", "Vase 花瓶、有田", c, 4), 0);
	assert_int_equal(caption_missing(NULL, NULL,
					 "a \xf0\x9f\x8f\xba b \xf0\x9f\x8f\xba "
					 "\xf0\x93\x80\x80 \xe2\x98\xba\xef\xb8\x8f",
					 c, 4),
			 2);
	assert_int_equal(c[0], 0x1f3fa);
	assert_int_equal(c[1], 0x13000);
	/* Past cap: counted, not written. */
	assert_int_equal(caption_missing(NULL, NULL, "\xf0\x9f\x8f\xba\xf0\x93\x80\x80", c, 1), 2);
	assert_int_equal(c[0], 0x1f3fa);
	assert_string_equal(caption_font_package(0x82b1), "fonts-noto-cjk");
	assert_string_equal(caption_font_package(0xac00), "fonts-noto-cjk");
	assert_string_equal(caption_font_package(0x1f3fa), "fonts-symbola");
	assert_string_equal(caption_font_package(0x13000), "fonts-noto-core");
	assert_string_equal(caption_font_package(0x0915), "fonts-noto-core");
	/* A font that does not open: said, and an error. */
	assert_true(caption_missing("/nonexistent.ttf", NULL, "x", c, 4) < 0);
}

/* A Japanese caption is drawn from the fallback, not as the default
 * font's boxes: its picture differs from that of other characters the
 * default font lacks (all the same box), and it is not refused. */
static void drawn_from_the_fallback(void **state)
{
	struct caption_config a = {.text = "花瓶", .size = 24, .box = "none"};
	struct caption_config b = {
	    .text = "\xf0\x93\x80\x80\xf0\x93\x80\x80", .size = 24, .box = "none"};
	struct image ia, ib;

	(void)state;
	assert_int_equal(caption_render(&a, NULL, &ia), 0);
	assert_int_equal(caption_render(&b, NULL, &ib), 0);
	assert_true(ia.width != ib.width || ia.height != ib.height ||
		    memcmp(ia.rgba, ib.rgba, (size_t)ia.width * ia.height * 4));
	image_release(&ia);
	image_release(&ib);
}

int main(void)
{
	const struct CMUnitTest pure[] = {
	    cmocka_unit_test(colors),  cmocka_unit_test(texts),	 cmocka_unit_test(placed),
	    cmocka_unit_test(drifts),  cmocka_unit_test(kerned), cmocka_unit_test(pictured),
	    cmocka_unit_test(refused), cmocka_unit_test(named),	 cmocka_unit_test(blended),
	};
	const struct CMUnitTest gl[] = {
	    cmocka_unit_test(upright),
	    cmocka_unit_test(turned),
	    cmocka_unit_test(stop_picked),
	    cmocka_unit_test(twenty_thousand_lines_fit),
	    cmocka_unit_test(hundred_thousand_chars_fit),
	    cmocka_unit_test(a_size_too_large_fits),
	    cmocka_unit_test(hundred_thousand_words_measured),
	    cmocka_unit_test(no_frame_yet_a_panel_sized_picture),
	    cmocka_unit_test(lines_that_fit),
	    cmocka_unit_test(missing_characters),
	    cmocka_unit_test(drawn_from_the_fallback),
	};
	int failed = cmocka_run_group_tests_name("caption picture", pure, NULL, NULL);

	return failed + cmocka_run_group_tests_name("caption drawn", gl, setup, NULL);
}
