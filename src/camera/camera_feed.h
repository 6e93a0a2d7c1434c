/* The live camera in the kiosk's loop: the camera (src/camera/camera.h), its GL
 * pass (src/camera/camera_texture.h), and what the app state is told. The loop
 * polls camera_feed_fd(); everything here returns at once. */
#ifndef MK_CAMERA_FEED_H
#define MK_CAMERA_FEED_H

#include "app/app.h"
#include "render/gl.h"
#include "app/options.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

struct camera_feed;

/* NULL when the settings turn the camera off or the backend has no EGL
 * (the camera exists with kms and egl-headless only). The GL context
 * must be current. */
struct camera_feed *camera_feed_new(const struct options *o, const struct gl *gl, bool egl);
/* The GL context must be current. */
void camera_feed_free(struct camera_feed *f);
int camera_feed_fd(const struct camera_feed *f);
/* Once per loop after the draw (revents 0), and after the display's
 * dispatch with the descriptor's revents: reads what the camera says
 * into the app (available or not, a new frame to draw), times the frame
 * just put on the screen, and streams exactly while the app shows the
 * camera. A camera lost while shown comes back on screen when it is back. */
void camera_feed_service(struct camera_feed *f, struct app *app, short revents,
			 bool display_waiting, uint64_t now_ns);
/* In a frame (context current, target bound): the newest frame into the
 * matcap texture; returns the texture to draw with, or 0 for the image
 * matcap. */
GLuint camera_feed_draw(struct camera_feed *f, const struct app *app);
/* --stats: frames shown, dropped, completion-to-flip time, CPU per frame. */
void camera_feed_print_stats(const struct camera_feed *f, FILE *out);

#endif
