#include "scene/text/caption.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

int caption_size(const struct caption_config *c)
{
	return (int)((c->size > 0 ? c->size : CAPTION_SIZE_DEFAULT) + 0.5);
}

bool caption_wanted(const struct caption_config *c)
{
	return (c->text && *c->text) || (c->logo && *c->logo);
}

static int hex(char ch)
{
	if (ch >= '0' && ch <= '9')
		return ch - '0';
	if (ch >= 'a' && ch <= 'f')
		return ch - 'a' + 10;
	if (ch >= 'A' && ch <= 'F')
		return ch - 'A' + 10;
	return -1;
}

bool caption_parse_color(const char *text, unsigned char out[4])
{
	size_t n = text ? strlen(text) : 0;

	if ((n != 7 && n != 9) || text[0] != '#')
		return false;
	out[3] = 255;
	for (size_t i = 0; i * 2 + 1 < n; i++) {
		int hi = hex(text[1 + 2 * i]), lo = hex(text[2 + 2 * i]);

		if (hi < 0 || lo < 0)
			return false;
		out[i] = (unsigned char)(hi * 16 + lo);
	}
	return true;
}

/* An INI value is one line: "\n" in it breaks the line, "\\" is a
 * backslash. */
char *caption_text(const struct caption_config *c, const char *name)
{
	const char *s = c->text;
	char *out, *o;

	if (s && !strcmp(s, "auto"))
		s = name;
	if (!s || !*s)
		return NULL;
	out = o = malloc(strlen(s) + 1);
	if (!out)
		return NULL;
	for (; *s; s++) {
		if (s[0] == '\\' && (s[1] == 'n' || s[1] == '\\')) {
			*o++ = s[1] == 'n' ? '\n' : '\\';
			s++;
		} else {
			*o++ = *s;
		}
	}
	*o = '\0';
	return out;
}

/* A triangle wave's smooth cousin, in whole pixels: the caption steps a
 * pixel at a time, a few times an hour, never redrawn for less. Two
 * periods that share no factor, so the path covers the square. */
void caption_place(const struct caption_config *c, int cw, int ch, int width, int height,
		   double seconds, int out[2])
{
	int pad = c->padding, x, y;
	int dx = 0, dy = 0;

	switch (c->position) {
	case CAPTION_BOTTOM_LEFT:
	case CAPTION_TOP_LEFT:
		x = pad;
		break;
	case CAPTION_BOTTOM_RIGHT:
	case CAPTION_TOP_RIGHT:
		x = width - cw - pad;
		break;
	default:
		x = (width - cw) / 2;
	}
	y = c->position == CAPTION_TOP_LEFT || c->position == CAPTION_TOP_RIGHT ||
		    c->position == CAPTION_TOP
		? pad
		: height - ch - pad;
	if (c->drift) {
		dx = (int)lround(CAPTION_DRIFT_PX * sin(2 * M_PI * seconds / (3 * 3600.0)));
		dy = (int)lround(CAPTION_DRIFT_PX * sin(2 * M_PI * seconds / (5 * 3600.0)));
	}
	out[0] = x + dx;
	out[1] = y + dy;
}

void caption_blend(const struct image *cap, int x, int y, struct image *frame)
{
	for (int r = 0; r < cap->height; r++)
		for (int c = 0; c < cap->width; c++) {
			const uint8_t *s = cap->rgba + ((size_t)r * cap->width + c) * 4;
			uint8_t *d;

			if (x + c < 0 || y + r < 0 || x + c >= frame->width ||
			    y + r >= frame->height)
				continue;
			d = frame->rgba + ((size_t)(y + r) * frame->width + x + c) * 4;
			for (int k = 0; k < 3; k++)
				d[k] = (uint8_t)(s[k] + d[k] * (255 - s[3]) / 255);
		}
}
