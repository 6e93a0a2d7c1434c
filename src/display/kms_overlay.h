/* The caption on a KMS overlay plane: its picture copied once into a dumb
 * ARGB8888 buffer (premultiplied, as KMS blends by default), put on an
 * overlay plane of the kiosk's CRTC above the model's frame where an
 * atomic test commit says the driver takes it (the Pi's vc4 has such
 * planes; vkms with enable_overlay=1 too). Then the GPU draws nothing for
 * it, and its drift moves the plane alone, with no new frame. The atomic
 * path only: each flip carries the plane (drm_atomic.c). */
#ifndef MK_KMS_OVERLAY_H
#define MK_KMS_OVERLAY_H

#include "display/drm.h"
#include "util/image.h"

#include <stdbool.h>
#include <xf86drmMode.h>

/* img at x, y of the upright panel, identified by serial. A new serial
 * (or the first call) uploads it and tests it: 0 when a plane takes it,
 * shown from the next flip on; -ENOTSUP when none does (not atomic, no
 * ARGB8888 overlay plane for the CRTC, or the test refused it), and the
 * plane is left off. The same serial moves it to x, y at once (a blocking
 * commit of the plane alone, no new frame). img NULL: off from the next
 * flip on. Returns 0 or a negative errno. */
int kms_overlay_set(struct drm *drm, const struct image *img, unsigned serial, int x, int y);
/* The same for struct display's overlay, ctx the struct drm. */
int kms_overlay_display(void *drm, const struct image *img, unsigned serial, int x, int y);
/* Add the plane's state to a flip's request (atomic_flip). */
void kms_overlay_add(const struct drm *drm, drmModeAtomicReq *req);
void kms_overlay_free(struct drm *drm);

#endif
