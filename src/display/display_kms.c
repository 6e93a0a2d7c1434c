/* Fullscreen on DRM/KMS: GBM buffers flipped onto the display on vblank,
 * with no window system. The loop sees one descriptor, an epoll set of
 * the DRM fd (flip events), udev (hotplug) and a retry timer (a display
 * held by another program, or no udev to tell us of a cable). */
#include "display/display.h"
#include "display/drm.h"
#include "display/egl_util.h"
#include "display/hotplug.h"
#include "display/kms_fb.h"
#include "display/kms_overlay.h"
#include "display/kms_scale.h"
#include "util/log.h"

#include <drm_fourcc.h>
#include <errno.h>
#include <gbm.h>
#include <poll.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <sys/stat.h>
#include <sys/timerfd.h>
#include <unistd.h>
#include <xf86drm.h>

#define RETRY_SECONDS 2

struct display_kms {
	struct display base;
	struct drm drm;
	/* GBM and EGL live on this fd; drm.fd is the same one, unless the
	 * display was busy at start and mode setting moved to a fresh open
	 * of the node once it was free (framebuffer ids are device-wide). */
	int gpu_fd;
	char *connector, *mode;
	bool exit_when_busy;
	int antialias; /* enum display_antialias */
	enum drm_api api;
	struct gbm_device *gbm;
	struct gbm_surface *surface;
	uint32_t format;
	EGLDisplay dpy;
	EGLConfig config;
	EGLContext ctx;
	EGLSurface egl_surface;
	struct gbm_bo *shown, *pending;
	bool connected, modeset, master;
	bool touched; /* we set a mode: the CRTC's old state goes back on exit */
	struct hotplug *hotplug;
	int epoll_fd, timer_fd;
	long flips;
	double first_flip_s, last_flip_s;
};

static struct display_kms *from_drm(struct drm *drm)
{
	return (struct display_kms *)((char *)drm - offsetof(struct display_kms, drm));
}

/* An EGL config whose native visual is the GBM format (otherwise the
 * colours come out in the wrong channels, or the surface is refused), and
 * with a depth buffer: without one the depth test passes everywhere and
 * the far side of the model shows through the near side. samples: at
 * least that many samples per pixel ([display] antialias), 0: none. */
static bool find_config(struct display_kms *k, EGLint depth, EGLint samples)
{
	/* Pairs: attribute, value. */
	const EGLint attribs[] = {EGL_SURFACE_TYPE,
				  EGL_WINDOW_BIT,
				  EGL_RED_SIZE,
				  8,
				  EGL_GREEN_SIZE,
				  8,
				  EGL_BLUE_SIZE,
				  8,
				  EGL_DEPTH_SIZE,
				  depth,
				  EGL_SAMPLE_BUFFERS,
				  samples ? 1 : 0,
				  EGL_SAMPLES,
				  samples,
				  EGL_RENDERABLE_TYPE,
				  EGL_OPENGL_ES2_BIT,
				  EGL_NONE};
	static const uint32_t formats[] = {DRM_FORMAT_XRGB8888, DRM_FORMAT_ARGB8888};
	EGLConfig configs[64];
	EGLint n = 0;

	if (!eglChooseConfig(k->dpy, attribs, configs, 64, &n))
		return false;
	for (int f = 0; f < 2; f++) {
		if (!gbm_device_is_format_supported(k->gbm, formats[f],
						    GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING))
			continue;
		/* Sorted by samples, fewest first: the first that scans out. */
		for (EGLint i = 0; i < n; i++) {
			EGLint id = 0;

			eglGetConfigAttrib(k->dpy, configs[i], EGL_NATIVE_VISUAL_ID, &id);
			if ((uint32_t)id == formats[f]) {
				k->config = configs[i];
				k->format = formats[f];
				return true;
			}
		}
	}
	return false;
}

/* The most samples any window config with a depth buffer offers, for
 * the log when the one asked for is not there. */
