/* The live camera in the kiosk's loop: the camera (src/camera/camera.h)
 * and its GL pass (src/camera/camera_texture.h). The feed says what
 * happened (the camera came or went, a frame arrived) and is told whether
 * the camera is shown; what that means for the kiosk is the app state's
 * business. The loop polls camera_feed_fd(); everything here returns at
 * once. */
#ifndef MK_CAMERA_FEED_H
#define MK_CAMERA_FEED_H

#include "camera/camera_texture.h"
#include "render/gl.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

enum camera_feed_use { CAMERA_FEED_OFF, CAMERA_FEED_ON };
enum camera_feed_import { CAMERA_FEED_IMPORT_AUTO, CAMERA_FEED_IMPORT_OFF };

/* [camera] in kiosk.ini. */
struct camera_feed_config {
	enum camera_feed_use use;	/* on: the camera is the matcap when there */
	char *id;			/* a libcamera id or an index; NULL: the first */
	int width, height;		/* asked of the camera */
	struct camera_view view;	/* the ball's circle in the frame, mirrored or not */
	double stall_s;			/* no frame for this long: the camera is lost */
	enum camera_feed_import import; /* auto: dmabufs imported where the driver can */
};

/* What one camera_feed_service call found. */
struct camera_feed_report {
	bool available; /* a camera is there and its frames can be drawn */
	bool frame;	/* a new frame arrived */
};

struct camera_feed;

/* NULL when the settings turn the camera off or the backend has no EGL
 * (the camera exists with kms and egl-headless only). shader_dir: NULL
 * for the built-in shaders. The GL context must be current. */
struct camera_feed *camera_feed_new(const struct camera_feed_config *cfg, const struct gl *gl,
				    const char *shader_dir, bool egl);
/* The GL context must be current. */
void camera_feed_free(struct camera_feed *f);
int camera_feed_fd(const struct camera_feed *f);
/* Once per loop after the draw (revents 0), and after the display's
 * dispatch with the descriptor's revents: reads what the camera says and
 * times the frame just put on the screen. f may be NULL (no camera). */
struct camera_feed_report camera_feed_service(struct camera_feed *f, short revents,
					      bool display_waiting, uint64_t now_ns);
/* Stream exactly while the camera is shown (cheap to call every loop). */
void camera_feed_stream(struct camera_feed *f, bool shown);
/* In a frame (context current, target bound): the newest frame into the
 * matcap texture; returns the texture to draw with, or 0 for the image
 * matcap. */
GLuint camera_feed_draw(struct camera_feed *f, bool shown);
/* --stats: frames shown, dropped, completion-to-flip time, CPU per frame. */
void camera_feed_print_stats(const struct camera_feed *f, FILE *out);

#endif
