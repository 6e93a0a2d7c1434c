/* What the EGL backends share: the GL loader hook and the EGL side of
 * the context's capabilities. */
#ifndef MK_EGL_UTIL_H
#define MK_EGL_UTIL_H

#include "render/gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdbool.h>

void *egl_proc(void *ctx, const char *name);
/* The EGL side of caps, once the context on dpy is current and gl_load
 * has read the GL side. */
void egl_read_caps(EGLDisplay dpy, struct gl_caps *caps);
const char *egl_error_string(EGLint err);

#endif
