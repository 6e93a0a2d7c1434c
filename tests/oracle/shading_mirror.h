/* The C mirror of the shaders, line for line: the body that
 * tests/oracle/shading_double.c and tests/oracle/shading_float.c each compile once, with
 *   real              the scalar type the values are kept in,
 *   prec              the type that names a precision,
 *   MIRROR(name)      the exported name (shading_x, or shading_x_f),
 *   FP_PARAM, FP_ARG  "enum shading_fp fp," or nothing,
 *   MEDIUMP, HIGHP    the precision of a fragment value declared so,
 *   SHADE_PRECISION   SHADE_P's in a program where it is highp,
 *   UV_PRECISION      the detail map's v_uv's (highp in matcap.frag),
 *   VERTEX            the vertex stage's (always highp),
 *   round_to(p, x)    x rounded to precision p.
 * Not a header for any other file.
 *
 * Every operation rounds once, as one GPU instruction would: a dot product
 * is three products and two sums, pow is exp2(y log2 x) as GPUs compute
 * it, a texture read returns a value of the sampler's precision. Each
 * GLSL line below is quoted above its C line where they differ in form. */
#include "oracle.h"

#include <math.h>

typedef struct {
	real x, y;
} vec2;
typedef struct {
	real x, y, z;
} vec3;
typedef struct {
	real x, y, z, w;
} vec4;

/* Constants and inputs enter at the precision of the value they join. */
static real in(prec p, double x)
{
	return round_to(p, x);
}

static real add(prec p, real a, real b)
{
	return round_to(p, (double)a + (double)b);
}

static real sub(prec p, real a, real b)
{
	return round_to(p, (double)a - (double)b);
}

static real mul(prec p, real a, real b)
{
	return round_to(p, (double)a * (double)b);
}

static real inversesqrt(prec p, real x)
{
	return round_to(p, 1.0 / sqrt((double)x));
}

static real sqrt_(prec p, real x)
{
	return round_to(p, sqrt((double)x));
}

static real fract(prec p, real x)
{
	return round_to(p, (double)x - floor((double)x));
}

static real clamp(real x, real lo, real hi)
{
	return x < lo ? lo : x > hi ? hi : x;
}

/* mix(a, b, t) = a (1 - t) + b t */
static real mix(prec p, real a, real b, real t)
{
	return add(p, mul(p, a, sub(p, in(p, 1.0), t)), mul(p, b, t));
}

/* GPUs compute pow(x, y) as exp2(y * log2(x)), each step rounded. */
static real pow_(prec p, real x, real y)
{
	real l = round_to(p, log2((double)x));

	return round_to(p, exp2((double)mul(p, y, l)));
}

static vec3 v3(prec p, double x, double y, double z)
{
	return (vec3){in(p, x), in(p, y), in(p, z)};
}

static vec3 v3_in(prec p, const double a[3])
{
	return v3(p, a[0], a[1], a[2]);
}

static void v3_out(vec3 v, double out[3])
{
	out[0] = v.x, out[1] = v.y, out[2] = v.z;
}

static vec3 add3(prec p, vec3 a, vec3 b)
{
	return (vec3){add(p, a.x, b.x), add(p, a.y, b.y), add(p, a.z, b.z)};
}

static vec3 sub3(prec p, vec3 a, vec3 b)
{
	return (vec3){sub(p, a.x, b.x), sub(p, a.y, b.y), sub(p, a.z, b.z)};
}

static vec3 scale3(prec p, vec3 a, real s)
{
	return (vec3){mul(p, a.x, s), mul(p, a.y, s), mul(p, a.z, s)};
}

static real dot3(prec p, vec3 a, vec3 b)
{
	return add(p, add(p, mul(p, a.x, b.x), mul(p, a.y, b.y)), mul(p, a.z, b.z));
}

static vec3 cross3(prec p, vec3 a, vec3 b)
{
	return (vec3){sub(p, mul(p, a.y, b.z), mul(p, a.z, b.y)),
		      sub(p, mul(p, a.z, b.x), mul(p, a.x, b.z)),
		      sub(p, mul(p, a.x, b.y), mul(p, a.y, b.x))};
}

/* reflect(i, n) = i - 2 dot(n, i) n */
static vec3 reflect(prec p, vec3 i, vec3 n)
{
	return sub3(p, i, scale3(p, n, mul(p, in(p, 2.0), dot3(p, n, i))));
}

/* A texture read: the coordinates reach the sampler at the precision they
 * have; the texel comes back at the sampler's (lowp/mediump). */
static vec4 texture2D(prec p, const struct shading_fragment *f, const void *tex, vec2 uv)
{
	double t[4];

	f->sample(tex, uv.x, uv.y, t);
	return (vec4){in(p, t[0]), in(p, t[1]), in(p, t[2]), in(p, t[3])};
}

