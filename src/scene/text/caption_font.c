/* The caption's fonts (caption_font.h). The caption's own font is read
 * whole through util/file.h (it is the operator's or a stick's path: a
 * FIFO there must not block); a fallback is an installed font that
 * fontconfig found, opened by FreeType from its path. */
#include "scene/text/caption.h"
#include "scene/text/caption_font.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <fontconfig/fontconfig.h>
#include <fribidi.h>
#include <hb-ft.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* No font is this large (Noto Sans CJK is 20 MB); read whole into memory. */
#define CAPTION_FONT_MAX (64 << 20)

struct caption_font {
	FT_Face face;
	hb_font_t *hb;
	FcPattern *from; /* the fallback's entry in sorted; NULL: the own font */
};

struct caption_fonts {
	FT_Library lib;
	struct caption_font font[1 + CAPTION_FONTS_MAX];
	int count;
	int pixels;
	const char *lang;
	FcFontSet *sorted; /* fontconfig's fallbacks, best first; NULL: not asked yet */
	bool asked;
};

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

static int font_add(struct caption_fonts *f, FT_Face face, FcPattern *from)
{
	struct caption_font *n = &f->font[f->count];

	if (FT_Set_Pixel_Sizes(face, 0, (FT_UInt)f->pixels)) {
		FT_Done_Face(face);
		return -EINVAL;
	}
	n->hb = hb_ft_font_create_referenced(face);
	if (!n->hb) {
		FT_Done_Face(face);
		return -ENOMEM;
	}
	n->face = face;
	n->from = from;
	f->count++;
	return 0;
}

static int open_own(struct caption_fonts *f, const char *path)
{
	FT_Face face = NULL;
	FT_Error e = font_face(f->lib, path, &face);

	/* FT_Err_Cannot_Open_Resource: font_face said why. */
	if (e == FT_Err_Unknown_File_Format)
		log_err("[caption] font %s: not a font file FreeType reads; expected TrueType or "
			"OpenType",
			path);
	else if (e && e != FT_Err_Cannot_Open_Resource)
		log_err("[caption] font %s: FreeType error %d", path, e);
	if (e)
		return -EINVAL;
	if (font_add(f, face, NULL)) {
		log_err("[caption] font %s: no size %d pixels in it", path, f->pixels);
		return -EINVAL;
	}
	return 0;
}

int caption_fonts_new(const char *path, int pixels, const char *lang, struct caption_fonts **out)
{
	struct caption_fonts *f = calloc(1, sizeof(*f));
	int ret = -ENOMEM;

	*out = NULL;
	if (!f || FT_Init_FreeType(&f->lib))
		goto fail;
	f->pixels = pixels;
	f->lang = lang;
	ret = open_own(f, path ? path : CAPTION_FONT_DEFAULT);
	if (ret)
		goto fail;
	*out = f;
	return 0;
fail:
	caption_fonts_free(f);
	return ret;
}

void caption_fonts_free(struct caption_fonts *f)
{
	if (!f)
		return;
	for (int i = 0; i < f->count; i++) {
		hb_font_destroy(f->font[i].hb);
		FT_Done_Face(f->font[i].face);
	}
	if (f->sorted)
		FcFontSetDestroy(f->sorted);
	if (f->lib)
		FT_Done_FreeType(f->lib);
	free(f);
}

void caption_fonts_set_size(struct caption_fonts *f, int pixels)
{
	f->pixels = pixels;
	for (int i = 0; i < f->count; i++) {
		FT_Set_Pixel_Sizes(f->font[i].face, 0, (FT_UInt)pixels);
		hb_ft_font_changed(f->font[i].hb);
	}
}

/* The installed fonts, best first for a sans-serif caption in f->lang:
 * asked once per set, when a character first needs it. */
static FcFontSet *fallbacks(struct caption_fonts *f)
{
	FcPattern *pat;
	FcResult res;

	if (f->asked)
		return f->sorted;
	f->asked = true;
	if (!FcInit())
		return NULL;
	pat = FcNameParse((const FcChar8 *)"sans-serif");
	if (!pat)
		return NULL;
	if (f->lang)
		FcPatternAddString(pat, FC_LANG, (const FcChar8 *)f->lang);
	FcConfigSubstitute(NULL, pat, FcMatchPattern);
	FcDefaultSubstitute(pat);
	f->sorted = FcFontSort(NULL, pat, FcFalse, NULL, &res);
	FcPatternDestroy(pat);
	return f->sorted;
}

/* The fallback font of sorted's entry p, opened now if it is not yet:
 * its index, or -1 (unreadable, or a bitmap font this caption cannot
 * scale, such as a colour emoji font). */
