/* The legacy KMS path: SetCrtc for the mode, PageFlip for each frame. */
#include "display/drm.h"
#include "util/log.h"

#include <errno.h>
#include <string.h>
#include <xf86drm.h>

static int legacy_flip(struct drm *drm, uint32_t fb, bool modeset)
{
	if (modeset) {
		if (drmModeSetCrtc(drm->fd, drm->crtc_id, fb, 0, 0, &drm->connector_id, 1,
				   &drm->mode)) {
			int err = -errno;

			log_err("%s: cannot set mode %s: %s%s", drm->connector_name, drm->mode.name,
				strerror(-err),
				err == -EACCES ? " (another program holds DRM master)" : "");
			return err;
		}
	}
	if (drmModePageFlip(drm->fd, drm->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, drm))
		return -errno;
	return 0;
}

static void legacy_disable(struct drm *drm)
{
	drmModeSetCrtc(drm->fd, drm->crtc_id, 0, 0, 0, NULL, 0, NULL);
}

static void legacy_destroy(struct drm *drm)
{
	(void)drm;
}

const struct drm_ops drm_legacy_ops = {
    .name = "legacy",
    .flip = legacy_flip,
    .disable = legacy_disable,
    .destroy = legacy_destroy,
};
