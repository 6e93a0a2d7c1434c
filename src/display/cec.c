#include "display/cec.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/cec-funcs.h>
#include <linux/cec.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

struct cec {
	struct cec_io io;
	int fd; /* the device's, or -1 with a fake io */
	char name[64];
	__u8 log_addr;
	__u16 phys_addr;
	bool said_silent; /* the TV's silence is in the journal */
};

static int device_ioctl(void *ctx, unsigned long request, void *arg)
{
	return ioctl(*(int *)ctx, request, arg);
}

/* A playback device, as a media player is: TVs accept Image View On and
 * Active Source from one. An address the adapter already has (another
 * program or the kernel's configuration) is kept. */
static int claim(struct cec *c)
{
	struct cec_log_addrs la = {0};

	if (c->io.ioctl(c->io.ctx, CEC_ADAP_G_LOG_ADDRS, &la))
		return -errno;
	if (la.num_log_addrs && la.log_addr[0] != CEC_LOG_ADDR_INVALID) {
		c->log_addr = la.log_addr[0];
		return 0;
	}
	memset(&la, 0, sizeof(la));
	la.cec_version = CEC_OP_CEC_VERSION_1_4;
	la.vendor_id = CEC_VENDOR_ID_NONE;
	la.num_log_addrs = 1;
	la.log_addr_type[0] = CEC_LOG_ADDR_TYPE_PLAYBACK;
	la.primary_device_type[0] = CEC_OP_PRIM_DEVTYPE_PLAYBACK;
	la.all_device_types[0] = CEC_OP_ALL_DEVTYPE_PLAYBACK;
	snprintf(la.osd_name, sizeof(la.osd_name), "matcap-kiosk");
	if (c->io.ioctl(c->io.ctx, CEC_ADAP_S_LOG_ADDRS, &la))
		return -errno;
	if (la.log_addr[0] == CEC_LOG_ADDR_INVALID)
		return -EADDRNOTAVAIL;
	c->log_addr = la.log_addr[0];
	return 0;
}

struct cec *cec_new_io(const struct cec_io *io, const char *name)
{
	struct cec *c = calloc(1, sizeof(*c));
	int ret;

	if (!c)
		return NULL;
	c->io = *io;
	c->fd = -1;
	snprintf(c->name, sizeof(c->name), "%s", name);
	ret = claim(c);
	if (ret) {
		log_err("cec %s: cannot claim a logical address: %s; the TV's power is left "
			"alone",
			name, strerror(-ret));
		goto fail;
	}
	if (c->io.ioctl(c->io.ctx, CEC_ADAP_G_PHYS_ADDR, &c->phys_addr))
		c->phys_addr = CEC_PHYS_ADDR_INVALID;
	log_info("cec %s: logical address %u, physical address %x.%x.%x.%x", name, c->log_addr,
		 c->phys_addr >> 12, (c->phys_addr >> 8) & 15, (c->phys_addr >> 4) & 15,
		 c->phys_addr & 15);
	return c;
fail:
	free(c);
	return NULL;
}

struct cec *cec_new(const char *path)
{
	int fd = open(path, O_RDWR | O_CLOEXEC);
	struct cec_io io = {.ioctl = device_ioctl};
	struct cec *c;

	if (fd < 0) {
		log_err("cec %s: cannot open: %s; the TV's power is left alone", path,
			strerror(errno));
		return NULL;
	}
	/* The fd lives in the struct; the io's context points at it. */
	io.ctx = &fd;
	c = cec_new_io(&io, path);
	if (!c) {
		close(fd);
		return NULL;
	}
	c->fd = fd;
	c->io.ctx = &c->fd;
	return c;
}

void cec_free(struct cec *c)
{
	if (!c)
		return;
	if (c->fd >= 0)
		close(c->fd);
	free(c);
}

/* 0 when the message was acknowledged. */
static int transmit(struct cec *c, struct cec_msg *msg)
{
	if (c->io.ioctl(c->io.ctx, CEC_TRANSMIT, msg))
		return -errno;
	return msg->tx_status & CEC_TX_STATUS_OK ? 0 : -EHOSTUNREACH;
}

int cec_power(struct cec *c, bool on)
{
	struct cec_msg msg;
	int ret;

	cec_msg_init(&msg, c->log_addr, CEC_LOG_ADDR_TV);
	if (on)
		cec_msg_image_view_on(&msg);
	else
		cec_msg_standby(&msg);
	ret = transmit(c, &msg);
	if (!ret && on && c->phys_addr != CEC_PHYS_ADDR_INVALID) {
		cec_msg_init(&msg, c->log_addr, CEC_LOG_ADDR_BROADCAST);
		cec_msg_active_source(&msg, c->phys_addr);
		ret = transmit(c, &msg);
	}
	if (ret && !c->said_silent)
		log_warn("cec %s: the TV did not take %s (%s); it is tried again at the next "
			 "change, and this is said once",
			 c->name, on ? "Image View On" : "Standby",
			 ret == -EHOSTUNREACH ? "no acknowledgement" : strerror(-ret));
	else if (!ret && c->said_silent)
		log_info("cec %s: the TV answers again", c->name);
	c->said_silent = ret != 0;
	return ret;
}
