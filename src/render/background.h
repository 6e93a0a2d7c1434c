/* What is drawn behind the model: a plain colour (the clear alone), a
 * vertical gradient or an image scaled to cover the screen (one quad).
 * The setting is parsed here, once; the image is decoded by whoever holds
 * the scene (once per scene), and uploaded once per background object. */
#ifndef MK_BACKGROUND_H
#define MK_BACKGROUND_H

#include "render/gl.h"
#include "render/wall.h"
#include "util/image.h"

#include <stdbool.h>
#include <stddef.h>

enum background_kind { BACKGROUND_COLOR, BACKGROUND_GRADIENT, BACKGROUND_IMAGE };

struct background_spec {
	enum background_kind kind;
	float top[3];	  /* the colour; a gradient's top */
	float bottom[3];  /* a gradient's bottom; the colour again otherwise */
	const char *path; /* an image: points into the parsed text */
};

/* What [display] background accepts, for the error messages. */
#define BACKGROUND_EXPECTED                                                                        \
	"a colour #rrggbb, a vertical gradient '#top, #bottom', or a PNG, JPEG or WebP file"

/* The kiosk's own: a dark grey gradient, lighter at the top. */
void background_spec_default(struct background_spec *out);
/* Parse text ("#1a2b3c", "#ffffff, #808080", "/path/shop.jpg"); NULL or
 * "" is the default. Returns 0, or -EINVAL with what is wrong in err
 * (without the key: the caller names it). out->path points into text. */
int background_parse(const char *text, struct background_spec *out, char *err, size_t n);
/* Whether text names a PNG or JPEG file (by its extension): a path the
 * settings take from the config file's folder. */
bool background_names_image(const char *text);
/* The colour the screen is cleared to: the colour, or the average of a
 * gradient (what shows where nothing else is drawn). */
void background_clear_color(const struct background_spec *s, float out[3]);

struct background;

/* The GL objects for s: a gradient's program, an image's program and
 * texture (img decoded from s->path; resampled to the GPU's largest
 * texture). A plain colour makes none. NULL on failure, after logging. */
struct background *background_new(const struct gl *gl, const struct background_spec *s,
				  const struct image *img);
void background_free(struct background *b);
/* Clear colour and depth, then the gradient or the image (one quad,
 * depth and culling off, left off), turned with the panel's rotation. */
void background_draw(const struct background *b, int width, int height, int rotation);
/* The same on a screen of a wall: its slice s (render/wall.h) of the
 * gradient or the image that covers the whole wall. */
void background_draw_slice(const struct background *b, const struct wall_slice *s, int rotation);

#endif