static EGLint most_samples(struct display_kms *k)
{
	const EGLint attribs[] = {EGL_SURFACE_TYPE,    EGL_WINDOW_BIT,	   EGL_DEPTH_SIZE, 16,
				  EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
	EGLConfig configs[256];
	EGLint n = 0, most = 0;

	if (!eglChooseConfig(k->dpy, attribs, configs, 256, &n))
		return 0;
	for (EGLint i = 0; i < n; i++) {
		EGLint s = 0;

		eglGetConfigAttrib(k->dpy, configs[i], EGL_SAMPLES, &s);
		if (s > most)
			most = s;
	}
	return most;
}

static int choose_config(struct display_kms *k, EGLint samples)
{
	EGLint depth = 0, got = 0;

	if (samples && !find_config(k, 24, samples) && !find_config(k, 16, samples)) {
		log_warn("kms: [display] antialias = %d: no EGL config with %d samples scans out "
			 "(the driver offers %d at most): drawing without",
			 samples, samples, most_samples(k));
		samples = 0;
	}
	/* 24 bits as the offscreen backends have; 16 where that is all. */
	if (!samples && !find_config(k, 24, 0) && !find_config(k, 16, 0)) {
		log_err("kms: no EGL config with a depth buffer scans out as XRGB8888 or "
			"ARGB8888");
		return -ENODEV;
	}
	eglGetConfigAttrib(k->dpy, k->config, EGL_DEPTH_SIZE, &depth);
	eglGetConfigAttrib(k->dpy, k->config, EGL_SAMPLES, &got);
	k->base.samples = got;
	log_debug("kms: EGL config %.4s with a %d-bit depth buffer, %d samples",
		  (const char *)&k->format, depth, got);
	return 0;
}

static int make_context(struct display_kms *k)
{
	static const EGLint ctx_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};

	k->ctx = eglCreateContext(k->dpy, k->config, EGL_NO_CONTEXT, ctx_attribs);
	/* Current without a surface until a display is connected, so the
	 * renderer can load the scene while the kiosk waits for a screen. */
	if (k->ctx == EGL_NO_CONTEXT ||
	    !eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, k->ctx)) {
		log_err("kms: cannot create an OpenGL ES 2.0 context: %s",
			egl_error_string(eglGetError()));
		return -ENODEV;
	}
	if (gl_load(&k->base.gl, egl_proc, NULL))
		return -ENOSYS;
	egl_read_caps(k->dpy, &k->base.gl.caps);
	return 0;
}

/* antialias = auto: whether the GPU is a software rasteriser is known
 * only from a context; on a real one the context is made again on a
 * multisampled config, where there is one (said, as for a number). */
static int antialias_auto(struct display_kms *k)
{
	EGLConfig plain = k->config;
	uint32_t format = k->format;
	int samples = display_antialias_samples(DISPLAY_AA_AUTO, k->base.gl.caps.software);

	if (!samples || (!find_config(k, 24, samples) && !find_config(k, 16, samples))) {
		k->config = plain;
		k->format = format;
		log_info("kms: antialias = auto: off (%s)",
			 samples ? "no multisampled config scans out" : "a software rasteriser");
		return 0;
	}
	eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
	eglDestroyContext(k->dpy, k->ctx);
	return choose_config(k, samples) ? -ENODEV : make_context(k);
}

