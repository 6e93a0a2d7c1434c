/* EGL on GBM for the KMS backend: one display, one config whose native
 * visual the scanout takes, one GLES2 context for every output. */
#ifndef MK_KMS_EGL_H
#define MK_KMS_EGL_H

#include "render/gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <gbm.h>
#include <stdint.h>

struct kms_egl {
	struct gbm_device *gbm;
	struct gl *gl; /* the display's table, loaded once the context is current */
	int antialias; /* enum display_antialias */
	EGLDisplay dpy;
	EGLConfig config;
	EGLContext ctx;
	uint32_t format; /* the config's native visual: DRM_FORMAT_XRGB8888 or ARGB8888 */
	int samples;	 /* per pixel of the config; 0: not multisampled */
};

/* The display, a config (antialias: [display] antialias; auto decides
 * once the context says whether the GPU is a software rasteriser) and a
 * context current without a surface, gl loaded. 0 or -ENODEV / -ENOSYS
 * after saying why. k->dpy is EGL_NO_DISPLAY until it is made. */
int kms_egl_init(struct kms_egl *k, struct gbm_device *gbm, int antialias, struct gl *gl);
void kms_egl_release(struct kms_egl *k);

#endif
