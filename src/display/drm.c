#include "display/drm.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <xf86drm.h>

#define MAX_DEVICES 16

void drm_connector_name(const drmModeConnector *c, char *buf, int len)
{
	const char *type = drmModeGetConnectorTypeName(c->connector_type);

	snprintf(buf, (size_t)len, "%s-%u", type ? type : "Unknown", c->connector_type_id);
}

/* A positive number of digits only, then *end is what follows. */
static bool parse_count(const char *s, int *out, const char **end)
{
	char *e;
	long v;

	if (*s < '0' || *s > '9')
		return false;
	v = strtol(s, &e, 10);
	*out = (int)v;
	*end = e;
	return v > 0 && v < 100000;
}

bool drm_parse_mode(const char *s, int *w, int *h, int *hz)
{
	const char *p;

	*hz = 0;
	if (!parse_count(s, w, &p) || *p != 'x' || !parse_count(p + 1, h, &p))
		return false;
	if (*p == '@' && !parse_count(p + 1, hz, &p))
		return false;
	return *p == '\0';
}

static bool has_connected(int fd)
{
	drmModeRes *res = drmModeGetResources(fd);
	bool found = false;

	for (int i = 0; res && i < res->count_connectors && !found; i++) {
		drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);

		found = c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0;
		drmModeFreeConnector(c);
	}
	drmModeFreeResources(res);
	return found;
}

/* The group that may open the node (video on Debian), for the message. */
static void node_group(const char *path, char *buf, size_t n)
{
	struct stat st;
	struct group *g = stat(path, &st) == 0 ? getgrgid(st.st_gid) : NULL;

	if (g && st.st_gid != 0)
		snprintf(buf, n,
			 "add the user to the '%s' group (the service runs with "
			 "SupplementaryGroups=video)",
			 g->gr_name);
	else
		snprintf(buf, n,
			 "it is readable by root only: give it a group, e.g. with a udev "
			 "rule GROUP=\"video\", and add the user to that group");
}

static int open_node(const char *path, bool quiet)
{
	int fd = open(path, O_RDWR | O_CLOEXEC);
	char hint[160];

	if (fd >= 0)
		return fd;
	fd = -errno;
	if (fd == -EACCES || fd == -EPERM) {
		node_group(path, hint, sizeof(hint));
		log_err("%s: permission denied: %s", path, hint);
	} else if (!quiet) {
		log_err("%s: cannot open: %s", path, strerror(-fd));
	}
	return fd;
}

/* The first primary node whose driver has a connected connector; then
 * the first one with any connector. A node that cannot be opened is said
 * once and not tried again. */
static int discover(struct drm *drm, bool quiet)
{
	drmDevicePtr devs[MAX_DEVICES];
	int n = drmGetDevices2(0, devs, MAX_DEVICES), ret = -ENODEV;
	unsigned int refused = 0;

	for (int pass = 0; pass < 2 && drm->fd < 0; pass++)
		for (int i = 0; i < n && drm->fd < 0; i++) {
			const char *node = devs[i]->nodes[DRM_NODE_PRIMARY];
			drmModeRes *res;
			int fd;

			if (!(devs[i]->available_nodes & (1 << DRM_NODE_PRIMARY)) ||
			    (refused & (1u << i)))
				continue;
			fd = open_node(node, quiet);
			if (fd < 0) {
				refused |= 1u << i;
				ret = fd;
				continue;
			}
			res = drmModeGetResources(fd);
			if (res && res->count_connectors > 0 && (pass == 1 || has_connected(fd))) {
				drm->fd = fd;
				snprintf(drm->path, sizeof(drm->path), "%s", node);
			} else {
				close(fd);
			}
			drmModeFreeResources(res);
		}
	if (n > 0)
		drmFreeDevices(devs, n);
	if (drm->fd >= 0)
		return 0;
	if (ret == -ENODEV && !quiet)
		log_err("no DRM device with a display output (is the display driver loaded?)");
	return ret;
}

int drm_open(struct drm *drm, const char *path, bool quiet)
{
	drm->fd = -1;
	if (!path)
		return discover(drm, quiet);
	drm->fd = open_node(path, quiet);
	if (drm->fd < 0)
		return drm->fd;
	snprintf(drm->path, sizeof(drm->path), "%s", path);
	return 0;
}

static void list_connectors(int fd, const drmModeRes *res, char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (int i = 0; i < res->count_connectors && len + 1 < n; i++) {
		drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
		char name[32];

		if (!c)
			continue;
		drm_connector_name(c, name, sizeof(name));
		len += (size_t)snprintf(buf + len, n - len, "%s%s (%s)", len ? ", " : "", name,
					c->connection == DRM_MODE_CONNECTED ? "connected"
									    : "disconnected");
		drmModeFreeConnector(c);
	}
}

