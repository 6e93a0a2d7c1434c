/* The renderer against the C mirror, pixel by pixel, on a sphere whose
 * normal is known at every point. The real renderer objects draw a fine
 * UV sphere through OSMesa; for each pixel inside the disk the ray
 * through its centre meets the unit sphere, which gives the analytic
 * normal and eye vector; the mirror shades them (for sem-vertex: at the
 * three vertices of the triangle hit, interpolated as the rasteriser
 * does), samples the matcap bilinearly in C, and the two colours are
 * compared. Each mode is held to a stated tolerance, and the mirror is
 * run in each precision to say which one llvmpipe's arithmetic follows.
 * Not a unit test: Mesa's own allocations would trip LeakSanitizer.
 * Exits 0 when every scene agrees, else 1. */
#include "render/bake.h"
#include "display/display.h"
#include "util/log.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "render/render.h"
#include "oracle/oracle.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIZE   256 /* the frame, square */
#define SLICES 256 /* the sphere: 1.4 degrees between vertices */
#define STACKS 128
#define TOL    3 /* of 255, per channel */

/* What each render must meet against its mirror: a share of the disk's
 * pixels within TOL, and no pixel beyond worst. At mediump a few pixels on
 * the gold matcap's sharp edges move by up to half a texel, which is up
 * to 55/255 there: the binary16 mirror against the binary32 one shows the
 * same (test_fp16.c bounds the uv itself). */
struct tolerance {
	double share;
	int worst;
};
static const struct tolerance highp_tol = {0.999, 8}, mediump_tol = {0.985, 64};

struct scene_case {
	const char *name;
	enum shading_mode mode;
	unsigned features;
	int lit;
};

static const struct scene_case cases[] = {
    {"normal", SHADING_NORMAL, 0, LIT_OFF},
    {"view", SHADING_VIEW, 0, LIT_OFF},
    {"sem-vertex", SHADING_SEM_VERTEX, 0, LIT_OFF},
    {"sem-fragment", SHADING_SEM_FRAGMENT, 0, LIT_OFF},
    {"view + iridescence", SHADING_VIEW, MATERIAL_IRIDESCENCE, LIT_OFF},
    {"lit", SHADING_VIEW, 0, LIT_ON},
};

/* GL_LINEAR with CLAMP_TO_EDGE, t = 0 on the image's first row. */
static void sample_clamped(const void *texture, double u, double v, double rgba[4])
{
	const struct image *img = texture;
	double x = u * img->width - 0.5, y = v * img->height - 0.5;
	int x0 = (int)floor(x), y0 = (int)floor(y);
	double fx = x - x0, fy = y - y0;

	for (int c = 0; c < 4; c++)
		rgba[c] = 0.0;
	for (int j = 0; j < 2; j++)
		for (int i = 0; i < 2; i++) {
			int xi = x0 + i < 0 ? 0 : x0 + i >= img->width ? img->width - 1 : x0 + i;
			int yj = y0 + j < 0 ? 0 : y0 + j >= img->height ? img->height - 1 : y0 + j;
			const uint8_t *p = img->rgba + ((size_t)yj * img->width + xi) * 4;
			double w = (i ? fx : 1 - fx) * (j ? fy : 1 - fy);

			for (int c = 0; c < 4; c++)
				rgba[c] += w * p[c] / 255.0;
		}
}

struct camera {
	double mv[16], proj[16], nm[9];
	double centre[3]; /* of the sphere, in view space */
};

/* The ray from the eye through pixel (col, row) of the frame read back
 * (rows top first), in view space: origin 0, direction d. */
static void pixel_ray(const struct camera *c, int col, int row, double d[3])
{
	double xn = 2.0 * (col + 0.5) / SIZE - 1.0, yn = 2.0 * (SIZE - row - 0.5) / SIZE - 1.0;

	d[0] = xn / c->proj[0];
	d[1] = yn / c->proj[5];
	d[2] = -1.0;
}

