/* The caption's picture: each line split into runs of one direction by
 * FriBidi (Unicode's bidi algorithm, brackets included), the runs put in
 * visual order, each shaped by HarfBuzz (kerning, ligatures, Arabic
 * joining) and drawn by FreeType, over the box, beside the logo. */
#include "scene/text/caption.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <fribidi.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb-ft.h>
#include <hb.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* No font is this large (Noto Sans CJK is 20 MB); read whole into memory. */
#define CAPTION_FONT_MAX (64 << 20)

struct glyph {
	unsigned id;
	long x, y; /* 26.6 pixels from the line's start on its baseline, y up */
	long pen;  /* 26.6: where its advance starts (a cut line ends here) */
};

struct line {
	struct glyph *g;
	size_t n, cap;
	long width; /* 26.6 */
};

struct run {
	int start, end;
	FriBidiLevel level;
};

static int push(struct line *l, unsigned id, long x, long y, long pen)
{
	if (l->n == l->cap) {
		size_t cap = l->cap ? l->cap * 2 : 32;
		struct glyph *g = realloc(l->g, cap * sizeof(*g));

		if (!g)
			return -ENOMEM;
		l->g = g;
		l->cap = cap;
	}
	l->g[l->n++] = (struct glyph){id, x, y, pen};
	return 0;
}

/* HarfBuzz gives a right-to-left run's glyphs in visual order already. */
static int shape_run(hb_font_t *font, const uint32_t *u, int len, const struct run *r,
		     struct line *l)
{
	hb_buffer_t *b = hb_buffer_create();
	const hb_glyph_info_t *info;
	const hb_glyph_position_t *pos;
	unsigned n;
	int ret = 0;

