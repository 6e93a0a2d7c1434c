/* What the EGL backends share: extension checks and the GL loader hook. */
#ifndef MK_EGL_UTIL_H
#define MK_EGL_UTIL_H

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdbool.h>

bool egl_has_extension(const char *list, const char *name);
void *egl_proc(void *ctx, const char *name);
const char *egl_error_string(EGLint err);

#endif
