#include "parts_models.h"
#include "gltf_parts.h"
#include "scene/mesh/mesh.h"
#include "util/image.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The triangles of src for which keep(t) holds, as a mesh of their own. */
static int sub_mesh(const struct mesh *src, bool (*keep)(const struct mesh *, uint32_t, void *),
		    void *arg, struct mesh *out)
{
	uint32_t *local = malloc(src->vertex_count * sizeof(uint32_t));
	uint32_t nv = 0, ni = 0;

	if (!local)
		return -1;
	memset(local, 0xff, src->vertex_count * sizeof(uint32_t));
	for (uint32_t t = 0; t < src->index_count / 3; t++)
		if (keep(src, t, arg))
			for (int k = 0; k < 3; k++, ni++)
				if (local[src->indices[t * 3 + k]] == UINT32_MAX)
					local[src->indices[t * 3 + k]] = nv++;
	if (mesh_alloc(out, nv, ni, true)) {
		free(local);
		return -1;
	}
	ni = 0;
	for (uint32_t t = 0; t < src->index_count / 3; t++)
		if (keep(src, t, arg))
			for (int k = 0; k < 3; k++)
				out->indices[ni++] = local[src->indices[t * 3 + k]];
	for (uint32_t v = 0; v < src->vertex_count; v++) {
		uint32_t l = local[v];

		if (l == UINT32_MAX)
			continue;
		memcpy(out->positions + l * 3, src->positions + v * 3, 12);
		memcpy(out->normals + l * 3, src->normals + v * 3, 12);
		memcpy(out->uvs + l * 2, src->uvs + v * 2, 8);
	}
	free(local);
	return 0;
}

static double centroid(const struct mesh *m, uint32_t t, int axis)
{
	double c = 0;

	for (int k = 0; k < 3; k++)
		c += m->positions[m->indices[t * 3 + k] * 3 + axis];
	return c / 3;
}

static bool upper(const struct mesh *m, uint32_t t, void *arg)
{
	return (centroid(m, t, 1) > 0) == (arg != NULL);
}

/* Triangles whose first vertex lies in band [lo, hi) of the vertex order
 * (the knot's length). */
static bool in_band(const struct mesh *m, uint32_t t, void *arg)
{
	const uint32_t *b = arg;
	uint32_t v = m->indices[t * 3];

	return v >= b[0] && v < b[1];
}

/* A w x h quad facing +z at depth z, centred at (cx, cy), its uvs 0..1. */
static int quad(struct mesh *m, double cx, double cy, double w, double h, double z)
{
	static const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};

	if (mesh_alloc(m, 4, 6, true))
		return -1;
	for (int v = 0; v < 4; v++) {
		double u = v == 1 || v == 2, t = v >= 2;

		m->positions[v * 3] = (float)(cx + (u - 0.5) * w);
		m->positions[v * 3 + 1] = (float)(cy + (t - 0.5) * h);
		m->positions[v * 3 + 2] = (float)z;
		m->normals[v * 3] = m->normals[v * 3 + 1] = 0.0f;
		m->normals[v * 3 + 2] = 1.0f;
		m->uvs[v * 2] = (float)u;
		m->uvs[v * 2 + 1] = (float)(1.0 - t);
	}
	memcpy(m->indices, idx, sizeof(idx));
	return 0;
}

/* A leaf: a sheet bent about the vertical, its hollow towards the camera
 * (+z), its normals outwards: from the front the camera sees its back. */
static int leaf(struct mesh *m)
{
	enum { NU = 24, NV = 8 };
	uint32_t i = 0;

	if (mesh_alloc(m, (NU + 1) * (NV + 1), NU * NV * 6, true))
		return -1;
	for (int b = 0; b <= NV; b++)
		for (int a = 0; a <= NU; a++) {
			double ang = (a / (double)NU - 0.5) * 2.4, y = b / (double)NV - 0.5;
			float *p = m->positions + (b * (NU + 1) + a) * 3;
			float *n = m->normals + (b * (NU + 1) + a) * 3;

			p[0] = (float)sin(ang), p[1] = (float)(y * 1.2), p[2] = (float)-cos(ang);
			n[0] = (float)sin(ang), n[1] = 0.0f, n[2] = (float)-cos(ang);
			m->uvs[(b * (NU + 1) + a) * 2] = (float)(a / (double)NU);
			m->uvs[(b * (NU + 1) + a) * 2 + 1] = (float)(b / (double)NV);
		}
	for (int b = 0; b < NV; b++)
		for (int a = 0; a < NU; a++) {
			uint32_t v = (uint32_t)(b * (NU + 1) + a);
			/* Wound counter-clockwise seen from outside (-z side). */
			uint32_t t[6] = {v, v + NU + 1, v + 1, v + 1, v + NU + 1, v + NU + 2};

			memcpy(m->indices + i, t, sizeof(t));
			i += 6;
		}
	return 0;
}