static int egl_init(struct display_kms *k)
{
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
	    (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	EGLint major, minor;
	int ret;

	k->dpy = get_display ? get_display(EGL_PLATFORM_GBM_KHR, k->gbm, NULL) : EGL_NO_DISPLAY;
	if (k->dpy == EGL_NO_DISPLAY || !eglInitialize(k->dpy, &major, &minor) ||
	    !eglBindAPI(EGL_OPENGL_ES_API)) {
		log_err("kms: EGL on GBM is not available: %s", egl_error_string(eglGetError()));
		return -ENODEV;
	}
	/* auto: a plain config first; antialias_auto decides once the
	 * context says what the GPU is. */
	if (choose_config(k, k->antialias == DISPLAY_AA_AUTO
				 ? 0
				 : display_antialias_samples(k->antialias, false)))
		return -ENODEV;
	ret = make_context(k);
	if (!ret && k->antialias == DISPLAY_AA_AUTO)
		ret = antialias_auto(k);
	if (!ret && k->base.samples)
		log_info("kms: antialias %d samples", k->base.samples);
	return ret;
}

static void on_flip(int fd, unsigned int frame, unsigned int sec, unsigned int usec, void *data)
{
	struct display_kms *k = from_drm(data);
	double t = sec + usec * 1e-6;

	(void)fd;
	(void)frame;
	/* The pending buffer is on screen: the one before it is free. */
	if (k->shown)
		gbm_surface_release_buffer(k->surface, k->shown);
	k->shown = k->pending;
	k->pending = NULL;
	k->base.waiting = false;
	if (k->flips++ == 0)
		k->first_flip_s = t;
	k->last_flip_s = k->base.flipped_s = t;
}

/* Let a flip in flight finish, so the buffer it shows is not freed under
 * the scanout (a vblank is 16 ms; a hung driver gets timeout_ms). */
static void drain_flip(struct display_kms *k, int timeout_ms)
{
	drmEventContext ev = {.version = 2, .page_flip_handler = on_flip};
	struct pollfd p = {.fd = k->drm.fd, .events = POLLIN};

	if (k->base.waiting && poll(&p, 1, timeout_ms) > 0)
		drmHandleEvent(k->drm.fd, &ev);
}

static void release_buffers(struct display_kms *k)
{
	if (k->pending)
		gbm_surface_release_buffer(k->surface, k->pending);
	if (k->shown)
		gbm_surface_release_buffer(k->surface, k->shown);
	k->pending = k->shown = NULL;
	k->base.waiting = false;
}

/* turn_off: the display went away, so stop scanning out of buffers that
 * are about to be freed; at exit the old mode is put back instead. */
static void disconnect(struct display_kms *k, bool turn_off)
{
	if (!k->connected)
		return;
	drain_flip(k, 100);
	if (turn_off && k->master && k->touched)
		k->drm.ops->disable(&k->drm);
	eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, k->ctx);
	release_buffers(k);
	eglDestroySurface(k->dpy, k->egl_surface);
	gbm_surface_destroy(k->surface);
	k->egl_surface = EGL_NO_SURFACE;
	k->surface = NULL;
	k->connected = false;
}

