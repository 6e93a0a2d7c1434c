/*
 * vm-hold: put a known picture on the display and keep it there, for tests
 * of programs that must give the screen back as they found it, or wait
 * for another program to let go of it.
 *
 *   vm-hold [-D DEV] [-m WxH] [-k]
 *
 * Sets a colour-bar framebuffer at mode WxH (default: the preferred mode)
 * on the first connected connector with legacy SetCrtc, prints
 *   hold crtc ID fb ID mode NAME
 * and sleeps until it is killed (SIGTERM).  Without -k it drops DRM master
 * at once, so another program can take the display while the framebuffer
 * (and what the CRTC showed) stays; with -k it keeps master, like a desktop
 * that holds the display.
 *
 * Built by tests/vm/build.sh into the board's initramfs.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include <drm_fourcc.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

static int die(const char *what)
{
	fprintf(stderr, "vm-hold: %s: %s\n", what, strerror(errno));
	return 1;
}

static drmModeConnector *first_connected(int fd, const drmModeRes *res)
{
	for (int i = 0; i < res->count_connectors; i++) {
		drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
		if (c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0)
			return c;
		drmModeFreeConnector(c);
	}
	return NULL;
}

static const drmModeModeInfo *pick_mode(const drmModeConnector *c, int w, int h)
{
	const drmModeModeInfo *m = &c->modes[0];
	for (int i = 0; i < c->count_modes; i++) {
		if (w && c->modes[i].hdisplay == w && c->modes[i].vdisplay == h)
			return &c->modes[i];
		if (!w && (c->modes[i].type & DRM_MODE_TYPE_PREFERRED))
			m = &c->modes[i];
	}
	return w ? NULL : m;
}

static uint32_t crtc_for(int fd, const drmModeRes *res, const drmModeConnector *c)
{
	for (int e = 0; e < c->count_encoders; e++) {
		drmModeEncoder *enc = drmModeGetEncoder(fd, c->encoders[e]);
		for (int i = 0; enc && i < res->count_crtcs; i++)
			if (enc->possible_crtcs & (1u << i)) {
				drmModeFreeEncoder(enc);
				return res->crtcs[i];
			}
		drmModeFreeEncoder(enc);
	}
	return 0;
}

/* Eight vertical colour bars, opaque. */
static int make_fb(int fd, uint32_t w, uint32_t h, uint32_t *fb_id)
{
	static const uint32_t bars[8] = { 0xffffff, 0xffff00, 0x00ffff, 0x00ff00,
					  0xff00ff, 0xff0000, 0x0000ff, 0x000000 };
	struct drm_mode_create_dumb c = { .width = w, .height = h, .bpp = 32 };
	struct drm_mode_map_dumb map = { 0 };
	uint32_t handles[4] = { 0 }, pitches[4] = { 0 }, offsets[4] = { 0 };
	uint8_t *px;

	if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &c))
		return die("CREATE_DUMB");
	handles[0] = c.handle;
	pitches[0] = c.pitch;
	if (drmModeAddFB2(fd, w, h, DRM_FORMAT_XRGB8888, handles, pitches, offsets, fb_id, 0))
		return die("ADDFB2");
	map.handle = c.handle;
	if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &map))
		return die("MAP_DUMB");
	px = mmap(NULL, c.size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, (off_t)map.offset);
	if (px == MAP_FAILED)
		return die("mmap");
	for (uint32_t y = 0; y < h; y++)
		for (uint32_t x = 0; x < w; x++)
			((uint32_t *)(px + (size_t)y * c.pitch))[x] = bars[x * 8 / w];
	munmap(px, c.size);
	return 0;
}

int main(int argc, char **argv)
{
	const char *dev = "/dev/dri/card0";
	int opt, keep = 0, w = 0, h = 0;

	while ((opt = getopt(argc, argv, "D:m:kh")) != -1) {
		switch (opt) {
		case 'D': dev = optarg; break;
		case 'm':
			if (sscanf(optarg, "%dx%d", &w, &h) != 2) {
				fprintf(stderr, "vm-hold: -m wants WIDTHxHEIGHT\n");
				return 2;
			}
			break;
		case 'k': keep = 1; break;
		default:
			fprintf(stderr, "usage: vm-hold [-D DEV] [-m WxH] [-k]\n");
			return opt == 'h' ? 0 : 2;
		}
	}
	int fd = open(dev, O_RDWR | O_CLOEXEC);
	if (fd < 0)
		return die(dev);
	if (!drmIsMaster(fd) && drmSetMaster(fd))
		return die("another program holds DRM master");
	drmModeRes *res = drmModeGetResources(fd);
	drmModeConnector *con = res ? first_connected(fd, res) : NULL;
	if (!con) {
		fprintf(stderr, "vm-hold: no connected connector on %s\n", dev);
		return 1;
	}
	const drmModeModeInfo *mode = pick_mode(con, w, h);
	uint32_t crtc = crtc_for(fd, res, con), fb = 0;
	if (!mode || !crtc) {
		fprintf(stderr, "vm-hold: no mode %dx%d or no CRTC\n", w, h);
		return 1;
	}
	if (make_fb(fd, mode->hdisplay, mode->vdisplay, &fb))
		return 1;
	drmModeModeInfo m = *mode;
	if (drmModeSetCrtc(fd, crtc, fb, 0, 0, &con->connector_id, 1, &m))
		return die("SetCrtc");
	if (!keep && drmDropMaster(fd))
		return die("DropMaster");
	printf("hold crtc %u fb %u mode %s master %s\n", crtc, fb, m.name, keep ? "kept" : "dropped");
	fflush(stdout);
	for (;;)
		pause();
}
