/* What the kiosk (src/camera/camera_link.c) and its camera helper process
 * (src/camera/camera.cc) say to each other over a SOCK_SEQPACKET socket: one
 * message per packet, dmabuf descriptors passed along with SCM_RIGHTS.
 * Both ends are the same binary, so the structs are shared as they are. */
#ifndef MK_CAMERA_PROTO_H
#define MK_CAMERA_PROTO_H

#include "camera/camera_math.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CAMERA_NAME_MAX	   256
#define CAMERA_MAX_BUFFERS 16

enum camera_msg_type {
	/* kiosk -> helper */
	CAMERA_MSG_CONFIG,  /* first, once */
	CAMERA_MSG_WANT,    /* stream or not */
	CAMERA_MSG_RELEASE, /* a frame's buffer goes back to the camera */
	/* helper -> kiosk */
	CAMERA_MSG_PRESENT, /* a camera is there (name) or not (empty name) */
	CAMERA_MSG_SESSION, /* streaming starts: the layout; BUFFERs follow */
	CAMERA_MSG_BUFFER,  /* one buffer's planes, its dmabufs attached */
	CAMERA_MSG_FRAME,   /* a buffer was filled */
};

struct camera_msg {
	uint32_t type;
	union {
		struct {
			char id[CAMERA_NAME_MAX];
			int32_t width, height, log_level;
		} config;
		struct {
			int32_t on;
		} want;
		struct {
			uint32_t generation;
			int32_t buffer;
		} release;
		struct {
			char name[CAMERA_NAME_MAX];
		} present;
		struct {
			uint32_t generation;
			int32_t buffers;
			struct camera_layout layout;
			int32_t encoding, range, colour_space_known;
		} session;
		struct {
			uint32_t generation;
			int32_t buffer;
			/* For each plane: which attached descriptor, and where
			 * in it the plane starts. */
			int32_t fd_index[CAMERA_MAX_PLANES];
			uint32_t offset[CAMERA_MAX_PLANES];
		} buffer;
		struct {
			uint32_t generation;
			int32_t buffer;
			uint32_t sequence;
			uint64_t completed_ns; /* CLOCK_MONOTONIC, as in both processes */
		} frame;
	} u;
};

/* Send one message with up to CAMERA_MAX_PLANES descriptors. Returns 0 or
 * a negative errno (-EAGAIN when the socket is full). */
int camera_msg_send(int sock, const struct camera_msg *m, const int *fds, int nfds);
/* Receive one message; its descriptors (close-on-exec) go to fds and
 * their count to *nfds. Returns 0, -EAGAIN when there is none, -EPIPE at
 * the end (the other side closed), or another negative errno. */
int camera_msg_recv(int sock, struct camera_msg *m, int *fds, int *nfds);

#ifdef __cplusplus
}
#endif

#endif
