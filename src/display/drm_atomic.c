/* The atomic KMS path: one commit per frame, non-blocking, with a flip
 * event. No in- or out-fences are used: vc4 on the Raspberry Pi has none,
 * and the flip event already tells the loop when the frame is on screen. */
#include "display/drm.h"
#include "display/kms_overlay.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <xf86drm.h>

enum {
	P_CONN_CRTC_ID,
	P_CRTC_MODE_ID,
	P_CRTC_ACTIVE,
	P_FB_ID,
	P_CRTC_ID,
	P_SRC_X,
	P_SRC_Y,
	P_SRC_W,
	P_SRC_H,
	P_CRTC_X,
	P_CRTC_Y,
	P_CRTC_W,
	P_CRTC_H,
	P_COUNT
};

struct atomic {
	uint32_t plane_id;
	uint32_t prop[P_COUNT];
	uint32_t mode_blob;
};

static uint32_t prop_id(int fd, uint32_t obj, uint32_t type, const char *name)
{
	drmModeObjectProperties *props = drmModeObjectGetProperties(fd, obj, type);
	uint32_t id = 0;

	for (uint32_t i = 0; props && i < props->count_props && !id; i++) {
		drmModePropertyRes *p = drmModeGetProperty(fd, props->props[i]);

		if (p && strcmp(p->name, name) == 0)
			id = p->prop_id;
		drmModeFreeProperty(p);
	}
	drmModeFreeObjectProperties(props);
	return id;
}

static bool is_primary(int fd, uint32_t plane)
{
	drmModeObjectProperties *props =
	    drmModeObjectGetProperties(fd, plane, DRM_MODE_OBJECT_PLANE);
	bool primary = false;

	for (uint32_t i = 0; props && i < props->count_props; i++) {
		drmModePropertyRes *p = drmModeGetProperty(fd, props->props[i]);

		if (p && strcmp(p->name, "type") == 0)
			primary = props->prop_values[i] == DRM_PLANE_TYPE_PRIMARY;
		drmModeFreeProperty(p);
	}
	drmModeFreeObjectProperties(props);
	return primary;
}

static uint32_t find_primary_plane(const struct drm *drm)
{
	drmModePlaneRes *res = drmModeGetPlaneResources(drm->fd);
	uint32_t found = 0;

	for (uint32_t i = 0; res && i < res->count_planes && !found; i++) {
		drmModePlane *p = drmModeGetPlane(drm->fd, res->planes[i]);

		if (p && (p->possible_crtcs & (1u << drm->crtc_index)) &&
		    is_primary(drm->fd, p->plane_id))
			found = p->plane_id;
		drmModeFreePlane(p);
	}
	drmModeFreePlaneResources(res);
	return found;
}

int drm_atomic_init(struct drm *drm)
{
	static const char *const plane_props[] = {"FB_ID", "CRTC_ID", "SRC_X",	"SRC_Y",  "SRC_W",
						  "SRC_H", "CRTC_X",  "CRTC_Y", "CRTC_W", "CRTC_H"};
	struct atomic *a;

	if (drmSetClientCap(drm->fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1) ||
	    drmSetClientCap(drm->fd, DRM_CLIENT_CAP_ATOMIC, 1))
		return -ENOTSUP;
	a = calloc(1, sizeof(*a));
	if (!a)
		return -ENOMEM;
	a->plane_id = find_primary_plane(drm);
	a->prop[P_CONN_CRTC_ID] =
	    prop_id(drm->fd, drm->connector_id, DRM_MODE_OBJECT_CONNECTOR, "CRTC_ID");
	a->prop[P_CRTC_MODE_ID] = prop_id(drm->fd, drm->crtc_id, DRM_MODE_OBJECT_CRTC, "MODE_ID");
	a->prop[P_CRTC_ACTIVE] = prop_id(drm->fd, drm->crtc_id, DRM_MODE_OBJECT_CRTC, "ACTIVE");
	for (int i = 0; i < 10; i++)
		a->prop[P_FB_ID + i] =
		    prop_id(drm->fd, a->plane_id, DRM_MODE_OBJECT_PLANE, plane_props[i]);
	for (int i = 0; i < P_COUNT; i++)
		if (!a->plane_id || !a->prop[i]) {
			free(a);
			drmSetClientCap(drm->fd, DRM_CLIENT_CAP_ATOMIC, 0);
			return -ENOTSUP;
		}
	drm->priv = a;
	return 0;
}

static void add_plane(drmModeAtomicReq *req, const struct drm *drm, const struct atomic *a,
		      uint32_t fb)
{
	uint32_t w = drm->mode.hdisplay, h = drm->mode.vdisplay;
	/* The source rectangle: the buffer, smaller than the CRTC's where the
	 * plane scales it up ([display] render_scale, kms_scale.c). */
	uint32_t sw = drm->src_w ? drm->src_w : w, sh = drm->src_h ? drm->src_h : h;
	uint64_t v[10] = {fb, drm->crtc_id, 0, 0, (uint64_t)sw << 16, (uint64_t)sh << 16, 0, 0, w,
			  h};

	for (int i = 0; i < 10; i++)
		drmModeAtomicAddProperty(req, a->plane_id, a->prop[P_FB_ID + i], v[i]);
}