static int fallback_open(struct caption_fonts *f, FcPattern *p)
{
	FcChar8 *file;
	FT_Face face;
	int index = 0;

	for (int i = 1; i < f->count; i++)
		if (f->font[i].from == p)
			return i;
	if (f->count == 1 + CAPTION_FONTS_MAX ||
	    FcPatternGetString(p, FC_FILE, 0, &file) != FcResultMatch)
		return -1;
	FcPatternGetInteger(p, FC_INDEX, 0, &index);
	if (FT_New_Face(f->lib, (const char *)file, index, &face))
		return -1;
	if (!FT_IS_SCALABLE(face)) {
		FT_Done_Face(face);
		return -1;
	}
	return font_add(f, face, p) ? -1 : f->count - 1;
}

int caption_fonts_pick(struct caption_fonts *f, uint32_t c)
{
	FcFontSet *set;

	if (FT_Get_Char_Index(f->font[0].face, c))
		return 0;
	for (int i = 1; i < f->count; i++)
		if (FT_Get_Char_Index(f->font[i].face, c))
			return i;
	set = fallbacks(f);
	for (int i = 0; set && i < set->nfont; i++) {
		FcCharSet *cs;
		int at;

		if (FcPatternGetCharSet(set->fonts[i], FC_CHARSET, 0, &cs) != FcResultMatch ||
		    !FcCharSetHasChar(cs, c))
			continue;
		at = fallback_open(f, set->fonts[i]);
		if (at > 0 && FT_Get_Char_Index(f->font[at].face, c))
			return at;
	}
	return -1;
}

hb_font_t *caption_fonts_hb(const struct caption_fonts *f, int i)
{
	return f->font[i].hb;
}

FT_Face caption_fonts_face(const struct caption_fonts *f, int i)
{
	return f->font[i].face;
}

int caption_char_invisible(uint32_t c)
{
	return c < 0x20 || c == 0x200b || c == 0x200c || c == 0x200d || c == 0x2060 ||
	       (c >= 0xfe00 && c <= 0xfe0f) || (c >= 0xe0100 && c <= 0xe01ef) || c == 0xfeff;
}

int caption_missing(const char *font, const char *lang, const char *utf8, uint32_t *out, int cap)
{
	size_t bytes = strlen(utf8);
	uint32_t *u = malloc((bytes + 1) * sizeof(*u));
	struct caption_fonts *f = NULL;
	int n = 0, len, ret = u ? caption_fonts_new(font, CAPTION_SIZE_DEFAULT, lang, &f) : -ENOMEM;

	if (ret)
		goto out;
	len =
	    (int)fribidi_charset_to_unicode(FRIBIDI_CHAR_SET_UTF8, utf8, (FriBidiStrIndex)bytes, u);
	for (int i = 0; i < len; i++) {
		bool seen = false;

		if (caption_char_invisible(u[i]) || caption_fonts_pick(f, u[i]) >= 0)
			continue;
		/* Among those kept only: a text is long, its missing few. */
		for (int k = 0; k < n && k < cap && !seen; k++)
			seen = out[k] == u[i];
		if (!seen && n < cap)
			out[n] = u[i];
		n += !seen;
	}
	ret = n;
out:
	caption_fonts_free(f);
	free(u);
	return ret;
}

const char *caption_font_package(uint32_t c)
{
	static const struct {
		uint32_t lo, hi;
		const char *package;
	} ranges[] = {
	    {0x1100, 0x11ff, "fonts-noto-cjk"},	  /* Hangul Jamo */
	    {0x2e80, 0x2fdf, "fonts-noto-cjk"},	  /* CJK radicals */
	    {0x3000, 0x9fff, "fonts-noto-cjk"},	  /* kana, CJK ideographs */
	    {0xac00, 0xd7af, "fonts-noto-cjk"},	  /* Hangul syllables */
	    {0xf900, 0xfaff, "fonts-noto-cjk"},	  /* CJK compatibility */
	    {0xff00, 0xffef, "fonts-noto-cjk"},	  /* full-width forms */
	    {0x20000, 0x3ffff, "fonts-noto-cjk"}, /* CJK extensions */
	    {0x2190, 0x21ff, "fonts-symbola"},	  /* arrows */
	    {0x2300, 0x23ff, "fonts-symbola"},	  /* technical */
	    {0x2600, 0x27bf, "fonts-symbola"},	  /* symbols, dingbats */
	    {0x2b00, 0x2bff, "fonts-symbola"},	  /* more arrows and stars */
	    {0x1f000, 0x1faff, "fonts-symbola"},  /* emoji */
	};

	for (size_t i = 0; i < sizeof(ranges) / sizeof(ranges[0]); i++)
		if (c >= ranges[i].lo && c <= ranges[i].hi)
			return ranges[i].package;
	return "fonts-noto-core";
}
