/* Analytic matcaps. Every material is lit by one shared studio rig (key
 * light up-left-front, fill from the right, a kicker from up-right-behind,
 * three softboxes), so switching matcaps in the kiosk changes the material,
 * not where the light comes from.
 *
 * Determinism: plain double arithmetic, fixed sample pattern, no random
 * numbers, no time. The build uses -std=c11, which turns off FMA contraction
 * in GCC, so the bytes do not depend on whether the CPU has FMA. */
#include "render/bake.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* 4x4 samples per pixel at the centres of a regular grid of strata: enough
 * for a smooth rim and crisp highlights, and needs no random numbers. */
#define SS 4

struct vec3 {
	double x, y, z;
};

/* A rectangular light panel seen from the sphere's centre: direction c, and
 * u, w spanning the panel's plane; half sizes in that plane at distance 1. */
struct softbox {
	struct vec3 c, u, w;
	double half_u, half_w;
	struct vec3 power;
};

#define SOFTBOXES 3

/* Everything the shaders share, derived once per bake on the stack. */
struct scene {
	struct vec3 key, fill, kick; /* directions towards the lights */
	struct vec3 key_h, kick_h;   /* Blinn half vectors with v = +z */
	struct softbox box[SOFTBOXES];
};

typedef struct vec3 (*shade_fn)(const struct scene *s, struct vec3 n);

static struct vec3 v3(double x, double y, double z)
{
	struct vec3 r = {x, y, z};
	return r;
}

static struct vec3 gray(double g)
{
	return v3(g, g, g);
}

static struct vec3 add(struct vec3 a, struct vec3 b)
{
	return v3(a.x + b.x, a.y + b.y, a.z + b.z);
}

static struct vec3 scale(struct vec3 a, double s)
{
	return v3(a.x * s, a.y * s, a.z * s);
}

static struct vec3 mul(struct vec3 a, struct vec3 b)
{
	return v3(a.x * b.x, a.y * b.y, a.z * b.z);
}

