/* gbm-linear: LD_PRELOAD shim for programs that trust gbm_bo_get_modifier().
 *
 * Mesa 22.3's kms_swrast (llvmpipe on a KMS device such as vkms) allocates
 * dumb buffers, which are linear, but gbm_bo_get_modifier() reports
 * DRM_FORMAT_MOD_INVALID for them.  A program that passes that value to
 * drmModeAddFB2WithModifiers(..., DRM_MODE_FB_MODIFIERS) gets a framebuffer
 * that no vkms plane accepts: the modeset fails with EINVAL.  Debian's kmscube
 * does exactly that.  This shim answers LINEAR instead of INVALID.
 *
 *   LD_PRELOAD=/usr/lib/vm/libgbm-linear.so kmscube
 *
 * Programs of our own should not need it: treat DRM_FORMAT_MOD_INVALID as
 * "no explicit modifier" and call drmModeAddFB2() without the flag.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>

#include <drm_fourcc.h>
#include <gbm.h>

uint64_t gbm_bo_get_modifier(struct gbm_bo *bo)
{
	static uint64_t (*real)(struct gbm_bo *);
	uint64_t mod;

	if (!real)
		real = (uint64_t(*)(struct gbm_bo *))dlsym(RTLD_NEXT, "gbm_bo_get_modifier");
	mod = real ? real(bo) : DRM_FORMAT_MOD_INVALID;
	return mod == DRM_FORMAT_MOD_INVALID ? DRM_FORMAT_MOD_LINEAR : mod;
}
