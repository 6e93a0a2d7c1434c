/* Fullscreen on DRM/KMS: GBM buffers flipped onto the display on vblank,
 * with no window system. One device, one EGL context, and one output per
 * connector driven ([display] outputs; one by default), each with its own
 * surface, CRTC and page flips (kms_output.c). The loop sees one
 * descriptor, an epoll set of the DRM fd (flip events), udev (hotplug)
 * and a retry timer (a display held by another program, or no udev to
 * tell us of a cable). */
#include "display/display.h"
#include "display/drm.h"
#include "display/hotplug.h"
#include "display/kms_egl.h"
#include "display/kms_output.h"
#include "display/kms_overlay.h"
#include "util/log.h"

#include <errno.h>
#include <gbm.h>
#include <stdio.h>
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
	struct kms_output out[KMS_OUTPUTS_MAX];
	int count;   /* outputs in out[] */
	int current; /* the one select_output made current */
	/* GBM and EGL live on this fd; the outputs' drm.fd is the same one,
	 * unless the display was busy at start and mode setting moved to a
	 * fresh open of the node once it was free (framebuffer ids are
	 * device-wide). */
	int gpu_fd;
	char *mode;
	bool exit_when_busy;
	enum drm_api api;
	struct gbm_device *gbm;
	struct kms_egl egl;
	bool master;
	struct hotplug *hotplug;
	int epoll_fd, timer_fd;
};

/* What the loop reads of the outputs: a flip pending anywhere holds the
 * next frame back (all outputs are drawn together), and the newest flip
 * is when the frame reached a screen. */
static void sum_up(struct display_kms *k)
{
	k->base.waiting = false;
	for (int i = 0; i < k->count; i++) {
		k->base.waiting |= k->out[i].pending != NULL;
		if (k->out[i].last_flip_s > k->base.flipped_s)
			k->base.flipped_s = k->out[i].last_flip_s;
	}
}

/* The CRTCs the other outputs drive, for drm_select to leave alone. */
static uint32_t crtcs_taken(const struct display_kms *k, const struct kms_output *o)
{
	uint32_t taken = 0;

	for (int i = 0; i < k->count; i++)
		if (&k->out[i] != o && k->out[i].connected)
			taken |= 1u << k->out[i].drm.crtc_index;
	return taken;
}

/* What the renderer reads of the output drawn: the surface's size (the
 * plane's scaled source, kms_scale.h) and whether the plane scales. */
static void take_size(struct display *d, const struct kms_output *o)
{
	d->width = (int)o->drm.src_w;
	d->height = (int)o->drm.src_h;
	d->plane_scaled = o->plane_scaled;
}

/* The output's connector, set up. -ENOENT: nothing is connected yet (not
 * an error: the kiosk waits for a cable). */
static int connect_output(struct display_kms *k, struct kms_output *o)
{
	int ret;

	if (o->gone)
		return -ENOENT;
	ret = kms_output_connect(o, &k->egl, k->api, k->mode, crtcs_taken(k, o), &k->base);
	if (ret == -EINVAL && k->count > 1) {
		log_err("kms: [display] outputs: %s is left out; the other outputs go on", o->want);
		o->gone = true;
	}
	if (ret)
		return ret;
	take_size(&k->base, o);
	k->base.refresh_ns = o->drm.mode.vrefresh ? 1000000000ull / o->drm.mode.vrefresh : 0;
	return 0;
}

/* One shot, armed again for as long as there is something to retry:
 * taking the display from a program that held it, or looking for a
 * cable where udev cannot tell us of one. */
static void schedule_retry(struct display_kms *k)
{
	struct itimerspec t = {.it_value = {.tv_sec = RETRY_SECONDS}}, now;
	bool waiting_for_cable = false;

	for (int i = 0; i < k->count; i++)
		waiting_for_cable |= !k->out[i].connected && !k->out[i].gone;
	if (timerfd_gettime(k->timer_fd, &now) == 0 &&
	    (now.it_value.tv_sec || now.it_value.tv_nsec))
		return; /* armed already: the retry keeps its time */
	if (!k->master || (waiting_for_cable && !k->hotplug))
		timerfd_settime(k->timer_fd, 0, &t, NULL);
}

