/* One output of the KMS backend: a connector, its mode and CRTC (struct
 * drm), a GBM surface on the backend's one EGL config, and the buffers
 * in flight. Each output flips on its own CRTC's vblank; the backend
 * (display_kms.c) holds one or several ([display] outputs) and the
 * device-wide things: the fd, DRM master, hotplug, the context. */
#ifndef MK_KMS_OUTPUT_H
#define MK_KMS_OUTPUT_H

#include "display/display.h"
#include "display/drm.h"
#include "display/kms_egl.h"

#include <gbm.h>
#include <stdbool.h>

struct kms_output {
	struct drm drm;
	char *want; /* the connector asked for; NULL: the first connected one */
	bool gone;  /* its connector does not exist: said once, never tried again */
	struct gbm_surface *surface;
	EGLSurface egl_surface;
	struct gbm_bo *shown, *pending; /* on screen, and flipped to it (waiting) */
	bool connected, modeset;
	bool touched; /* we set a mode: the CRTC's old state goes back on exit */
	bool plane_scaled;
	long flips;
	double first_flip_s, last_flip_s;
};

/* Select the connector (skipping CRTCs in taken, a mask of CRTC indices
 * other outputs drive), set up the modesetting ops and a surface of its
 * mode (or of the plane's scaled source, kms_scale.h). 0, -ENOENT (not
 * connected: wait for a cable), -EINVAL (no such connector, said), or
 * another negative errno. d: for kms_scale_plane's GPU question. */
int kms_output_connect(struct kms_output *o, const struct kms_egl *e, enum drm_api api,
		       const char *mode, uint32_t taken, const struct display *d);
/* Drop the modesetting ops (atomic's property ids): before they are set
 * up again, when mode setting moves to another fd, and at exit. */
void kms_output_ops_reset(struct kms_output *o);
/* Stop using it: the flip in flight finished, buffers and surface freed.
 * turn_off: the display went away, so the CRTC stops scanning out (only
 * where we set its mode and are master). The context stays current with
 * no surface. */
void kms_output_disconnect(struct kms_output *o, const struct kms_egl *e, bool turn_off,
			   bool master);
/* The drawn frame onto the screen: swap, lock, flip at the next vblank
 * (with a modeset the first time or after a wake). 0, -EACCES (another
 * program took the display), or another negative errno. */
int kms_output_present(struct kms_output *o, const struct kms_egl *e, int gpu_fd);
/* The flip events waiting on fd, every output's (each event names its
 * output): a finished flip frees the buffer shown before it. */
void kms_output_events(int fd);
/* Let o's flip in flight finish, so that the buffer it shows is not freed
 * under the scanout (a vblank is 16 ms; a hung driver gets timeout_ms). */
void kms_output_drain(struct kms_output *o, int timeout_ms);
/* The buffer on screen, read back rows top first. */
int kms_output_read(const struct kms_output *o, struct image *out);
/* For the journal: how many frames reached the screen (named: one of
 * several outputs). */
void kms_output_log_flips(const struct kms_output *o, bool named);

#endif
