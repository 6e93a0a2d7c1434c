/* vm-grab: see what the virtual board's display shows.
 *
 *   vm-grab [-D /dev/dri/card0] [-c CRTC_ID] [-o OUT.png|OUT.ppm]
 *       Read back the framebuffer an active CRTC scans out right now (the
 *       front buffer of whichever program holds DRM master, e.g. the kiosk)
 *       and write it as PNG or binary PPM (by the name's ending).  Prints one
 *       line: crtc, fb id, size, format, modifier, mode, and "differ=N", the
 *       number of pixels unlike the top-left one (0: a flat screen).  Needs
 *       root (CAP_SYS_ADMIN), not DRM master; the master the kernel hands
 *       to the first opener of an unheld display is dropped at once.
 *
 *   vm-grab -w [-D /dev/dri/card0] [-o OUT.png|OUT.ppm]
 *       Writeback self-test: become master, put a test pattern on the
 *       primary plane, capture vkms's composed output through its writeback
 *       connector, compare it with the pattern (exit 0 when equal) and
 *       optionally write the capture.  vkms in Linux 6.1 cannot clone its
 *       encoders, so the CRTC drives the writeback connector alone (Virtual-1
 *       is detached meanwhile).  Fails while another program holds master.
 *
 * Built by tests/vm/build.sh into the board's initramfs.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <drm_fourcc.h>
#include <zlib.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

struct mapping {
	void *ptr;
	size_t size;
};

static int map_handle(int fd, uint32_t handle, size_t size, struct mapping *m)
{
	struct drm_mode_map_dumb map = { .handle = handle };

	if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &map) != 0) {
		fprintf(stderr, "vm-grab: MAP_DUMB on handle %u: %s\n", handle, strerror(errno));
		return -errno;
	}
	m->ptr = mmap(NULL, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, (off_t)map.offset);
	if (m->ptr == MAP_FAILED) {
		fprintf(stderr, "vm-grab: mmap of %zu bytes: %s\n", size, strerror(errno));
		return -errno;
	}
	m->size = size;
	return 0;
}

/* RGB of one pixel; 0 when the format is one we read. */
static int pixel_rgb(uint32_t format, const uint8_t *p, uint8_t rgb[3])
{
	switch (format) {
	case DRM_FORMAT_XRGB8888:
	case DRM_FORMAT_ARGB8888:
		rgb[0] = p[2]; rgb[1] = p[1]; rgb[2] = p[0];
		return 0;
	case DRM_FORMAT_XBGR8888:
	case DRM_FORMAT_ABGR8888:
		rgb[0] = p[0]; rgb[1] = p[1]; rgb[2] = p[2];
		return 0;
	case DRM_FORMAT_RGB565: {
		unsigned v = (unsigned)p[0] | ((unsigned)p[1] << 8);
		rgb[0] = (uint8_t)(((v >> 11) & 31) * 255 / 31);
		rgb[1] = (uint8_t)(((v >> 5) & 63) * 255 / 63);
		rgb[2] = (uint8_t)((v & 31) * 255 / 31);
		return 0;
	}
	default:
		return -1;
	}
}

static int bytes_per_pixel(uint32_t format)
{
	return format == DRM_FORMAT_RGB565 ? 2 : 4;
}

static int ends_with(const char *s, const char *suffix)
{
	size_t n = strlen(s), m = strlen(suffix);
	return n >= m && strcasecmp(s + n - m, suffix) == 0;
}

static int png_chunk(FILE *f, const char *type, const uint8_t *data, uint32_t len)
{
	uint8_t be[4] = { (uint8_t)(len >> 24), (uint8_t)(len >> 16), (uint8_t)(len >> 8), (uint8_t)len };
	uLong crc = crc32(crc32(0L, Z_NULL, 0), (const Bytef *)type, 4);

	if (len)
		crc = crc32(crc, data, len);
	uint8_t cb[4] = { (uint8_t)(crc >> 24), (uint8_t)(crc >> 16), (uint8_t)(crc >> 8), (uint8_t)crc };
	return fwrite(be, 1, 4, f) == 4 && fwrite(type, 1, 4, f) == 4 && (!len || fwrite(data, 1, len, f) == len) &&
			       fwrite(cb, 1, 4, f) == 4
		       ? 0
		       : -1;
}

