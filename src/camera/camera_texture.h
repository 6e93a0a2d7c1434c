/* The camera frame as a matcap: a small GL pass that converts a frame
 * (RGB or YCbCr, any stride) to RGB, crops it to the circle the ball
 * fills, mirrors it if asked, and draws it into a square RGBA texture
 * that the renderer samples instead of its image matcap. The frame is
 * imported as EGLImages where the driver takes its dmabufs (zero copy),
 * else uploaded from the mapped planes. */
#ifndef MK_CAMERA_TEXTURE_H
#define MK_CAMERA_TEXTURE_H

#include "camera/camera.h"
#include "render/gl.h"
#include "util/image.h"

#include <stdbool.h>

/* Where the ball is: see camera_crop_make(). */
struct camera_view {
	double cx, cy, radius;
	bool mirror;
};

enum camera_path { CAMERA_PATH_NONE, CAMERA_PATH_IMPORT, CAMERA_PATH_UPLOAD };

struct camera_texture;

/* size: the matcap's side in pixels. The GL context must be current, for
 * this and every call below. allow_import false: upload always. */
struct camera_texture *camera_texture_new(const struct gl *gl, const char *shader_dir, int size,
					  bool allow_import);
void camera_texture_free(struct camera_texture *t);
void camera_texture_set_view(struct camera_texture *t, const struct camera_view *v);
/* Draw the frame into the texture. Leaves the framebuffer binding and
 * viewport as it found them. Returns 0, or a negative errno after
 * logging (the texture then keeps the last good frame). */
int camera_texture_update(struct camera_texture *t, const struct camera_frame *f);
/* 0 until a frame was drawn. */
GLuint camera_texture_id(const struct camera_texture *t);
/* How the last frame got to the GPU. */
enum camera_path camera_texture_path(const struct camera_texture *t);
const char *camera_path_name(enum camera_path p);
/* The texture's pixels, rows from its first (t = 0: the ball's top). */
int camera_texture_read(struct camera_texture *t, struct image *out);

#endif
