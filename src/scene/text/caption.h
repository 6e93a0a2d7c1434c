/* [caption]: a few lines of text and a logo over the model, drawn once
 * into a picture on the CPU (any thread) when the text changes, then
 * shown as one quad or on an overlay plane. Text is shaped by HarfBuzz
 * (kerning, ligatures, Arabic joining), put in visual order by FriBidi
 * (right-to-left runs) and drawn by FreeType. */
#ifndef MK_CAPTION_H
#define MK_CAPTION_H

#include "util/image.h"

#include <stdbool.h>
#include <stddef.h>

/* fonts-dejavu-core (a Depends of the package): Latin, Greek, Cyrillic,
 * Hebrew and Arabic. */
#define CAPTION_FONT_DEFAULT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

enum caption_position {
	CAPTION_BOTTOM_LEFT,
	CAPTION_BOTTOM_RIGHT,
	CAPTION_TOP_LEFT,
	CAPTION_TOP_RIGHT,
	CAPTION_BOTTOM,
	CAPTION_TOP,
};

/* What [caption] accepts, for the error messages. */
#define CAPTION_COLOR_EXPECTED "a colour #rrggbb or #rrggbbaa (aa: opacity)"

struct caption_config {
	char *text;  /* "\n" starts a line; "auto": the model's name; NULL: none */
	char *font;  /* a TrueType/OpenType file; NULL: CAPTION_FONT_DEFAULT */
	char *color; /* the text's; NULL: white */
	char *box;   /* the box behind it; NULL: black at 60%; "none": no box */
	char *logo;  /* a PNG/JPEG drawn left of the text at its own size; NULL: none */
	double size; /* the text's size in pixels (em); 0: the default */
	int padding; /* pixels inside the box, and from the screen's edge */
	enum caption_position position;
	bool drift; /* move a few pixels over hours against burn-in */
	/* Not a setting: the language of text (a BCP 47 code such as "ja",
	 * from [caption] languages), for its line breaks and its fallback
	 * font's glyphs; NULL: none said. */
	const char *lang;
	char *languages; /* [caption] languages: "en de fr", the first shown first */
};

/* The most pictures of [frame] stops' texts a model has, each drawn as
 * the caption is (state/view.h's FRAME_STOPS at most). */
#define CAPTION_STOPS 8

/* The default size, in pixels of the panel. */
#define CAPTION_SIZE_DEFAULT 28

/* The size c asks for, in whole pixels. */
int caption_size(const struct caption_config *c);

/* Whether c shows anything (a text or a logo). */
bool caption_wanted(const struct caption_config *c);

/* Parse "#rrggbb" or "#rrggbbaa" into straight RGBA bytes; false when
 * text is neither. */
bool caption_parse_color(const char *text, unsigned char out[4]);

/* The text c shows: c->text with "\n" made line breaks, or name for
 * "auto" (NULL name: nothing). Malloc'd; NULL when there is none. */
char *caption_text(const struct caption_config *c, const char *name);

/* Draw c (its text, or name for "auto") into out: premultiplied RGBA, the
 * box's size, rows top first. The font and the logo are read here.
 * Returns 0, -ENOENT when c shows nothing (out empty), or a negative
 * errno after logging what failed (the file and why). */
int caption_render(const struct caption_config *c, const char *name, struct image *out);

/* Where a caption must fit, and who says so when it does not. */
/* The frame a caption is laid out in before the display's is known: a
 * large panel's. Wrapped within IMAGE_MAX_SIDE instead, a long text made
 * a picture of 8192x8192 (256 MiB) before it was fitted. */
#define CAPTION_FRAME_GUESS_W 1920
#define CAPTION_FRAME_GUESS_H 1080

struct caption_fit {
	int width, height; /* the frame (turned for the panel); 0: CAPTION_FRAME_GUESS_* */
	const char *what;  /* the journal's name for the text, e.g. "[caption] text" */
	bool quiet;	   /* a draw for a frame not known yet: nothing said */
};

/* What the layout kept of a text (caption_layout_fit). */
struct caption_cut {
	int lines, shown; /* lines in the text, lines kept */
	int cut;	  /* kept lines cut at the side with an ellipsis */
};

/* How many of `lines` lines line_h pixels high fit in max_h pixels:
 * at least one. */
int caption_lines_fit(int lines, long line_h, long max_h);

/* caption_render, laid out within fit's frame (less the padding outside
 * the box and inside it, and the logo): lines past the frame's height are
 * left out and the last one kept ends with an ellipsis; a line wider than
 * the frame is cut with one (at the size asked: the size is not reduced,
 * so a caption reads as the operator set it). One warning names fit->what
 * and what was cut. *cut (may be NULL) says it. */
int caption_render_fit(const struct caption_config *c, const char *name,
		       const struct caption_fit *fit, struct image *out, struct caption_cut *cut);

/* Blend the caption's picture over frame (straight RGBA, opaque) with its
 * top-left corner at x, y, clipped: the frame --status reads back when an
 * overlay plane shows the caption, as the screen shows it. */
void caption_blend(const struct image *cap, int x, int y, struct image *frame);

/* Where the caption's top-left corner goes on a width x height screen
 * (already turned for the panel), its drift at seconds added: within
 * +-CAPTION_DRIFT_PX, each axis on its own period of hours, whole pixels. */
#define CAPTION_DRIFT_PX 6
void caption_place(const struct caption_config *c, int cw, int ch, int width, int height,
		   double seconds, int out[2]);

#endif