/* Write the image as PNG (name ends in .png) or binary PPM; count the
 * pixels that differ from the top-left one into *differ. */
static int write_image(const char *path, const uint8_t *base, uint32_t format, uint32_t w, uint32_t h,
		       uint32_t pitch, size_t *differ)
{
	int png = path && ends_with(path, ".png"), bpp = bytes_per_pixel(format), ret = -1;
	size_t rowlen = (size_t)w * 3 + (png ? 1 : 0), rawlen = rowlen * h;
	uint8_t *raw = malloc(rawlen), *z = NULL, corner[3];
	FILE *f = NULL;

	*differ = 0;
	if (!raw) {
		fprintf(stderr, "vm-grab: out of memory\n");
		return -1;
	}
	if (pixel_rgb(format, base, corner) != 0) {
		fprintf(stderr, "vm-grab: pixel format %.4s not handled\n", (const char *)&format);
		goto out;
	}
	for (uint32_t y = 0; y < h; y++) {
		uint8_t *row = raw + rowlen * y;
		const uint8_t *src = base + (size_t)y * pitch;
		if (png)
			*row++ = 0; /* filter: none */
		for (uint32_t x = 0; x < w; x++) {
			pixel_rgb(format, src + (size_t)x * bpp, row + (size_t)x * 3);
			if (memcmp(row + (size_t)x * 3, corner, 3) != 0)
				(*differ)++;
		}
	}
	if (!path) {
		ret = 0;
		goto out;
	}
	f = fopen(path, "wb");
	if (!f) {
		fprintf(stderr, "vm-grab: %s: %s\n", path, strerror(errno));
		goto out;
	}
	if (png) {
		uLongf zlen = compressBound(rawlen);
		uint8_t ihdr[13] = { (uint8_t)(w >> 24), (uint8_t)(w >> 16), (uint8_t)(w >> 8), (uint8_t)w,
				     (uint8_t)(h >> 24), (uint8_t)(h >> 16), (uint8_t)(h >> 8), (uint8_t)h,
				     8, 2, 0, 0, 0 };
		z = malloc(zlen);
		if (!z || compress2(z, &zlen, raw, rawlen, 6) != Z_OK) {
			fprintf(stderr, "vm-grab: compression failed\n");
			goto out;
		}
		if (fwrite("\x89PNG\r\n\x1a\n", 1, 8, f) != 8 || png_chunk(f, "IHDR", ihdr, 13) ||
		    png_chunk(f, "IDAT", z, (uint32_t)zlen) || png_chunk(f, "IEND", NULL, 0))
			goto out;
	} else if (fprintf(f, "P6\n%u %u\n255\n", w, h) < 0 || fwrite(raw, 1, rawlen, f) != rawlen) {
		goto out;
	}
	ret = 0;
out:
	if (f && fclose(f) != 0 && ret == 0) {
		fprintf(stderr, "vm-grab: %s: %s\n", path, strerror(errno));
		ret = -1;
	}
	free(z);
	free(raw);
	return ret;
}