/* Output i is drawn next: its size and whether its plane scales. */
static int kms_select_output(struct display *d, int i)
{
	struct display_kms *k = (struct display_kms *)d;
	struct kms_output *o;

	if (i < 0 || i >= k->count)
		return -EINVAL;
	o = &k->out[i];
	k->current = i;
	d->output_name = o->connected ? o->drm.connector_name : o->want;
	if (!o->connected)
		return -EAGAIN;
	take_size(d, o);
	return 0;
}

static int kms_begin_frame(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;
	struct kms_output *o = &k->out[k->current];

	if (!o->connected || !k->master)
		return -EAGAIN;
	/* One context, a surface per output: draw into this one's. */
	if (k->count > 1 && !eglMakeCurrent(k->egl.dpy, o->egl_surface, o->egl_surface, k->egl.ctx))
		return -EIO;
	d->gl.Viewport(0, 0, d->width, d->height);
	return 0;
}

static void say_busy(struct display_kms *k, bool exiting)
{
	char who[96];

	drm_master_holder(&k->out[0].drm, who, sizeof(who));
	if (exiting)
		log_err("kms: %s is held by %s (it is DRM master): exiting, as [display] on_busy "
			"= exit says",
			k->out[0].drm.path, who);
	else
		log_warn("kms: %s is held by %s (it is DRM master): waiting for it, as "
			 "[display] on_busy = wait says (trying every %d s)",
			 k->out[0].drm.path, who, RETRY_SECONDS);
}

static int kms_present(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;
	int ret = kms_output_present(&k->out[k->current], &k->egl, k->gpu_fd);

	sum_up(k);
	if (ret != -EACCES)
		return ret;
	/* Another program took the display (a VT switch, a desktop). */
	k->master = false;
	for (int i = 0; i < k->count; i++)
		k->out[i].modeset = true;
	say_busy(k, k->exit_when_busy);
	if (k->exit_when_busy)
		return ret;
	schedule_retry(k);
	return -EAGAIN;
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
	epoll_ctl(k->epoll_fd, EPOLL_CTL_DEL, k->out[0].drm.fd, NULL);
	if (k->out[0].drm.fd != k->gpu_fd)
		close(k->out[0].drm.fd);
	watch(k, fd);
	for (int i = 0; i < k->count; i++) {
		struct kms_output *o = &k->out[i];

		o->drm.fd = fd;
		kms_output_ops_reset(o);
		if (o->connected && drm_ops_init(&o->drm, k->api))
			kms_output_disconnect(o, &k->egl, false, k->master);
	}
}

static int take_master(struct display_kms *k)
{
	int fd = drm_acquire_master(&k->out[0].drm);

	if (fd < 0)
		return 0;
	if (fd != k->out[0].drm.fd)
		move_to_fd(k, fd);
	k->master = true;
	for (int i = 0; i < k->count; i++)
		k->out[i].modeset = true;
	log_info("kms: %s is free now: taking the display", k->out[0].drm.path);
	return 1;
}

/* A cable in or out, or a synthetic udev event: act only on a change. */
static int reprobe(struct display_kms *k, struct kms_output *o)
{
	int ret;

	if (o->gone || (o->connected && drm_still_connected(&o->drm)))
		return 0;
	if (o->connected) {
		kms_output_disconnect(o, &k->egl, true, k->master);
		if (k->count > 1)
			log_warn("kms: %s was disconnected; the other outputs go on, and it is "
				 "waited for",
				 o->drm.connector_name);
		else
			log_warn("kms: %s was disconnected; waiting for a display",
				 o->drm.connector_name);
	}
	ret = connect_output(k, o);
	if (ret == 0)
		return 1;
	if (ret != -ENOENT && !o->gone)
		log_warn("kms: a display is connected but cannot be used; waiting for another");
	return 0;
}