/* ---- shaders/mapping.glsl ---- */

static vec3 safe_normalize(prec p, vec3 v)
{
	real l2 = dot3(p, v, v);

	/* return l2 > 1.0e-6 ? v * inversesqrt(l2) : vec3(0.0, 0.0, 1.0); */
	return l2 > in(p, 1.0e-6) ? scale3(p, v, inversesqrt(p, l2)) : v3(p, 0.0, 0.0, 1.0);
}

/* vec2(n.x, -n.y) * 0.5 + 0.5 */
static vec2 matcap_normal(prec p, vec3 n)
{
	real half = in(p, 0.5);

	return (vec2){add(p, mul(p, n.x, half), half), add(p, mul(p, -n.y, half), half)};
}

static vec2 matcap_view(prec p, vec3 n, vec3 eye_to_point)
{
	vec3 v = {-eye_to_point.x, -eye_to_point.y, -eye_to_point.z};
	real h2 = add(p, mul(p, v.z, v.z), mul(p, v.x, v.x));
	/* h2 > 1.0e-4 ? vec3(v.z, 0.0, -v.x) * inversesqrt(h2) : vec3(1.0, 0.0, 0.0) */
	vec3 x = h2 > in(p, 1.0e-4) ? scale3(p, (vec3){v.z, 0, -v.x}, inversesqrt(p, h2))
				    : v3(p, 1.0, 0.0, 0.0);
	vec3 y = cross3(p, v, x);
	real k = in(p, 0.495), half = in(p, 0.5);

	/* vec2(dot(x, n), -dot(y, n)) * 0.495 + 0.5 */
	return (vec2){add(p, mul(p, dot3(p, x, n), k), half),
		      add(p, mul(p, -dot3(p, y, n), k), half)};
}

static vec2 matcap_sem(prec p, vec3 n, vec3 eye_to_point)
{
	vec3 h = add3(p, reflect(p, eye_to_point, n), v3(p, 0.0, 0.0, 1.0));
	real l2 = dot3(p, h, h);

	/* h = l2 > 1.0e-6 ? h * inversesqrt(l2) : safe_normalize(vec3(n.xy, 0.0)); */
	h = l2 > in(p, 1.0e-6) ? scale3(p, h, inversesqrt(p, l2))
			       : safe_normalize(p, (vec3){n.x, n.y, 0});
	return matcap_normal(p, h); /* vec2(h.x, -h.y) * 0.5 + 0.5 */
}

/* ---- shaders/material.glsl ---- */

static real iridescence_hue(prec p, real n_dot_e, real range, real average, real shift, real map_a)
{
	real one = in(p, 1.0);

	/* (1.0 - n_dot_e * n_dot_e) * range + average - shift * (1.0 - map_a) */
	return sub(p, add(p, mul(p, sub(p, one, mul(p, n_dot_e, n_dot_e)), range), average),
		   mul(p, shift, sub(p, one, map_a)));
}

/* ph: the precision of h (SHADE_P), p: of the rest (the default). */
static vec3 hsv_to_rgb(prec ph, prec p, real h, real s, real v)
{
	const double offset[3] = {1.0, 2.0 / 3.0, 1.0 / 3.0};
	real rgb[3];

	for (int k = 0; k < 3; k++) {
		/* vec3 p = abs(fract(vec3(h) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
		 * at h's precision, kept at the default */
		real wrapped = fract(ph, add(ph, h, in(ph, offset[k])));
		real q = in(p, fabs((double)sub(ph, mul(ph, wrapped, in(ph, 6.0)), in(ph, 3.0))));
		/* v * mix(vec3(1.0), clamp(p - 1.0, 0.0, 1.0), s) */
		real c = clamp(sub(p, q, in(p, 1.0)), 0, 1);

		rgb[k] = mul(p, v, mix(p, in(p, 1.0), c, s));
	}
	return (vec3){rgb[0], rgb[1], rgb[2]};
}

static vec3 detail_normal(prec p, vec3 n, vec4 tangent, vec2 rg)
{
	real one = in(p, 1.0), two = in(p, 2.0);
	vec2 xy = {sub(p, mul(p, rg.x, two), one), sub(p, mul(p, rg.y, two), one)};
	real z = sqrt_(p, fmax(sub(p, one, add(p, mul(p, xy.x, xy.x), mul(p, xy.y, xy.y))), 0.0));
	vec3 t3 = {tangent.x, tangent.y, tangent.z};
	vec3 t = safe_normalize(p, sub3(p, t3, scale3(p, n, dot3(p, n, t3))));
	/* cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0) */
	vec3 b = scale3(p, cross3(p, n, t), in(p, tangent.w < 0 ? -1.0 : 1.0));

	/* safe_normalize(t * xy.x + b * xy.y + n * z) */
	return safe_normalize(
	    p, add3(p, add3(p, scale3(p, t, xy.x), scale3(p, b, xy.y)), scale3(p, n, z)));
}

