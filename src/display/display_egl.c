/* Headless OpenGL ES 2.0 on EGL with no window system: the device platform
 * (a real GPU, such as NVIDIA's driver offers) or Mesa's surfaceless
 * platform, drawing into a framebuffer object. */
#include "display/display.h"
#include "display/egl_util.h"
#include "util/log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* OpenGL ES 3.0's multisampling, loaded where the context has it (the
 * table of render/gl.h is ES 2.0's). */
#define GL_READ_FRAMEBUFFER 0x8CA8
#define GL_DRAW_FRAMEBUFFER 0x8CA9
#define GL_MAX_SAMPLES	    0x8D57
#define GL_RGBA8	    0x8058
#define GL_DEPTH24	    0x81A6 /* DEPTH_COMPONENT24(_OES) */
typedef void (*storage_multisample_fn)(GLenum, GLsizei, GLenum, GLsizei, GLsizei);
typedef void (*blit_fn)(GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield, GLenum);
typedef void (*texture_multisample_fn)(GLenum, GLenum, GLenum, GLuint, GLint, GLsizei);

struct display_egl {
	struct display base;
	EGLDisplay dpy;
	EGLContext ctx;
	GLuint fbo, color, depth;
	/* Multisampled: drawn into msaa_fbo and resolved into fbo at
	 * present (ES 3.0), or resolved by the GPU as the texture is written
	 * (EXT_multisampled_render_to_texture: fbo alone, no copy). */
	GLuint msaa_fbo, msaa_color, msaa_depth;
	blit_fn blit;
};

/* A hardware device if there is one, since glvnd would otherwise hand the
 * surfaceless platform to Mesa's software driver on a machine with a GPU. */
static EGLDisplay egl_open_device(bool want_hardware)
{
	PFNEGLQUERYDEVICESEXTPROC query_devices =
	    (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
	PFNEGLQUERYDEVICESTRINGEXTPROC device_string =
	    (PFNEGLQUERYDEVICESTRINGEXTPROC)eglGetProcAddress("eglQueryDeviceStringEXT");
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
	    (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	EGLDeviceEXT devs[8];
	EGLint n = 0;

	if (!query_devices || !device_string || !get_display || !query_devices(8, devs, &n))
		return EGL_NO_DISPLAY;
	for (EGLint i = 0; i < n; i++) {
		const char *ext = device_string(devs[i], EGL_EXTENSIONS);
		bool software = gl_extension_listed(ext, "EGL_MESA_device_software");

		if (software != want_hardware)
			return get_display(EGL_PLATFORM_DEVICE_EXT, devs[i], NULL);
	}
	return EGL_NO_DISPLAY;
}

static EGLDisplay egl_open_headless(void)
{
	const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
	    (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	EGLDisplay dpy = EGL_NO_DISPLAY;

	if (gl_extension_listed(client, "EGL_EXT_platform_device"))
		dpy = egl_open_device(true);
	if (dpy == EGL_NO_DISPLAY && get_display &&
	    gl_extension_listed(client, "EGL_MESA_platform_surfaceless"))
		dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
	if (dpy == EGL_NO_DISPLAY && gl_extension_listed(client, "EGL_EXT_platform_device"))
		dpy = egl_open_device(false);
	return dpy;
}

static int egl_make_context(struct display_egl *e)
{
	static const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
						EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
	static const EGLint ctx_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
	EGLConfig config = NULL;
	EGLint major, minor, n = 0;

	if (!eglInitialize(e->dpy, &major, &minor)) {
		log_err("egl-headless: eglInitialize failed: %s", egl_error_string(eglGetError()));
		return -ENODEV;
	}
	if (!eglBindAPI(EGL_OPENGL_ES_API))
		return -ENOSYS;
	/* Surfaceless contexts need no config where KHR_no_config_context is
	 * offered; otherwise take any ES2-capable one, we draw into an FBO. */
	if (!gl_extension_listed(eglQueryString(e->dpy, EGL_EXTENSIONS),
				 "EGL_KHR_no_config_context") &&
	    (!eglChooseConfig(e->dpy, config_attribs, &config, 1, &n) || n < 1)) {
		log_err("egl-headless: no OpenGL ES 2.0 config");
		return -ENODEV;
	}
	e->ctx = eglCreateContext(e->dpy, config, EGL_NO_CONTEXT, ctx_attribs);
	if (e->ctx == EGL_NO_CONTEXT ||
	    !eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx)) {
		log_err("egl-headless: cannot create an OpenGL ES 2.0 context: %s",
			egl_error_string(eglGetError()));
		return -ENODEV;
	}
	return 0;
}

/* The context's OpenGL ES major version, from "OpenGL ES 3.2 Mesa ...". */
static int es_major(const struct gl *gl)
{
	const char *v = (const char *)gl->GetString(GL_VERSION);
	int major = 2;

	if (v && sscanf(v, "OpenGL ES %d", &major) != 1)
		major = 2;
	return major;
}

static int samples_allowed(const struct gl *gl, int samples)
{
	GLint max = 0;

	gl->GetIntegerv(GL_MAX_SAMPLES, &max);
	if (gl->GetError() != GL_NO_ERROR || max < 1)
		return 0;
	return samples < max ? samples : max;
}

/* The multisampled colour and depth that ES 3.0 resolves into fbo. */
static int make_msaa_es3(struct display_egl *e, int samples)
{
	struct gl *gl = &e->base.gl;
	storage_multisample_fn storage =
	    (storage_multisample_fn)eglGetProcAddress("glRenderbufferStorageMultisample");
	GLsizei w = e->base.width, h = e->base.height;

	e->blit = (blit_fn)eglGetProcAddress("glBlitFramebuffer");
	if (!storage || !e->blit)
		return -ENOSYS;
	gl->GenRenderbuffers(1, &e->msaa_color);
	gl->BindRenderbuffer(GL_RENDERBUFFER, e->msaa_color);
	storage(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
	gl->GenRenderbuffers(1, &e->msaa_depth);
	gl->BindRenderbuffer(GL_RENDERBUFFER, e->msaa_depth);
	storage(GL_RENDERBUFFER, samples, GL_DEPTH24, w, h);
	gl->GenFramebuffers(1, &e->msaa_fbo);
	gl->BindFramebuffer(GL_FRAMEBUFFER, e->msaa_fbo);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
				    e->msaa_color);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
				    e->msaa_depth);
	return gl->CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE ? 0 : -EIO;
}

/* The frame's own texture and depth, multisampled where the GPU resolves
 * them as it writes them out (tilers: Mali, Adreno, PowerVR). */
static int make_msaa_ext(struct display_egl *e, int samples)
{
	struct gl *gl = &e->base.gl;
	storage_multisample_fn storage =
	    (storage_multisample_fn)eglGetProcAddress("glRenderbufferStorageMultisampleEXT");
	texture_multisample_fn texture =
	    (texture_multisample_fn)eglGetProcAddress("glFramebufferTexture2DMultisampleEXT");

	if (!storage || !texture)
		return -ENOSYS;
	gl->BindFramebuffer(GL_FRAMEBUFFER, e->fbo);
	texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, e->color, 0, samples);
	gl->BindRenderbuffer(GL_RENDERBUFFER, e->depth);
	storage(GL_RENDERBUFFER, samples, gl->caps.depth24 ? GL_DEPTH24 : GL_DEPTH_COMPONENT16,
		e->base.width, e->base.height);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, e->depth);
	return gl->CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE ? 0 : -EIO;
}