static int grab(int fd, uint32_t crtc_id, const char *out)
{
	drmModeRes *res = drmModeGetResources(fd);
	drmModeCrtc *crtc = NULL;
	drmModeFB2 *fb = NULL;
	struct mapping m = { 0 };
	int ret = 1;

	if (!res) {
		fprintf(stderr, "vm-grab: not a KMS device: %s\n", strerror(errno));
		return 1;
	}
	for (int i = 0; i < res->count_crtcs && !crtc; i++) {
		if (crtc_id && res->crtcs[i] != crtc_id)
			continue;
		crtc = drmModeGetCrtc(fd, res->crtcs[i]);
		if (crtc && !crtc->buffer_id) {
			drmModeFreeCrtc(crtc);
			crtc = NULL;
		}
	}
	if (!crtc) {
		fprintf(stderr, "vm-grab: no CRTC%s scans out a framebuffer (is the program still running?)\n",
			crtc_id ? " with that id" : "");
		goto out;
	}
	fb = drmModeGetFB2(fd, crtc->buffer_id);
	if (!fb || !fb->handles[0]) {
		fprintf(stderr, "vm-grab: GETFB2 %u gave no handle (run as root): %s\n", crtc->buffer_id,
			strerror(errno));
		goto out;
	}
	if (map_handle(fd, fb->handles[0], (size_t)fb->pitches[0] * fb->height + fb->offsets[0], &m) != 0)
		goto out;
	/* Only a region as large as the mode is on screen. */
	uint32_t w = fb->width, h = fb->height;
	if (crtc->mode_valid) {
		if (crtc->mode.hdisplay < w)
			w = crtc->mode.hdisplay;
		if (crtc->mode.vdisplay < h)
			h = crtc->mode.vdisplay;
	}
	const uint8_t *base = (const uint8_t *)m.ptr + fb->offsets[0] + (size_t)crtc->y * fb->pitches[0] +
			      (size_t)crtc->x * bytes_per_pixel(fb->pixel_format);
	size_t differ = 0;
	ret = write_image(out, base, fb->pixel_format, w, h, fb->pitches[0], &differ) == 0 ? 0 : 1;
	printf("crtc %u fb %u %ux%u %.4s pitch %u modifier 0x%" PRIx64 " mode %s differ=%zu\n", crtc->crtc_id,
	       fb->fb_id, fb->width, fb->height, (const char *)&fb->pixel_format, fb->pitches[0], fb->modifier,
	       crtc->mode_valid ? crtc->mode.name : "-", differ);
out:
	if (m.ptr)
		munmap(m.ptr, m.size);
	if (fb) {
		for (int i = 0; i < 4; i++)
			if (fb->handles[i] && (i == 0 || fb->handles[i] != fb->handles[0]))
				drmCloseBufferHandle(fd, fb->handles[i]);
		drmModeFreeFB2(fb);
	}
	drmModeFreeCrtc(crtc);
	drmModeFreeResources(res);
	return ret;
}

/* ---- writeback self-test */

struct dumb {
	uint32_t handle, pitch, fb_id;
	uint64_t size;
	struct mapping m;
};

static int dumb_create(int fd, uint32_t w, uint32_t h, struct dumb *d)
{
	struct drm_mode_create_dumb c = { .width = w, .height = h, .bpp = 32 };
	uint32_t handles[4] = { 0 }, pitches[4] = { 0 }, offsets[4] = { 0 };

	if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &c) != 0) {
		fprintf(stderr, "vm-grab: CREATE_DUMB %ux%u: %s\n", w, h, strerror(errno));
		return -1;
	}
	d->handle = c.handle;
	d->pitch = c.pitch;
	d->size = c.size;
	handles[0] = c.handle;
	pitches[0] = c.pitch;
	if (drmModeAddFB2(fd, w, h, DRM_FORMAT_XRGB8888, handles, pitches, offsets, &d->fb_id, 0) != 0) {
		fprintf(stderr, "vm-grab: ADDFB2: %s\n", strerror(errno));
		return -1;
	}
	return map_handle(fd, d->handle, (size_t)d->size, &d->m);
}

static uint32_t prop_id(int fd, uint32_t obj, uint32_t type, const char *name)
{
	drmModeObjectProperties *props = drmModeObjectGetProperties(fd, obj, type);
	uint32_t id = 0;

	for (uint32_t i = 0; props && i < props->count_props && !id; i++) {
		drmModePropertyRes *p = drmModeGetProperty(fd, props->props[i]);
		if (p && strcmp(p->name, name) == 0)
			id = p->prop_id;
		drmModeFreeProperty(p);
	}
	drmModeFreeObjectProperties(props);
	if (!id)
		fprintf(stderr, "vm-grab: object %u has no property %s\n", obj, name);
	return id;
}

static int add(drmModeAtomicReq *req, int fd, uint32_t obj, uint32_t type, const char *name, uint64_t v)
{
	uint32_t id = prop_id(fd, obj, type, name);
	return id && drmModeAtomicAddProperty(req, obj, id, v) >= 0 ? 0 : -1;
}