static vec3 lit_blinn_phong(prec p, vec3 n, vec3 e, vec3 l, vec3 base, real shininess)
{
	real diffuse = (real)fmax(dot3(p, n, l), 0.0);
	vec3 h = safe_normalize(p, sub3(p, l, e));
	/* diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0 */
	real specular = diffuse > 0 ? pow_(p, (real)fmax(dot3(p, n, h), 0.0), shininess) : 0;
	real shade =
	    add(p, in(p, SHADING_LIT_AMBIENT), mul(p, in(p, 1.0 - SHADING_LIT_AMBIENT), diffuse));
	real highlight = mul(p, in(p, SHADING_LIT_SPECULAR), specular);

	/* base * (LIT_AMBIENT + (1.0 - LIT_AMBIENT) * diffuse) + vec3(LIT_SPECULAR * specular) */
	return add3(p, scale3(p, base, shade), (vec3){highlight, highlight, highlight});
}

/* ---- shaders/matcap.vert (highp: the vertex language has it) ---- */

void MIRROR(shading_vertex)(FP_PARAM const double modelview[16], const double normal_matrix[9],
			    bool ortho, const double position[3], const double normal[3],
			    double eye_out[3], double normal_out[3], double matcap_uv[2])
{
	prec p = VERTEX;
	real pos[4] = {in(p, position[0]), in(p, position[1]), in(p, position[2]), 1};
	real nrm[3] = {in(p, normal[0]), in(p, normal[1]), in(p, normal[2])};
	real pv[3], nv[3];
	vec3 eye;
	vec2 uv;

	/* vec4 p = u_modelview * vec4(a_position, 1.0); vec3 n = u_normal_matrix * a_normal; */
	for (int r = 0; r < 3; r++) {
		pv[r] = mul(p, in(p, modelview[r]), pos[0]);
		nv[r] = mul(p, in(p, normal_matrix[r]), nrm[0]);
		for (int c = 1; c < 4; c++)
			pv[r] = add(p, pv[r], mul(p, in(p, modelview[c * 4 + r]), pos[c]));
		for (int c = 1; c < 3; c++)
			nv[r] = add(p, nv[r], mul(p, in(p, normal_matrix[c * 3 + r]), nrm[c]));
	}
	eye = ortho ? v3(p, 0.0, 0.0, -1.0) : (vec3){pv[0], pv[1], pv[2]};
	/* v_matcap_uv = matcap_sem(safe_normalize(n), safe_normalize(eye)); */
	uv = matcap_sem(p, safe_normalize(p, (vec3){nv[0], nv[1], nv[2]}), safe_normalize(p, eye));
	v3_out(eye, eye_out);
	normal_out[0] = nv[0], normal_out[1] = nv[1], normal_out[2] = nv[2];
	matcap_uv[0] = uv.x, matcap_uv[1] = uv.y;
}

/* ---- shaders/matcap.frag ---- */

/* A value stored into a variable of precision p. */
static vec3 round3(prec p, vec3 v)
{
	return (vec3){in(p, v.x), in(p, v.y), in(p, v.z)};
}

static vec3 matcap_color(prec p, const struct shading_fragment *f, vec3 n, vec3 e)
{
	vec2 uv = f->mode == SHADING_NORMAL ? matcap_normal(p, n)
		  : f->mode == SHADING_VIEW ? matcap_view(p, n, e)
					    : matcap_sem(p, n, e);
	vec4 c = texture2D(p, f, f->matcap_texture, uv);

	return (vec3){c.x, c.y, c.z};
}

/* n and e at precision pn (SHADE_P), as the hue */
static vec3 iridescence(FP_PARAM const struct shading_fragment *f, vec3 color, prec pn, vec3 n,
			vec3 e, real map_a)
{
	prec p = MEDIUMP, ph = pn;
	const double *u = f->iridescence_uniform;
	/* float hue = iridescence_hue(dot(n, e), u_iridescence.x, .y, .z, map_a); */
	real hue = iridescence_hue(ph, in(ph, dot3(pn, n, e)), in(ph, u[0]), in(ph, u[1]),
				   in(ph, u[2]), in(ph, map_a));
	vec3 film;

	if (f->ramp) {
		/* texture2D(u_ramp, vec2(fract(hue), 0.5)).rgb */
		vec4 t = texture2D(p, f, f->ramp_texture, (vec2){fract(ph, hue), in(ph, 0.5)});

		film = (vec3){t.x, t.y, t.z};
	} else {
		film = hsv_to_rgb(ph, p, hue, in(p, f->hsv[0]), in(p, f->hsv[1]));
	}
	/* color = mix(color, film, u_iridescence.w): at the uniform's precision */
	return round3(p, (vec3){mix(ph, color.x, film.x, in(ph, u[3])),
				mix(ph, color.y, film.y, in(ph, u[3])),
				mix(ph, color.z, film.z, in(ph, u[3]))});
}

