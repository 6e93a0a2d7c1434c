#include "state/view.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RAD (M_PI / 180.0)

void frame_config_defaults(struct frame_config *f)
{
	memset(f, 0, sizeof(*f));
	f->yaw = f->pitch = NAN;
	f->zoom = 1.0;
	f->yaw_min = f->yaw_max = f->pitch_min = f->pitch_max = NAN;
}

/* The turn that takes the model's up axis to +y (right-handed, the
 * shortest one; -y: half a turn about x). */
static struct quat up_turn(enum frame_up up)
{
	switch (up) {
	case FRAME_UP_NEG_Y:
		return quat_from_axis_angle(1, 0, 0, M_PI);
	case FRAME_UP_Z:
		return quat_from_axis_angle(1, 0, 0, -M_PI / 2);
	case FRAME_UP_NEG_Z:
		return quat_from_axis_angle(1, 0, 0, M_PI / 2);
	case FRAME_UP_X:
		return quat_from_axis_angle(0, 0, 1, M_PI / 2);
	case FRAME_UP_NEG_X:
		return quat_from_axis_angle(0, 0, 1, -M_PI / 2);
	default:
		return (struct quat){1, 0, 0, 0};
	}
}

int frame_base(const struct frame_config *f, struct quat *out, char *err, size_t n)
{
	struct quat q = up_turn(f->up);
	double r, p, y;
	char tail;

	if (f->orientation && *f->orientation) {
		if (sscanf(f->orientation, "%lf %lf %lf %c", &r, &p, &y, &tail) != 3 ||
		    !isfinite(r) || !isfinite(p) || !isfinite(y)) {
			snprintf(err, n, "expected three numbers ROLL PITCH YAW in degrees");
			return -1;
		}
		/* Roll about z, then pitch about x, then yaw about y, after up. */
		q = quat_multiply(quat_from_axis_angle(0, 0, 1, r * RAD), q);
		q = quat_multiply(quat_from_axis_angle(1, 0, 0, p * RAD), q);
		q = quat_multiply(quat_from_axis_angle(0, 1, 0, y * RAD), q);
	}
	*out = quat_normalize(q);
	return 0;
}

/* One of a stop's last words, KEY=VALUE at `at`: its value (to the end
 * of what is left of the stop: a clip's or a variant's name may have
 * spaces) into dst, and the word cut off the stop. */
static int stop_word(char *at, const char *key, const char *what, char *dst, char *err, size_t n)
{
	size_t len;

	*at = '\0';
	at += strlen(key);
	len = strlen(at);
	while (len && (at[len - 1] == ' ' || at[len - 1] == '\t'))
		len--;
	if (dst[0] || !len || len >= FRAME_STOP_CLIP || at[0] == ' ' || at[0] == '\t') {
		snprintf(err, n, "a stop's %s names %s of up to %d bytes, once, after its text",
			 key, what, FRAME_STOP_CLIP - 1);
		return -1;
	}
	memcpy(dst, at, len);
	return 0;
}

/* The last `key` in s, or NULL. */
static char *last_of(char *s, const char *key)
{
	char *last = NULL;

	for (char *at = strstr(s, key); at; at = strstr(at + 1, key))
		last = at;
	return last;
}

/* A stop's optional last words, animation=CLIP, variant=NAME and
 * hotspot=NAME (after its text, if any, in any order), cut off s into
 * st: the latest one first. */
static int stop_clip(char *s, struct frame_stop *st, char *err, size_t n)
{
	static const char *const words[3] = {"animation=", "variant=", "hotspot="};
	static const char *const what[3] = {"a clip (its name, an index or all)",
					    "a variant of the model (its name)",
					    "a hotspot of the model (its [hotspot.NAME]'s NAME)"};
	char *q = strrchr(s, '"'), *into[3] = {st->animation, st->variant, st->hotspot};

	/* One more pass than words: a word given twice is said as such. */
	for (int i = 0; i < 4; i++) {
		char *at = NULL;
		int k = -1;

		for (int w = 0; w < 3; w++) {
			char *f = last_of(q ? q : s, words[w]);

			if (f && (!at || f > at))
				at = f, k = w;
		}
		if (at && stop_word(at, words[k], what[k], into[k], err, n))
			return -1;
	}
	return 0;
}