/* The nearest hit of ray t d with the unit sphere about c->centre. */
static bool hit_sphere(const struct camera *c, const double d[3], double q[3])
{
	double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
	double dc = d[0] * c->centre[0] + d[1] * c->centre[1] + d[2] * c->centre[2];
	double cc =
	    c->centre[0] * c->centre[0] + c->centre[1] * c->centre[1] + c->centre[2] * c->centre[2];
	double disc = dc * dc - dd * (cc - 1.0), t;

	if (disc <= 0.0)
		return false;
	t = (dc - sqrt(disc)) / dd;
	for (int k = 0; k < 3; k++)
		q[k] = t * d[k];
	return true;
}

/* Moller-Trumbore: the ray's barycentric weights in triangle abc. */
static bool hit_triangle(const double d[3], const double a[3], const double b[3], const double c[3],
			 double w[3])
{
	double e1[3], e2[3], p[3], tv[3], qv[3], det, u, v;

	for (int k = 0; k < 3; k++)
		e1[k] = b[k] - a[k], e2[k] = c[k] - a[k], tv[k] = -a[k];
	p[0] = d[1] * e2[2] - d[2] * e2[1];
	p[1] = d[2] * e2[0] - d[0] * e2[2];
	p[2] = d[0] * e2[1] - d[1] * e2[0];
	det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
	if (fabs(det) < 1e-15)
		return false;
	u = (tv[0] * p[0] + tv[1] * p[1] + tv[2] * p[2]) / det;
	qv[0] = tv[1] * e1[2] - tv[2] * e1[1];
	qv[1] = tv[2] * e1[0] - tv[0] * e1[2];
	qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
	v = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) / det;
	w[0] = 1.0 - u - v, w[1] = u, w[2] = v;
	return u >= -1e-9 && v >= -1e-9 && u + v <= 1.0 + 1e-9;
}

static void view_position(const struct camera *c, const float *p, double out[3])
{
	for (int r = 0; r < 3; r++)
		out[r] =
		    c->mv[r] * p[0] + c->mv[4 + r] * p[1] + c->mv[8 + r] * p[2] + c->mv[12 + r];
}

/* sem-vertex: the triangle of the UV sphere the ray meets (near the cell
 * the sphere hit q falls in), its three vertices through the vertex stage
 * of the mirror, and their uv interpolated with the ray's weights, which
 * are the perspective-correct ones. */
static bool vertex_uv(int fp, const struct camera *c, const struct mesh *m, const double d[3],
		      const double q[3], double uv[2])
{
	double p[3] = {q[0] - c->centre[0], q[1] - c->centre[1], q[2] - c->centre[2]};
	double theta = acos(fmax(-1.0, fmin(1.0, p[1]))), phi = atan2(-p[0], p[2]);
	int j0 = (int)floor((phi < 0 ? phi + 2 * M_PI : phi) / (2 * M_PI) * SLICES);
	int i0 = (int)floor(theta / M_PI * STACKS);

	for (int dj = -1; dj <= 1; dj++)
		for (int di = -1; di <= 1; di++) {
			int j = (j0 + dj + SLICES) % SLICES, i = i0 + di;
			uint32_t a = (uint32_t)((STACKS + 1) * j + i), b = a + STACKS + 1;
			uint32_t tri[2][3] = {{a, b, a + 1}, {b, b + 1, a + 1}};

			if (i < 0 || i >= STACKS)
				continue;
			for (int t = 0; t < 2; t++) {
				double v[3][3], w[3], vuv[3][2], eye[3], vn[3];

				for (int k = 0; k < 3; k++)
					view_position(c, m->positions + tri[t][k] * 3, v[k]);
				if (!hit_triangle(d, v[0], v[1], v[2], w))
					continue;
				for (int k = 0; k < 3; k++) {
					double pos[3], nrm[3];

					for (int x = 0; x < 3; x++) {
						pos[x] = m->positions[tri[t][k] * 3 + x];
						nrm[x] = m->normals[tri[t][k] * 3 + x];
					}
					if (fp < 0)
						shading_vertex(c->mv, c->nm, false, pos, nrm, eye,
							       vn, vuv[k]);
					else
						shading_vertex_f((enum shading_fp)fp, c->mv, c->nm,
								 false, pos, nrm, eye, vn, vuv[k]);
				}
				for (int x = 0; x < 2; x++)
					uv[x] =
					    w[0] * vuv[0][x] + w[1] * vuv[1][x] + w[2] * vuv[2][x];
				return true;
			}
		}
	return false;
}