void MIRROR(shading_fragment)(FP_PARAM const struct shading_fragment *f, double rgb[3])
{
	prec p = MEDIUMP;
	/* SHADE_P in mapping.glsl: the normal and eye vectors and what is
	 * made of them, highp in a program with the lit mode or iridescence. */
	prec pn = f->lit || f->iridescence ? SHADE_PRECISION : MEDIUMP;
	vec4 detail = {1, 1, 1, 1};
	vec3 color;

	if (f->detail_map) {
		vec2 uv = {in(UV_PRECISION, f->uv[0]), in(UV_PRECISION, f->uv[1])};

		detail = texture2D(p, f, f->detail_texture, uv);
	}
	if (f->mode == SHADING_SEM_VERTEX) {
		vec2 uv = {in(p, f->matcap_uv[0]), in(p, f->matcap_uv[1])};
		vec4 c = texture2D(p, f, f->matcap_texture, uv);

		color = (vec3){c.x, c.y, c.z};
	} else {
		vec3 n = safe_normalize(pn, v3_in(pn, f->normal));
		vec3 e = safe_normalize(pn, v3_in(pn, f->eye));

		if (f->detail_normal) {
			const double *t = f->tangent;
			vec4 tangent = {in(pn, t[0]), in(pn, t[1]), in(pn, t[2]), in(pn, t[3])};

			n = detail_normal(pn, n, tangent, (vec2){detail.x, detail.y});
		}
		if (f->lit)
			color = round3(p, lit_blinn_phong(pn, n, e, v3_in(pn, f->light),
							  v3_in(pn, f->base_color),
							  in(pn, f->shininess)));
		else
			color = matcap_color(p, f, round3(p, n), round3(p, e));
		if (f->iridescence)
			color = iridescence(FP_ARG f, color, pn, n, e, detail.w);
	}
	if (f->detail_map) /* color *= detail.b; */
		color = scale3(p, color, detail.z);
	v3_out(color, rgb);
}

/* ---- each function alone, at the precision the fragment stage gives it ---- */

void MIRROR(shading_safe_normalize)(FP_PARAM const double v[3], double out[3])
{
	v3_out(safe_normalize(MEDIUMP, v3_in(MEDIUMP, v)), out);
}

void MIRROR(shading_uv_normal)(FP_PARAM const double n[3], double uv[2])
{
	vec2 r = matcap_normal(MEDIUMP, v3_in(MEDIUMP, n));

	uv[0] = r.x, uv[1] = r.y;
}

void MIRROR(shading_uv_view)(FP_PARAM const double n[3], const double e[3], double uv[2])
{
	vec2 r = matcap_view(MEDIUMP, v3_in(MEDIUMP, n), v3_in(MEDIUMP, e));

	uv[0] = r.x, uv[1] = r.y;
}

void MIRROR(shading_uv_sem)(FP_PARAM const double n[3], const double e[3], double uv[2])
{
	vec2 r = matcap_sem(MEDIUMP, v3_in(MEDIUMP, n), v3_in(MEDIUMP, e));

	uv[0] = r.x, uv[1] = r.y;
}

double MIRROR(shading_iridescence_hue)(FP_PARAM double n_dot_e, double range, double average,
				       double shift, double map_a)
{
	prec p = SHADE_PRECISION;

	return iridescence_hue(p, in(p, n_dot_e), in(p, range), in(p, average), in(p, shift),
			       in(p, map_a));
}

void MIRROR(shading_hsv_to_rgb)(FP_PARAM double h, double s, double v, double rgb[3])
{
	v3_out(hsv_to_rgb(SHADE_PRECISION, MEDIUMP, in(SHADE_PRECISION, h), in(MEDIUMP, s),
			  in(MEDIUMP, v)),
	       rgb);
}

void MIRROR(shading_detail_normal)(FP_PARAM const double n[3], const double tangent[4],
				   const double rg[2], double out[3])
{
	prec p = MEDIUMP;
	vec4 t = {in(p, tangent[0]), in(p, tangent[1]), in(p, tangent[2]), in(p, tangent[3])};

	v3_out(detail_normal(p, v3_in(p, n), t, (vec2){in(p, rg[0]), in(p, rg[1])}), out);
}

void MIRROR(shading_blinn_phong)(FP_PARAM const double n[3], const double e[3], const double l[3],
				 const double base[3], double shininess, double rgb[3])
{
	prec p = SHADE_PRECISION;

	v3_out(lit_blinn_phong(p, v3_in(p, n), v3_in(p, e), v3_in(p, l), v3_in(p, base),
			       in(p, shininess)),
	       rgb);
}
