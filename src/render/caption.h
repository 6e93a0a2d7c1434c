/* The caption on the GL path: its picture (scene/caption.h) uploaded once,
 * then one blended quad at the end of each frame, at the panel's full
 * resolution, pixel for pixel, turned with the panel. */
#ifndef MK_RENDER_CAPTION_H
#define MK_RENDER_CAPTION_H

#include "render/gl.h"
#include "scene/text/caption.h"
#include "util/image.h"

struct caption_gl;

/* Upload img (premultiplied RGBA) and build the quad's program; c's
 * placement (position, padding, drift) is kept. NULL after logging. */
struct caption_gl *caption_gl_new(const struct gl *gl, const struct image *img,
				  const struct caption_config *c);
void caption_gl_free(struct caption_gl *cap);
/* Where its top-left corner is at seconds on a width x height frame
 * turned by rotation (in the turned screen's pixels). */
void caption_gl_at(const struct caption_gl *cap, double seconds, int width, int height,
		   int rotation, int out[2]);
/* Blend it over the frame (depth test off; blending left off). */
void caption_gl_draw(const struct caption_gl *cap, double seconds, int width, int height,
		     int rotation);
/* The same with its top-left corner at at (the turned screen's pixels):
 * a hotspot's label beside its badge. */
void caption_gl_draw_at(const struct caption_gl *cap, const int at[2], int width, int height,
			int rotation);
/* Its size in pixels. */
void caption_gl_size(const struct caption_gl *cap, int size[2]);

#endif