/* One stop: three numbers, an optional quoted text and an optional clip. */
static int stop_parse(char *s, struct frame_stop *st, char *err, size_t n)
{
	char *q, *end;
	int used = 0;
	double y, p, z;

	memset(st, 0, sizeof(*st));
	if (stop_clip(s, st, err, n))
		return -1;
	q = strchr(s, '"');
	if (q) {
		end = strrchr(q + 1, '"');
		if (!end) {
			snprintf(err, n, "a stop's text has no closing quote");
			return -1;
		}
		if ((size_t)(end - q - 1) >= FRAME_STOP_TEXT ||
		    strspn(end + 1, " \t") != strlen(end + 1)) {
			snprintf(err, n,
				 "a stop's text is longer than %d bytes, or text follows it",
				 FRAME_STOP_TEXT - 1);
			return -1;
		}
		memcpy(st->text, q + 1, (size_t)(end - q - 1));
		*q = '\0';
	}
	if (sscanf(s, "%lf %lf %lf %n", &y, &p, &z, &used) != 3 || s[used] || !isfinite(y) ||
	    !isfinite(p) || !(z > 0 && z <= 20)) {
		snprintf(err, n,
			 "each stop is YAW PITCH ZOOM \"text\" animation=CLIP variant=NAME "
			 "hotspot=NAME (degrees, degrees, a zoom above 0 up to 20; the text, "
			 "clip, variant and hotspot optional)");
		return -1;
	}
	st->yaw = y * RAD;
	st->pitch = p * RAD;
	st->zoom = z;
	return 0;
}

int frame_stops_parse(const char *text, struct frame_stop *out, int max, char *err, size_t n)
{
	char *copy = text ? strdup(text) : NULL, *save = NULL;
	int count = 0, ret = 0;

	if (!text || !*text)
		return 0;
	if (!copy) {
		snprintf(err, n, "out of memory");
		return -1;
	}
	for (char *t = strtok_r(copy, ";", &save); t && !ret; t = strtok_r(NULL, ";", &save)) {
		if (strspn(t, " \t") == strlen(t))
			continue;
		if (count == max) {
			snprintf(err, n, "more than %d stops", max);
			ret = -1;
		} else {
			ret = stop_parse(t, &out[count], err, n);
			count += ret ? 0 : 1;
		}
	}
	free(copy);
	return ret ? -1 : count;
}

double frame_start_yaw(const struct frame_config *f, double fallback)
{
	return isnan(f->yaw) ? fallback : f->yaw;
}

double frame_start_pitch(const struct frame_config *f, double fallback)
{
	return isnan(f->pitch) ? fallback : f->pitch;
}

static int limits(double lo, double hi, const char *what, bool *on, double *a, double *b, char *err,
		  size_t n)
{
	*on = !isnan(lo) || !isnan(hi);
	*a = isnan(lo) ? -1e9 : lo * RAD;
	*b = isnan(hi) ? 1e9 : hi * RAD;
	if (*a <= *b)
		return 0;
	snprintf(err, n, "%s_min is above %s_max", what, what);
	return -1;
}

