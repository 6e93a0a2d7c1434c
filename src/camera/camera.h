/* A live camera through libcamera.
 *
 * libcamera 0.0.3 runs in a helper process (src/camera/camera.cc: this same
 * binary, started again under the name CAMERA_HELPER_NAME), because in
 * the paths where a camera goes away it aborts the process it runs in:
 * stopping a camera whose device vanished fails an assertion, and a
 * device that comes back to the same CameraManager is a fatal duplicate.
 * The kiosk side (src/camera/camera_link.c) must outlive that: when the helper
 * dies, stalls or loses its camera, the kiosk shows its image matcaps
 * and starts a fresh helper after a while.
 *
 * The helper sends each completed frame as a small message naming the
 * buffer; the buffers themselves are dmabufs it passed once, which the
 * kiosk maps (or imports as EGLImages). The main loop polls camera_fd()
 * and keeps only the newest frame: one that completes before the last
 * was taken replaces it, and the one replaced goes back to the camera at
 * once. Nothing here blocks. */
#ifndef MK_CAMERA_H
#define MK_CAMERA_H

#include "camera/camera_math.h"

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* argv[0] of the helper process; main() hands it to camera_helper_main. */
#define CAMERA_HELPER_NAME "matcap-kiosk-camera"
/* The helper's end of the socket. */
#define CAMERA_HELPER_FD 3

struct camera_config {
	/* A libcamera camera id, or a whole number: the index in the list
	 * libcamera gives (0 the first). NULL or "": the first. */
	const char *id;
	int width, height; /* asked for; the camera may adjust them */
	double stall_s;	   /* no frame for this long: the camera is lost */
	int log_level;	   /* enum log_level, for the helper */
};

struct camera_frame_plane {
	int fd;		     /* dmabuf, for importing it as an EGLImage */
	unsigned offset;     /* of the plane in the dmabuf */
	const uint8_t *data; /* the plane, mapped for reading; NULL if not */
};

struct camera_frame {
	struct camera_layout layout; /* size, format, strides */
	struct camera_frame_plane plane[CAMERA_MAX_PLANES];
	enum camera_encoding encoding; /* YCbCr formats only */
	enum camera_range range;
	bool colour_space_known; /* false: encoding and range are assumed */
	unsigned generation;	 /* changes each time the camera is opened */
	int buffer;		 /* which of the camera's buffers, 0..n-1 */
	unsigned sequence;
	uint64_t completed_ns; /* CLOCK_MONOTONIC when the request completed */
};

struct camera_state {
	bool present;	  /* a camera to open is there (and has not stalled) */
	bool streaming;	  /* it is open and its buffers are here */
	bool frame;	  /* a frame newer than the last taken is waiting */
	const char *name; /* the camera's id, or NULL */
};

/* Starts the helper. NULL only when the process is out of memory or
 * descriptors; a machine with no camera gets an object that reports no
 * camera (and picks one up when it appears). */
struct camera *camera_new(const struct camera_config *cfg);
/* Ends the helper; frames taken are invalid after it. */
void camera_free(struct camera *c);
/* Readable when camera_dispatch has something to do. */
int camera_fd(const struct camera *c);
/* Reads what the helper said and acts on the timers (a stall, starting a
 * new helper); says where the camera stands. */
void camera_dispatch(struct camera *c, struct camera_state *out);
/* Stream while on; close the camera when off. Cheap to call every loop. */
void camera_set_streaming(struct camera *c, bool on);
/* The newest frame, or NULL when none is newer than the last taken. The
 * frame taken before goes back to the camera now: its pixels were read
 * when it was drawn, and the display has flipped since. The frame stays
 * valid until the next camera_take, camera_dispatch or camera_free. */
const struct camera_frame *camera_take(struct camera *c);
/* Bracket CPU reads of a frame's mapped planes (dmabuf cache coherency). */
void camera_frame_cpu_access(const struct camera_frame *f, bool begin);

/* The helper process: serves the socket at fd until the kiosk closes it.
 * Returns the exit status. */
int camera_helper_main(int fd);

#ifdef __cplusplus
}
#endif

#endif
