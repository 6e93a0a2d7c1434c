/* One connector of the KMS backend, from its cable to its page flips (see
 * kms_output.h); what is device-wide is display_kms.c's. */
#include "display/kms_output.h"
#include "display/egl_util.h"
#include "display/kms_fb.h"
#include "display/kms_scale.h"
#include "util/log.h"

#include <errno.h>
#include <poll.h>
#include <stddef.h>
#include <xf86drm.h>

static struct kms_output *from_drm(void *drm)
{
	return (struct kms_output *)((char *)drm - offsetof(struct kms_output, drm));
}

static void on_flip(int fd, unsigned int frame, unsigned int sec, unsigned int usec, void *data)
{
	struct kms_output *o = from_drm(data);
	double t = sec + usec * 1e-6;

	(void)fd;
	(void)frame;
	/* The pending buffer is on screen: the one before it is free. */
	if (o->shown)
		gbm_surface_release_buffer(o->surface, o->shown);
	o->shown = o->pending;
	o->pending = NULL;
	if (o->flips++ == 0)
		o->first_flip_s = t;
	o->last_flip_s = t;
}

void kms_output_events(int fd)
{
	drmEventContext ev = {.version = 2, .page_flip_handler = on_flip};

	drmHandleEvent(fd, &ev);
}

void kms_output_drain(struct kms_output *o, int timeout_ms)
{
	struct pollfd p = {.fd = o->drm.fd, .events = POLLIN};

	/* Another output's event may come first: read until o's has (a
	 * bounded number of times: a descriptor in error polls readable). */
	for (int i = 0; o->pending && i < 2 * KMS_OUTPUTS_MAX && poll(&p, 1, timeout_ms) > 0; i++)
		kms_output_events(o->drm.fd);
}

static void release_buffers(struct kms_output *o)
{
	if (o->pending)
		gbm_surface_release_buffer(o->surface, o->pending);
	if (o->shown)
		gbm_surface_release_buffer(o->surface, o->shown);
	o->pending = o->shown = NULL;
}

void kms_output_disconnect(struct kms_output *o, const struct kms_egl *e, bool turn_off,
			   bool master)
{
	if (!o->connected)
		return;
	kms_output_drain(o, 100);
	if (turn_off && master && o->touched)
		o->drm.ops->disable(&o->drm);
	eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx);
	release_buffers(o);
	eglDestroySurface(e->dpy, o->egl_surface);
	gbm_surface_destroy(o->surface);
	o->egl_surface = EGL_NO_SURFACE;
	o->surface = NULL;
	o->connected = false;
}

static int make_surface(struct kms_output *o, const struct kms_egl *e)
{
	int w = (int)o->drm.src_w, h = (int)o->drm.src_h; /* kms_scale_plane's */

	o->surface = gbm_surface_create(e->gbm, (uint32_t)w, (uint32_t)h, e->format,
					GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
	if (!o->surface)
		return -ENOMEM;
	o->egl_surface =
	    eglCreateWindowSurface(e->dpy, e->config, (EGLNativeWindowType)o->surface, NULL);
	if (o->egl_surface == EGL_NO_SURFACE ||
	    !eglMakeCurrent(e->dpy, o->egl_surface, o->egl_surface, e->ctx)) {
		log_err("kms: %s: cannot make a %dx%d EGL surface: %s", o->drm.connector_name, w, h,
			egl_error_string(eglGetError()));
		if (o->egl_surface != EGL_NO_SURFACE)
			eglDestroySurface(e->dpy, o->egl_surface);
		gbm_surface_destroy(o->surface);
		o->egl_surface = EGL_NO_SURFACE;
		o->surface = NULL;
		return -ENODEV;
	}
	return 0;
}

void kms_output_ops_reset(struct kms_output *o)
{
	if (o->drm.ops)
		o->drm.ops->destroy(&o->drm);
	o->drm.ops = NULL;
}

int kms_output_connect(struct kms_output *o, const struct kms_egl *e, enum drm_api api,
		       const char *mode, uint32_t taken, const struct display *d)
{
	int ret;

	o->drm.crtcs_taken = taken;
	if ((ret = drm_select(&o->drm, o->want, mode)))
		return ret;
	kms_output_ops_reset(o);
	ret = drm_ops_init(&o->drm, api);
	o->plane_scaled = !ret && kms_scale_plane(&o->drm, e->gbm, e->format, d);
	if (!ret)
		ret = make_surface(o, e);
	if (ret)
		return ret;
	o->connected = true;
	o->modeset = true;
	log_info("kms: %s %s@%u, %s modesetting", o->drm.connector_name, o->drm.mode.name,
		 o->drm.mode.vrefresh, o->drm.ops->name);
	return 0;
}

int kms_output_present(struct kms_output *o, const struct kms_egl *e, int gpu_fd)
{
	struct gbm_bo *bo;
	uint32_t fb;
	int ret;

	/* The live loop never presents while a flip is pending; a caller
	 * that draws frames back to back (--frames) waits for it here. */
	kms_output_drain(o, 1000);
	if (!eglSwapBuffers(e->dpy, o->egl_surface))
		return -EIO;
	bo = gbm_surface_lock_front_buffer(o->surface);
	fb = bo ? kms_fb_for_bo(gpu_fd, bo) : 0;
	if (fb && o->modeset)
		drm_save(&o->drm);
	ret = fb ? o->drm.ops->flip(&o->drm, fb, o->modeset) : -EIO;
	if (ret) {
		if (bo)
			gbm_surface_release_buffer(o->surface, bo);
		return ret;
	}
	o->touched |= o->modeset;
	o->pending = bo;
	o->modeset = false;
	return 0;
}

int kms_output_read(const struct kms_output *o, struct image *out)
{
	struct gbm_bo *bo = o->shown ? o->shown : o->pending;
	int w = bo ? (int)gbm_bo_get_width(bo) : 0, h = bo ? (int)gbm_bo_get_height(bo) : 0;
	uint32_t stride = 0;
	void *map_data = NULL;
	uint8_t *px;
	int ret;

	if (!bo)
		return -ENODATA;
	px = gbm_bo_map(bo, 0, 0, (uint32_t)w, (uint32_t)h, GBM_BO_TRANSFER_READ, &stride,
			&map_data);
	if (!px)
		return -EIO;
	ret = image_alloc(out, w, h);
	for (int y = 0; !ret && y < h; y++)
		for (int x = 0; x < w; x++) {
			/* XRGB8888 is little-endian B, G, R, X in memory. */
			const uint8_t *s = px + (size_t)y * stride + (size_t)x * 4;
			uint8_t *p = out->rgba + ((size_t)y * (size_t)w + (size_t)x) * 4;

			p[0] = s[2];
			p[1] = s[1];
			p[2] = s[0];
			p[3] = 255;
		}
	gbm_bo_unmap(bo, map_data);
	return ret;
}

void kms_output_log_flips(const struct kms_output *o, bool named)
{
	double span = o->last_flip_s - o->first_flip_s;
	const char *name = named ? o->drm.connector_name : "";
	const char *sep = named ? ": " : "";

	if (o->flips > 1 && span > 0)
		log_info("kms: %s%s%ld page flips in %.1f s (%.1f per second)", name, sep, o->flips,
			 span, (double)(o->flips - 1) / span);
	else
		log_info("kms: %s%s%ld page flips", name, sep, o->flips);
}