static drmModeConnector *find_connector(int fd, const drmModeRes *res, const char *name)
{
	for (int i = 0; i < res->count_connectors; i++) {
		drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
		char n[32];

		if (!c)
			continue;
		drm_connector_name(c, n, sizeof(n));
		if (name ? strcmp(n, name) == 0
			 : c->connection == DRM_MODE_CONNECTED && c->count_modes > 0)
			return c;
		drmModeFreeConnector(c);
	}
	return NULL;
}

/* "1024x768@60, 800x600@60, ...": each size and rate once (a monitor
 * lists some several times with other timings), "..." when cut short. */
static void list_modes(const drmModeConnector *c, char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (int i = 0; i < c->count_modes; i++) {
		const drmModeModeInfo *m = &c->modes[i];
		char one[32];
		bool seen = false;

		for (int j = 0; j < i && !seen; j++)
			seen = c->modes[j].hdisplay == m->hdisplay &&
			       c->modes[j].vdisplay == m->vdisplay &&
			       c->modes[j].vrefresh == m->vrefresh;
		if (seen)
			continue;
		snprintf(one, sizeof(one), "%s%dx%d@%d", len ? ", " : "", m->hdisplay, m->vdisplay,
			 m->vrefresh);
		if (len + strlen(one) + 5 >= n) {
			snprintf(buf + len, n - len, ", ...");
			return;
		}
		len += (size_t)snprintf(buf + len, n - len, "%s", one);
	}
}

/* The mode asked for; else the preferred one; else the largest. */
static int find_mode(const drmModeConnector *c, int w, int h, int hz)
{
	int best = -1;

	for (int i = 0; i < c->count_modes; i++) {
		const drmModeModeInfo *m = &c->modes[i];

		if (w && m->hdisplay == w && m->vdisplay == h && (!hz || (int)m->vrefresh == hz))
			return i;
		if (!w && (m->type & DRM_MODE_TYPE_PREFERRED))
			return i;
		if (!w && (best < 0 || m->hdisplay * m->vdisplay >
					   c->modes[best].hdisplay * c->modes[best].vdisplay))
			best = i;
	}
	return w ? -1 : best;
}

static int pick_mode(struct drm *drm, const drmModeConnector *c, const char *want)
{
	int w = 0, h = 0, hz = 0, i;
	char list[1024];

	if (want && !drm_parse_mode(want, &w, &h, &hz)) {
		log_err("display mode '%s' is not WIDTHxHEIGHT or WIDTHxHEIGHT@HZ", want);
		return -EINVAL;
	}
	i = find_mode(c, w, h, hz);
	if (i < 0) {
		list_modes(c, list, sizeof(list));
		log_err("%s: there is no mode %s; the modes are: %s", drm->connector_name, want,
			list);
		return -EINVAL;
	}
	drm->mode = c->modes[i];
	return 0;
}

/* A CRTC that one of the connector's encoders can drive, preferring the
 * one already driving it (no flicker, and what we restore on exit). */
static int pick_crtc(struct drm *drm, const drmModeRes *res, const drmModeConnector *c)
{
	drmModeEncoder *cur = c->encoder_id ? drmModeGetEncoder(drm->fd, c->encoder_id) : NULL;
	uint32_t crtc = cur ? cur->crtc_id : 0;

	drmModeFreeEncoder(cur);
	for (int i = 0; crtc && i < res->count_crtcs; i++)
		if (res->crtcs[i] == crtc && (drm->crtcs_taken & (1u << i)))
			crtc = 0; /* another output of ours drives it now */
	for (int e = 0; !crtc && e < c->count_encoders; e++) {
		drmModeEncoder *enc = drmModeGetEncoder(drm->fd, c->encoders[e]);

		for (int i = 0; enc && i < res->count_crtcs && !crtc; i++)
			if ((enc->possible_crtcs & (1u << i)) && !(drm->crtcs_taken & (1u << i)))
				crtc = res->crtcs[i];
		drmModeFreeEncoder(enc);
	}
	for (int i = 0; i < res->count_crtcs; i++)
		if (res->crtcs[i] == crtc)
			drm->crtc_index = i;
	drm->crtc_id = crtc;
	return crtc ? 0 : -ENODEV;
}

int drm_select(struct drm *drm, const char *connector, const char *mode)
{
	drmModeRes *res = drmModeGetResources(drm->fd);
	drmModeConnector *c = NULL;
	char list[512];
	int ret = -ENODEV;

	if (!res) {
		log_err("%s has no mode-setting resources (a render-only GPU?)", drm->path);
		goto out;
	}
	c = find_connector(drm->fd, res, connector);
	if (!c || c->connection != DRM_MODE_CONNECTED || c->count_modes == 0) {
		list_connectors(drm->fd, res, list, sizeof(list));
		ret = connector && !c ? -EINVAL : -ENOENT;
		if (ret == -EINVAL)
			log_err("connector %s does not exist on %s; the connectors are: %s",
				connector, drm->path, list);
		goto out;
	}
	drm->connector_id = c->connector_id;
	drm_connector_name(c, drm->connector_name, sizeof(drm->connector_name));
	ret = pick_mode(drm, c, mode);
	if (!ret && pick_crtc(drm, res, c)) {
		log_err("%s: no CRTC can drive it", drm->connector_name);
		ret = -ENODEV;
	}
out:
	drmModeFreeConnector(c);
	drmModeFreeResources(res);
	return ret;
}

