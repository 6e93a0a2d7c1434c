/* Offscreen rendering in software through Mesa's OSMesa: the reference for
 * golden images and CI. The library is opened with dlopen and kept local
 * so its gl* symbols never shadow another driver's, and so the kiosk runs
 * on a board where libOSMesa is not installed. Mesa 25.1 and later have no
 * OSMesa: the Makefile then builds without MK_HAVE_OSMESA, and the backend
 * is only a message pointing at egl-headless (the same renders through EGL
 * surfaceless on llvmpipe). */
#include "display/display.h"
#include "util/log.h"

#ifndef MK_HAVE_OSMESA

struct display *display_osmesa_new(const struct display_config *cfg)
{
	(void)cfg;
	log_err("osmesa: this build has no OSMesa (Mesa 25.1 and later dropped it); use "
		"--backend egl-headless");
	return NULL;
}

#else

#include <GL/osmesa.h>
#include <dlfcn.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#define OSMESA_LIBRARY "libOSMesa.so.8"

struct osmesa_api {
	OSMesaContext (*CreateContextAttribs)(const int *attribs, OSMesaContext share);
	GLboolean (*MakeCurrent)(OSMesaContext ctx, void *buf, GLenum type, GLsizei w, GLsizei h);
	void (*DestroyContext)(OSMesaContext ctx);
	OSMESAproc (*GetProcAddress)(const char *name);
};

struct display_osmesa {
	struct display base;
	void *lib;
	struct osmesa_api api;
	OSMesaContext ctx;
	uint8_t *pixels;
};

static void *osmesa_proc(void *ctx, const char *name)
{
	struct display_osmesa *o = ctx;
	OSMESAproc p = o->api.GetProcAddress(name);
	void *v;

	memcpy(&v, &p, sizeof(v));
	return v;
}

static int osmesa_begin_frame(struct display *d)
{
	struct display_osmesa *o = (struct display_osmesa *)d;

	if (!o->api.MakeCurrent(o->ctx, o->pixels, GL_UNSIGNED_BYTE, d->width, d->height))
		return -EIO;
	d->gl.Viewport(0, 0, d->width, d->height);
	return 0;
}

static int osmesa_present(struct display *d)
{
	/* Nothing is shown, but the frame must be complete before readback or
	 * before the bench stops its clock. */
	d->gl.Finish();
	return 0;
}

static void osmesa_destroy(struct display *d)
{
	struct display_osmesa *o = (struct display_osmesa *)d;

	if (o->ctx)
		o->api.DestroyContext(o->ctx);
	if (o->lib)
		dlclose(o->lib);
	free(o->pixels);
	free(o);
}

static int osmesa_bind(struct display_osmesa *o)
{
	void *sym[4];
	static const char *const names[4] = {"OSMesaCreateContextAttribs", "OSMesaMakeCurrent",
					     "OSMesaDestroyContext", "OSMesaGetProcAddress"};

	o->lib = dlopen(OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
	if (!o->lib) {
		log_err("osmesa: cannot load %s (install libosmesa6): %s", OSMESA_LIBRARY,
			dlerror());
		return -ENOENT;
	}
	for (int i = 0; i < 4; i++) {
		sym[i] = dlsym(o->lib, names[i]);
		if (!sym[i]) {
			log_err("osmesa: %s lacks %s", OSMESA_LIBRARY, names[i]);
			return -ENOSYS;
		}
	}
	memcpy(&o->api.CreateContextAttribs, &sym[0], sizeof(void *));
	memcpy(&o->api.MakeCurrent, &sym[1], sizeof(void *));
	memcpy(&o->api.DestroyContext, &sym[2], sizeof(void *));
	memcpy(&o->api.GetProcAddress, &sym[3], sizeof(void *));
	return 0;
}

struct display *display_osmesa_new(const struct display_config *cfg)
{
	/* A compatibility context: Mesa accepts GLSL ES 1.00 shaders there
	 * (ARB_ES2_compatibility), so the same sources run as on the kiosk. */
	static const int attribs[] = {OSMESA_FORMAT,
				      OSMESA_RGBA,
				      OSMESA_DEPTH_BITS,
				      24,
				      OSMESA_PROFILE,
				      OSMESA_COMPAT_PROFILE,
				      OSMESA_CONTEXT_MAJOR_VERSION,
				      2,
				      OSMESA_CONTEXT_MINOR_VERSION,
				      1,
				      0};
	struct display_osmesa *o = calloc(1, sizeof(*o));

	if (!o)
		return NULL;
	o->base.name = "osmesa";
	o->base.width = cfg->width > 0 ? cfg->width : 1280;
	o->base.height = cfg->height > 0 ? cfg->height : 720;
	o->base.begin_frame = osmesa_begin_frame;
	o->base.present = osmesa_present;
	o->base.read_frame = display_read_rgba;
	o->base.get_fd = display_no_fd;
	o->base.dispatch = display_no_dispatch;
	o->base.destroy = osmesa_destroy;
	/* auto is off on a software rasteriser, which OSMesa always is. */
	if (cfg->antialias > DISPLAY_AA_OFF)
		log_warn("osmesa: [display] antialias = %d: OSMesa has no multisampling, drawing "
			 "without",
			 display_antialias_samples(cfg->antialias, false));
	if (osmesa_bind(o))
		goto fail;
	o->pixels = malloc((size_t)o->base.width * (size_t)o->base.height * 4);
	o->ctx = o->api.CreateContextAttribs(attribs, NULL);
	if (!o->pixels || !o->ctx) {
		log_err("osmesa: cannot create a %dx%d context", o->base.width, o->base.height);
		goto fail;
	}
	if (!o->api.MakeCurrent(o->ctx, o->pixels, GL_UNSIGNED_BYTE, o->base.width,
				o->base.height)) {
		log_err("osmesa: cannot make the context current");
		goto fail;
	}
	if (gl_load(&o->base.gl, osmesa_proc, o))
		goto fail;
	log_info("osmesa: %s, %dx%d", (const char *)o->base.gl.GetString(GL_RENDERER),
		 o->base.width, o->base.height);
	return &o->base;
fail:
	osmesa_destroy(&o->base);
	return NULL;
}

#endif