struct agreement {
	long pixels, within;
	int worst;
};

static void shade_pixel(int fp, const struct shading_fragment *f, double rgb[3])
{
	if (fp < 0)
		shading_fragment(f, rgb);
	else
		shading_fragment_f((enum shading_fp)fp, f, rgb);
}

/* Compare one frame with the mirror in precision fp (-1: double). */
static struct agreement compare(int fp, const struct scene_case *sc, const struct camera *c,
				const struct mesh *m, const struct material *mat,
				const struct image *matcap, const struct image *frame,
				const float *light)
{
	struct agreement a = {0, 0, 0};
	struct shading_fragment f = {
	    .mode = sc->mode,
	    .iridescence = (sc->features & MATERIAL_IRIDESCENCE) != 0,
	    .lit = sc->lit == LIT_ON,
	    .iridescence_uniform = {mat->hue_range, mat->hue_average, mat->hue_shift, mat->opacity},
	    .hsv = {mat->saturation, mat->value},
	    .light = {light[0], light[1], light[2]},
	    .base_color = {mat->base_color[0], mat->base_color[1], mat->base_color[2]},
	    .shininess = mat->shininess,
	    .sample = sample_clamped,
	    .matcap_texture = matcap};

	for (int row = 0; row < SIZE; row++)
		for (int col = 0; col < SIZE; col++) {
			double d[3], q[3], rgb[3], nd[3], nq[3];
			const uint8_t *px = frame->rgba + ((size_t)row * SIZE + col) * 4;
			bool rim = false;
			int worst = 0;

			pixel_ray(c, col, row, d);
			if (!hit_sphere(c, d, q))
				continue;
			/* The rim: a neighbour off the sphere (the polygon's edge
			 * and the disk's differ there). */
			for (int k = 0; k < 4; k++) {
				pixel_ray(c, col + (k == 0) - (k == 1), row + (k == 2) - (k == 3),
					  nd);
				rim |= !hit_sphere(c, nd, nq);
			}
			if (rim)
				continue;
			for (int k = 0; k < 3; k++) {
				f.normal[k] = q[k] - c->centre[k];
				f.eye[k] = q[k];
			}
			if (sc->mode == SHADING_SEM_VERTEX &&
			    !vertex_uv(fp, c, m, d, q, f.matcap_uv))
				continue;
			shade_pixel(fp, &f, rgb);
			for (int k = 0; k < 3; k++) {
				int diff =
				    abs((int)lround(fmin(fmax(rgb[k], 0.0), 1.0) * 255.0) - px[k]);

				worst = diff > worst ? diff : worst;
			}
			a.pixels++;
			a.within += worst <= TOL;
			a.worst = worst > a.worst ? worst : a.worst;
		}
	return a;
}

/* Draw the case (every float highp, or mediump but for SHADE_P) and read it. */
static int draw(struct display *d, struct renderer *r, bool highp, struct image *frame)
{
	struct view v = {.orientation = quat_identity()};

	if (renderer_set_precision(r, highp))
		return -1;
	d->begin_frame(d);
	renderer_draw(r, &v, SIZE, SIZE);
	d->present(d);
	return d->read_frame(d, frame);
}

/* One line: the render at `highp` against the mirror in every precision;
 * the render must agree with the mirror in `held` within tol. */
static int report(const char *name, bool highp, int held, const struct tolerance *tol,
		  const struct scene_case *sc, const struct camera *c, const struct mesh *m,
		  const struct material *mat, const struct image *matcap, const struct image *frame,
		  const float *light)
{
	int bad = 0;

	printf("%-19s %-7s", name, highp ? "highp" : "mediump");
	for (int fp = -1; fp < SHADING_FP_COUNT; fp++) {
		struct agreement a = compare(fp, sc, c, m, mat, matcap, frame, light);
		double share = (double)a.within / (double)a.pixels;

		printf(" | %6.2f%% %3d", 100.0 * share, a.worst);
		if (fp == held &&
		    (a.pixels < 30000 || share < tol->share || a.worst > tol->worst)) {
			fprintf(stderr, "%s, %s: %ld pixels, %.2f%% within %d/255, worst %d\n",
				name, highp ? "highp" : "mediump", a.pixels, 100.0 * share, TOL,
				a.worst);
			bad = 1;
		}
	}
	printf("\n");
	return bad;
}