int frame_to_app(const struct frame_config *f, double yaw_deg, double pitch_deg,
		 struct app_frame *out, char *err, size_t n)
{
	memset(out, 0, sizeof(*out));
	out->yaw0 = frame_start_yaw(f, yaw_deg) * RAD;
	out->pitch0 = frame_start_pitch(f, pitch_deg) * RAD;
	out->zoom0 = f->zoom > 0 ? f->zoom : 1.0;
	out->zoom_min = f->zoom_min > 0 ? f->zoom_min : 0.5;
	out->zoom_max = f->zoom_max > 0 ? f->zoom_max : 4.0;
	out->direction = f->attract_direction ? -1.0 : 1.0;
	out->sway = f->attract_sway * RAD;
	out->stop_seconds = f->stop_seconds;
	if (limits(f->yaw_min, f->yaw_max, "yaw", &out->yaw_limited, &out->yaw_min, &out->yaw_max,
		   err, n) ||
	    limits(f->pitch_min, f->pitch_max, "pitch", &out->pitch_limited, &out->pitch_min,
		   &out->pitch_max, err, n))
		return -1;
	if (out->zoom_min > out->zoom_max) {
		snprintf(err, n, "zoom_min is above zoom_max");
		return -1;
	}
	out->stop_count = frame_stops_parse(f->stops, out->stops, FRAME_STOPS, err, n);
	return out->stop_count < 0 ? -1 : 0;
}

double ease_at(double p0, double v0, double p1, double v1, double d, double t, double *speed)
{
	double s, h00, h10, h01, h11;

	if (!(d > 0) || t >= d) {
		*speed = v1;
		return p1;
	}
	if (t <= 0) {
		*speed = v0;
		return p0;
	}
	s = t / d;
	/* Cubic Hermite: position and speed at both ends. */
	h00 = 2 * s * s * s - 3 * s * s + 1;
	h10 = s * s * s - 2 * s * s + s;
	h01 = -2 * s * s * s + 3 * s * s;
	h11 = s * s * s - s * s;
	*speed = ((6 * s * s - 6 * s) * p0 + (3 * s * s - 4 * s + 1) * d * v0 +
		  (-6 * s * s + 6 * s) * p1 + (3 * s * s - 2 * s) * d * v1) /
		 d;
	return h00 * p0 + h10 * d * v0 + h01 * p1 + h11 * d * v1;
}

static double clampd(double x, double lo, double hi)
{
	return x < lo ? lo : x > hi ? hi : x;
}

void attract_path_make(struct attract_path *p, const struct app_frame *f, double home, double speed)
{
	memset(p, 0, sizeof(*p));
	p->home = home;
	if (f->sway > 0) {
		/* A swing about home, no further than the limits allow. */
		p->centre = home;
		p->amplitude = f->sway;
		if (f->yaw_limited)
			p->amplitude =
			    fmin(p->amplitude, fmin(home - f->yaw_min, f->yaw_max - home));
	} else if (f->yaw_limited) {
		/* Turntable between the limits: back and forth. */
		p->centre = (f->yaw_min + f->yaw_max) / 2;
		p->amplitude = (f->yaw_max - f->yaw_min) / 2;
	} else {
		p->velocity = speed * f->direction;
		return;
	}
	if (!(p->amplitude > 1e-9)) {
		p->amplitude = 0;
		return;
	}
	p->omega = speed / p->amplitude * f->direction;
	p->phase = asin(clampd((home - p->centre) / p->amplitude, -1, 1));
}

double attract_path_at(const struct attract_path *p, double t, double *speed)
{
	if (p->amplitude == 0) {
		*speed = p->velocity;
		return p->home + p->velocity * t;
	}
	*speed = p->amplitude * p->omega * cos(p->phase + p->omega * t);
	return p->centre + p->amplitude * sin(p->phase + p->omega * t);
}

int app_frame_hotspot_step(const struct app_frame *f, int shown, bool select)
{
	int n = f->stop_count;

	if (f->hotspot_count > 0) /* a hotspot is what a visitor's press is for */
		return FRAME_STOPS + hotspot_next(f->hotspot_count, shown - FRAME_STOPS);
	if (!select || n < 1)
		return -1;
	return shown < 0 || shown >= n ? 0 : (shown + 1) % n;
}
