/* Hotspots: points on a model a curator names ([hotspot.NAME] in the
 * model's NAME.ini or in kiosk.ini) with a text and a look. Plain data and
 * pure decisions: a value's words, which hotspot comes next, the yaw and
 * pitch that turn a point to the visitor (the fade at the silhouette and
 * the label's place are the renderer's: render/hotspot_gl.h). The settings reader
 * (config/hotspot_settings.c) fills a set; the tour, the renderer and the
 * tests ask these functions the same questions. */
#ifndef MK_HOTSPOT_H
#define MK_HOTSPOT_H

#include <stdbool.h>
#include <stddef.h>

/* Hotspots a model may have, and the bytes (with the NUL) of a name, a
 * node's name and a text. */
#define HOTSPOTS     8
#define HOTSPOT_NAME 32
#define HOTSPOT_NODE 64
#define HOTSPOT_TEXT 160
#define HOTSPOT_FILE 160
/* Languages a hotspot's text[LANG] may be given in, and a code's bytes:
 * config/lang_text.h's LANG_MAX and LANG_CODE_MAX (checked there). */
#define HOTSPOT_LANGS	  6
#define HOTSPOT_LANG_CODE 16

enum hotspot_look { HOTSPOT_DOT, HOTSPOT_BADGE };

struct hotspot {
	char name[HOTSPOT_NAME]; /* NAME of [hotspot.NAME] */
	/* Where: a point in the model's coordinates, or a node's origin
	 * (node[0] != 0) as the frame's pose places it. */
	bool has_point;
	double point[3];
	char node[HOTSPOT_NODE];
	bool has_normal;  /* else only the depth hides it, nothing fades it */
	double normal[3]; /* unit length */
	enum hotspot_look look;
	float color[4];		 /* straight RGBA, 0..1 */
	char text[HOTSPOT_TEXT]; /* text = : the first language's */
	/* text[LANG] = : the same in other languages, in the order read. */
	struct hotspot_lang {
		char lang[HOTSPOT_LANG_CODE];
		char text[HOTSPOT_TEXT];
		int line;
	} langs[HOTSPOT_LANGS];
	int lang_count;
	int line; /* of its first key (the reader says no section line), for the journal */
	/* The file it was read from (cut to fit), for an error found only
	 * once the model is loaded (a node the model lacks). */
	char file[HOTSPOT_FILE];
};

/* Fixed arrays: a settings struct copied by assignment copies it whole. */
struct hotspot_set {
	int count;
	struct hotspot items[HOTSPOTS];
	/* Left out for an error (said in the journal) in the files read:
	 * the kiosk shows the rest, --check-config calls the settings bad. */
	int dropped;
};

/* A hotspot's text: the one accessor every reader goes through. Its
 * text[lang], else its text[first] (the first of [caption] languages),
 * else its plain text (lang_text_get's order for the caption); "" where
 * it has none. lang, first: NULL or a code, matched without case. */
const char *hotspot_text(const struct hotspot *h, const char *lang, const char *first);
/* Set h's text in lang (a code the caller checked). 0; -EEXIST when
 * lang is set already, -ENOSPC when HOTSPOT_LANGS are, -E2BIG when the
 * text is longer than HOTSPOT_TEXT - 1 bytes. */
int hotspot_set_text(struct hotspot *h, const char *lang, const char *text, int line);

/* A value's words. 0, or -1 with err saying what was expected. */
int hotspot_parse_vec3(const char *value, double out[3], char *err, size_t n);
int hotspot_parse_normal(const char *value, double out[3], char *err, size_t n);
int hotspot_parse_look(const char *value, enum hotspot_look *out, char *err, size_t n);
/* #rrggbb or #rrggbbaa. */
int hotspot_parse_color(const char *value, float out[4], char *err, size_t n);
/* A hotspot as written before any key: a dot, its colour the default. */
void hotspot_init(struct hotspot *h, const char *name, int line);

/* The index of the hotspot called name, or -1. */
int hotspot_find(const struct hotspot_set *s, const char *name);
/* The hotspot after current (-1, or one past the last: none shown yet)
 * of count, wrapping; -1 when there is none. */
int hotspot_next(int count, int current);

/* The app's yaw and pitch (radians; the view turns the model by
 * pitch about x after yaw about y, content_view's order) that bring the
 * direction dir (in the model's frame after its base turn: the normal
 * where given, else from the centre to the point) to face the visitor
 * (+z, towards the camera). A zero direction gives 0, 0. */
void hotspot_facing(const double dir[3], double *yaw, double *pitch);

#endif
