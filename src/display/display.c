#include "display/display.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int display_read_rgba(struct display *d, struct image *out)
{
	size_t row = (size_t)d->width * 4;
	uint8_t *tmp;
	int ret = image_alloc(out, d->width, d->height);

	if (ret)
		return ret;
	tmp = malloc(row);
	if (!tmp) {
		image_release(out);
		return -ENOMEM;
	}
	d->gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
	d->gl.ReadPixels(0, 0, d->width, d->height, GL_RGBA, GL_UNSIGNED_BYTE, out->rgba);
	/* GL's origin is bottom left; images are stored top first. */
	for (int y = 0; y < d->height / 2; y++) {
		uint8_t *a = out->rgba + (size_t)y * row;
		uint8_t *b = out->rgba + (size_t)(d->height - 1 - y) * row;
		memcpy(tmp, a, row);
		memcpy(a, b, row);
		memcpy(b, tmp, row);
	}
	free(tmp);
	return 0;
}

int display_antialias_samples(int antialias, bool software)
{
	switch (antialias) {
	case DISPLAY_AA_AUTO:
		return software ? 0 : 4;
	case DISPLAY_AA_2:
		return 2;
	case DISPLAY_AA_4:
		return 4;
	case DISPLAY_AA_8:
		return 8;
	default:
		return 0;
	}
}

int display_no_fd(struct display *d)
{
	(void)d;
	return -1;
}

int display_no_dispatch(struct display *d)
{
	(void)d;
	return 0;
}

int display_outputs_parse(const char *list, char (*names)[32], int max, char *err, size_t n)
{
	char seen[KMS_OUTPUTS_MAX][32];
	int count = 0;

	for (const char *p = list; *p;) {
		size_t len = strcspn(p, ", \t");

		if (len == 0) {
			p++;
			continue;
		}
		if (len >= 32) {
			snprintf(err, n, "'%.*s' is too long for a connector's name", (int)len, p);
			return -1;
		}
		if (count == max || count == KMS_OUTPUTS_MAX) {
			snprintf(err, n, "more than %d outputs",
				 max < KMS_OUTPUTS_MAX ? max : KMS_OUTPUTS_MAX);
			return -1;
		}
		memcpy(seen[count], p, len);
		seen[count][len] = '\0';
		for (int i = 0; i < count; i++)
			if (strcmp(seen[i], seen[count]) == 0) {
				snprintf(err, n, "%s is named twice", seen[count]);
				return -1;
			}
		if (names)
			memcpy(names[count], seen[count], 32);
		count++;
		p += len;
	}
	if (!count)
		snprintf(err, n,
			 "no connector named; expected names such as HDMI-A-1, HDMI-A-2, or all");
	return count ? count : -1;
}