static int check_case(struct display *d, const struct scene_case *sc, const struct mesh *m,
		      const struct image *matcap)
{
	static const float light[3] = {-0.5499f, 0.6198f, 0.5599f}; /* render.c's */
	struct material_config cfg;
	struct material mat = {0};
	struct renderer *r = renderer_new(&d->gl, NULL);
	struct view v = {.orientation = quat_identity()};
	struct camera c;
	struct image frame = {0};
	float mv[16], proj[16];
	int bad = 1;

	material_config_defaults(&cfg);
	cfg.iridescence = sc->features & MATERIAL_IRIDESCENCE ? MATERIAL_ON : MATERIAL_OFF;
	cfg.lit = sc->lit;
	if (!r || material_load(&mat, &cfg, m, true) || renderer_set_material(r, &mat) ||
	    renderer_set_mesh(r, m) || renderer_set_matcap(r, matcap) ||
	    renderer_set_mode(r, sc->mode, false)) {
		fprintf(stderr, "%s: the renderer failed\n", sc->name);
		goto out;
	}
	render_matrices(&v, SIZE, SIZE, mv, proj);
	for (int k = 0; k < 16; k++)
		c.mv[k] = mv[k], c.proj[k] = proj[k];
	for (int col = 0; col < 3; col++)
		for (int row = 0; row < 3; row++)
			c.nm[col * 3 + row] = mv[col * 4 + row];
	for (int k = 0; k < 3; k++)
		c.centre[k] = c.mv[12 + k];
	/* llvmpipe computes highp in binary32: the float mirror must match.
	 * Its mediump is narrower (Mesa lowers part of it to 16 bits); the
	 * binary16 mirror stands for it, within the same tolerance. */
	if (draw(d, r, true, &frame))
		goto out;
	bad = report(sc->name, true, SHADING_FP32, &highp_tol, sc, &c, m, &mat, matcap, &frame,
		     light);
	image_release(&frame);
	if (draw(d, r, false, &frame)) {
		bad = 1;
		goto out;
	}
	bad |= report("", false, SHADING_FP16_HIGHP, &mediump_tol, sc, &c, m, &mat, matcap, &frame,
		      light);
out:
	material_release(&mat);
	image_release(&frame);
	renderer_free(r);
	return bad;
}

int main(void)
{
	struct display_config cfg = {.width = SIZE, .height = SIZE};
	struct display *d;
	struct mesh sphere;
	struct image matcap;
	int bad = 0;

	log_set_level(LOG_WARN);
#ifdef MK_HAVE_OSMESA
	d = display_osmesa_new(&cfg);
#else /* Mesa without OSMesa: the same renders through EGL */
	d = display_egl_new(&cfg);
#endif
	if (!d || mesh_uv_sphere(&sphere, SLICES, STACKS) || bake_matcap(BAKE_GOLD, 256, &matcap))
		return 1;
	printf("%dx%d: share of the disk's pixels (less a 1-pixel rim) within %d/255 per "
	       "channel, and the worst, against the mirror in\n%-27s |  double     |  %-10s | "
	       " %-10s |  %s\n",
	       SIZE, SIZE, TOL, "", shading_fp_name(SHADING_FP32),
	       shading_fp_name(SHADING_FP16_HIGHP), shading_fp_name(SHADING_FP16));
	printf("held: highp to %s, %.1f%% and none beyond %d; mediump to %s, %.1f%% and none "
	       "beyond %d\n",
	       shading_fp_name(SHADING_FP32), highp_tol.share * 100, highp_tol.worst,
	       shading_fp_name(SHADING_FP16_HIGHP), mediump_tol.share * 100, mediump_tol.worst);
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++)
		bad |= check_case(d, &cases[i], &sphere, &matcap);
	image_release(&matcap);
	mesh_release(&sphere);
	display_free(d);
	printf("%s\n", bad ? "FAILED" : "the renderer agrees with the C mirror");
	return bad;
}
