#include "display/kms_fb.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <xf86drm.h>
#include <xf86drmMode.h>
#include <drm_fourcc.h>

struct kms_fb {
	int fd;
	uint32_t id;
};

static void fb_destroy(struct gbm_bo *bo, void *data)
{
	struct kms_fb *fb = data;

	(void)bo;
	if (fb->id)
		drmModeRmFB(fb->fd, fb->id);
	free(fb);
}

/* Modifiers only when the bo has a real one and the driver takes them:
 * Mesa's software GBM reports DRM_FORMAT_MOD_INVALID, and vkms refuses a
 * framebuffer made with that at modeset. */
static int add_fb(int fd, struct gbm_bo *bo, uint32_t *id)
{
	uint32_t handles[4] = {0}, pitches[4] = {0}, offsets[4] = {0};
	uint64_t mods[4] = {0}, mod = gbm_bo_get_modifier(bo), cap = 0;
	uint32_t w = gbm_bo_get_width(bo), h = gbm_bo_get_height(bo);
	uint32_t format = gbm_bo_get_format(bo);
	int planes = gbm_bo_get_plane_count(bo);

	for (int i = 0; i < planes && i < 4; i++) {
		handles[i] = gbm_bo_get_handle_for_plane(bo, i).u32;
		pitches[i] = gbm_bo_get_stride_for_plane(bo, i);
		offsets[i] = gbm_bo_get_offset(bo, i);
		mods[i] = mod;
	}
	drmGetCap(fd, DRM_CAP_ADDFB2_MODIFIERS, &cap);
	if (mod != DRM_FORMAT_MOD_INVALID && cap &&
	    !drmModeAddFB2WithModifiers(fd, w, h, format, handles, pitches, offsets, mods, id,
					DRM_MODE_FB_MODIFIERS))
		return 0;
	if (!drmModeAddFB2(fd, w, h, format, handles, pitches, offsets, id, 0))
		return 0;
	/* Old drivers know only depth and bpp. */
	if (!drmModeAddFB(fd, w, h, 24, 32, pitches[0], handles[0], id))
		return 0;
	return -errno;
}

uint32_t kms_fb_for_bo(int drm_fd, struct gbm_bo *bo)
{
	struct kms_fb *fb = gbm_bo_get_user_data(bo);
	int ret;

	if (fb)
		return fb->id;
	fb = calloc(1, sizeof(*fb));
	if (!fb)
		return 0;
	fb->fd = drm_fd;
	ret = add_fb(drm_fd, bo, &fb->id);
	if (ret) {
		log_err("kms: cannot make a framebuffer: %s", strerror(-ret));
		free(fb);
		return 0;
	}
	gbm_bo_set_user_data(bo, fb, fb_destroy);
	return fb->id;
}