static void drop_msaa(struct display_egl *e)
{
	struct gl *gl = &e->base.gl;

	if (e->msaa_fbo)
		gl->DeleteFramebuffers(1, &e->msaa_fbo);
	if (e->msaa_color)
		gl->DeleteRenderbuffers(1, &e->msaa_color);
	if (e->msaa_depth)
		gl->DeleteRenderbuffers(1, &e->msaa_depth);
	e->msaa_fbo = e->msaa_color = e->msaa_depth = 0;
	e->blit = NULL;
}

/* [display] antialias: the first way the context offers, else none
 * (said once). */
static void egl_make_msaa(struct display_egl *e, int antialias)
{
	struct gl *gl = &e->base.gl;
	const char *ext = (const char *)gl->GetString(GL_EXTENSIONS);
	int want = display_antialias_samples(antialias, gl->caps.software);
	int samples = want ? samples_allowed(gl, want) : 0;
	const char *how = NULL;

	if (!want)
		return;
	if (samples && gl_extension_listed(ext, "GL_EXT_multisampled_render_to_texture") &&
	    make_msaa_ext(e, samples) == 0)
		how = "resolved as it is written (EXT_multisampled_render_to_texture)";
	else if (samples && es_major(gl) >= 3 && make_msaa_es3(e, samples) == 0)
		how = "resolved by a blit (OpenGL ES 3.0)";
	if (how) {
		GLint got = 0;

		/* What the driver made: llvmpipe makes 4 for 2. */
		gl->BindFramebuffer(GL_FRAMEBUFFER, e->msaa_fbo ? e->msaa_fbo : e->fbo);
		gl->GetIntegerv(GL_SAMPLES, &got);
		e->base.samples = samples = got > 0 ? got : samples;
		log_info("egl-headless: antialias %d samples (%d asked), %s", samples, want, how);
		return;
	}
	drop_msaa(e);
	log_warn("egl-headless: no multisampling in this context (OpenGL ES %d, %d samples at "
		 "most): drawing without",
		 es_major(gl), samples);
}

