/* A setting's value as a settings file would write it: what
 * --check-config -v prints beside where each value came from. */
#include "config/settings.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const void *field(const struct options *o, const struct option_def *d)
{
	return (const char *)o + d->offset;
}

/* A number whose 0 is a word ([display] render_scale's auto). */
static void number_text(const struct option_def *d, double v, char *buf, size_t n)
{
	if (d->choices && v == 0)
		snprintf(buf, n, "%s", d->choices[0]);
	else if (isnan(v)) /* [frame] yaw and the like: another setting's */
		snprintf(buf, n, "unset");
	else
		snprintf(buf, n, "%g", v);
}

static void choice_text(const struct options *o, const struct option_def *d, char *buf, size_t n)
{
	int i = 0;

	if (d->kind == K_LEVEL) {
		enum log_level level;

		memcpy(&level, field(o, d), sizeof(level));
		while (i < LOG_LEVELS - 1 && log_levels[i] != level)
			i++;
	} else if (d->size == sizeof(bool)) {
		bool b;

		memcpy(&b, field(o, d), sizeof(b));
		i = b;
	} else {
		memcpy(&i, field(o, d), sizeof(i));
	}
	snprintf(buf, n, "%s", i >= 0 ? d->choices[i] : "?");
}

void option_value_text(const struct options *o, const struct option_def *d, char *buf, size_t n)
{
	const char *s;
	double v;
	int wh[2];
	bool b;

	switch (d->kind) {
	case K_STRING:
		memcpy(&s, field(o, d), sizeof(s));
		snprintf(buf, n, "%s", s ? s : "");
		return;
	case K_FLAG:
		memcpy(&b, field(o, d), sizeof(b));
		snprintf(buf, n, "%s", b ? "true" : "false");
		return;
	case K_SIZE:
	case K_PAIR:
		memcpy(wh, field(o, d), sizeof(wh));
		snprintf(buf, n, d->kind == K_SIZE ? "%dx%d" : "%d,%d", wh[0], wh[1]);
		return;
	case K_CHOICE:
	case K_LEVEL:
		choice_text(o, d, buf, n);
		return;
	case K_INT:
		memcpy(&wh[0], field(o, d), sizeof(int));
		number_text(d, wh[0], buf, n);
		return;
	default: /* K_DOUBLE, K_DEGREES (kept in radians); a float by its size */
		if (d->size == sizeof(float)) {
			float f;

			memcpy(&f, field(o, d), sizeof(f));
			v = f;
		} else {
			memcpy(&v, field(o, d), sizeof(v));
		}
		number_text(d, d->kind == K_DEGREES ? v * 180 / M_PI : v, buf, n);
	}
}
