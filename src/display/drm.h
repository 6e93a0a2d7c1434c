/* DRM/KMS output: finding the device, the connector and the mode, and the
 * two ways to put a framebuffer on the screen, behind one small struct of
 * function pointers, the way kmscube splits drm-legacy.c and
 * drm-atomic.c. */
#ifndef MK_DRM_H
#define MK_DRM_H

#include <stdbool.h>
#include <stdint.h>
#include <xf86drmMode.h>

struct drm;

/* The order of [display] kms_api's words: auto, atomic, legacy. */
enum drm_api { DRM_API_AUTO, DRM_API_ATOMIC, DRM_API_LEGACY };

struct drm_ops {
	const char *name;
	/* The atomic backend: the overlay and scaling planes need it. A flag
	 * rather than a comparison with &drm_atomic_ops, so that what
	 * drm_atomic.c calls (kms_overlay.c) does not refer back to it. */
	bool atomic;
	/* Show fb and request an event at the next vblank. The first call
	 * (or any after a hotplug) also sets the mode. Never blocks. */
	int (*flip)(struct drm *drm, uint32_t fb, bool modeset);
	/* Turn the output off (the display went away). Blocks. */
	void (*disable)(struct drm *drm);
	/* Let the screen sleep, keeping the mode and the connector: ACTIVE
	 * 0 on the CRTC (atomic), the connector's DPMS off (legacy). The
	 * next flip with modeset wakes it. Blocks; returns 0 or -errno. */
	int (*sleep)(struct drm *drm);
	void (*destroy)(struct drm *drm);
};

struct drm {
	int fd; /* the one that sets modes and gets the flip events */
	char path[64];
	const struct drm_ops *ops;
	uint32_t connector_id;
	uint32_t crtc_id;
	int crtc_index;
	/* Indices of the CRTCs other outputs of this device drive ([display]
	 * outputs): drm_select picks none of them. */
	uint32_t crtcs_taken;
	drmModeModeInfo mode;
	char connector_name[32];
	/* The primary plane's source: the buffer's size, smaller than the
	 * mode's where the plane scales it up (atomic only), chosen by
	 * display/kms_scale.c from scale_want ([display] render_scale, 0:
	 * auto); 0: the mode's size. */
	uint32_t src_w, src_h;
	double scale_want;
	/* What the CRTC showed before our first modeset, restored on exit. */
	drmModeCrtc *saved_crtc;
	void *priv;		     /* the atomic backend's property ids */
	struct kms_overlay *overlay; /* the caption's plane (kms_overlay.h); NULL: none */
};

/* Open path, or find the first primary node with a connected connector
 * (a Raspberry Pi has a render-only v3d card beside the display one);
 * with none connected, the first with any connector, to wait on. Sets
 * drm->fd and drm->path; returns 0 or a negative errno after saying why
 * (naming the group that grants access when permission is refused).
 * quiet: say nothing when there is simply no display output. */
int drm_open(struct drm *drm, const char *path, bool quiet);

/* Pick the connector (by name, or the first connected one), its mode
 * ("WxH" or "WxH@Hz", else the preferred, else the largest) and a CRTC.
 * Returns 0, -ENOENT when no display is connected (the caller waits for
 * one), or -EINVAL after listing what exists when a name does not. */
int drm_select(struct drm *drm, const char *connector, const char *mode);
/* [display] outputs = all: the names of fd's connectors (writeback ones
 * left out: they show nothing), at most max. Returns how many. */
int drm_connector_list(int fd, char (*names)[32], int max);
/* True while the selected connector is connected and offers our mode:
 * a hotplug event that changed nothing needs no new modeset. Asked with
 * drmModeGetConnectorCurrent, the state the kernel already knows: no
 * forced probe (an EDID read over DDC takes tens of milliseconds, on the
 * loop thread). The kernel updates that state before it sends the
 * hotplug event; only a change found here is probed for real (drm_select). */
bool drm_still_connected(const struct drm *drm);

/* Atomic when the driver offers it (never requiring fences), else legacy;
 * or the one asked for. -ENOTSUP after saying so when atomic was asked
 * for and the driver has none. */
int drm_ops_init(struct drm *drm, enum drm_api api);
extern const struct drm_ops drm_legacy_ops;
extern const struct drm_ops drm_atomic_ops;
int drm_atomic_init(struct drm *drm);
/* Whether the driver would take the modeset that shows fb (with the
 * plane's source as src_w x src_h say): an atomic TEST_ONLY commit, which
 * changes nothing. Returns 0 or the commit's negative errno. */
int drm_atomic_test(struct drm *drm, uint32_t fb);

/* DRM master: only one program may set modes. drm_master_holder names
 * the one that holds it ("kmscube (pid 42)") where the kernel's debugfs
 * is readable, else "another program". drm_acquire_master becomes master
 * once the holder has gone: SET_MASTER on drm->fd where that is allowed
 * (root), else a fresh open of the node, which the kernel makes master
 * when no one is. Returns drm->fd or the new fd (the caller moves mode
 * setting to it), or -EBUSY while the display is still held. */
void drm_master_holder(const struct drm *drm, char *buf, int len);
int drm_acquire_master(struct drm *drm);

/* Remember the CRTC as it is (before our first modeset), and give it back
 * as it was: its framebuffer and mode, or off. */
void drm_save(struct drm *drm);
void drm_restore(struct drm *drm);

/* For messages and tests: "HDMI-A-1" from the type and type id. */
void drm_connector_name(const drmModeConnector *c, char *buf, int len);
/* Parse "1920x1080" or "1920x1080@60". Returns false when malformed. */
bool drm_parse_mode(const char *s, int *w, int *h, int *hz);

#endif
