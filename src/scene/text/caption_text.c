/* The caption's picture: each paragraph broken into lines that fit
 * (caption_wrap.c), each line split into runs of one direction by
 * FriBidi (Unicode's bidi algorithm, brackets included), the runs put in
 * visual order, each cut where its characters need another font
 * (caption_font.c), shaped by HarfBuzz (kerning, ligatures, Arabic
 * joining) and drawn by FreeType, over the box, beside the logo. */
#include "scene/text/caption.h"
#include "scene/text/caption_font.h"
#include "scene/text/caption_wrap.h"
#include "util/log.h"

#include <errno.h>
#include <fribidi.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct glyph {
	unsigned id;
	int font;     /* caption_fonts' index */
	int cluster;  /* the code point it came from, in the text shaped */
	long x, y;    /* 26.6 pixels from the line's start on its baseline, y up */
	long pen;     /* 26.6: where its advance starts (a cut line ends here) */
	long advance; /* 26.6 */
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

static int push(struct line *l, struct glyph g)
{
	if (l->n == l->cap) {
		size_t cap = l->cap ? l->cap * 2 : 32;
		struct glyph *g = realloc(l->g, cap * sizeof(*g));

		if (!g)
			return -ENOMEM;
		l->g = g;
		l->cap = cap;
	}
	l->g[l->n++] = g;
	return 0;
}

/* One piece of a run in one font. HarfBuzz gives a right-to-left
 * piece's glyphs in visual order already. */
