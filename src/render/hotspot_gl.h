/* Hotspots on the GL path: a disc (or a numbered badge) at each point's
 * projection, drawn right after the model in the same pass, with the
 * depth test against the model's depth: a point behind the model is
 * hidden by the model itself, not guessed from its normal. GLES2 cannot
 * read a depth buffer back, and the overlay plane's buffer has no depth,
 * so the discs are composited into the scene's frame (the caption's text
 * stays on its layer). Where the points are is plain maths, kept here
 * for the tests and a tap's hit test. */
#ifndef MK_HOTSPOT_GL_H
#define MK_HOTSPOT_GL_H

#include "render/gl.h"

#include <stdbool.h>

#define RENDER_HOTSPOTS 8

/* A hotspot as the renderer draws it: in the mesh's unit sphere (the
 * loader's centring and scale applied, content/content_hotspot.c). */
struct render_hotspot {
	float point[3];
	float normal[3];
	bool has_normal; /* else nothing fades it: only the depth hides it */
	bool badge;	 /* a numbered disc; else a dot */
	int number;	 /* shown on a badge: 1, 2, ... */
	float color[4];	 /* straight RGBA */
};

/* Where a hotspot is on a width x height frame: pixels from the top-left
 * corner (the picture's rows as a PNG has them), its depth in the depth
 * buffer's 0..1 pulled towards the eye by HOTSPOT_DEPTH_BIAS, how much
 * of it shows at the silhouette, and whether it is before the eye. */
struct hotspot_place {
	double x, y, depth, fade;
	bool ahead;
};

/* The pull towards the eye, in the unit sphere's units: a point on the
 * surface passes the test against that surface, one a little inside a
 * thin part too; the far side of the model is a diameter away. */
#define HOTSPOT_DEPTH_BIAS 0.03

/* modelview and projection as render_matrices makes them. */
void hotspot_project(const struct render_hotspot *h, const float modelview[16],
		     const float projection[16], bool ortho, int width, int height,
		     struct hotspot_place *out);
/* How much of a badge shows for a unit normal and the unit direction from
 * the point to the eye (both in the camera's frame): 1 facing, fading to
 * 0 as the surface turns edge-on, 0 behind. */
double hotspot_fade(const double normal[3], const double to_eye[3]);
/* A disc's radius in pixels on a frame whose short side is short_side. */
double hotspot_radius(bool badge, int short_side);
/* A label of w x h pixels beside a disc at (x, y) of radius r on a
 * width x height screen, margin pixels kept free at its edges: to the
 * right, else to the left, else below, else above, moved in to stay on
 * screen, never over the disc while one of those fits. out: its
 * top-left corner. */
void hotspot_label_place(double x, double y, double r, int w, int h, int width, int height,
			 int margin, int out[2]);

struct hotspot_gl;

/* The program and the digits' texture; NULL after logging. */
struct hotspot_gl *hotspot_gl_new(const struct gl *gl);
void hotspot_gl_free(struct hotspot_gl *g);
/* Draw count hotspots over the model just drawn (its depth buffer bound;
 * depth writes off, blending left off). */
void hotspot_gl_draw(const struct hotspot_gl *g, const struct render_hotspot *hs, int count,
		     const float modelview[16], const float projection[16], bool ortho,
		     int rotation, int width, int height);

#endif