	hb_buffer_add_utf32(b, u, len, (unsigned)r->start, r->end - r->start);
	hb_buffer_set_direction(b, r->level & 1 ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
	hb_buffer_guess_segment_properties(b);
	hb_shape(font, b, NULL, 0);
	info = hb_buffer_get_glyph_infos(b, &n);
	pos = hb_buffer_get_glyph_positions(b, &n);
	for (unsigned i = 0; i < n && !ret; i++) {
		ret = push(l, info[i].codepoint, l->width + pos[i].x_offset, pos[i].y_offset,
			   l->width);
		l->width += pos[i].x_advance;
	}
	if (!hb_buffer_allocation_successful(b))
		ret = -ENOMEM;
	hb_buffer_destroy(b);
	return ret;
}

/* Rule L2: from the highest level down to the lowest odd one, reverse
 * every sequence of runs at that level or higher. */
static void reorder_runs(struct run *runs, int n)
{
	FriBidiLevel hi = 0, lo_odd = 255;

	for (int i = 0; i < n; i++) {
		hi = runs[i].level > hi ? runs[i].level : hi;
		if (runs[i].level & 1 && runs[i].level < lo_odd)
			lo_odd = runs[i].level;
	}
	for (int lev = hi; lev >= lo_odd && lev > 0; lev--)
		for (int i = 0; i < n;) {
			int j = i;

			while (j < n && runs[j].level >= lev)
				j++;
			for (int a = i, b = j - 1; a < b; a++, b--) {
				struct run t = runs[a];

				runs[a] = runs[b];
				runs[b] = t;
			}
			i = j > i ? j : i + 1;
		}
}

static int split_runs(const FriBidiLevel *lv, int len, struct run *runs)
{
	int n = 0;

	for (int i = 0; i < len; i++) {
		if (n && runs[n - 1].level == lv[i]) {
			runs[n - 1].end = i + 1;
			continue;
		}
		runs[n++] = (struct run){i, i + 1, lv[i]};
	}
	return n;
}

/* One line of UTF-8 (bytes long, no line break): its paragraph direction
 * from its first strong letter, as a reader expects. */
static int shape_line(hb_font_t *font, const char *utf8, int bytes, struct line *l)
{
	uint32_t *u = malloc(((size_t)bytes + 1) * sizeof(*u));
	FriBidiCharType *types = malloc(((size_t)bytes + 1) * sizeof(*types));
	FriBidiBracketType *brackets = malloc(((size_t)bytes + 1) * sizeof(*brackets));
	FriBidiLevel *lv = malloc(((size_t)bytes + 1) * sizeof(*lv));
	struct run *runs = malloc(((size_t)bytes + 1) * sizeof(*runs));
	FriBidiParType dir = FRIBIDI_PAR_ON;
	int len, n, ret = -ENOMEM;

	if (!u || !types || !brackets || !lv || !runs)
		goto out;
	len = (int)fribidi_charset_to_unicode(FRIBIDI_CHAR_SET_UTF8, utf8, bytes, u);
	fribidi_get_bidi_types(u, len, types);
	fribidi_get_bracket_types(u, len, types, brackets);
	ret = -EINVAL;
	if (len && !fribidi_get_par_embedding_levels_ex(types, brackets, len, &dir, lv))
		goto out;
	n = split_runs(lv, len, runs);
	reorder_runs(runs, n);
	ret = 0;
	for (int i = 0; i < n && !ret; i++)
		ret = shape_run(font, u, len, &runs[i], l);
out:
	free(u);
	free(types);
	free(brackets);
	free(lv);
	free(runs);
	return ret;
}

static void blend(uint8_t *px, const unsigned char c[4], unsigned cover)
{
	unsigned a = cover * c[3] / 255;

	for (int k = 0; k < 3; k++)
		px[k] = (uint8_t)((c[k] * a + px[k] * (255 - a)) / 255);
	px[3] = (uint8_t)(a + px[3] * (255 - a) / 255);
}

static void draw_glyphs(FT_Face face, const struct line *l, long x, long base,
			const unsigned char color[4], struct image *img)
{
	for (size_t i = 0; i < l->n; i++) {
		FT_GlyphSlot s;
		long gx, gy;

		if (FT_Load_Glyph(face, l->g[i].id, FT_LOAD_RENDER))
			continue;
		s = face->glyph;
		if (s->bitmap.pixel_mode != FT_PIXEL_MODE_GRAY)
			continue;
		gx = x + ((l->g[i].x + 32) >> 6) + s->bitmap_left;
		gy = base - ((l->g[i].y + 32) >> 6) - s->bitmap_top;
		for (unsigned r = 0; r < s->bitmap.rows; r++)
			for (unsigned c = 0; c < s->bitmap.width; c++) {
				long px = gx + c, py = gy + r;

				if (px < 0 || py < 0 || px >= img->width || py >= img->height)
					continue;
				blend(img->rgba + (py * img->width + px) * 4, color,
				      s->bitmap.buffer[r * s->bitmap.pitch + c]);
			}
	}
}

static void draw_logo(const struct image *logo, int x0, int y0, struct image *img)
{
	for (int y = 0; y < logo->height; y++)
		for (int x = 0; x < logo->width; x++) {
			const uint8_t *s = logo->rgba + (y * logo->width + x) * 4;

			blend(img->rgba + ((y0 + y) * img->width + x0 + x) * 4, s, 255);
		}
}

struct layout {
	struct line *lines;
	int count;
	long text_w, line_h, ascender; /* whole pixels */
	struct caption_cut cut;
};

int caption_lines_fit(int lines, long line_h, long max_h)
{
	long n = line_h > 0 ? max_h / line_h : lines;

	n = n < 1 ? 1 : n;
	return n < lines ? (int)n : lines;
}

/* The line cut to max (26.6) with an ellipsis at its end (in visual
 * order: a right-to-left line loses its last letters on the right too),
 * or only ended with one when `more` (lines were left out below). */
static int ellipsize(hb_font_t *font, struct line *l, long max, bool more)
{
	hb_codepoint_t id = 0;
	int dots = 1;
	long ell;
	size_t k = l->n;
	int ret = 0;

	if (!more && l->width <= max)
		return 0;
	/* A font without U+2026 has three full stops. */
	if (!hb_font_get_nominal_glyph(font, 0x2026, &id)) {
		hb_font_get_nominal_glyph(font, '.', &id);
		dots = 3;
	}
	ell = dots * (long)hb_font_get_glyph_h_advance(font, id);
	while (k > 0 && (k < l->n ? l->g[k].pen : l->width) + ell > max)
		k--;
	l->width = k < l->n ? l->g[k].pen : l->width;
	l->n = k;
	for (int i = 0; i < dots && !ret; i++) {
		ret = push(l, id, l->width, 0, l->width);
		l->width += ell / dots;
	}
	return ret;
}

/* The lines that fit max_h pixels, each cut to max_w: only those kept are
 * shaped (a text of 20,000 lines is a few). */
static int shape_text(hb_font_t *font, FT_Face face, const char *text, long max_w, long max_h,
		      struct layout *lay)
{
	int ret = 0;

