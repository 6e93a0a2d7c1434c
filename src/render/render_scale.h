/* [display] render_scale: the scene drawn into fewer pixels than the
 * panel has, and scaled up on the way out. Where the KMS primary plane
 * scales (display/kms_scale.c) the display's buffer is already the small
 * one and this pass does nothing; elsewhere it is one GL pass: the scene
 * into a framebuffer object of the scaled size, then a full-screen quad
 * that samples it with linear filtering into the display's framebuffer
 * (GLES2 has no glBlitFramebuffer; a quad is one draw on any GPU).
 *
 * The frame's order: the display's begin_frame, render_scale_begin, the
 * scene (renderer_draw at the size begin gave), render_scale_end, then
 * the full-resolution overlays (the caption, the logo: drawn at the
 * display's width x height, never scaled), then the display's present.
 * Where the KMS plane scales (struct display's plane_scaled), the
 * display's buffer itself is the small one: an overlay drawn by GL there
 * is scaled with the frame, so it belongs on an overlay plane of its own;
 * one that cannot have one needs the GL pass (no plane scaling). */
#ifndef MK_RENDER_SCALE_H
#define MK_RENDER_SCALE_H

#include "render/gl.h"

#include <stdbool.h>

#define RENDER_SCALE_MIN 0.5

/* The scale for a width x height panel: want itself (0.5 to 1), or for
 * auto (0) 1 up to a budget of pixels, 1920x1080 on a software rasteriser
 * and 2560x1440 on a GPU, and on a larger panel the largest step of 0.05
 * that draws no more than the budget, at least RENDER_SCALE_MIN (0.5 for
 * 4K in software, 0.65 on a GPU). plane: the display's plane would scale
 * (free); without it the GL pass shades every panel pixel once more,
 * which on a software rasteriser costs more than it saves, so auto stays at 1
 * there. The figures: tests/bench/report/speed-error.md. */
double render_scale_pick(double want, int width, int height, bool software, bool plane);
/* The scaled buffer's size: rounded to whole pixels, at least 1x1. */
void render_scale_size(double scale, int width, int height, int *w, int *h);

struct render_scale;

/* want: [display] render_scale (0: auto). samples: the display's
 * multisampling (struct display's samples): the scaled buffer is not
 * multisampled, said once where that is more than 0. Makes no GL object
 * until a frame needs one. */
struct render_scale *render_scale_new(const struct gl *gl, double want, int samples,
				      const char *shader_dir);
/* With the context current. */
void render_scale_free(struct render_scale *s);

/* After the display's begin_frame, with its framebuffer bound: where the
 * scale for width x height is under 1 and the plane does not scale
 * (plane: struct display's plane_scaled), binds the scaled framebuffer
 * (made on the first frame and again when the size changes) and its
 * viewport. *w, *h: the size to draw the scene at (width x height at 1,
 * or when the framebuffer cannot be made: said once, drawn full size). */
void render_scale_begin(struct render_scale *s, bool plane, int width, int height, int *w, int *h);
/* The scaled scene up into the display's framebuffer, its viewport full
 * size again; nothing where begin drew full size. Full-resolution
 * overlays draw after this. */
void render_scale_end(struct render_scale *s);

#endif