/* 64 x 64 RGBA from a function of (x, y). */
static int png(const char *dir, const char *name, int w, int h,
	       void (*texel)(int x, int y, int w, int h, uint8_t *rgba), char *path, size_t size)
{
	struct image img;
	int ret;

	snprintf(path, size, "%s/%s", dir, name);
	if (image_alloc(&img, w, h))
		return 1;
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++)
			texel(x, y, w, h, img.rgba + (y * w + x) * 4);
	ret = image_write_png(path, &img);
	image_release(&img);
	return ret != 0;
}

static void checker(int x, int y, int w, int h, uint8_t *p)
{
	bool on = ((x * 8 / w) + (y * 8 / h)) % 2;

	p[0] = 255, p[1] = on ? 140 : 255, p[2] = on ? 0 : 255, p[3] = 255;
}

static void stripes(int x, int y, int w, int h, uint8_t *p)
{
	bool on = (x * 6 / w) % 2;

	(void)y, (void)h;
	p[0] = on ? 20 : 255, p[1] = on ? 60 : 255, p[2] = 255, p[3] = 255;
}

/* A red oval label with a white band; transparent outside the oval. */
static void label(int x, int y, int w, int h, uint8_t *p)
{
	double u = (x + 0.5) / w - 0.5, v = (y + 0.5) / h - 0.5;
	bool in = u * u / 0.2 + v * v / 0.2 < 1.0, band = fabs(v) < 0.08;

	p[0] = 220, p[1] = band ? 240 : 30, p[2] = band ? 240 : 30, p[3] = in ? 255 : 0;
}

/* A tangent-space normal map of round bumps, 8 x 8 over the map. */
static void bumps(int x, int y, int w, int h, uint8_t *p)
{
	double u = (x + 0.5) / w * 8.0, v = (y + 0.5) / h * 8.0;
	double dx = 0.8 * cos(u * 6.2832), dy = 0.8 * cos(v * 6.2832);
	double len = sqrt(dx * dx + dy * dy + 1.0);

	p[0] = (uint8_t)lround((dx / len * 0.5 + 0.5) * 255.0);
	p[1] = (uint8_t)lround((dy / len * 0.5 + 0.5) * 255.0);
	p[2] = (uint8_t)lround((1.0 / len * 0.5 + 0.5) * 255.0);
	p[3] = 255;
}

static int put_more(const char *dir, const char *name, const struct gltf_part *parts,
		    const struct gltf_part_more *more, int n)
{
	char path[4096];

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	if (gltf_write_parts_more(path, parts, more, n)) {
		fprintf(stderr, "mkmodels: cannot write %s\n", path);
		return 1;
	}
	return 0;
}

static int put(const char *dir, const char *name, const struct gltf_part *parts, int n)
{
	return put_more(dir, name, parts, NULL, n);
}

/* A label whose base map (stripes) reads TEXCOORD_0 and whose emissive
 * map reads TEXCOORD_1, through its own transform: the second set swaps
 * u and v, so the label's white band runs up the quad where the first set
 * would lay it across. */
static int two_sets(const char *dir, const struct mesh *s, const struct mesh *q,
		    const char *tex_base, const char *tex_label)
{
	static const char glow[] = "\"emissiveFactor\":[1,0.6,0.2]";
	static const char glow_info[] = "\"texCoord\":1,\"extensions\":{\"KHR_texture_transform\":{"
					"\"offset\":[0.25,0],\"scale\":[0.5,1]}}";
	struct gltf_part label[2] = {{s, {0.5, 0.5, 0.55, 1}, NULL, NULL, NULL, 1, NULL},
				     {q, {0.4, 0.4, 0.4, 1}, tex_base, glow, NULL, 1, NULL}};
	struct gltf_part_more more[2] = {{NULL, NULL, 0, 0, NULL, 0},
					 {tex_label, glow_info, 0, 0, NULL, 1}};
	float *uv1 = malloc((size_t)q->vertex_count * 8 + 1);
	int bad;

	if (!uv1)
		return 1;
	for (uint32_t i = 0; i < q->vertex_count; i++) {
		uv1[i * 2] = q->uvs[i * 2 + 1];
		uv1[i * 2 + 1] = q->uvs[i * 2];
	}
	more[1].uv1 = uv1;
	bad = put_more(dir, "parts-emissive-uv1.glb", label, more, 2);
	free(uv1);
	return bad;
}