int drm_connector_list(int fd, char (*names)[32], int max)
{
	drmModeRes *res = drmModeGetResources(fd);
	int n = 0;

	for (int i = 0; res && i < res->count_connectors && n < max; i++) {
		drmModeConnector *c = drmModeGetConnectorCurrent(fd, res->connectors[i]);

		if (c && c->connector_type != DRM_MODE_CONNECTOR_WRITEBACK)
			drm_connector_name(c, names[n++], 32);
		drmModeFreeConnector(c);
	}
	drmModeFreeResources(res);
	return n;
}

/* The same mode, but for its picture aspect ratio: the kernel adds that
 * flag only for a client with DRM_CLIENT_CAP_ATOMIC, which the first output
 * sets after it picked its mode (EDID modes can have one: virtio-gpu gives
 * its 640x480 4:3), so it is no sign of another display. */
static bool same_mode(drmModeModeInfo a, drmModeModeInfo b)
{
	a.flags &= ~(uint32_t)DRM_MODE_FLAG_PIC_AR_MASK;
	b.flags &= ~(uint32_t)DRM_MODE_FLAG_PIC_AR_MASK;
	return memcmp(&a, &b, sizeof(a)) == 0;
}

bool drm_still_connected(const struct drm *drm)
{
	drmModeConnector *c = drmModeGetConnectorCurrent(drm->fd, drm->connector_id);
	bool ok = c && c->connection == DRM_MODE_CONNECTED;

	for (int i = 0; ok && i < c->count_modes; i++)
		if (same_mode(c->modes[i], drm->mode)) {
			drmModeFreeConnector(c);
			return true;
		}
	drmModeFreeConnector(c);
	return false;
}

int drm_ops_init(struct drm *drm, enum drm_api api)
{
	if (api != DRM_API_LEGACY && drm_atomic_init(drm) == 0) {
		drm->ops = &drm_atomic_ops;
		return 0;
	}
	if (api == DRM_API_ATOMIC) {
		log_err("%s: the driver offers no atomic modesetting ([display] kms_api = atomic); "
			"use auto or legacy",
			drm->path);
		return -ENOTSUP;
	}
	drm->ops = &drm_legacy_ops;
	return 0;
}

/* debugfs lists each client of the device with its master flag:
 *   command   pid dev master a   uid      magic */
void drm_master_holder(const struct drm *drm, char *buf, int len)
{
	struct stat st;
	char path[64], line[256], cmd[64], master;
	int pid, dev;
	FILE *f = NULL;

	snprintf(buf, (size_t)len, "another program");
	if (fstat(drm->fd, &st) == 0) {
		snprintf(path, sizeof(path), "/sys/kernel/debug/dri/%u/clients", minor(st.st_rdev));
		f = fopen(path, "r");
	}
	while (f && fgets(line, sizeof(line), f))
		if (sscanf(line, "%63s %d %d %c", cmd, &pid, &dev, &master) == 4 && master == 'y' &&
		    pid != getpid()) {
			snprintf(buf, (size_t)len, "%s (pid %d)", cmd, pid);
			break;
		}
	if (f)
		fclose(f);
}

int drm_acquire_master(struct drm *drm)
{
	int fd;

	if (drmIsMaster(drm->fd) || drmSetMaster(drm->fd) == 0)
		return drm->fd;
	fd = open(drm->path, O_RDWR | O_CLOEXEC);
	if (fd >= 0 && drmIsMaster(fd))
		return fd;
	if (fd >= 0)
		close(fd);
	return -EBUSY;
}

void drm_save(struct drm *drm)
{
	if (!drm->saved_crtc)
		drm->saved_crtc = drmModeGetCrtc(drm->fd, drm->crtc_id);
}

void drm_restore(struct drm *drm)
{
	drmModeCrtc *s = drm->saved_crtc;
	int ret;

	if (!s)
		return;
	/* Legacy SetCrtc works beside atomic and is what the console used.
	 * A CRTC that was off (no mode, or no framebuffer) is turned off. */
	if (s->mode_valid && s->buffer_id)
		ret = drmModeSetCrtc(drm->fd, s->crtc_id, s->buffer_id, s->x, s->y,
				     &drm->connector_id, 1, &s->mode);
	else
		ret = drmModeSetCrtc(drm->fd, s->crtc_id, 0, 0, 0, NULL, 0, NULL);
	if (ret)
		log_warn("%s: could not restore the previous mode: %s", drm->connector_name,
			 strerror(errno));
	else
		log_debug("%s: previous mode restored (framebuffer %u, %s)", drm->connector_name,
			  s->buffer_id, s->mode_valid ? s->mode.name : "off");
	drmModeFreeCrtc(s);
	drm->saved_crtc = NULL;
}
