#include "display/kms_scale.h"
#include "display/kms_fb.h"
#include "render/render_scale.h"
#include "util/log.h"

#include <errno.h>
#include <string.h>

/* A scanout buffer of the scaled size with a framebuffer, only for the
 * test: the commit needs a real one of the format the surface will use. */
static int test_scaled(struct drm *drm, struct gbm_device *gbm, uint32_t format)
{
	struct gbm_bo *bo = gbm_bo_create(gbm, drm->src_w, drm->src_h, format,
					  GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
	uint32_t fb = bo ? kms_fb_for_bo(gbm_device_get_fd(gbm), bo) : 0;
	int ret = fb ? drm_atomic_test(drm, fb) : -ENOMEM;

	/* The framebuffer goes with the buffer (kms_fb.c). */
	if (bo)
		gbm_bo_destroy(bo);
	return ret;
}

/* The plane's source back to the mode's size: no scaling. */
static bool unscaled(struct drm *drm)
{
	drm->src_w = drm->mode.hdisplay;
	drm->src_h = drm->mode.vdisplay;
	return false;
}

bool kms_scale_plane(struct drm *drm, struct gbm_device *gbm, uint32_t format,
		     const struct display *d)
{
	int mw = drm->mode.hdisplay, mh = drm->mode.vdisplay, w, h, ret;
	double scale = render_scale_pick(drm->scale_want, mw, mh, d->gl.caps.software, true);

	if (scale >= 1)
		return unscaled(drm);
	if (!drm->ops || !drm->ops->atomic) {
		log_info("kms: render_scale %.2f: legacy modesetting scales no plane: a GL pass "
			 "scales the frame",
			 scale);
		return unscaled(drm);
	}
	render_scale_size(scale, mw, mh, &w, &h);
	drm->src_w = (uint32_t)w;
	drm->src_h = (uint32_t)h;
	ret = test_scaled(drm, gbm, format);
	if (ret) {
		log_info("kms: render_scale %.2f: the primary plane cannot scale %dx%d up to %dx%d "
			 "(the test commit says %s): a GL pass scales the frame",
			 scale, w, h, mw, mh, strerror(-ret));
		return unscaled(drm);
	}
	log_info("kms: render_scale %.2f: the primary plane scales %dx%d up to %dx%d", scale, w, h,
		 mw, mh);
	return true;
}
