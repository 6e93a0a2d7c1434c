#include "display/kms_overlay.h"
#include "util/log.h"

#include <drm_fourcc.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <xf86drm.h>

enum {
	O_FB_ID,
	O_CRTC_ID,
	O_SRC_X,
	O_SRC_Y,
	O_SRC_W,
	O_SRC_H,
	O_CRTC_X,
	O_CRTC_Y,
	O_CRTC_W,
	O_CRTC_H,
	O_COUNT
};

struct kms_overlay {
	int fd;
	uint32_t plane, prop[O_COUNT];
	uint32_t zpos;	     /* its zpos property where it may be set; 0: none */
	uint64_t zpos_max;   /* put above the primary plane */
	uint32_t handle, fb; /* the dumb buffer and its framebuffer; 0: none */
	int width, height, x, y;
	unsigned serial;
	bool shown; /* on the plane; false: off (at the next flip) */
};

/* A plane property's id, and its value and range's top. */
static uint32_t plane_prop(int fd, uint32_t plane, const char *name, uint64_t *value, uint64_t *max,
			   bool *immutable)
{
	drmModeObjectProperties *props =
	    drmModeObjectGetProperties(fd, plane, DRM_MODE_OBJECT_PLANE);
	uint32_t id = 0;

	for (uint32_t i = 0; props && i < props->count_props && !id; i++) {
		drmModePropertyRes *p = drmModeGetProperty(fd, props->props[i]);

		if (p && !strcmp(p->name, name)) {
			id = p->prop_id;
			if (value)
				*value = props->prop_values[i];
			if (max && p->count_values >= 2)
				*max = p->values[1];
			if (immutable)
				*immutable = p->flags & DRM_MODE_PROP_IMMUTABLE;
		}
		drmModeFreeProperty(p);
	}
	drmModeFreeObjectProperties(props);
	return id;
}

static bool takes_argb(const drmModePlane *p)
{
	for (uint32_t i = 0; i < p->count_formats; i++)
		if (p->formats[i] == DRM_FORMAT_ARGB8888)
			return true;
	return false;
}

/* The first overlay plane of the CRTC that scans out ARGB8888. */
static uint32_t find_plane(const struct drm *drm)
{
	drmModePlaneRes *res = drmModeGetPlaneResources(drm->fd);
	uint32_t found = 0;

	for (uint32_t i = 0; res && i < res->count_planes && !found; i++) {
		drmModePlane *p = drmModeGetPlane(drm->fd, res->planes[i]);
		uint64_t type = 0;

		if (p && (p->possible_crtcs & (1u << drm->crtc_index)) && takes_argb(p) &&
		    plane_prop(drm->fd, p->plane_id, "type", &type, NULL, NULL) &&
		    type == DRM_PLANE_TYPE_OVERLAY)
			found = p->plane_id;
		drmModeFreePlane(p);
	}
	drmModeFreePlaneResources(res);
	return found;
}

static struct kms_overlay *overlay_new(const struct drm *drm)
{
	static const char *const names[O_COUNT] = {"FB_ID",  "CRTC_ID", "SRC_X",  "SRC_Y",
						   "SRC_W",  "SRC_H",	"CRTC_X", "CRTC_Y",
						   "CRTC_W", "CRTC_H"};
	struct kms_overlay *o;
	bool immutable = true;

	if (!drm->ops || !drm->ops->atomic)
		return NULL;
	o = calloc(1, sizeof(*o));
	if (!o)
		return NULL;
	o->fd = drm->fd;
	o->plane = find_plane(drm);
	for (int i = 0; i < O_COUNT && o->plane; i++)
		if (!(o->prop[i] = plane_prop(o->fd, o->plane, names[i], NULL, NULL, NULL)))
			o->plane = 0;
	if (!o->plane) {
		free(o);
		return NULL;
	}
	o->zpos = plane_prop(o->fd, o->plane, "zpos", NULL, &o->zpos_max, &immutable);
	if (immutable)
		o->zpos = 0;
	return o;
}

static void drop_buffer(struct kms_overlay *o)
{
	struct drm_mode_destroy_dumb d = {.handle = o->handle};

	if (o->fb)
		drmModeRmFB(o->fd, o->fb);
	if (o->handle)
		drmIoctl(o->fd, DRM_IOCTL_MODE_DESTROY_DUMB, &d);
	o->fb = o->handle = 0;
}

/* RGBA bytes into ARGB8888, which is B, G, R, A in memory. */
static void copy_pixels(uint8_t *dst, uint32_t pitch, const struct image *img)
{
	for (int y = 0; y < img->height; y++)
		for (int x = 0; x < img->width; x++) {
			const uint8_t *s = img->rgba + ((size_t)y * img->width + x) * 4;
			uint8_t *d = dst + (size_t)y * pitch + x * 4;

			d[0] = s[2];
			d[1] = s[1];
			d[2] = s[0];
			d[3] = s[3];
		}
}

