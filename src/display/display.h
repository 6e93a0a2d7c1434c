/* Where the pixels go. One small file per backend fills this struct, the
 * way kmscube splits drm-legacy.c and drm-atomic.c behind one interface;
 * the renderer only ever sees the GL table (with what the context can
 * do, gl.caps, read once when the backend made it) and the size. */
#ifndef MK_DISPLAY_H
#define MK_DISPLAY_H

#include "render/gl.h"
#include "util/image.h"

#include <stdbool.h>
#include <stddef.h>

struct display_config {
	int width; /* 0: the backend's natural size (the mode, for KMS) */
	int height;
	const char *device;    /* KMS: /dev/dri/cardN, NULL to discover */
	const char *connector; /* KMS: HDMI-A-1, NULL for the first connected */
	const char *outputs;   /* KMS: "HDMI-A-1, HDMI-A-2" or "all"; NULL: connector alone */
	const char *mode;      /* KMS: WxH or WxH@Hz, NULL for the preferred */
	int antialias;	       /* enum display_antialias */
	bool exit_when_busy;   /* KMS: exit when another program holds the display */
	int kms_api;	       /* KMS: 0 auto, 1 atomic, 2 legacy (enum drm_api) */
	bool quiet;	       /* KMS: probing for auto, say nothing when absent */
	double render_scale;   /* [display] render_scale: 0.5 to 1; 0: auto */
};

/* [display] antialias, in the settings' order. */
enum display_antialias {
	DISPLAY_AA_AUTO,
	DISPLAY_AA_OFF,
	DISPLAY_AA_2,
	DISPLAY_AA_4,
	DISPLAY_AA_8
};

/* The samples per pixel asked for: auto is 4 on a GPU and none on a
 * software rasteriser, where they cost more than they give (the figures:
 * tests/bench/report/speed-error.md). 0: off. */
int display_antialias_samples(int antialias, bool software);

/* [display] outputs: at most this many connectors driven at once. */
#define KMS_OUTPUTS_MAX 4

struct display {
	const char *name;
	int width; /* of the image the renderer draws, before any rotation */
	int height;
	struct gl gl;
	int samples; /* multisampled with this many samples per pixel; 0: not */
	/* KMS: the primary plane scales the width x height buffer up to the
	 * mode ([display] render_scale, src/display/kms_scale.c): the scene
	 * is drawn 1:1, with no GL pass (render/render_scale.h). */
	bool plane_scaled;
	/* A presented frame has not reached the screen yet (a page flip is
	 * pending): draw nothing new until dispatch() clears it. */
	bool waiting;
	/* KMS: one refresh of the mode, and when the last frame reached the
	 * screen (its flip's vblank, CLOCK_MONOTONIC s). 0 where there is no
	 * vblank (offscreen: a frame is shown when it is presented). */
	uint64_t refresh_ns;
	double flipped_s;

	/* Several outputs ([display] outputs, KMS): the frame is drawn once
	 * for each, after select_output(d, i) for i below outputs made it
	 * current (width, height, plane_scaled and output_name are then
	 * its); -EAGAIN: that one shows nothing now (not connected), the
	 * others go on. outputs 1 and select_output NULL where there is
	 * one; output_name NULL where it has no name. */
	int outputs;
	const char *output_name;
	int (*select_output)(struct display *d, int i);
	/* Make the context current and bind the target to draw into. */
	int (*begin_frame)(struct display *d);
	/* Hand the frame over: a page flip for KMS, a finish for offscreen. */
	int (*present)(struct display *d);
	/* Read the last drawn frame back, rows top first. */
	int (*read_frame)(struct display *d, struct image *out);
	/* A descriptor for the main poll loop, or -1 when there is none. */
	int (*get_fd)(struct display *d);
	/* Called when get_fd is readable (page flip done, hotplug). Returns
	 * 1 when everything must be drawn again (a display came back), 0, or
	 * a negative errno when the display is gone for good. */
	int (*dispatch)(struct display *d);
	/* Let the screen sleep (on false) or wake it (on true); NULL where
	 * there is no screen (the offscreen backends). While asleep nothing
	 * is presented; the first frame after waking sets the mode again.
	 * Returns 0 or a negative errno after logging. */
	int (*set_power)(struct display *d, bool on);
	/* The caption on a plane of its own over the frame (kms_overlay.h):
	 * img (premultiplied RGBA, identified by serial) at x, y of the
	 * upright panel. 0: on a plane from the next frame on, or moved there
	 * at once for the same serial; -ENOTSUP: no plane takes it, draw it
	 * with GL. img NULL: off. NULL where there are no planes; ctx:
	 * overlay_ctx. */
	int (*overlay)(void *ctx, const struct image *img, unsigned serial, int x, int y);
	void *overlay_ctx;
	void (*destroy)(struct display *d);
};

struct display *display_osmesa_new(const struct display_config *cfg);
struct display *display_egl_new(const struct display_config *cfg);
struct display *display_kms_new(const struct display_config *cfg);
/* The same, and when it returns NULL, why in *err: -EACCES (forbidden:
 * the node's permissions), -EBUSY (another program is DRM master and
 * [display] on_busy = exit), -ENODEV (no such display), or another
 * negative errno. */
struct display *display_kms_open(const struct display_config *cfg, int *err);

/* [display] outputs' names, split at commas and blanks, into names (at
 * most max, each under 32 bytes; names NULL: only checked). Returns how
 * many, or -1 with why in err (n bytes) when there is none, one is too
 * long, repeated, or there are too many. "all" is the caller's. */
int display_outputs_parse(const char *list, char (*names)[32], int max, char *err, size_t n);

/* Shared by the backends: glReadPixels into an image, flipped to rows top first. */
int display_read_rgba(struct display *d, struct image *out);
/* For backends with nothing to wait for (the offscreen ones). */
int display_no_fd(struct display *d);
int display_no_dispatch(struct display *d);

static inline void display_free(struct display *d)
{
	if (d)
		d->destroy(d);
}

#endif
