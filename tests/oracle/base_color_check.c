/* The glTF base colour through the whole program against a reference
 * written from the specifications, pixel by pixel. A fine UV sphere is
 * written as glTF with all three parts of the base colour (COLOR_0 as
 * normalized bytes, a baseColorFactor, a baseColorTexture with a
 * KHR_texture_transform), loaded by the loader, resolved by material.c and
 * drawn through OSMesa. For each pixel inside the disk the ray through
 * its centre meets the unit sphere; at that point the reference takes
 * the matcap colour from the C mirror (tests/oracle), the vertex colour
 * from its formula, the UV from the sphere's parametrisation through the
 * transform as the extension defines it (translation x rotation x scale),
 * the texel by bilinear filtering with GL_REPEAT, and multiplies them as
 * three.js's MeshMatcapMaterial does: in linear light, with the exact
 * piecewise sRGB curves, encoded again at the end. The two are compared
 * per channel. Not a unit test: Mesa's own allocations would trip
 * LeakSanitizer. Exits 0 when every format agrees within the tolerance. */
#include "display/display.h"
#include "gltf_write.h"
#include "maps.h"
#include "oracle/oracle.h"
#include "render/bake.h"
#include "render/render.h"
#include "scene/gltf/gltf.h"
#include "scene/mesh/material.h"
#include "util/log.h"

#include <ftw.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define SIZE   256
#define SLICES 256
#define STACKS 128
#define TOL    3 /* of 255, per channel */

/* The model's base colour, as written into the file. */
static const double factor[4] = {1.0, 0.9, 0.75, 1.0};
static const double offset[2] = {0.25, 0.1}, rotation = 0.3, scale[2] = {2.0, 1.5};
#define TRANSFORM "\"offset\":[0.25,0.1],\"rotation\":0.3,\"scale\":[2,1.5]"

/* What the check must meet: a share of the disk's pixels within TOL, and
 * no pixel beyond worst. At mediump, as mirror_check holds the matcap
 * alone: its sharp edges move by up to half a texel there. */
struct tolerance {
	double share;
	int worst;
};
static const struct tolerance highp_tol = {0.99, 8}, mediump_tol = {0.985, 64};

/* COLOR_0 at point p; white for the model written without it (one colour,
 * the factor: the loader keeps it as a constant, not per vertex). */
static void vertex_color(const double p[3], bool color_0, double rgb[3])
{
	for (int k = 0; k < 3; k++)
		rgb[k] = color_0 ? 0.3 + 0.6 * (0.5 + 0.5 * p[k]) : 1.0;
}