static int upload(struct kms_overlay *o, const struct image *img)
{
	struct drm_mode_create_dumb c = {
	    .width = (uint32_t)img->width, .height = (uint32_t)img->height, .bpp = 32};
	struct drm_mode_map_dumb m = {0};
	uint32_t handles[4] = {0}, pitches[4] = {0}, offsets[4] = {0};
	void *map;

	drop_buffer(o);
	if (drmIoctl(o->fd, DRM_IOCTL_MODE_CREATE_DUMB, &c))
		return -errno;
	o->handle = m.handle = c.handle;
	if (drmIoctl(o->fd, DRM_IOCTL_MODE_MAP_DUMB, &m))
		return -errno;
	map = mmap(NULL, c.size, PROT_WRITE, MAP_SHARED, o->fd, (off_t)m.offset);
	if (map == MAP_FAILED)
		return -errno;
	copy_pixels(map, c.pitch, img);
	munmap(map, c.size);
	handles[0] = c.handle;
	pitches[0] = c.pitch;
	if (drmModeAddFB2(o->fd, c.width, c.height, DRM_FORMAT_ARGB8888, handles, pitches, offsets,
			  &o->fb, 0))
		return -errno;
	o->width = img->width;
	o->height = img->height;
	return 0;
}

static void add_props(const struct kms_overlay *o, uint32_t crtc, drmModeAtomicReq *req)
{
	uint64_t w = (uint64_t)o->width, h = (uint64_t)o->height;
	uint64_t v[O_COUNT] = {
	    o->fb, crtc, 0, 0, w << 16, h << 16, (uint64_t)(int64_t)o->x, (uint64_t)(int64_t)o->y,
	    w,	   h};

	if (!o->shown) {
		drmModeAtomicAddProperty(req, o->plane, o->prop[O_FB_ID], 0);
		drmModeAtomicAddProperty(req, o->plane, o->prop[O_CRTC_ID], 0);
		return;
	}
	for (int i = 0; i < O_COUNT; i++)
		drmModeAtomicAddProperty(req, o->plane, o->prop[i], v[i]);
	if (o->zpos)
		drmModeAtomicAddProperty(req, o->plane, o->zpos, o->zpos_max);
}

void kms_overlay_add(const struct drm *drm, drmModeAtomicReq *req)
{
	if (drm->overlay)
		add_props(drm->overlay, drm->crtc_id, req);
}

static int commit(const struct drm *drm, uint32_t flags)
{
	drmModeAtomicReq *req = drmModeAtomicAlloc();
	int ret;

	if (!req)
		return -ENOMEM;
	add_props(drm->overlay, drm->crtc_id, req);
	ret = drmModeAtomicCommit(drm->fd, req, flags, NULL) ? -errno : 0;
	drmModeAtomicFree(req);
	return ret;
}

/* A new picture: uploaded, then the driver asked whether the plane takes
 * it over the frame as it is now. */
static int show(struct drm *drm, const struct image *img, int x, int y)
{
	struct kms_overlay *o = drm->overlay;
	int ret = upload(o, img);

	o->x = x;
	o->y = y;
	o->shown = true;
	if (!ret)
		ret = commit(drm, DRM_MODE_ATOMIC_TEST_ONLY);
	if (!ret) {
		log_info("kms: the caption (%dx%d) is on overlay plane %u", img->width, img->height,
			 o->plane);
		return 0;
	}
	log_info("kms: overlay plane %u does not take the caption (%s): drawn with GL", o->plane,
		 strerror(-ret));
	o->shown = false;
	drop_buffer(o);
	return -ENOTSUP;
}

int kms_overlay_set(struct drm *drm, const struct image *img, unsigned serial, int x, int y)
{
	struct kms_overlay *o = drm->overlay;

	if (!img) {
		if (o)
			o->shown = false;
		return 0;
	}
	if (!o && !(o = drm->overlay = overlay_new(drm)))
		return -ENOTSUP;
	if (serial != o->serial || !o->shown) {
		o->serial = serial;
		return show(drm, img, x, y);
	}
	if (x == o->x && y == o->y)
		return 0;
	o->x = x;
	o->y = y;
	/* Blocking: once in minutes, at most a vblank's wait. */
	return commit(drm, 0);
}

int kms_overlay_display(void *drm, const struct image *img, unsigned serial, int x, int y)
{
	return kms_overlay_set(drm, img, serial, x, y);
}

void kms_overlay_free(struct drm *drm)
{
	if (!drm->overlay)
		return;
	drop_buffer(drm->overlay);
	free(drm->overlay);
	drm->overlay = NULL;
}