	lay->line_h = (face->size->metrics.height + 63) / 64;
	lay->ascender = (face->size->metrics.ascender + 63) / 64;
	lay->cut.lines = 1;
	for (const char *p = text; *p; p++)
		lay->cut.lines += *p == '\n';
	lay->count = caption_lines_fit(lay->cut.lines, lay->line_h, max_h);
	lay->cut.shown = lay->count;
	lay->lines = calloc((size_t)lay->count, sizeof(*lay->lines));
	if (!lay->lines)
		return -ENOMEM;
	for (int i = 0; i < lay->count && !ret; i++) {
		const char *end = strchr(text, '\n');
		int bytes = end ? (int)(end - text) : (int)strlen(text);
		bool more = i == lay->count - 1 && lay->count < lay->cut.lines;

		ret = shape_line(font, text, bytes, &lay->lines[i]);
		lay->cut.cut += lay->lines[i].width > (max_w - 1) * 64;
		if (!ret)
			ret = ellipsize(font, &lay->lines[i], (max_w - 1) * 64, more);
		if (lay->lines[i].width / 64 + 1 > lay->text_w)
			lay->text_w = lay->lines[i].width / 64 + 1;
		text = end ? end + 1 : text + bytes;
	}
	return ret;
}

static void layout_release(struct layout *lay)
{
	for (int i = 0; lay->lines && i < lay->count; i++)
		free(lay->lines[i].g);
	free(lay->lines);
}

static void fill(struct image *img, const unsigned char c[4])
{
	for (long i = 0; i < (long)img->width * img->height; i++) {
		uint8_t *px = img->rgba + i * 4;

		for (int k = 0; k < 3; k++)
			px[k] = (uint8_t)(c[k] * c[3] / 255);
		px[3] = c[3];
	}
}

/* Text right of the logo, each line aligned to the caption's side. */
static int compose(const struct caption_config *c, FT_Face face, const struct layout *lay,
		   const struct image *logo, struct image *out)
{
	unsigned char color[4] = {255, 255, 255, 255}, box[4] = {0, 0, 0, 153};
	long text_h = lay->count ? lay->count * lay->line_h : 0;
	long gap = logo->width && lay->count ? c->padding : 0;
	long inner_w = logo->width + gap + lay->text_w;
	long inner_h = text_h > logo->height ? text_h : logo->height;
	long x0, y0;
	int ret;

	if (c->color && !caption_parse_color(c->color, color)) {
		log_err("[caption] color = '%s': expected %s", c->color, CAPTION_COLOR_EXPECTED);
		return -EINVAL;
	}
	if (c->box && !strcmp(c->box, "none"))
		box[3] = 0;
	else if (c->box && !caption_parse_color(c->box, box)) {
		log_err("[caption] box = '%s': expected none or %s", c->box,
			CAPTION_COLOR_EXPECTED);
		return -EINVAL;
	}
	ret = -EFBIG;
	if (inner_w + 2 * c->padding <= IMAGE_MAX_SIDE &&
	    inner_h + 2 * c->padding <= IMAGE_MAX_SIDE)
		ret =
		    image_alloc(out, (int)inner_w + 2 * c->padding, (int)inner_h + 2 * c->padding);
	if (ret) {
		log_err("[caption]: a caption of %ldx%ld pixels: %s", inner_w + 2 * c->padding,
			inner_h + 2 * c->padding, strerror(-ret));
		return ret;
	}
	fill(out, box);
	if (logo->width)
		draw_logo(logo, c->padding, c->padding + (int)(inner_h - logo->height) / 2, out);
	x0 = c->padding + logo->width + gap;
	y0 = c->padding + (inner_h - text_h) / 2;
	for (int i = 0; i < lay->count; i++) {
		long w = lay->lines[i].width / 64, x = x0;
		bool right =
		    c->position == CAPTION_BOTTOM_RIGHT || c->position == CAPTION_TOP_RIGHT;

		if (right)
			x = x0 + lay->text_w - w;
		else if (c->position == CAPTION_BOTTOM || c->position == CAPTION_TOP)
			x = x0 + (lay->text_w - w) / 2;
		draw_glyphs(face, &lay->lines[i], x, y0 + i * lay->line_h + lay->ascender, color,
			    out);
	}
	return 0;
}

/* FreeType calls it as the face is done: the bytes it was made from. */
static void font_data_free(void *object)
{
	free(((FT_Face)object)->generic.data);
}

/* Read here (util/file.h), not opened by FreeType by path: a FIFO there
 * would block its open, and a device node is opened before any check. The
 * bytes live as long as the face (its generic finalizer frees them). */
static FT_Error font_face(FT_Library lib, const char *path, FT_Face *face)
{
	unsigned char *data;
	size_t size;
	int ret = file_read_all(path, CAPTION_FONT_MAX, &data, &size);
	FT_Error e;

	if (ret && file_refusal(ret))
		log_err("[caption] font %s: %s", path, file_refusal(ret));
	else if (ret == -EFBIG)
		log_err("[caption] font %s: larger than %d MiB", path, CAPTION_FONT_MAX >> 20);
	else if (ret)
		log_err("[caption] font %s: cannot open it: %s", path, strerror(-ret));
	if (ret)
		return FT_Err_Cannot_Open_Resource;
	e = FT_New_Memory_Face(lib, data, (FT_Long)size, 0, face);
	if (e) {
		free(data);
		return e;
	}
	(*face)->generic.data = data;
	(*face)->generic.finalizer = font_data_free;
	return 0;
}

static int open_font(const struct caption_config *c, FT_Library *lib, FT_Face *face)
{
	const char *path = c->font ? c->font : CAPTION_FONT_DEFAULT;
	double size = c->size > 0 ? c->size : CAPTION_SIZE_DEFAULT;
	FT_Error e;

	if (FT_Init_FreeType(lib))
		return -ENOMEM;
	e = font_face(*lib, path, face);
	if (!e)
		e = FT_Set_Pixel_Sizes(*face, 0, (FT_UInt)(size + 0.5));
	/* FT_Err_Cannot_Open_Resource: font_face said why. */
	if (e == FT_Err_Unknown_File_Format)
		log_err("[caption] font %s: not a font file FreeType reads; expected TrueType or "
			"OpenType",
			path);
	else if (e && e != FT_Err_Cannot_Open_Resource)
		log_err("[caption] font %s: FreeType error %d", path, e);
	if (e)
		return -EINVAL;
	return 0;
}

/* The text's room: the frame less the margin outside the box, the padding
 * inside it, and the logo with its gap. At least a pixel: an ellipsis
 * then shows, a little past the frame. */
static void text_room(const struct caption_config *c, const struct caption_fit *fit,
		      const struct image *logo, bool text, long room[2])
{
	long frame[2] = {fit && fit->width > 0 ? fit->width - 2L * c->padding : IMAGE_MAX_SIDE,
			 fit && fit->height > 0 ? fit->height - 2L * c->padding : IMAGE_MAX_SIDE};
	long gap = logo->width && text ? c->padding : 0;

	for (int k = 0; k < 2; k++) {
		frame[k] = frame[k] > IMAGE_MAX_SIDE ? IMAGE_MAX_SIDE : frame[k];
		room[k] = frame[k] - 2L * c->padding - (k ? 0 : logo->width + gap);
		room[k] = room[k] < 1 ? 1 : room[k];
	}
}

/* The size is the operator's unless one line is taller than the frame:
 * then the largest that fits one, down to CAPTION_SIZE_FLOOR. Returns the
 * size used. */
#define CAPTION_SIZE_FLOOR 8
static int fit_size(const struct caption_config *c, FT_Face face, long room_h)
{
	int size = (int)((c->size > 0 ? c->size : CAPTION_SIZE_DEFAULT) + 0.5);
	long line_h = (face->size->metrics.height + 63) / 64;

	if (line_h <= room_h || size <= CAPTION_SIZE_FLOOR)
		return size;
	size = (int)((long)size * room_h / line_h);
	size = size < CAPTION_SIZE_FLOOR ? CAPTION_SIZE_FLOOR : size;
	FT_Set_Pixel_Sizes(face, 0, (FT_UInt)size);
	return size;
}

static void say_cut(const struct caption_config *c, const struct caption_fit *fit, int size,
		    const struct caption_cut *cut)
{
	int asked = (int)((c->size > 0 ? c->size : CAPTION_SIZE_DEFAULT) + 0.5);
	char smaller[96] = "";

	if (!fit || fit->quiet || (cut->shown == cut->lines && !cut->cut && size == asked))
		return;
	if (size != asked)
		snprintf(smaller, sizeof(smaller), ", at size %d, not %d (a line is taller)", size,
			 asked);
	log_warn("%s: the caption does not fit the %dx%d frame: %d of its %d lines shown%s, "
		 "%d cut at the side with an ellipsis%s",
		 fit->what ? fit->what : "[caption] text", fit->width ? fit->width : IMAGE_MAX_SIDE,
		 fit->height ? fit->height : IMAGE_MAX_SIDE, cut->shown, cut->lines,
		 cut->shown < cut->lines ? " (the last ends with an ellipsis)" : "", cut->cut,
		 smaller);
}

int caption_render_fit(const struct caption_config *c, const char *name,
		       const struct caption_fit *fit, struct image *out, struct caption_cut *cut)
{
	char *text = caption_text(c, name);
	struct image logo = {0};
	struct layout lay = {0};
	FT_Library lib = NULL;
	FT_Face face = NULL;
	hb_font_t *font = NULL;
	long room[2];
	int ret = 0, size;

	memset(out, 0, sizeof(*out));
	if (!text && !(c->logo && *c->logo)) {
		ret = -ENOENT;
		goto out;
	}
	if (c->logo && *c->logo)
		ret = image_load(c->logo, &logo);
	if (!ret)
		ret = open_font(c, &lib, &face);
	if (!ret && text) {
		text_room(c, fit, &logo, true, room);
		size = fit_size(c, face, room[1]);
		font = hb_ft_font_create_referenced(face);
		ret = font ? shape_text(font, face, text, room[0], room[1], &lay) : -ENOMEM;
		if (ret)
			log_err("[caption] text: cannot shape it: %s", strerror(-ret));
		else
			say_cut(c, fit, size, &lay.cut);
	}
	if (!ret)
		ret = compose(c, face, &lay, &logo, out);
	if (cut)
		*cut = lay.cut;
out:
	layout_release(&lay);
	if (font)
		hb_font_destroy(font);
	if (face)
		FT_Done_Face(face);
	if (lib)
		FT_Done_FreeType(lib);
	image_release(&logo);
	free(text);
	return ret;
}

int caption_render(const struct caption_config *c, const char *name, struct image *out)
{
	struct caption_fit fit = {0, 0, NULL, false};

	return caption_render_fit(c, name, &fit, out, NULL);
}
