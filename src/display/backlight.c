#include "display/backlight.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* bl_power takes the framebuffer blank levels: 0 unblank, 4 powerdown. */
#define BL_POWER_ON   "0"
#define BL_POWER_DOWN "4"

struct backlight {
	char dir[512];
};

static int write_value(const struct backlight *b, const char *file, const char *value)
{
	char path[600];
	int fd, ret = 0;

	snprintf(path, sizeof(path), "%s/%s", b->dir, file);
	fd = open(path, O_WRONLY | O_CLOEXEC);
	if (fd < 0)
		return -errno;
	if (write(fd, value, strlen(value)) < 0)
		ret = -errno;
	close(fd);
	return ret;
}

static int first_device(const char *class_dir, char *name, size_t size)
{
	DIR *d = opendir(class_dir);
	struct dirent *e;
	int ret = -ENOENT;

	if (!d)
		return -errno;
	while ((e = readdir(d)))
		if (e->d_name[0] != '.') {
			snprintf(name, size, "%s", e->d_name);
			ret = 0;
			break;
		}
	closedir(d);
	return ret;
}

struct backlight *backlight_new(const char *class_dir)
{
	struct backlight *b;
	char name[256];

	if (first_device(class_dir, name, sizeof(name))) {
		log_info("backlight: none under %s (an HDMI screen sleeps through KMS alone)",
			 class_dir);
		return NULL;
	}
	b = calloc(1, sizeof(*b));
	if (!b)
		return NULL;
	snprintf(b->dir, sizeof(b->dir), "%s/%s", class_dir, name);
	log_info("backlight: %s", b->dir);
	return b;
}

void backlight_free(struct backlight *b)
{
	free(b);
}

int backlight_power(struct backlight *b, bool on)
{
	int ret = write_value(b, "bl_power", on ? BL_POWER_ON : BL_POWER_DOWN);

	if (ret)
		log_err("backlight %s: cannot switch it %s: %s", b->dir, on ? "on" : "off",
			strerror(-ret));
	return ret;
}