/* Unlit, emission and spec-gloss (issue 37): a scan's unlit textured top
 * above a shaded bottom; a glowing label, its emissive map on TEXCOORD_1
 * through its own transform, before a grey body; a spec-gloss top
 * (diffuse texture and factor) above a spec-gloss bottom (factor). */
static int light_models(const char *dir, const struct mesh *s, const struct mesh *top,
			const struct mesh *bottom, const struct mesh *q, const char *tex_a,
			const char *tex_b, const char *tex_label)
{
	static const char unlit[] = "\"extensions\":{\"KHR_materials_unlit\":{}}";
	static const char glow[] =
	    "\"emissiveFactor\":[1,0.6,0.2],\"extensions\":{"
	    "\"KHR_materials_emissive_strength\":{\"emissiveStrength\":1.5}}";
	static const char glow_info[] =
	    "\"texCoord\":1,\"extensions\":{\"KHR_texture_transform\":{\"texCoord\":1,"
	    "\"offset\":[0.5,0],\"scale\":[0.5,1]}}";
	struct gltf_part scan[2] = {{top, {1, 1, 1, 1}, tex_a, unlit, NULL, 1, NULL},
				    {bottom, {1, 1, 1, 1}, tex_b, NULL, NULL, 1, NULL}};
	struct gltf_part label[2] = {{s, {0.5, 0.5, 0.55, 1}, NULL, NULL, NULL, 1, NULL},
				     {q, {0.2, 0.2, 0.2, 1}, NULL, glow, NULL, 1, NULL}};
	struct gltf_part_more label_more[2] = {{NULL, NULL, 0, 0, NULL, 0},
					       {tex_label, glow_info, 1, 0, NULL, 0}};
	struct gltf_part sg[2] = {{top, {0.9, 0.6, 0.4, 1}, tex_a, NULL, NULL, 1, NULL},
				  {bottom, {0.3, 0.5, 1, 1}, NULL, NULL, NULL, 1, NULL}};
	struct gltf_part_more sg_more[2] = {{NULL, NULL, 0, 1, NULL, 0},
					    {NULL, NULL, 0, 1, NULL, 0}};

	return put(dir, "parts-unlit.glb", scan, 2) |
	       put_more(dir, "parts-emissive.glb", label, label_more, 2) |
	       put_more(dir, "parts-specgloss.glb", sg, sg_more, 2) |
	       two_sets(dir, s, q, tex_b, tex_label);
}