/* The mode, the connector on the CRTC and the CRTC on, for a modeset. */
static int add_modeset(drmModeAtomicReq *req, struct drm *drm, struct atomic *a)
{
	if (a->mode_blob)
		drmModeDestroyPropertyBlob(drm->fd, a->mode_blob);
	a->mode_blob = 0;
	if (drmModeCreatePropertyBlob(drm->fd, &drm->mode, sizeof(drm->mode), &a->mode_blob))
		return -errno;
	drmModeAtomicAddProperty(req, drm->connector_id, a->prop[P_CONN_CRTC_ID], drm->crtc_id);
	drmModeAtomicAddProperty(req, drm->crtc_id, a->prop[P_CRTC_MODE_ID], a->mode_blob);
	drmModeAtomicAddProperty(req, drm->crtc_id, a->prop[P_CRTC_ACTIVE], 1);
	return 0;
}

int drm_atomic_test(struct drm *drm, uint32_t fb)
{
	struct atomic *a = drm->priv;
	drmModeAtomicReq *req = drmModeAtomicAlloc();
	int ret;

	if (!req)
		return -ENOMEM;
	ret = add_modeset(req, drm, a);
	if (!ret) {
		add_plane(req, drm, a, fb);
		if (drmModeAtomicCommit(drm->fd, req,
					DRM_MODE_ATOMIC_TEST_ONLY | DRM_MODE_ATOMIC_ALLOW_MODESET,
					NULL))
			ret = -errno;
	}
	drmModeAtomicFree(req);
	return ret;
}

static int atomic_flip(struct drm *drm, uint32_t fb, bool modeset)
{
	struct atomic *a = drm->priv;
	drmModeAtomicReq *req = drmModeAtomicAlloc();
	uint32_t flags = DRM_MODE_PAGE_FLIP_EVENT | DRM_MODE_ATOMIC_NONBLOCK;
	int ret = 0;

	if (!req)
		return -ENOMEM;
	if (modeset) {
		ret = add_modeset(req, drm, a);
		if (ret)
			goto out;
		flags |= DRM_MODE_ATOMIC_ALLOW_MODESET;
	}
	add_plane(req, drm, a, fb);
	kms_overlay_add(drm, req);
	if (drmModeAtomicCommit(drm->fd, req, flags, drm)) {
		ret = -errno;
		if (modeset)
			log_err("%s: cannot set mode %s: %s%s", drm->connector_name, drm->mode.name,
				strerror(-ret),
				ret == -EACCES ? " (another program holds DRM master)" : "");
	}
out:
	drmModeAtomicFree(req);
	return ret;
}

static void atomic_disable(struct drm *drm)
{
	struct atomic *a = drm->priv;
	drmModeAtomicReq *req = drmModeAtomicAlloc();

	if (!req)
		return;
	drmModeAtomicAddProperty(req, drm->connector_id, a->prop[P_CONN_CRTC_ID], 0);
	drmModeAtomicAddProperty(req, drm->crtc_id, a->prop[P_CRTC_MODE_ID], 0);
	drmModeAtomicAddProperty(req, drm->crtc_id, a->prop[P_CRTC_ACTIVE], 0);
	drmModeAtomicAddProperty(req, a->plane_id, a->prop[P_FB_ID], 0);
	drmModeAtomicAddProperty(req, a->plane_id, a->prop[P_CRTC_ID], 0);
	/* The caption's plane too; the next frame's test puts it back. */
	kms_overlay_set(drm, NULL, 0, 0, 0);
	kms_overlay_add(drm, req);
	drmModeAtomicCommit(drm->fd, req, DRM_MODE_ATOMIC_ALLOW_MODESET, NULL);
	drmModeAtomicFree(req);
}

static int atomic_sleep(struct drm *drm)
{
	struct atomic *a = drm->priv;
	drmModeAtomicReq *req = drmModeAtomicAlloc();
	int ret = 0;

	if (!req)
		return -ENOMEM;
	/* An inactive CRTC may keep its mode: the atomic form of DPMS off. */
	drmModeAtomicAddProperty(req, drm->crtc_id, a->prop[P_CRTC_ACTIVE], 0);
	if (drmModeAtomicCommit(drm->fd, req, DRM_MODE_ATOMIC_ALLOW_MODESET, NULL))
		ret = -errno;
	drmModeAtomicFree(req);
	return ret;
}

static void atomic_destroy(struct drm *drm)
{
	struct atomic *a = drm->priv;

	if (a && a->mode_blob)
		drmModeDestroyPropertyBlob(drm->fd, a->mode_blob);
	kms_overlay_free(drm);
	free(a);
	drm->priv = NULL;
}

const struct drm_ops drm_atomic_ops = {
    .name = "atomic",
    .atomic = true,
    .flip = atomic_flip,
    .disable = atomic_disable,
    .sleep = atomic_sleep,
    .destroy = atomic_destroy,
};