static int shape_piece(const struct caption_fonts *fonts, int fi, const uint32_t *u, int len,
		       int start, int end, bool rtl, struct line *l)
{
	hb_buffer_t *b = hb_buffer_create();
	const hb_glyph_info_t *info;
	const hb_glyph_position_t *pos;
	unsigned n;
	int ret = 0;

	hb_buffer_add_utf32(b, u, len, (unsigned)start, end - start);
	hb_buffer_set_direction(b, rtl ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
	hb_buffer_guess_segment_properties(b);
	hb_shape(caption_fonts_hb(fonts, fi), b, NULL, 0);
	info = hb_buffer_get_glyph_infos(b, &n);
	pos = hb_buffer_get_glyph_positions(b, &n);
	for (unsigned i = 0; i < n && !ret; i++) {
		ret = push(l, (struct glyph){info[i].codepoint, fi, (int)info[i].cluster,
					     l->width + pos[i].x_offset, pos[i].y_offset, l->width,
					     pos[i].x_advance});
		l->width += pos[i].x_advance;
	}
	if (!hb_buffer_allocation_successful(b))
		ret = -ENOMEM;
	hb_buffer_destroy(b);
	return ret;
}

static bool is_mark(uint32_t c)
{
	hb_unicode_general_category_t g =
	    hb_unicode_general_category(hb_unicode_funcs_get_default(), c);

	return g == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK ||
	       g == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
	       g == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

/* The font of c after a character in font prev: a joiner, a variation
 * selector or a mark that font has stays with its letter; a character
 * no font has is the caption's own font's box. */
static int font_of(struct caption_fonts *fonts, uint32_t c, int prev)
{
	int fi;

	if (prev >= 0 && (caption_char_invisible(c) ||
			  (is_mark(c) && FT_Get_Char_Index(caption_fonts_face(fonts, prev), c))))
		return prev;
	fi = caption_fonts_pick(fonts, c);
	return fi < 0 ? 0 : fi;
}

/* A run of one direction, cut where the font changes; a right-to-left
 * run's pieces go right to left. */
static int shape_run(struct caption_fonts *fonts, const uint32_t *u, int len, const struct run *r,
		     struct line *l)
{
	int n = r->end - r->start, ret = 0;
	int *fi = malloc((size_t)(n > 0 ? n : 1) * sizeof(*fi));
	bool rtl = r->level & 1;

	if (!fi)
		return -ENOMEM;
	for (int i = 0; i < n; i++)
		fi[i] = font_of(fonts, u[r->start + i], i ? fi[i - 1] : -1);
	for (int k = 0; k < n && !ret;) {
		/* The k-th code point from the run's visual start. */
		int a = rtl ? n - 1 - k : k, b = a;

		while (rtl ? b > 0 && fi[b - 1] == fi[a] : b + 1 < n && fi[b + 1] == fi[a])
			b += rtl ? -1 : 1;
		ret = shape_piece(fonts, fi[a], u, len, r->start + (rtl ? b : a),
				  r->start + (rtl ? a : b) + 1, rtl, l);
		k += (rtl ? a - b : b - a) + 1;
	}
	free(fi);
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

/* One line of code points (no line break): its paragraph direction from
 * its first strong letter, as a reader expects. */
static int shape_line(struct caption_fonts *fonts, const uint32_t *u, int len, struct line *l)
{
	FriBidiCharType *types = malloc(((size_t)len + 1) * sizeof(*types));
	FriBidiBracketType *brackets = malloc(((size_t)len + 1) * sizeof(*brackets));
	FriBidiLevel *lv = malloc(((size_t)len + 1) * sizeof(*lv));
	struct run *runs = malloc(((size_t)len + 1) * sizeof(*runs));
	FriBidiParType dir = FRIBIDI_PAR_ON;
	int n, ret = -ENOMEM;

	if (!types || !brackets || !lv || !runs)
		goto out;
	fribidi_get_bidi_types(u, len, types);
	fribidi_get_bracket_types(u, len, types, brackets);
	ret = -EINVAL;
	if (len && !fribidi_get_par_embedding_levels_ex(types, brackets, len, &dir, lv))
		goto out;
	n = split_runs(lv, len, runs);
	reorder_runs(runs, n);
	ret = 0;
	for (int i = 0; i < n && !ret; i++)
		ret = shape_run(fonts, u, len, &runs[i], l);
out:
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

static void draw_glyphs(const struct caption_fonts *fonts, const struct line *l, long x, long base,
			const unsigned char color[4], struct image *img)
{
	for (size_t i = 0; i < l->n; i++) {
		FT_Face face = caption_fonts_face(fonts, l->g[i].font);
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
	long step;
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
	step = ell / dots;
	for (int i = 0; i < dots && !ret; i++) {
		ret = push(l, (struct glyph){id, 0, -1, l->width, 0, l->width, step});
		l->width += step;
	}
	return ret;
}

/* Code points shaped at once to measure: HarfBuzz stops shaping a
 * buffer past a budget of operations (its defence against hostile
 * text), and the rest would measure nothing and fit one line. */
#define MEASURE_CHUNK 2048

/* Where a chunk from start ends: at a blank near the budget, so that a
 * word is shaped whole (kerning, Arabic joining), else at the budget. */
static int chunk_end(const uint32_t *u, int start, int len)
{
	int end = start + MEASURE_CHUNK;

	if (end >= len)
		return len;
	for (int i = end; i > end - MEASURE_CHUNK / 8; i--)
		if (u[i - 1] == ' ')
			return i;
	return end;
}

/* Each code point's advance in the paragraph u (26.6): the glyphs of
 * its cluster, shaped a chunk at a time. */
static int advances(struct caption_fonts *fonts, const uint32_t *u, int len, long *adv)
{
	int ret = 0;

	for (int i = 0; i < len; i++)
		adv[i] = 0;
	for (int start = 0, end; start < len && !ret; start = end) {
		struct line l = {0};

		end = chunk_end(u, start, len);
		ret = shape_line(fonts, u + start, end - start, &l);
		for (size_t i = 0; !ret && i < l.n; i++)
			if (l.g[i].cluster >= 0 && l.g[i].cluster < end - start)
				adv[start + l.g[i].cluster] += l.g[i].advance;
		free(l.g);
	}
	return ret;
}

/* One paragraph (bytes of UTF-8, no '\n') wrapped into max_w, its lines
 * that fit the room shaped into lay's free lines, all of them counted. */
static int wrap_paragraph(struct caption_fonts *fonts, const char *lang, const char *utf8,
			  int bytes, long max_w, int room, struct layout *lay)
{
	uint32_t *u = malloc(((size_t)bytes + 1) * sizeof(*u));
	long *adv = malloc(((size_t)bytes + 1) * sizeof(*adv));
	struct caption_span *spans = malloc(((size_t)room + 1) * sizeof(*spans));
	int len, n, ret = -ENOMEM;

	if (!u || !adv || !spans)
		goto out;
	len = (int)fribidi_charset_to_unicode(FRIBIDI_CHAR_SET_UTF8, utf8, bytes, u);
	ret = advances(fonts, u, len, adv);
	n = ret ? 0 : caption_wrap(u, adv, len, lang, max_w, spans, room);
	if (n < 0)
		ret = n;
	if (!ret && !n)
		spans[n++] = (struct caption_span){0, 0, 0}; /* an empty line */
	for (int i = 0; !ret && i < n && i < room; i++) {
		struct line *l = &lay->lines[lay->count++];

		ret = shape_line(fonts, u + spans[i].start, spans[i].end - spans[i].start, l);
	}
	lay->cut.lines += ret ? 0 : n;
out:
	free(u);
	free(adv);
	free(spans);
	return ret;
}

/* The lines that fit max_h pixels, the text wrapped to max_w: only the
 * paragraphs with lines kept are shaped (a text of 20,000 lines is a
 * few), the others counted a line each. */
static int shape_text(struct caption_fonts *fonts, const char *lang, const char *text, long max_w,
		      long max_h, struct layout *lay)
{
	FT_Face face = caption_fonts_face(fonts, 0);
	int ret = 0, fit;

	lay->line_h = (face->size->metrics.height + 63) / 64;
	lay->ascender = (face->size->metrics.ascender + 63) / 64;
	fit = caption_lines_fit(INT32_MAX, lay->line_h, max_h);
	lay->lines = calloc((size_t)fit, sizeof(*lay->lines));
	if (!lay->lines)
		return -ENOMEM;
	while (!ret) {
		const char *end = strchr(text, '\n');
		int bytes = end ? (int)(end - text) : (int)strlen(text);

		if (lay->count < fit)
			ret = wrap_paragraph(fonts, lang, text, bytes, (max_w - 1) * 64,
					     fit - lay->count, lay);
		else
			lay->cut.lines++;
		if (!end)
			break;
		text = end + 1;
	}
	lay->cut.shown = lay->count;
	for (int i = 0; i < lay->count && !ret; i++) {
		struct line *l = &lay->lines[i];
		bool more = i == lay->count - 1 && lay->count < lay->cut.lines;

		lay->cut.cut += l->width > (max_w - 1) * 64;
		ret = ellipsize(caption_fonts_hb(fonts, 0), l, (max_w - 1) * 64, more);
		if (l->width / 64 + 1 > lay->text_w)
			lay->text_w = l->width / 64 + 1;
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
static int compose(const struct caption_config *c, const struct caption_fonts *fonts,
		   const struct layout *lay, const struct image *logo, struct image *out)
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
		draw_glyphs(fonts, &lay->lines[i], x, y0 + i * lay->line_h + lay->ascender, color,
			    out);
	}
	return 0;
}

/* The text's room: the frame less the margin outside the box, the padding
 * inside it, and the logo with its gap. At least a pixel: an ellipsis
 * then shows, a little past the frame. */
static void text_room(const struct caption_config *c, const struct caption_fit *fit,
		      const struct image *logo, bool text, long room[2])
{
	long frame[2] = {
	    (fit && fit->width > 0 ? fit->width : CAPTION_FRAME_GUESS_W) - 2L * c->padding,
	    (fit && fit->height > 0 ? fit->height : CAPTION_FRAME_GUESS_H) - 2L * c->padding};
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
static int fit_size(const struct caption_config *c, struct caption_fonts *fonts, long room_h)
{
	int size = (int)((c->size > 0 ? c->size : CAPTION_SIZE_DEFAULT) + 0.5);
	FT_Face face = caption_fonts_face(fonts, 0);
	long line_h = (face->size->metrics.height + 63) / 64;

	if (line_h <= room_h || size <= CAPTION_SIZE_FLOOR)
		return size;
	size = (int)((long)size * room_h / line_h);
	size = size < CAPTION_SIZE_FLOOR ? CAPTION_SIZE_FLOOR : size;
	caption_fonts_set_size(fonts, size);
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
	struct caption_fonts *fonts = NULL;
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
		ret = caption_fonts_new(c->font, caption_size(c), c->lang, &fonts);
	if (!ret && text) {
		text_room(c, fit, &logo, true, room);
		size = fit_size(c, fonts, room[1]);
		ret = shape_text(fonts, c->lang, text, room[0], room[1], &lay);
		if (ret)
			log_err("[caption] text: cannot shape it: %s", strerror(-ret));
		else
			say_cut(c, fit, size, &lay.cut);
	}
	if (!ret)
		ret = compose(c, fonts, &lay, &logo, out);
	if (cut)
		*cut = lay.cut;
out:
	layout_release(&lay);
	caption_fonts_free(fonts);
	image_release(&logo);
	free(text);
	return ret;
}

int caption_render(const struct caption_config *c, const char *name, struct image *out)
{
	struct caption_fit fit = {0, 0, NULL, false};

	return caption_render_fit(c, name, &fit, out, NULL);
}
