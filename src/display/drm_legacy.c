/* The legacy KMS path: SetCrtc for the mode, PageFlip for each frame. */
#include "display/drm.h"
#include "util/log.h"

#include <errno.h>
#include <string.h>
#include <xf86drm.h>

/* The connector's DPMS property: legacy modesetting's way to sleep. */
static int set_dpms(struct drm *drm, uint64_t value)
{
	drmModeObjectProperties *props =
	    drmModeObjectGetProperties(drm->fd, drm->connector_id, DRM_MODE_OBJECT_CONNECTOR);
	int ret = -ENOENT;

	for (uint32_t i = 0; props && i < props->count_props && ret == -ENOENT; i++) {
		drmModePropertyRes *p = drmModeGetProperty(drm->fd, props->props[i]);

		if (p && !strcmp(p->name, "DPMS"))
			ret = drmModeConnectorSetProperty(drm->fd, drm->connector_id, p->prop_id,
							  value)
				  ? -errno
				  : 0;
		drmModeFreeProperty(p);
	}
	drmModeFreeObjectProperties(props);
	return ret;
}

static int legacy_flip(struct drm *drm, uint32_t fb, bool modeset)
{
	if (modeset) {
		/* Awake again after legacy_sleep; a CRTC that was never
		 * asleep ignores it. */
		set_dpms(drm, DRM_MODE_DPMS_ON);
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

static int legacy_sleep(struct drm *drm)
{
	return set_dpms(drm, DRM_MODE_DPMS_OFF);
}

static void legacy_destroy(struct drm *drm)
{
	(void)drm;
}

const struct drm_ops drm_legacy_ops = {
    .name = "legacy",
    .flip = legacy_flip,
    .disable = legacy_disable,
    .sleep = legacy_sleep,
    .destroy = legacy_destroy,
};
