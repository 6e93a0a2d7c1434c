/* The one EGL display, config and context of the KMS backend, on GBM:
 * every output's surface is made on this config, so one context draws
 * them all. */
#include "display/kms_egl.h"
#include "display/display.h"
#include "display/egl_util.h"
#include "util/log.h"

#include <drm_fourcc.h>
#include <errno.h>

/* An EGL config whose native visual is the GBM format (otherwise the
 * colours come out in the wrong channels, or the surface is refused), and
 * with a depth buffer: without one the depth test passes everywhere and
 * the far side of the model shows through the near side. samples: at
 * least that many samples per pixel ([display] antialias), 0: none. */
static bool find_config(struct kms_egl *k, EGLint depth, EGLint samples)
{
	/* Pairs: attribute, value. */
	const EGLint attribs[] = {EGL_SURFACE_TYPE,
				  EGL_WINDOW_BIT,
				  EGL_RED_SIZE,
				  8,
				  EGL_GREEN_SIZE,
				  8,
				  EGL_BLUE_SIZE,
				  8,
				  EGL_DEPTH_SIZE,
				  depth,
				  EGL_SAMPLE_BUFFERS,
				  samples ? 1 : 0,
				  EGL_SAMPLES,
				  samples,
				  EGL_RENDERABLE_TYPE,
				  EGL_OPENGL_ES2_BIT,
				  EGL_NONE};
	static const uint32_t formats[] = {DRM_FORMAT_XRGB8888, DRM_FORMAT_ARGB8888};
	EGLConfig configs[64];
	EGLint n = 0;

	if (!eglChooseConfig(k->dpy, attribs, configs, 64, &n))
		return false;
	for (int f = 0; f < 2; f++) {
		if (!gbm_device_is_format_supported(k->gbm, formats[f],
						    GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING))
			continue;
		/* Sorted by samples, fewest first: the first that scans out. */
		for (EGLint i = 0; i < n; i++) {
			EGLint id = 0;

			eglGetConfigAttrib(k->dpy, configs[i], EGL_NATIVE_VISUAL_ID, &id);
			if ((uint32_t)id == formats[f]) {
				k->config = configs[i];
				k->format = formats[f];
				return true;
			}
		}
	}
	return false;
}

/* The most samples any window config with a depth buffer offers, for
 * the log when the one asked for is not there. */
static EGLint most_samples(struct kms_egl *k)
{
	const EGLint attribs[] = {EGL_SURFACE_TYPE,    EGL_WINDOW_BIT,	   EGL_DEPTH_SIZE, 16,
				  EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
	EGLConfig configs[256];
	EGLint n = 0, most = 0;

	if (!eglChooseConfig(k->dpy, attribs, configs, 256, &n))
		return 0;
	for (EGLint i = 0; i < n; i++) {
		EGLint s = 0;

		eglGetConfigAttrib(k->dpy, configs[i], EGL_SAMPLES, &s);
		if (s > most)
			most = s;
	}
	return most;
}

static int choose_config(struct kms_egl *k, EGLint samples)
{
	EGLint depth = 0, got = 0;

	if (samples && !find_config(k, 24, samples) && !find_config(k, 16, samples)) {
		log_warn("kms: [display] antialias = %d: no EGL config with %d samples scans out "
			 "(the driver offers %d at most): drawing without",
			 samples, samples, most_samples(k));
		samples = 0;
	}
	/* 24 bits as the offscreen backends have; 16 where that is all. */
	if (!samples && !find_config(k, 24, 0) && !find_config(k, 16, 0)) {
		log_err("kms: no EGL config with a depth buffer scans out as XRGB8888 or "
			"ARGB8888");
		return -ENODEV;
	}
	eglGetConfigAttrib(k->dpy, k->config, EGL_DEPTH_SIZE, &depth);
	eglGetConfigAttrib(k->dpy, k->config, EGL_SAMPLES, &got);
	k->samples = got;
	log_debug("kms: EGL config %.4s with a %d-bit depth buffer, %d samples",
		  (const char *)&k->format, depth, got);
	return 0;
}

static int make_context(struct kms_egl *k)
{
	static const EGLint ctx_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};

	k->ctx = eglCreateContext(k->dpy, k->config, EGL_NO_CONTEXT, ctx_attribs);
	/* Current without a surface until a display is connected, so the
	 * renderer can load the scene while the kiosk waits for a screen. */
	if (k->ctx == EGL_NO_CONTEXT ||
	    !eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, k->ctx)) {
		log_err("kms: cannot create an OpenGL ES 2.0 context: %s",
			egl_error_string(eglGetError()));
		return -ENODEV;
	}
	if (gl_load(k->gl, egl_proc, NULL))
		return -ENOSYS;
	egl_read_caps(k->dpy, &k->gl->caps);
	return 0;
}

/* antialias = auto: whether the GPU is a software rasteriser is known
 * only from a context; on a real one the context is made again on a
 * multisampled config, where there is one (said, as for a number). */
static int antialias_auto(struct kms_egl *k)
{
	EGLConfig plain = k->config;
	uint32_t format = k->format;
	int samples = display_antialias_samples(DISPLAY_AA_AUTO, k->gl->caps.software);

	if (!samples || (!find_config(k, 24, samples) && !find_config(k, 16, samples))) {
		k->config = plain;
		k->format = format;
		log_info("kms: antialias = auto: off (%s)",
			 samples ? "no multisampled config scans out" : "a software rasteriser");
		return 0;
	}
	eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
	eglDestroyContext(k->dpy, k->ctx);
	return choose_config(k, samples) ? -ENODEV : make_context(k);
}

int kms_egl_init(struct kms_egl *k, struct gbm_device *gbm, int antialias, struct gl *gl)
{
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
	    (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	EGLint major, minor;
	int ret;

	k->gbm = gbm;
	k->gl = gl;
	k->antialias = antialias;
	k->ctx = EGL_NO_CONTEXT;

	k->dpy = get_display ? get_display(EGL_PLATFORM_GBM_KHR, k->gbm, NULL) : EGL_NO_DISPLAY;
	if (k->dpy == EGL_NO_DISPLAY || !eglInitialize(k->dpy, &major, &minor) ||
	    !eglBindAPI(EGL_OPENGL_ES_API)) {
		log_err("kms: EGL on GBM is not available: %s", egl_error_string(eglGetError()));
		return -ENODEV;
	}
	/* auto: a plain config first; antialias_auto decides once the
	 * context says what the GPU is. */
	if (choose_config(k, k->antialias == DISPLAY_AA_AUTO
				 ? 0
				 : display_antialias_samples(k->antialias, false)))
		return -ENODEV;
	ret = make_context(k);
	if (!ret && k->antialias == DISPLAY_AA_AUTO)
		ret = antialias_auto(k);
	if (!ret && k->samples)
		log_info("kms: antialias %d samples", k->samples);
	return ret;
}

void kms_egl_release(struct kms_egl *k)
{
	if (k->ctx != EGL_NO_CONTEXT) {
		eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		eglDestroyContext(k->dpy, k->ctx);
	}
	if (k->dpy != EGL_NO_DISPLAY)
		eglTerminate(k->dpy);
	k->ctx = EGL_NO_CONTEXT;
	k->dpy = EGL_NO_DISPLAY;
}
