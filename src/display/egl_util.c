#include "display/egl_util.h"

#include <string.h>

void *egl_proc(void *ctx, const char *name)
{
	void (*p)(void) = eglGetProcAddress(name);
	void *v;

	(void)ctx;
	memcpy(&v, &p, sizeof(v));
	return v;
}

void egl_read_caps(EGLDisplay dpy, struct gl_caps *caps)
{
	caps->egl_display = dpy;
	caps->dmabuf_import = gl_extension_listed(eglQueryString(dpy, EGL_EXTENSIONS),
						  "EGL_EXT_image_dma_buf_import");
}

const char *egl_error_string(EGLint err)
{
	switch (err) {
	case EGL_SUCCESS:
		return "EGL_SUCCESS";
	case EGL_NOT_INITIALIZED:
		return "EGL_NOT_INITIALIZED";
	case EGL_BAD_ACCESS:
		return "EGL_BAD_ACCESS";
	case EGL_BAD_ALLOC:
		return "EGL_BAD_ALLOC";
	case EGL_BAD_ATTRIBUTE:
		return "EGL_BAD_ATTRIBUTE";
	case EGL_BAD_CONFIG:
		return "EGL_BAD_CONFIG";
	case EGL_BAD_CONTEXT:
		return "EGL_BAD_CONTEXT";
	case EGL_BAD_DISPLAY:
		return "EGL_BAD_DISPLAY";
	case EGL_BAD_MATCH:
		return "EGL_BAD_MATCH";
	case EGL_BAD_NATIVE_WINDOW:
		return "EGL_BAD_NATIVE_WINDOW";
	case EGL_BAD_PARAMETER:
		return "EGL_BAD_PARAMETER";
	case EGL_BAD_SURFACE:
		return "EGL_BAD_SURFACE";
	default:
		return "unknown EGL error";
	}
}