int parts_models_write(const char *dir)
{
	char tex_a[4096], tex_b[4096], tex_label[4096], tex_bumps[4096];
	struct mesh s, top, bottom, q1, q2, l;
	int bad = png(dir, "tex-checker.png", 64, 64, checker, tex_a, sizeof(tex_a)) |
		  png(dir, "tex-stripes.png", 64, 64, stripes, tex_b, sizeof(tex_b)) |
		  png(dir, "tex-label.png", 128, 64, label, tex_label, sizeof(tex_label)) |
		  png(dir, "tex-bumps.png", 64, 64, bumps, tex_bumps, sizeof(tex_bumps));

	if (bad || mesh_uv_sphere(&s, 48, 24) || sub_mesh(&s, upper, &s, &top) ||
	    sub_mesh(&s, upper, NULL, &bottom))
		return 1;
	/* Two halves, each its own base map. */
	{
		struct gltf_part p[2] = {{&top, {1, 1, 1, 1}, tex_a, NULL, NULL, 1, NULL},
					 {&bottom, {1, 1, 1, 1}, tex_b, NULL, NULL, 1, NULL}};

		bad |= put(dir, "parts-textures.glb", p, 2);
	}
	/* Two halves, each its own normal map: bumps above, none below. */
	{
		struct gltf_part p[2] = {{&top, {1, 1, 1, 1}, NULL, NULL, NULL, 1, tex_bumps},
					 {&bottom, {1, 1, 1, 1}, NULL, NULL, NULL, 1, NULL}};

		bad |= put(dir, "parts-normals.glb", p, 2);
	}
	/* Two halves, each its own iridescent film: a thick one above (its
	 * hue turns fast), a thin one below. */
	{
		static const char *const film[2] = {
		    "\"extensions\":{\"KHR_materials_iridescence\":{\"iridescenceFactor\":1,"
		    "\"iridescenceThicknessMaximum\":900}}",
		    "\"extensions\":{\"KHR_materials_iridescence\":{\"iridescenceFactor\":0.6,"
		    "\"iridescenceThicknessMaximum\":150}}"};
		struct gltf_part p[2] = {{&top, {1, 1, 1, 1}, NULL, film[0], NULL, 1, NULL},
					 {&bottom, {1, 1, 1, 1}, NULL, film[1], NULL, 1, NULL}};

		bad |= put(dir, "parts-iridescence.glb", p, 2);
	}
	/* A label in front of a grey body: MASK, cut where its map is clear. */
	if (quad(&q1, 0, 0.1, 1.2, 0.6, 1.05))
		return 1;
	bad |= light_models(dir, &s, &top, &bottom, &q1, tex_a, tex_b, tex_label);
	{
		struct gltf_part p[2] = {{&s, {0.7, 0.75, 0.8, 1}, NULL, NULL, NULL, 1, NULL},
					 {&q1,
					  {1, 1, 1, 1},
					  tex_label,
					  "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.5",
					  NULL,
					  1,
					  NULL}};

		bad |= put(dir, "parts-mask.glb", p, 2);
	}
	mesh_release(&q1);
	/* Two panes of glass in front of a red body, overlapping: BLEND,
	 * drawn after it, the farther first. */
	if (quad(&q1, -0.25, 0, 1.0, 1.0, 1.1) || quad(&q2, 0.25, -0.2, 1.0, 0.8, 1.4))
		return 1;
	{
		struct gltf_part p[3] = {
		    {&s, {1, 0.35, 0.25, 1}, NULL, NULL, NULL, 1, NULL},
		    {&q2, {0.2, 1, 0.3, 0.5}, NULL, "\"alphaMode\":\"BLEND\"", NULL, 1, NULL},
		    {&q1, {0.2, 0.4, 1, 0.5}, NULL, "\"alphaMode\":\"BLEND\"", NULL, 1, NULL}};

		bad |= put(dir, "parts-blend.glb", p, 3);
	}
	/* A leaf seen from its hollow side: only double sided shows it. */
	if (leaf(&l))
		return 1;
	{
		struct gltf_part p[1] = {
		    {&l, {0.45, 0.85, 0.35, 1}, NULL, "\"doubleSided\":true", NULL, 1, NULL}};

		bad |= put(dir, "parts-leaf.glb", p, 1);
	}
	mesh_release(&q1);
	mesh_release(&q2);
	mesh_release(&l);
	mesh_release(&s);
	mesh_release(&top);
	mesh_release(&bottom);
	return bad;
}

int parts_models_write_bench(const char *dir)
{
	enum { BANDS = 64 };
	char tex[4096];
	struct mesh k, bands[BANDS];
	struct gltf_part p[BANDS];
	int bad = png(dir, "tex-checker.png", 64, 64, checker, tex, sizeof(tex));

	if (bad || mesh_torus_knot(&k, 784, 64))
		return 1;
	for (int b = 0; b < BANDS; b++) {
		uint32_t band[2] = {k.vertex_count * b / BANDS, k.vertex_count * (b + 1) / BANDS};
		double h = b / (double)BANDS * 6.2832;

		if (sub_mesh(&k, in_band, band, &bands[b]))
			return 1;
		p[b] = (struct gltf_part){
		    &bands[b],
		    {0.6 + 0.4 * cos(h), 0.6 + 0.4 * cos(h + 2.1), 0.6 + 0.4 * cos(h + 4.2), 1},
		    b % 8 ? NULL : tex,
		    NULL,
		    NULL,
		    1,
		    NULL};
	}
	bad |= put(dir, "knot-64-materials.glb", p, BANDS);
	for (int b = 0; b < BANDS; b++)
		mesh_release(&bands[b]);
	mesh_release(&k);
	return bad;
}
