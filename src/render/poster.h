/* The poster: a still image shown from the start until the model is ready,
 * so the screen is not black (or a console) while a large model loads.
 * It needs no renderer: its own small program, gone once drawn. */
#ifndef MK_POSTER_H
#define MK_POSTER_H

#include "render/gl.h"
#include "util/image.h"

struct background;

/* Draw the background (render/background.h), then img (NULL: none) fitted inside
 * width x height, turned by rotation degrees (the panel's). Returns 0,
 * or a negative errno after logging (the background is drawn anyway). */
int poster_draw(const struct gl *gl, const struct image *img, int width, int height, int rotation,
		const struct background *bg);

#endif
