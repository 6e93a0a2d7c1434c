/* [display] render_scale on KMS: the primary plane scales a smaller
 * buffer up to the mode, where the driver can, and then the GPU draws
 * the scaled frame 1:1 with no GL pass (render/render_scale.h does the
 * scaling elsewhere). */
#ifndef MK_KMS_SCALE_H
#define MK_KMS_SCALE_H

#include "display/display.h"
#include "display/drm.h"

#include <gbm.h>
#include <stdbool.h>
#include <stdint.h>

/* After drm_ops_init, before the surface is made: sets drm->src_w x
 * src_h, the size to make the surface. The scale is drm->scale_want's
 * for the mode (auto asks d's GPU whether it is a software rasteriser).
 * Under 1, on atomic modesetting, an atomic TEST_ONLY commit of a
 * scanout buffer of the scaled size, the plane's source that size and
 * its CRTC rectangle the mode's, decides: taken, the source is the
 * scaled size and true is returned; refused (vkms scales no plane),
 * said, and false: the source is the mode's size and the GL pass
 * (render/render_scale.h) scales. Legacy modesetting scales no plane. */
bool kms_scale_plane(struct drm *drm, struct gbm_device *gbm, uint32_t format,
		     const struct display *d);

#endif