static int writeback_test(int fd, const char *out)
{
	drmModeRes *res = NULL;
	drmModePlaneRes *planes = NULL;
	drmModeConnector *con = NULL, *wb = NULL;
	drmModeAtomicReq *req = NULL;
	struct dumb src = { 0 }, dst = { 0 };
	uint32_t crtc_id = 0, crtc_index = 0, plane_id = 0, blob = 0;
	int32_t fence = -1;
	int ret = 1;

	if (drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1) || drmSetClientCap(fd, DRM_CLIENT_CAP_ATOMIC, 1) ||
	    drmSetClientCap(fd, DRM_CLIENT_CAP_WRITEBACK_CONNECTORS, 1)) {
		fprintf(stderr, "vm-grab: atomic/writeback client caps refused: %s\n", strerror(errno));
		return 1;
	}
	if (drmSetMaster(fd) != 0) {
		fprintf(stderr, "vm-grab: cannot become DRM master (another program holds it): %s\n", strerror(errno));
		return 1;
	}
	res = drmModeGetResources(fd);
	planes = drmModeGetPlaneResources(fd);
	if (!res || !planes)
		goto out;
	for (int i = 0; i < res->count_connectors; i++) {
		drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
		if (c && c->connector_type == DRM_MODE_CONNECTOR_WRITEBACK && !wb)
			wb = c;
		else if (c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0 && !con)
			con = c;
		else
			drmModeFreeConnector(c);
	}
	if (!con || !wb) {
		fprintf(stderr, "vm-grab: need a connected connector and a writeback connector (vkms enable_writeback=1)\n");
		goto out;
	}
	/* The writeback connector's possible CRTCs decide which CRTC we use. */
	drmModeEncoder *enc = drmModeGetEncoder(fd, wb->encoders[0]);
	for (int i = 0; enc && i < res->count_crtcs; i++) {
		if (enc->possible_crtcs & (1u << i)) {
			crtc_id = res->crtcs[i];
			crtc_index = (uint32_t)i;
			break;
		}
	}
	drmModeFreeEncoder(enc);
	for (uint32_t i = 0; i < planes->count_planes && !plane_id; i++) {
		drmModePlane *p = drmModeGetPlane(fd, planes->planes[i]);
		uint32_t tp = prop_id(fd, planes->planes[i], DRM_MODE_OBJECT_PLANE, "type");
		drmModeObjectProperties *props = drmModeObjectGetProperties(fd, planes->planes[i], DRM_MODE_OBJECT_PLANE);
		for (uint32_t k = 0; props && k < props->count_props; k++)
			if (props->props[k] == tp && props->prop_values[k] == DRM_PLANE_TYPE_PRIMARY && p &&
			    (p->possible_crtcs & (1u << crtc_index)))
				plane_id = p->plane_id;
		drmModeFreeObjectProperties(props);
		drmModeFreePlane(p);
	}
	if (!crtc_id || !plane_id) {
		fprintf(stderr, "vm-grab: no CRTC/primary plane for the writeback connector\n");
		goto out;
	}
	drmModeModeInfo mode = con->modes[0];
	for (int i = 0; i < con->count_modes; i++)
		if (con->modes[i].type & DRM_MODE_TYPE_PREFERRED)
			mode = con->modes[i];
	uint32_t w = mode.hdisplay, h = mode.vdisplay;
	if (dumb_create(fd, w, h, &src) || dumb_create(fd, w, h, &dst))
		goto out;
	/* Eight colour bars over a horizontal gradient, opaque. */
	static const uint32_t bars[8] = { 0xffffff, 0xffff00, 0x00ffff, 0x00ff00,
					  0xff00ff, 0xff0000, 0x0000ff, 0x000000 };
	for (uint32_t y = 0; y < h; y++) {
		uint32_t *row = (uint32_t *)((uint8_t *)src.m.ptr + (size_t)y * src.pitch);
		for (uint32_t x = 0; x < w; x++)
			row[x] = y < h / 2 ? bars[x * 8 / w] : (x * 255 / (w - 1)) * 0x010101u;
	}
	memset(dst.m.ptr, 0x55, dst.size);
	if (drmModeCreatePropertyBlob(fd, &mode, sizeof(mode), &blob) != 0)
		goto out;
	req = drmModeAtomicAlloc();
	if (add(req, fd, crtc_id, DRM_MODE_OBJECT_CRTC, "MODE_ID", blob) ||
	    add(req, fd, crtc_id, DRM_MODE_OBJECT_CRTC, "ACTIVE", 1) ||
	    add(req, fd, con->connector_id, DRM_MODE_OBJECT_CONNECTOR, "CRTC_ID", 0) ||
	    add(req, fd, wb->connector_id, DRM_MODE_OBJECT_CONNECTOR, "CRTC_ID", crtc_id) ||
	    add(req, fd, wb->connector_id, DRM_MODE_OBJECT_CONNECTOR, "WRITEBACK_FB_ID", dst.fb_id) ||
	    add(req, fd, wb->connector_id, DRM_MODE_OBJECT_CONNECTOR, "WRITEBACK_OUT_FENCE_PTR",
		(uint64_t)(uintptr_t)&fence) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "FB_ID", src.fb_id) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "CRTC_ID", crtc_id) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "SRC_X", 0) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "SRC_Y", 0) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "SRC_W", (uint64_t)w << 16) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "SRC_H", (uint64_t)h << 16) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "CRTC_X", 0) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "CRTC_Y", 0) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "CRTC_W", w) ||
	    add(req, fd, plane_id, DRM_MODE_OBJECT_PLANE, "CRTC_H", h))
		goto out;
	if (drmModeAtomicCommit(fd, req, DRM_MODE_ATOMIC_ALLOW_MODESET, NULL) != 0) {
		fprintf(stderr, "vm-grab: atomic commit with writeback: %s\n", strerror(errno));
		goto out;
	}
	struct pollfd pfd = { .fd = fence, .events = POLLIN };
	if (fence < 0 || poll(&pfd, 1, 5000) != 1) {
		fprintf(stderr, "vm-grab: writeback fence %d did not signal in 5 s\n", (int)fence);
		goto out;
	}
	size_t bad = 0;
	for (uint32_t y = 0; y < h; y++) {
		const uint32_t *a = (const uint32_t *)((uint8_t *)src.m.ptr + (size_t)y * src.pitch);
		const uint32_t *b = (const uint32_t *)((uint8_t *)dst.m.ptr + (size_t)y * dst.pitch);
		for (uint32_t x = 0; x < w; x++)
			for (int s = 0; s < 24; s += 8) {
				int d = (int)((a[x] >> s) & 0xff) - (int)((b[x] >> s) & 0xff);
				if (d > 1 || d < -1) {
					bad++;
					break;
				}
			}
	}
	printf("writeback %ux%u %s via crtc %u: %zu of %u pixels differ from the pattern\n", w, h, mode.name,
	       crtc_id, bad, w * h);
	size_t differ;
	if (out && write_image(out, dst.m.ptr, DRM_FORMAT_XRGB8888, w, h, dst.pitch, &differ) != 0)
		goto out;
	ret = bad == 0 ? 0 : 1;
