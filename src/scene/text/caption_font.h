/* A caption's fonts: the one [caption] font names, then, for the
 * characters it lacks, fallbacks fontconfig finds among the installed
 * fonts (FcFontSort, best first for the caption's language), each opened
 * the first time a character needs it. One set per drawing, on the
 * worker: fontconfig reads its cache files. */
#ifndef MK_CAPTION_FONT_H
#define MK_CAPTION_FONT_H

#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb.h>
#include <stdint.h>

/* The caption's own font and at most this many fallbacks. */
#define CAPTION_FONTS_MAX 8

struct caption_fonts;

/* path: the caption's font (NULL: CAPTION_FONT_DEFAULT) at pixels;
 * lang: the text's language ("ja" picks Japanese glyphs over Chinese in
 * a font with both; NULL: fontconfig's). 0, or a negative errno after
 * the journal said which font and why. */
int caption_fonts_new(const char *path, int pixels, const char *lang, struct caption_fonts **out);
void caption_fonts_free(struct caption_fonts *f);

/* Every font at pixels (the caption's size made smaller to fit). */
void caption_fonts_set_size(struct caption_fonts *f, int pixels);

/* Which font draws c: 0 the caption's own, a fallback's index, or -1
 * when no installed font has it (it is drawn as the own font's box). */
int caption_fonts_pick(struct caption_fonts *f, uint32_t c);

/* Font i (0 <= i < the fonts opened), as HarfBuzz and FreeType see it. */
hb_font_t *caption_fonts_hb(const struct caption_fonts *f, int i);
FT_Face caption_fonts_face(const struct caption_fonts *f, int i);

/* Whether a character needs no glyph of its own (a line break, a joiner,
 * a variation selector): never counted as missing. */
int caption_char_invisible(uint32_t c);

/* The distinct characters of utf8 that neither font (NULL: the
 * default) nor any installed font has, as caption_fonts_pick finds
 * them for lang: at most cap into out; returns how many there are (past
 * cap a character may be counted again), or
 * a negative errno (the font did not open: the journal said why). */
int caption_missing(const char *font, const char *lang, const char *utf8, uint32_t *out, int cap);

/* The Debian package with a font that has c: fonts-noto-cjk for
 * Chinese, Japanese and Korean, fonts-symbola for emoji and symbols (an
 * outline font: fonts-noto-color-emoji's bitmaps are not drawn), else
 * fonts-noto-core (most other scripts). */
const char *caption_font_package(uint32_t c);

#endif
