/* A DRM framebuffer for each GBM buffer object, made once and kept on the
 * bo (gbm frees it with the bo). */
#ifndef MK_KMS_FB_H
#define MK_KMS_FB_H

#include <gbm.h>
#include <stdint.h>

/* Returns the framebuffer id, or 0 after logging. */
uint32_t kms_fb_for_bo(int drm_fd, struct gbm_bo *bo);

#endif