out:
	if (fence >= 0)
		close(fence);
	if (req)
		drmModeAtomicFree(req);
	drmModeFreeConnector(con);
	drmModeFreeConnector(wb);
	drmModeFreePlaneResources(planes);
	drmModeFreeResources(res);
	return ret;
}

int main(int argc, char **argv)
{
	const char *dev = "/dev/dri/card0", *out = NULL;
	uint32_t crtc_id = 0;
	int opt, wb = 0;

	while ((opt = getopt(argc, argv, "D:c:o:wh")) != -1) {
		switch (opt) {
		case 'D': dev = optarg; break;
		case 'c': crtc_id = (uint32_t)strtoul(optarg, NULL, 0); break;
		case 'o': out = optarg; break;
		case 'w': wb = 1; break;
		default:
			fprintf(stderr, "usage: vm-grab [-D DEV] [-c CRTC_ID] [-o OUT.png|.ppm]   read back the scanout\n"
					"       vm-grab -w [-D DEV] [-o OUT.png|.ppm]                writeback self-test\n");
			return opt == 'h' ? 0 : 2;
		}
	}
	int fd = open(dev, O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		fprintf(stderr, "vm-grab: %s: %s\n", dev, strerror(errno));
		return 1;
	}
	/* The first to open a primary node with no master becomes master: a
	 * readback must not be, or a program starting now could not set its
	 * mode ("failed to set mode: Permission denied").  Let go at once. */
	if (!wb && drmIsMaster(fd))
		drmDropMaster(fd);
	int ret = wb ? writeback_test(fd, out) : grab(fd, crtc_id, out);
	close(fd);
	return ret;
}