static double dot(struct vec3 a, struct vec3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static struct vec3 cross(struct vec3 a, struct vec3 b)
{
	return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static struct vec3 normalize(struct vec3 a)
{
	double len = sqrt(dot(a, a));

	return len > 0.0 ? scale(a, 1.0 / len) : a;
}

static struct vec3 mix(struct vec3 a, struct vec3 b, double t)
{
	return add(scale(a, 1.0 - t), scale(b, t));
}

static double clamp01(double x)
{
	return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
}

static double smoothstep(double e0, double e1, double x)
{
	double t = clamp01((x - e0) / (e1 - e0));

	return t * t * (3.0 - 2.0 * t);
}

/* Wrapped Lambert: light reaches past the terminator by w, as in materials
 * that scatter a little below the surface; w = 0 is plain Lambert. */
static double wrap(double ndl, double w)
{
	double d = (ndl + w) / (1.0 + w);

	return d > 0.0 ? d : 0.0;
}

static double blinn(struct vec3 n, struct vec3 h, double exponent)
{
	double c = dot(n, h);

	return c > 0.0 ? pow(c, exponent) : 0.0;
}

/* Schlick's Fresnel; cos_v = n.v = n.z since the viewer is along +z. */
static double schlick(double f0, double cos_v)
{
	double m = 1.0 - clamp01(cos_v);
	double m2 = m * m;

	return f0 + (1.0 - f0) * m2 * m2 * m;
}

static struct vec3 schlick3(struct vec3 f0, double cos_v)
{
	return v3(schlick(f0.x, cos_v), schlick(f0.y, cos_v), schlick(f0.z, cos_v));
}

/* Mirror direction of the view vector v = (0, 0, 1) about n. */
static struct vec3 reflect_view(struct vec3 n)
{
	return v3(2.0 * n.z * n.x, 2.0 * n.z * n.y, 2.0 * n.z * n.z - 1.0);
}

static struct softbox softbox_make(struct vec3 dir, double half_u, double half_w, double power)
{
	struct softbox b;

	b.c = normalize(dir);
	/* Panels hang upright: u is horizontal, w the panel's "up" (so dir
	 * must not point straight up or down). */
	b.u = normalize(cross(v3(0.0, 1.0, 0.0), b.c));
	b.w = cross(b.c, b.u);
	b.half_u = half_u;
	b.half_w = half_w;
	b.power = gray(power);
	return b;
}

static void scene_init(struct scene *s)
{
	const struct vec3 v = {0.0, 0.0, 1.0};

	s->key = normalize(v3(-0.55, 0.62, 0.56));
	s->fill = normalize(v3(0.80, -0.15, 0.45));
	s->kick = normalize(v3(0.70, 0.55, -0.20));
	s->key_h = normalize(add(s->key, v));
	s->kick_h = normalize(add(s->kick, v));
	/* The key panel sits where the key light is, so diffuse shading and
	 * reflections agree; a tall strip on the right and a wide overhead
	 * panel give mirrors the shapes that make them read as metal. */
	s->box[0] = softbox_make(s->key, 0.36, 0.28, 6.0);
	s->box[1] = softbox_make(v3(0.95, 0.10, -0.10), 0.10, 0.80, 4.0);
	s->box[2] = softbox_make(v3(0.30, 1.0, 0.15), 0.45, 0.20, 3.0);
}

/* 1 inside the panel, 0 outside, with a ramp of relative width edge so a
 * soft edge can stand in for a slightly rough surface. */
static double softbox_mask(const struct softbox *b, struct vec3 d, double edge)
{
	double t = dot(d, b->c);
	double su, sw;

	if (t <= 0.0)
		return 0.0;
	su = fabs(dot(d, b->u)) / (t * b->half_u);
	sw = fabs(dot(d, b->w)) / (t * b->half_w);
	return (1.0 - smoothstep(1.0 - edge, 1.0 + edge, su)) *
	       (1.0 - smoothstep(1.0 - edge, 1.0 + edge, sw));
}

/* Radiance of the studio seen along direction d: a dark floor, a bright
 * cyclorama glow at the horizon, dim walls above it and a lighter ceiling,
 * plus the softboxes. The light/dark alternation is what makes a mirror read
 * as chrome rather than grey paint. The horizon sits a little below eye level
 * (the camera looks slightly down), which puts its reflection just under the
 * middle of a mirror ball, as in a photograph. */
static struct vec3 studio_env(const struct scene *s, struct vec3 d, double edge)
{
	const struct vec3 glow = {0.62, 0.62, 0.64};
	const struct vec3 wall = {0.07, 0.075, 0.085};
	const struct vec3 ceiling = {0.42, 0.44, 0.48};
	const struct vec3 floor_near = {0.010, 0.009, 0.008};
	const struct vec3 floor_far = {0.07, 0.065, 0.06};
	double h = d.y + 0.10;
	struct vec3 sky = mix(glow, wall, smoothstep(0.0, 0.40, h));
	struct vec3 ground = mix(floor_near, floor_far, smoothstep(0.0, 0.9, -h));
	struct vec3 c;

	sky = mix(sky, ceiling, smoothstep(0.55, 1.0, h));
	c = mix(ground, sky, smoothstep(-edge, edge, h));
	for (int i = 0; i < SOFTBOXES; i++)
		c = add(c, scale(s->box[i].power, softbox_mask(&s->box[i], d, edge)));
	return c;
}

/* Rough dielectrics get light from the upper hemisphere (sky, ceiling)
 * more than from the floor. */
static double hemi(struct vec3 n, double sky, double ground)
{
	return ground + (sky - ground) * (0.5 + 0.5 * n.y);
}

static struct vec3 shade_clay_red(const struct scene *s, struct vec3 n)
{
	const struct vec3 albedo = {0.56, 0.075, 0.045};
	double g = 1.0 - clamp01(n.z);
	/* Dusty clay loses light towards grazing angles; keep it slight. */
	double rim = 1.0 - 0.30 * g * g * g;
	double light = 1.05 * wrap(dot(n, s->key), 0.25) + 0.16 * wrap(dot(n, s->fill), 0.5) +
		       hemi(n, 0.10, 0.03);
	double spec = 0.045 * blinn(n, s->key_h, 12.0);

	return add(scale(albedo, light * rim), gray(spec));
}

static struct vec3 shade_black_shiny(const struct scene *s, struct vec3 n)
{
	const struct vec3 albedo = {0.010, 0.010, 0.012};
	double light = wrap(dot(n, s->key), 0.1) + 0.3 * hemi(n, 1.0, 0.2);
	/* Clear lacquer: 4% reflection face-on, rising to a mirror at grazing
	 * angles, which is what draws the bright top rim and dark bottom. */
	double f = schlick(0.04, n.z);
	struct vec3 env = scale(studio_env(s, reflect_view(n), 0.01), f);
	double spec = 4.0 * blinn(n, s->key_h, 900.0) + 2.0 * blinn(n, s->kick_h, 500.0);

	return add(add(scale(albedo, light), env), gray(spec));
}

static struct vec3 shade_skin(const struct scene *s, struct vec3 n)
{
	const struct vec3 albedo = {0.80, 0.42, 0.30};
	const struct vec3 blood = {0.55, 0.06, 0.03};
	double ndl = dot(n, s->key);
	/* Fake subsurface: red light travels furthest under skin, so red wraps
	 * furthest past the terminator, and a blood-red band glows along it. */
	struct vec3 key = v3(wrap(ndl, 0.50), wrap(ndl, 0.20), wrap(ndl, 0.12));
	double band = 1.0 - smoothstep(0.0, 0.45, fabs(ndl + 0.05));
	double fill = 0.08 * wrap(dot(n, s->fill), 0.5) + hemi(n, 0.05, 0.015);
	struct vec3 diffuse = mul(albedo, add(key, gray(fill)));
	double g = 1.0 - clamp01(n.z);
	/* Skin's oily layer gives a broad soft sheen, stronger at grazing. */
	double sheen = 0.08 * blinn(n, s->key_h, 20.0) + 0.05 * g * g * g * g * (0.5 + 0.5 * n.y);

	return add(add(diffuse, scale(blood, 0.16 * band)), gray(sheen));
}

static double luminance(struct vec3 c)
{
	return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

static struct vec3 shade_gold(const struct scene *s, struct vec3 n)
{
	const struct vec3 f0 = {1.0, 0.78, 0.34};
	/* Soft panel edges stand in for a polished but not perfect surface. */
	struct vec3 env = studio_env(s, reflect_view(n), 0.08);
	struct vec3 f = schlick3(f0, n.z);
	/* Dim parts of a gold reflection are mostly light that bounced off
	 * gold already (the ball's own surroundings), so they take the tint
	 * up to three times: deep orange shadows instead of olive grey. */
	double k = 1.0 + 2.0 * (1.0 - clamp01(luminance(env)));

	/* Roll the softboxes off instead of clipping them, so highlights
	 * stay pale gold rather than turning white. */
	env = scale(env, 1.5 / (1.0 + 0.5 * luminance(env)));

	return mul(env, v3(pow(f.x, k), pow(f.y, k), pow(f.z, k)));
}

static struct vec3 shade_chrome_studio(const struct scene *s, struct vec3 n)
{
	struct vec3 env = studio_env(s, reflect_view(n), 0.012);

	return scale(env, schlick(0.95, n.z));
}

/* A smooth hue wheel (cosine palette): no HSV sectors, so no creases. */
static struct vec3 hue_rgb(double hue)
{
	const double tau = 6.283185307179586;

	return v3(0.5 + 0.5 * cos(tau * hue), 0.5 + 0.5 * cos(tau * (hue - 1.0 / 3.0)),
		  0.5 + 0.5 * cos(tau * (hue - 2.0 / 3.0)));
}

static struct vec3 shade_pearl(const struct scene *s, struct vec3 n)
{
	const struct vec3 base = {0.80, 0.78, 0.76};
	/* Nacre's thin layers: hue shifts with n.v (the iridescence of
	 * shaders/material.glsl, hue = (1 - (n.v)^2) * range + average),
	 * kept pastel. */
	double hue = (1.0 - n.z * n.z) * 0.55 + 0.45;
	struct vec3 albedo = mul(base, mix(gray(1.0), hue_rgb(hue), 0.22));
	double light = 0.85 * wrap(dot(n, s->key), 0.6) + 0.18 * wrap(dot(n, s->fill), 0.6) +
		       hemi(n, 0.16, 0.06);
	double sheen = 0.30 * blinn(n, s->key_h, 40.0) + 0.10 * blinn(n, s->kick_h, 30.0);
	struct vec3 env = scale(studio_env(s, reflect_view(n), 0.35), 0.4 * schlick(0.04, n.z));

	return add(add(scale(albedo, light), env), gray(sheen));
}

struct material {
	const char *name;
	shade_fn shade;
	/* Nothing sharp inside the disk: only the rim needs supersampling. */
	int smooth;
};

static const struct material materials[BAKE_COUNT] = {
    [BAKE_CLAY_RED] = {"clay-red", shade_clay_red, 1},
    [BAKE_BLACK_SHINY] = {"black-shiny", shade_black_shiny, 0},
    [BAKE_SKIN] = {"skin", shade_skin, 1},
    [BAKE_GOLD] = {"gold", shade_gold, 0},
    [BAKE_CHROME_STUDIO] = {"chrome-studio", shade_chrome_studio, 0},
    [BAKE_PEARL] = {"pearl", shade_pearl, 1},
};

const char *bake_name(enum bake_material m)
{
	if ((unsigned)m >= BAKE_COUNT)
		return NULL;
	return materials[m].name;
}

/* Outside the disk the normal is clamped to the rim, so the rim colour
 * extends outward instead of black. */
static struct vec3 disk_normal(double x, double y)
{
	double r2 = x * x + y * y;

	if (r2 < 1.0)
		return v3(x, y, sqrt(1.0 - r2));
	return normalize(v3(x, y, 0.0));
}

/* The standard sRGB transfer function (IEC 61966-2-1), not a 2.2 gamma. */
static uint8_t srgb8(double linear)
{
	double c = clamp01(linear);

	c = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
	return (uint8_t)(c * 255.0 + 0.5);
}

/* Samples per axis for one pixel. Smooth materials take one sample except
 * within 1.5 pixels of the rim, where the normal turns fastest and the disk
 * edge must be anti-aliased; that keeps the kiosk's fallback bake fast. */
static int pixel_samples(const struct material *mat, int px, int py, int size)
{
	double x = (px + 0.5) / size * 2.0 - 1.0;
	double y = 1.0 - (py + 0.5) / size * 2.0;

	if (!mat->smooth || fabs(sqrt(x * x + y * y) - 1.0) < 3.0 / size)
		return SS;
	return 1;
}

static void shade_pixel(const struct scene *s, const struct material *mat, int px, int py, int size,
			uint8_t *rgba)
{
	int ss = pixel_samples(mat, px, py, size);
	struct vec3 sum = gray(0.0);

	for (int j = 0; j < ss; j++) {
		for (int i = 0; i < ss; i++) {
			double x = (px + (i + 0.5) / ss) / size * 2.0 - 1.0;
			double y = 1.0 - (py + (j + 0.5) / ss) / size * 2.0;
			struct vec3 c = mat->shade(s, disk_normal(x, y));

			/* Clamp before averaging: a highlight's anti-aliased
			 * edge is then judged as displayed, not in HDR. */
			sum = add(sum, v3(clamp01(c.x), clamp01(c.y), clamp01(c.z)));
		}
	}
	sum = scale(sum, 1.0 / (ss * ss));
	rgba[0] = srgb8(sum.x);
	rgba[1] = srgb8(sum.y);
	rgba[2] = srgb8(sum.z);
	rgba[3] = 255;
}

int bake_matcap(enum bake_material m, int size, struct image *out)
{
	struct scene s;
	int ret;

	out->width = 0;
	out->height = 0;
	out->rgba = NULL;
	if ((unsigned)m >= BAKE_COUNT) {
		log_err("bake: material %d unknown, expected 0..%d", (int)m, BAKE_COUNT - 1);
		return -EINVAL;
	}
	if (size < 1 || size > IMAGE_MAX_SIDE) {
		log_err("bake: size %d out of range, expected 1..%d", size, IMAGE_MAX_SIDE);
		return -EINVAL;
	}
	ret = image_alloc(out, size, size);
	if (ret) {
		log_err("bake: cannot allocate a %dx%d image", size, size);
		return ret;
	}
	scene_init(&s);
	for (int py = 0; py < size; py++)
		for (int px = 0; px < size; px++)
			shade_pixel(&s, &materials[m], px, py, size,
				    out->rgba + ((size_t)py * (size_t)size + (size_t)px) * 4);
	return 0;
}