static int egl_make_fbo(struct display_egl *e)
{
	struct gl *gl = &e->base.gl;
	/* 16-bit depth is all core ES2 promises; take 24 where offered so the
	 * result matches the software reference more closely. */
	GLenum depth_format = gl->caps.depth24 ? GL_DEPTH24 : GL_DEPTH_COMPONENT16;

	gl->GenTextures(1, &e->color);
	gl->BindTexture(GL_TEXTURE_2D, e->color);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, e->base.width, e->base.height, 0, GL_RGBA,
		       GL_UNSIGNED_BYTE, NULL);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	gl->GenRenderbuffers(1, &e->depth);
	gl->BindRenderbuffer(GL_RENDERBUFFER, e->depth);
	gl->RenderbufferStorage(GL_RENDERBUFFER, depth_format, e->base.width, e->base.height);
	gl->GenFramebuffers(1, &e->fbo);
	gl->BindFramebuffer(GL_FRAMEBUFFER, e->fbo);
	gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, e->color, 0);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, e->depth);
	if (gl->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
		log_err("egl-headless: framebuffer %dx%d incomplete", e->base.width,
			e->base.height);
		return -EIO;
	}
	return 0;
}

static int egl_begin_frame(struct display *d)
{
	struct display_egl *e = (struct display_egl *)d;

	/* Another context may be current in this thread (the bench draws on
	 * several displays in turn); making one current that is costs nothing. */
	if (eglGetCurrentContext() != e->ctx &&
	    !eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx))
		return -EIO;
	d->gl.BindFramebuffer(GL_FRAMEBUFFER, e->msaa_fbo ? e->msaa_fbo : e->fbo);
	d->gl.Viewport(0, 0, d->width, d->height);
	return 0;
}

static int egl_present(struct display *d)
{
	struct display_egl *e = (struct display_egl *)d;

	/* The samples resolved into the frame read_frame reads. */
	if (e->msaa_fbo) {
		d->gl.BindFramebuffer(GL_READ_FRAMEBUFFER, e->msaa_fbo);
		d->gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, e->fbo);
		e->blit(0, 0, d->width, d->height, 0, 0, d->width, d->height, GL_COLOR_BUFFER_BIT,
			GL_NEAREST);
		d->gl.BindFramebuffer(GL_FRAMEBUFFER, e->fbo);
	}
	d->gl.Finish();
	return 0;
}

static void egl_destroy(struct display *d)
{
	struct display_egl *e = (struct display_egl *)d;

	if (e->ctx != EGL_NO_CONTEXT) {
		drop_msaa(e);
		if (e->fbo) {
			d->gl.DeleteFramebuffers(1, &e->fbo);
			d->gl.DeleteRenderbuffers(1, &e->depth);
			d->gl.DeleteTextures(1, &e->color);
		}
		eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		eglDestroyContext(e->dpy, e->ctx);
	}
	if (e->dpy != EGL_NO_DISPLAY)
		eglTerminate(e->dpy);
	free(e);
}

struct display *display_egl_new(const struct display_config *cfg)
{
	struct display_egl *e = calloc(1, sizeof(*e));

	if (!e)
		return NULL;
	e->base.name = "egl-headless";
	e->base.width = cfg->width > 0 ? cfg->width : 1280;
	e->base.height = cfg->height > 0 ? cfg->height : 720;
	e->base.begin_frame = egl_begin_frame;
	e->base.present = egl_present;
	e->base.read_frame = display_read_rgba;
	e->base.get_fd = display_no_fd;
	e->base.dispatch = display_no_dispatch;
	e->base.destroy = egl_destroy;
	e->ctx = EGL_NO_CONTEXT;
	e->dpy = egl_open_headless();
	if (e->dpy == EGL_NO_DISPLAY) {
		log_err("egl-headless: no EGL device or surfaceless platform (install "
			"libegl-mesa0)");
		goto fail;
	}
	if (egl_make_context(e) || gl_load(&e->base.gl, egl_proc, NULL))
		goto fail;
	egl_read_caps(e->dpy, &e->base.gl.caps);
	if (egl_make_fbo(e))
		goto fail;
	egl_make_msaa(e, cfg->antialias);
	log_info("egl-headless: %s, %s, %dx%d", (const char *)e->base.gl.GetString(GL_RENDERER),
		 (const char *)e->base.gl.GetString(GL_VERSION), e->base.width, e->base.height);
	return &e->base;
fail:
	egl_destroy(&e->base);
	return NULL;
}