static int reprobe_all(struct display_kms *k, bool only_absent)
{
	int redraw = 0;

	for (int i = 0; i < k->count; i++)
		if (!only_absent || !k->out[i].connected)
			redraw |= reprobe(k, &k->out[i]);
	return redraw;
}

static int kms_dispatch(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;
	struct epoll_event events[4];
	int n = epoll_wait(k->epoll_fd, events, 4, 0), redraw = 0;
	uint64_t expirations;

	for (int i = 0; i < n; i++) {
		int fd = events[i].data.fd;

		if (fd == k->out[0].drm.fd) {
			kms_output_events(fd);
		} else if (fd == k->timer_fd) {
			if (read(fd, &expirations, sizeof(expirations)) <= 0)
				continue;
			if (!k->master)
				redraw |= take_master(k);
			if (!k->hotplug)
				redraw |= reprobe_all(k, true);
		} else if (k->hotplug && hotplug_read(k->hotplug)) {
			redraw |= reprobe_all(k, false);
		}
	}
	sum_up(k);
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

	return kms_output_read(&k->out[k->current], out);
}

static void kms_destroy(struct display *d)
{
	struct display_kms *k = (struct display_kms *)d;

	for (int i = 0; i < k->count; i++) {
		struct kms_output *o = &k->out[i];

		if (o->connected) {
			kms_output_drain(o, 100);
			kms_output_log_flips(o, k->count > 1);
		}
		if (k->master && o->touched)
			drm_restore(&o->drm);
		kms_output_disconnect(o, &k->egl, false, k->master);
		kms_output_ops_reset(o);
		if (o->drm.saved_crtc)
			drmModeFreeCrtc(o->drm.saved_crtc);
		free(o->want);
	}
	kms_egl_release(&k->egl);
	if (k->gbm)
		gbm_device_destroy(k->gbm);
	hotplug_free(k->hotplug);
	if (k->epoll_fd >= 0)
		close(k->epoll_fd);
	if (k->timer_fd >= 0)
		close(k->timer_fd);
	if (k->out[0].drm.fd >= 0 && k->out[0].drm.fd != k->gpu_fd)
		close(k->out[0].drm.fd);
	if (k->gpu_fd >= 0)
		close(k->gpu_fd);
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
	if (fstat(k->gpu_fd, &st) == 0)
		k->hotplug = hotplug_new(st.st_rdev);
	if ((ret = watch(k, k->gpu_fd)) || (ret = watch(k, k->timer_fd)) ||
	    (k->hotplug && (ret = watch(k, hotplug_fd(k->hotplug)))))
		return ret;
	return 0;
}

static int kms_set_power(struct display *d, bool on)
{
	struct display_kms *k = (struct display_kms *)d;
	int ret = 0;

	for (int i = 0; i < k->count; i++) {
		struct kms_output *o = &k->out[i];
		int r;

		/* On: the next present is a modeset, which wakes the CRTC. */
		o->modeset |= on;
		if (on || !o->connected || !o->touched)
			continue;
		kms_output_drain(o, 1000);
		r = o->drm.ops->sleep(&o->drm);
		if (r)
			log_err("kms: %s cannot sleep (%s modesetting): %s", o->drm.connector_name,
				o->drm.ops->name, strerror(-r));
		else
			log_info("kms: %s asleep", o->drm.connector_name);
		ret = ret ? ret : r; /* one that cannot sleep leaves the others asleep */
	}
	sum_up(k);
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
	k->base.select_output = kms_select_output;
	k->base.destroy = kms_destroy;
	k->gpu_fd = k->epoll_fd = k->timer_fd = -1;
	k->egl.dpy = EGL_NO_DISPLAY;
	k->egl.ctx = EGL_NO_CONTEXT;
	k->mode = cfg->mode ? strdup(cfg->mode) : NULL;
	k->exit_when_busy = cfg->exit_when_busy;
	k->api = (enum drm_api)cfg->kms_api;
	for (int i = 0; i < KMS_OUTPUTS_MAX; i++) {
		k->out[i].drm.fd = -1;
		k->out[i].drm.scale_want = cfg->render_scale;
		k->out[i].egl_surface = EGL_NO_SURFACE;
	}
}

