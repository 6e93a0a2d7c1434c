/* Keyframe samplers and the clip clock: the time-dependent half of
 * anim.h, pure arithmetic. */
#include "scene/anim/anim.h"

#include <math.h>
#include <string.h>

void anim_quat_slerp(const float a[4], const float b[4], double u, float out[4])
{
	double d = 0, bb[4], wa, wb, len = 0;

	for (int i = 0; i < 4; i++)
		d += (double)a[i] * b[i];
	for (int i = 0; i < 4; i++) // the shorter way: b or -b, the nearer
		bb[i] = d < 0 ? -(double)b[i] : b[i];
	d = fabs(d);
	if (d > 0.9995) { // nearly equal: sin(theta) vanishes, lerp is exact enough
		wa = 1 - u;
		wb = u;
	} else {
		double theta = acos(d), st = sin(theta);

		wa = sin((1 - u) * theta) / st;
		wb = sin(u * theta) / st;
	}
	double r[4];
	for (int i = 0; i < 4; i++) {
		r[i] = wa * a[i] + wb * bb[i];
		len += r[i] * r[i];
	}
	len = len > 0 ? sqrt(len) : 1;
	for (int i = 0; i < 4; i++)
		out[i] = (float)(r[i] / len);
}

const char *anim_sampler_check(const struct anim_sampler *s)
{
	if (s->count == 0)
		return "no keys (expected at least one input time)";
	if (s->width <= 0)
		return "no values per key";
	for (size_t k = 0; k < s->count; k++) {
		if (!isfinite(s->input[k]) || s->input[k] < 0)
			return "an input time is negative or not finite";
		if (k > 0 && !(s->input[k] > s->input[k - 1]))
			return "input times do not increase strictly";
	}
	size_t n = s->count * (size_t)s->width * (s->interp == ANIM_CUBICSPLINE ? 3 : 1);
	for (size_t i = 0; i < n; i++)
		if (!isfinite(s->output[i]))
			return "an output value is not finite";
	return NULL;
}

/* The value (not tangent) of key k. */
static const float *key_value(const struct anim_sampler *s, size_t k)
{
	size_t w = (size_t)s->width;

	return s->interp == ANIM_CUBICSPLINE ? s->output + (k * 3 + 1) * w : s->output + k * w;
}

/* The last key whose time is at or before t (t inside the keys' span). */
static size_t key_before(const struct anim_sampler *s, double t)
{
	size_t lo = 0, hi = s->count - 1;

	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (s->input[mid] <= t)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

static void normalize4(float q[4])
{
	double len = 0;

	for (int i = 0; i < 4; i++)
		len += (double)q[i] * q[i];
	if (len <= 0)
		return;
	len = sqrt(len);
	for (int i = 0; i < 4; i++)
		q[i] = (float)(q[i] / len);
}

/* glTF's cubic Hermite spline between keys k and k+1 (spec, appendix C). */
static void cubic(const struct anim_sampler *s, size_t k, double u, double td, float *out)
{
	size_t w = (size_t)s->width;
	const float *v0 = s->output + (k * 3 + 1) * w, *b0 = s->output + (k * 3 + 2) * w;
	const float *a1 = s->output + ((k + 1) * 3) * w, *v1 = s->output + ((k + 1) * 3 + 1) * w;
	double u2 = u * u, u3 = u2 * u;
	double h00 = 2 * u3 - 3 * u2 + 1, h10 = td * (u3 - 2 * u2 + u);
	double h01 = -2 * u3 + 3 * u2, h11 = td * (u3 - u2);

	for (size_t i = 0; i < w; i++)
		out[i] = (float)(h00 * v0[i] + h10 * b0[i] + h01 * v1[i] + h11 * a1[i]);
}

void anim_sampler_eval(const struct anim_sampler *s, bool rotation, double t, float *out)
{
	size_t w = (size_t)s->width;

	if (s->count == 1 || t <= s->input[0]) {
		memcpy(out, key_value(s, 0), w * sizeof(float));
		return;
	}
	if (t >= s->input[s->count - 1]) {
		memcpy(out, key_value(s, s->count - 1), w * sizeof(float));
		return;
	}
	size_t k = key_before(s, t);
	double td = (double)s->input[k + 1] - s->input[k];
	double u = (t - s->input[k]) / td;
	const float *a = key_value(s, k), *b = key_value(s, k + 1);

	switch (s->interp) {
	case ANIM_STEP:
		memcpy(out, a, w * sizeof(float));
		break;
	case ANIM_LINEAR:
		if (rotation && w == 4) {
			anim_quat_slerp(a, b, u, out);
			break;
		}
		for (size_t i = 0; i < w; i++)
			out[i] = (float)(a[i] + u * ((double)b[i] - a[i]));
		break;
	case ANIM_CUBICSPLINE:
		cubic(s, k, u, td, out);
		if (rotation && w == 4)
			normalize4(out);
		break;
	}
}

static uint64_t period_ns(const struct anim_clock *c)
{
	return c->loop == ANIM_PINGPONG ? c->duration_ns * 2 : c->duration_ns;
}

void anim_clock_init(struct anim_clock *c, double duration, enum anim_loop loop, double speed)
{
	memset(c, 0, sizeof(*c));
	c->duration_ns = duration > 0 && isfinite(duration) ? (uint64_t)llround(duration * 1e9) : 0;
	c->loop = loop;
	c->speed = speed > 0 && isfinite(speed) ? speed : 1.0;
}

/* Moves the phase on by n nanoseconds of clip time, wrapped. */
static void phase_add(struct anim_clock *c, uint64_t n)
{
	uint64_t p = period_ns(c);

	if (p == 0)
		return;
	if (c->loop == ANIM_ONCE) {
		c->phase_ns = n >= p - c->phase_ns ? p : c->phase_ns + n;
		return;
	}
	c->phase_ns = (c->phase_ns + n % p) % p;
}

void anim_clock_advance(struct anim_clock *c, uint64_t wall_ns)
{
	double scaled = (double)wall_ns * c->speed + c->carry;
	double whole = floor(scaled);

	c->carry = scaled - whole;
	if (whole >= 18446744073709549568.0) // past uint64: beyond any loop anyway
		whole = 18446744073709549568.0;
	phase_add(c, (uint64_t)whole);
}

void anim_clock_seek(struct anim_clock *c, double seconds)
{
	c->phase_ns = 0;
	c->carry = 0;
	if (!(seconds > 0))
		return;
	// Whole seconds and the fraction apart, so a --time of months keeps
	// its nanoseconds.
	double whole = floor(seconds);
	uint64_t p = period_ns(c);

	if (p == 0)
		return;
	// A million seconds a step: exact in uint64 nanoseconds at any speed
	// the settings allow; the options cap --time below 31 years.
	for (int i = 0; i < 1000 && whole > 0; i++) {
		double chunk = whole > 1e6 ? 1e6 : whole;

		anim_clock_advance(c, (uint64_t)(chunk * 1e9));
		whole -= chunk;
	}
	anim_clock_advance(c, (uint64_t)llround((seconds - floor(seconds)) * 1e9));
}

double anim_clock_time(const struct anim_clock *c)
{
	uint64_t t = c->phase_ns;

	if (c->loop == ANIM_PINGPONG && t > c->duration_ns)
		t = 2 * c->duration_ns - t;
	return (double)t / 1e9;
}

bool anim_clock_moving(const struct anim_clock *c)
{
	return c->duration_ns > 0 && !(c->loop == ANIM_ONCE && c->phase_ns >= c->duration_ns);
}