static int make_surface(struct display_kms *k)
{
	int w = (int)k->drm.src_w, h = (int)k->drm.src_h; /* kms_scale_plane's */

	k->surface = gbm_surface_create(k->gbm, (uint32_t)w, (uint32_t)h, k->format,
					GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
	if (!k->surface)
		return -ENOMEM;
	k->egl_surface =
	    eglCreateWindowSurface(k->dpy, k->config, (EGLNativeWindowType)k->surface, NULL);
	if (k->egl_surface == EGL_NO_SURFACE ||
	    !eglMakeCurrent(k->dpy, k->egl_surface, k->egl_surface, k->ctx)) {
		log_err("kms: cannot make a %dx%d EGL surface: %s", w, h,
			egl_error_string(eglGetError()));
		if (k->egl_surface != EGL_NO_SURFACE)
			eglDestroySurface(k->dpy, k->egl_surface);
		gbm_surface_destroy(k->surface);
		k->egl_surface = EGL_NO_SURFACE;
		k->surface = NULL;
		return -ENODEV;
	}
	k->base.width = w;
	k->base.height = h;
	return 0;
}

static void ops_reset(struct display_kms *k)
{
	if (k->drm.ops)
		k->drm.ops->destroy(&k->drm);
	k->drm.ops = NULL;
}

/* Find the display and set up a surface of its mode. -ENOENT: nothing is
 * connected yet (not an error: the kiosk waits for a cable). */
static int connect_display(struct display_kms *k)
{
	int ret = drm_select(&k->drm, k->connector, k->mode);

	if (ret)
		return ret;
	ops_reset(k);
	ret = drm_ops_init(&k->drm, k->api);
	k->base.plane_scaled = !ret && kms_scale_plane(&k->drm, k->gbm, k->format, &k->base);
	if (!ret)
		ret = make_surface(k);
	if (ret)
		return ret;
	k->connected = true;
	k->modeset = true;
	k->base.refresh_ns = k->drm.mode.vrefresh ? 1000000000ull / k->drm.mode.vrefresh : 0;
	log_info("kms: %s %s@%u, %s modesetting", k->drm.connector_name, k->drm.mode.name,
		 k->drm.mode.vrefresh, k->drm.ops->name);
	return 0;
}

/* One shot, armed again for as long as there is something to retry:
 * taking the display from a program that held it, or looking for a
 * cable where udev cannot tell us of one. */
static void schedule_retry(struct display_kms *k)
{
	struct itimerspec t = {.it_value = {.tv_sec = RETRY_SECONDS}}, now;

	if (timerfd_gettime(k->timer_fd, &now) == 0 &&
	    (now.it_value.tv_sec || now.it_value.tv_nsec))
		return; /* armed already: the retry keeps its time */
	if (!k->master || (!k->connected && !k->hotplug))
		timerfd_settime(k->timer_fd, 0, &t, NULL);
}

static int kms_begin_frame(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;

	if (!k->connected || !k->master)
		return -EAGAIN;
	d->gl.Viewport(0, 0, d->width, d->height);
	return 0;
}

static void say_busy(struct display_kms *k, bool exiting)
{
	char who[96];

	drm_master_holder(&k->drm, who, sizeof(who));
	if (exiting)
		log_err("kms: %s is held by %s (it is DRM master): exiting, as [display] on_busy "
			"= exit says",
			k->drm.path, who);
	else
		log_warn("kms: %s is held by %s (it is DRM master): waiting for it, as "
			 "[display] on_busy = wait says (trying every %d s)",
			 k->drm.path, who, RETRY_SECONDS);
}

static int kms_present(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;
	struct gbm_bo *bo;
	uint32_t fb;
	int ret;

	/* The live loop never presents while a flip is pending; a caller
	 * that draws frames back to back (--frames) waits for it here. */
	drain_flip(k, 1000);
	if (!eglSwapBuffers(k->dpy, k->egl_surface))
		return -EIO;
	bo = gbm_surface_lock_front_buffer(k->surface);
	fb = bo ? kms_fb_for_bo(k->gpu_fd, bo) : 0;
	if (fb && k->modeset)
		drm_save(&k->drm);
	ret = fb ? k->drm.ops->flip(&k->drm, fb, k->modeset) : -EIO;
	if (ret) {
		if (bo)
			gbm_surface_release_buffer(k->surface, bo);
		if (ret != -EACCES)
			return ret;
		/* Another program took the display (a VT switch, a desktop). */
		k->master = false;
		k->modeset = true;
		say_busy(k, k->exit_when_busy);
		if (k->exit_when_busy)
			return ret;
		schedule_retry(k);
		return -EAGAIN;
	}
	k->touched |= k->modeset;
	k->pending = bo;
	k->modeset = false;
	d->waiting = true;
	return 0;
}

static int watch(struct display_kms *k, int fd)
{
	struct epoll_event ev = {.events = EPOLLIN, .data.fd = fd};

	return epoll_ctl(k->epoll_fd, EPOLL_CTL_ADD, fd, &ev) ? -errno : 0;
}

/* Mode setting moves to fd, which is master: flip events come there,
 * and the client caps (atomic) are per open file. */
static void move_to_fd(struct display_kms *k, int fd)
{
	epoll_ctl(k->epoll_fd, EPOLL_CTL_DEL, k->drm.fd, NULL);
	if (k->drm.fd != k->gpu_fd)
		close(k->drm.fd);
	k->drm.fd = fd;
	watch(k, fd);
	ops_reset(k);
	if (k->connected && drm_ops_init(&k->drm, k->api))
		disconnect(k, false);
}

static int take_master(struct display_kms *k)
{
	int fd = drm_acquire_master(&k->drm);

	if (fd < 0)
		return 0;
	if (fd != k->drm.fd)
		move_to_fd(k, fd);
	k->master = true;
	k->modeset = true;
	log_info("kms: %s is free now: taking the display", k->drm.path);
	return 1;
}

/* A cable in or out, or a synthetic udev event: act only on a change. */
static int reprobe(struct display_kms *k)
{
	int ret;

	if (k->connected && drm_still_connected(&k->drm))
		return 0;
	if (k->connected) {
		disconnect(k, true);
		log_warn("kms: %s was disconnected; waiting for a display", k->drm.connector_name);
	}
	ret = connect_display(k);
	if (ret == 0)
		return 1;
	if (ret != -ENOENT)
		log_warn("kms: a display is connected but cannot be used; waiting for another");
	return 0;
}

static int kms_dispatch(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;
	drmEventContext ev = {.version = 2, .page_flip_handler = on_flip};
	struct epoll_event events[4];
	int n = epoll_wait(k->epoll_fd, events, 4, 0), redraw = 0;
	uint64_t expirations;

	for (int i = 0; i < n; i++) {
		int fd = events[i].data.fd;

		if (fd == k->drm.fd) {
			drmHandleEvent(fd, &ev);
		} else if (fd == k->timer_fd) {
			if (read(fd, &expirations, sizeof(expirations)) <= 0)
				continue;
			if (!k->master)
				redraw |= take_master(k);
			if (!k->connected && !k->hotplug)
				redraw |= reprobe(k);
		} else if (k->hotplug && hotplug_read(k->hotplug)) {
			redraw |= reprobe(k);
		}
	}
	schedule_retry(k);
	return redraw;
}

static int kms_get_fd(struct display *d)
{
	return ((struct display_kms *)d)->epoll_fd;
}

/* The buffer on screen, mapped and read: what the plane scans out. */
static int kms_read_frame(struct display *d, struct image *out)
{
	struct display_kms *k = (struct display_kms *)d;
	struct gbm_bo *bo = k->shown ? k->shown : k->pending;
	uint32_t stride = 0;
	void *map_data = NULL;
	uint8_t *px;
	int ret;

	if (!bo)
		return -ENODATA;
	px = gbm_bo_map(bo, 0, 0, (uint32_t)d->width, (uint32_t)d->height, GBM_BO_TRANSFER_READ,
			&stride, &map_data);
	if (!px)
		return -EIO;
	ret = image_alloc(out, d->width, d->height);
	for (int y = 0; !ret && y < d->height; y++)
		for (int x = 0; x < d->width; x++) {
			/* XRGB8888 is little-endian B, G, R, X in memory. */
			const uint8_t *s = px + (size_t)y * stride + (size_t)x * 4;
			uint8_t *o = out->rgba + ((size_t)y * (size_t)d->width + (size_t)x) * 4;

			o[0] = s[2];
			o[1] = s[1];
			o[2] = s[0];
			o[3] = 255;
		}
	gbm_bo_unmap(bo, map_data);
	return ret;
}

/* For the journal and the tests: how many frames reached the screen. */
static void log_flips(const struct display_kms *k)
{
	double span = k->last_flip_s - k->first_flip_s;

	if (k->flips > 1 && span > 0)
		log_info("kms: %ld page flips in %.1f s (%.1f per second)", k->flips, span,
			 (double)(k->flips - 1) / span);
	else
		log_info("kms: %ld page flips", k->flips);
}

static void kms_destroy(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;

	if (k->connected) {
		drain_flip(k, 100);
		log_flips(k);
	}
	if (k->master && k->touched)
		drm_restore(&k->drm);
	disconnect(k, false);
	ops_reset(k);
	if (k->ctx != EGL_NO_CONTEXT) {
		eglMakeCurrent(k->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		eglDestroyContext(k->dpy, k->ctx);
	}
	if (k->dpy != EGL_NO_DISPLAY)
		eglTerminate(k->dpy);
	if (k->gbm)
		gbm_device_destroy(k->gbm);
	hotplug_free(k->hotplug);
	if (k->epoll_fd >= 0)
		close(k->epoll_fd);
	if (k->timer_fd >= 0)
		close(k->timer_fd);
	if (k->drm.fd >= 0 && k->drm.fd != k->gpu_fd)
		close(k->drm.fd);
	if (k->gpu_fd >= 0)
		close(k->gpu_fd);
	if (k->drm.saved_crtc)
		drmModeFreeCrtc(k->drm.saved_crtc);
	free(k->connector);
	free(k->mode);
	free(k);
}

/* Each errno is read right after the call that set it: the next call
 * (timerfd_create, or udev's in hotplug_new) could change it. */
static int open_fds(struct display_kms *k)
{
	struct stat st;
	int ret;

	k->epoll_fd = epoll_create1(EPOLL_CLOEXEC);
	if (k->epoll_fd < 0)
		return -errno;
	k->timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC | TFD_NONBLOCK);
	if (k->timer_fd < 0)
		return -errno;
	if (fstat(k->drm.fd, &st) == 0)
		k->hotplug = hotplug_new(st.st_rdev);
	if ((ret = watch(k, k->drm.fd)) || (ret = watch(k, k->timer_fd)) ||
	    (k->hotplug && (ret = watch(k, hotplug_fd(k->hotplug)))))
		return ret;
	return 0;
}

static int kms_set_power(struct display *d, bool on)
{
	struct display_kms *k = (struct display_kms *)d;
	int ret;

	if (on) {
		/* The next present is a modeset, which wakes the CRTC. */
		k->modeset = true;
		return 0;
	}
	if (!k->connected || !k->touched)
		return 0;
	drain_flip(k, 1000);
	ret = k->drm.ops->sleep(&k->drm);
	if (ret)
		log_err("kms: %s cannot sleep (%s modesetting): %s", k->drm.connector_name,
			k->drm.ops->name, strerror(-ret));
	else
		log_info("kms: %s asleep", k->drm.connector_name);
	return ret;
}

static void init_base(struct display_kms *k, const struct display_config *cfg)
{
	k->base.name = "kms";
	/* Until a display is connected, a size for the projection. */
	k->base.width = 1920;
	k->base.height = 1080;
	k->base.begin_frame = kms_begin_frame;
	k->base.present = kms_present;
	k->base.read_frame = kms_read_frame;
	k->base.get_fd = kms_get_fd;
	k->base.dispatch = kms_dispatch;
	k->base.set_power = kms_set_power;
	k->base.overlay = kms_overlay_display;
	k->base.overlay_ctx = &k->drm;
	k->base.destroy = kms_destroy;
	k->drm.fd = k->gpu_fd = k->epoll_fd = k->timer_fd = -1;
	k->dpy = EGL_NO_DISPLAY;
	k->ctx = EGL_NO_CONTEXT;
	k->connector = cfg->connector ? strdup(cfg->connector) : NULL;
	k->mode = cfg->mode ? strdup(cfg->mode) : NULL;
	k->exit_when_busy = cfg->exit_when_busy;
	k->antialias = cfg->antialias;
	k->drm.scale_want = cfg->render_scale;
	k->api = (enum drm_api)cfg->kms_api;
}

/* The first program to open the node is master; one that opens it while
 * another holds it is not, and may not set modes until that one is gone. */
static int check_master(struct display_kms *k)
{
	k->master = drmIsMaster(k->drm.fd) || drmSetMaster(k->drm.fd) == 0;
	if (k->master)
		return 0;
	say_busy(k, k->exit_when_busy);
	return k->exit_when_busy ? -EBUSY : 0;
}

struct display *display_kms_open(const struct display_config *cfg, int *err)
{
	struct display_kms *k = calloc(1, sizeof(*k));
	int ret = -ENOMEM;

	if (!k)
		goto out;
	init_base(k, cfg);
	/* A display output with nothing connected yet is a kiosk waiting for
	 * its screen, for auto too: only a machine with none draws a PNG. */
	if ((ret = drm_open(&k->drm, cfg->device, cfg->quiet)))
		goto fail;
	k->gpu_fd = k->drm.fd;
	k->gbm = gbm_create_device(k->gpu_fd);
	if (!k->gbm) {
		log_err("kms: GBM cannot use %s (is Mesa's DRI driver installed?)", k->drm.path);
		ret = -ENODEV;
		goto fail;
	}
	if ((ret = egl_init(k)) || (ret = open_fds(k)) || (ret = check_master(k)))
		goto fail;
	ret = connect_display(k);
	if (ret == -ENOENT)
		log_warn("kms: no display is connected to %s; waiting for one", k->drm.path);
	else if (ret)
		goto fail;
	schedule_retry(k);
	return &k->base;
fail:
	kms_destroy(&k->base);
out:
	if (err)
		*err = ret < 0 ? ret : -ENODEV;
	return NULL;
}

struct display *display_kms_new(const struct display_config *cfg)
{
	return display_kms_open(cfg, NULL);
}