/* The first program to open the node is master; one that opens it while
 * another holds it is not, and may not set modes until that one is gone. */
static int check_master(struct display_kms *k)
{
	k->master = drmIsMaster(k->gpu_fd) || drmSetMaster(k->gpu_fd) == 0;
	if (k->master)
		return 0;
	say_busy(k, k->exit_when_busy);
	return k->exit_when_busy ? -EBUSY : 0;
}

/* [display] outputs: its names (or every connector, for all), else the
 * one [display] connector (NULL: the first connected). */
static void name_outputs(struct display_kms *k, const struct display_config *cfg)
{
	char names[KMS_OUTPUTS_MAX][32], why[128];
	int n = 0;

	if (cfg->outputs && strcmp(cfg->outputs, "all") == 0)
		n = drm_connector_list(k->gpu_fd, names, KMS_OUTPUTS_MAX);
	else if (cfg->outputs)
		n = display_outputs_parse(cfg->outputs, names, KMS_OUTPUTS_MAX, why, sizeof(why));
	if (n < 0)
		log_err("kms: [display] outputs = %s: %s; driving one output", cfg->outputs, why);
	k->count = n > 0 ? n : 1;
	for (int i = 0; i < k->count; i++) {
		struct kms_output *o = &k->out[i];

		o->want = n > 0 ? strdup(names[i]) : cfg->connector ? strdup(cfg->connector) : NULL;
		if (i > 0) {
			o->drm.fd = k->out[0].drm.fd;
			memcpy(o->drm.path, k->out[0].drm.path, sizeof(o->drm.path));
		}
	}
	if (k->count > 1)
		log_info("kms: %d outputs: %s", k->count, cfg->outputs);
	else { /* the caption's own plane: only with one output */
		k->base.overlay = kms_overlay_display;
		k->base.overlay_ctx = &k->out[0].drm;
	}
	k->base.outputs = k->count;
}

/* Every output tried: -ENOENT when none is connected (waited for), the
 * first other error when none can be used. */
static int connect_outputs(struct display_kms *k)
{
	int ret = -ENOENT, first = 0;

	for (int i = 0; i < k->count; i++) {
		int r = connect_output(k, &k->out[i]);

		if (r == 0)
			ret = 0;
		else if (r != -ENOENT && !first)
			first = r;
	}
	if (ret == -ENOENT && first)
		ret = first;
	if (!ret)
		k->current = 0;
	return ret;
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
	if ((ret = drm_open(&k->out[0].drm, cfg->device, cfg->quiet)))
		goto fail;
	k->gpu_fd = k->out[0].drm.fd;
	k->count = 1;
	k->gbm = gbm_create_device(k->gpu_fd);
	if (!k->gbm) {
		log_err("kms: GBM cannot use %s (is Mesa's DRI driver installed?)",
			k->out[0].drm.path);
		ret = -ENODEV;
		goto fail;
	}
	if ((ret = kms_egl_init(&k->egl, k->gbm, cfg->antialias, &k->base.gl)))
		goto fail;
	k->base.samples = k->egl.samples;
	if ((ret = open_fds(k)) || (ret = check_master(k)))
		goto fail;
	name_outputs(k, cfg);
	ret = connect_outputs(k);
	if (ret == -ENOENT)
		log_warn("kms: no display is connected to %s; waiting for one", k->out[0].drm.path);
	else if (ret)
		goto fail;
	sum_up(k);
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