static double srgb_to_linear(double c)
{
	return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double linear_to_srgb(double c)
{
	return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

/* GL_LINEAR with CLAMP_TO_EDGE (the matcap), t = 0 on the first row. */
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

/* GL_LINEAR with GL_REPEAT (the base map). */
static void sample_repeat(const struct image *img, double u, double v, double rgb[3])
{
	double x = (u - floor(u)) * img->width - 0.5, y = (v - floor(v)) * img->height - 0.5;
	int x0 = (int)floor(x), y0 = (int)floor(y);
	double fx = x - x0, fy = y - y0;

	rgb[0] = rgb[1] = rgb[2] = 0.0;
	for (int j = 0; j < 2; j++)
		for (int i = 0; i < 2; i++) {
			int xi = ((x0 + i) % img->width + img->width) % img->width;
			int yj = ((y0 + j) % img->height + img->height) % img->height;
			const uint8_t *p = img->rgba + ((size_t)yj * img->width + xi) * 4;
			double w = (i ? fx : 1 - fx) * (j ? fy : 1 - fy);

			for (int c = 0; c < 3; c++)
				rgb[c] += w * p[c] / 255.0;
		}
}

/* The sphere's UV at unit point p (src/scene/mesh/mesh_gen.c's parametrisation)
 * through KHR_texture_transform. */
static void base_uv(const double p[3], double uv[2])
{
	double phi = atan2(-p[0], p[2]), u, v, c = cos(rotation), s = sin(rotation);

	if (phi < 0)
		phi += 2 * M_PI;
	u = 1.0 - phi / (2 * M_PI);
	v = acos(fmax(-1.0, fmin(1.0, p[1]))) / M_PI;
	uv[0] = c * scale[0] * u + s * scale[1] * v + offset[0];
	uv[1] = -s * scale[0] * u + c * scale[1] * v + offset[1];
}

struct agreement {
	long pixels, within;
	int worst;
	double sum;
};

/* The reference colour at unit-sphere point p (model = view orientation),
 * with normal n and eye vector e in view space. */
static void reference(const double p[3], const double n[3], const double e[3], bool color_0,
		      const struct image *matcap, const struct image *map, double rgb[3])
{
	struct shading_fragment f = {
	    .mode = SHADING_VIEW, .sample = sample_clamped, .matcap_texture = matcap};
	double mc[3], col[3], tex[3], uv[2];

	memcpy(f.normal, n, sizeof(f.normal));
	memcpy(f.eye, e, sizeof(f.eye));
	shading_fragment(&f, mc);
	vertex_color(p, color_0, col);
	base_uv(p, uv);
	sample_repeat(map, uv[0], uv[1], tex);
	for (int k = 0; k < 3; k++)
		rgb[k] = linear_to_srgb(srgb_to_linear(mc[k]) * col[k] * factor[k] *
					srgb_to_linear(tex[k]));
}

static bool hit(const double mv[16], const double proj[16], int col, int row, double q[3])
{
	double d[3] = {(2.0 * (col + 0.5) / SIZE - 1.0) / proj[0],
		       (2.0 * (SIZE - row - 0.5) / SIZE - 1.0) / proj[5], -1.0};
	double c[3] = {mv[12], mv[13], mv[14]};
	double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
	double dc = d[0] * c[0] + d[1] * c[1] + d[2] * c[2];
	double disc = dc * dc - dd * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - 1.0), t;

	if (disc <= 0.0)
		return false;
	t = (dc - sqrt(disc)) / dd;
	for (int k = 0; k < 3; k++)
		q[k] = t * d[k];
	return true;
}

static struct agreement compare(const struct image *frame, bool color_0, const struct image *matcap,
				const struct image *map)
{
	struct view v = {.orientation = quat_identity()};
	struct agreement a = {0, 0, 0, 0.0};
	float mvf[16], projf[16];
	double mv[16], proj[16];

	render_matrices(&v, SIZE, SIZE, mvf, projf);
	for (int k = 0; k < 16; k++)
		mv[k] = mvf[k], proj[k] = projf[k];
	for (int row = 0; row < SIZE; row++)
		for (int col = 0; col < SIZE; col++) {
			double q[3], nq[3], p[3], rgb[3];
			const uint8_t *px = frame->rgba + ((size_t)row * SIZE + col) * 4;
			bool rim = false;
			int worst = 0;

			if (!hit(mv, proj, col, row, q))
				continue;
			for (int k = 0; k < 4; k++)
				rim |= !hit(mv, proj, col + (k == 0) - (k == 1),
					    row + (k == 2) - (k == 3), nq);
			for (int k = 0; k < 3; k++)
				p[k] = q[k] - mv[12 + k];
			/* The rim, and the poles, where a UV sphere's u is
			 * undefined and its polar triangles blend it. */
			if (rim || fabs(p[1]) > 0.99)
				continue;
			reference(p, p, q, color_0, matcap, map, rgb);
			for (int k = 0; k < 3; k++) {
				double ref = fmin(fmax(rgb[k], 0.0), 1.0) * 255.0;
				int diff = abs((int)lround(ref) - px[k]);

				a.sum += fabs(ref - px[k]);
				worst = diff > worst ? diff : worst;
			}
			a.pixels++;
			a.within += worst <= TOL;
			a.worst = worst > a.worst ? worst : a.worst;
		}
	return a;
}

static int write_model(const char *dir, bool color_0, char *path, size_t size)
{
	struct gltf_write_opts o = {.index_bytes = 4,
				    .with_normals = 1,
				    .bad_index = -1,
				    .with_uvs = 1,
				    .embed_images = 1,
				    .base_factor = factor,
				    .texture_transform = TRANSFORM,
				    .color_type = 5121,
				    .color_components = 4};
	char base[4096];
	struct mesh s;
	int ret;

	if (maps_write(dir) || mesh_uv_sphere(&s, SLICES, STACKS) || mesh_alloc_colors(&s))
		return -1;
	for (uint32_t v = 0; v < s.vertex_count; v++) {
		double p[3] = {s.positions[v * 3], s.positions[v * 3 + 1], s.positions[v * 3 + 2]},
		       c[3];

		vertex_color(p, true, c);
		for (int k = 0; k < 3; k++)
			s.colors[v * 4 + k] = (float)c[k];
		s.colors[v * 4 + 3] = 1.0f;
	}
	snprintf(base, sizeof(base), "%s/base.png", dir);
	snprintf(path, size, "%s/sphere-%s.glb", dir, color_0 ? "colored" : "factor");
	o.base_color_png = base;
	o.color_type = color_0 ? o.color_type : 0;
	ret = gltf_write(path, &s, &o);
	mesh_release(&s);
	return ret;
}

/* Load, draw in vertex format f at highp or mediump, compare; prints one
 * line. */
static int check_format(struct display *d, const char *model, bool color_0, enum vertex_format f,
			bool highp, const struct image *matcap, const struct image *map)
{
	const struct tolerance *tol = highp ? &highp_tol : &mediump_tol;
	struct gltf_options go = {.textures = GLTF_TEXTURE_BASE_COLOR};
	struct material_config cfg;
	struct material mat = {0};
	struct mesh m = {0};
	struct renderer *r = renderer_new(&d->gl, NULL);
	struct view v = {.orientation = quat_identity()};
	struct image frame = {0};
	struct agreement a;
	double share;
	int bad = 1;

	material_config_defaults(&cfg);
	if (!r || gltf_load_options(model, &go, &m) || material_load(&mat, &cfg, &m, true) ||
	    mat.features != (MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP) ||
	    (m.colors != NULL) != color_0) {
		fprintf(stderr, "the model or its base colour did not load\n");
		goto out;
	}
	renderer_set_vertex_format(r, f);
	if (renderer_set_material(r, &mat) || renderer_set_mesh(r, &m) ||
	    renderer_set_matcap(r, matcap) || renderer_set_mode(r, SHADING_VIEW, false) ||
	    renderer_set_precision(r, highp)) {
		fprintf(stderr, "the renderer failed\n");
		goto out;
	}
	d->begin_frame(d);
	renderer_draw(r, &v, SIZE, SIZE);
	d->present(d);
	if (d->read_frame(d, &frame))
		goto out;
	a = compare(&frame, color_0, matcap, map);
	share = (double)a.within / (double)a.pixels;
	bad = a.pixels < 30000 || share < tol->share || a.worst > tol->worst;
	printf("%-8s %-8s %-7s %ld pixels: %.2f%% within %d/255, worst %d/255, mean %.3f/255\n",
	       color_0 ? "COLOR_0" : "constant", f == VERTEX_COMPACT ? "compact" : "float32",
	       highp ? "highp" : "mediump", a.pixels, 100.0 * share, TOL, a.worst,
	       a.sum / (3.0 * (double)a.pixels));
out:
	image_release(&frame);
	material_release(&mat);
	mesh_release(&m);
	renderer_free(r);
	return bad;
}

static int remove_one(const char *path, const struct stat *st, int flag, struct FTW *f)
{
	(void)st, (void)flag, (void)f;
	return remove(path);
}

int main(void)
{
	struct display_config cfg = {.width = SIZE, .height = SIZE};
	char dir[] = "/tmp/base-color-check.XXXXXX", model[4096], factor_model[4096],
	     map_path[4096];
	struct display *d;
	struct image matcap = {0}, map = {0};
	int bad = 1;

	log_set_level(LOG_WARN);
	if (!mkdtemp(dir))
		return 1;
#ifdef MK_HAVE_OSMESA
	d = display_osmesa_new(&cfg);
#else /* Mesa without OSMesa: the same renders through EGL */
	d = display_egl_new(&cfg);
#endif
	snprintf(map_path, sizeof(map_path), "%s/base.png", dir);
	if (d && !write_model(dir, true, model, sizeof(model)) &&
	    !write_model(dir, false, factor_model, sizeof(factor_model)) &&
	    !image_load(map_path, &map) && !bake_matcap(BAKE_GOLD, 256, &matcap)) {
		printf("%dx%d, the gold matcap x COLOR_0 x baseColorFactor x baseColorTexture "
		       "(KHR_texture_transform); held: highp %.1f%% within %d/255 and none beyond "
		       "%d, mediump %.1f%% and none beyond %d\n",
		       SIZE, SIZE, highp_tol.share * 100, TOL, highp_tol.worst,
		       mediump_tol.share * 100, mediump_tol.worst);
		bad = check_format(d, model, true, VERTEX_COMPACT, true, &matcap, &map);
		bad |= check_format(d, model, true, VERTEX_FLOAT32, true, &matcap, &map);
		bad |= check_format(d, model, true, VERTEX_COMPACT, false, &matcap, &map);
		/* Without COLOR_0 the one colour is a constant attribute. */
		bad |= check_format(d, factor_model, false, VERTEX_COMPACT, true, &matcap, &map);
		bad |= check_format(d, factor_model, false, VERTEX_FLOAT32, false, &matcap, &map);
	}
	image_release(&matcap);
	image_release(&map);
	display_free(d);
	nftw(dir, remove_one, 8, FTW_DEPTH | FTW_PHYS);
	printf("%s\n", bad ? "FAILED" : "the base colour agrees with the reference");
	return bad;
}
