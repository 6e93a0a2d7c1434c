#include "scene/mesh/mesh.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* glTF's defaults: one truth for a material made (mesh_material_default)
 * and for the one a mesh without materials draws with (mesh_material_at).
 * const: never written. */
static const struct mesh_material material_default = {
    .base_color = {1, 1, 1},
    .base_alpha = 1,
    .alpha_cutoff = 0.5f,
    .iridescence_ior = 1.3f,
    .thickness_min = 100,
    .thickness_max = 400,
    .normal_scale = 1,
    .occlusion_strength = 1,
    .base_transform = {1, 0, 0, 1, 0, 0},
    .emissive_transform = {1, 0, 0, 1, 0, 0},
};

void mesh_material_default(struct mesh_material *mat)
{
	*mat = material_default;
}

int mesh_alloc(struct mesh *m, uint32_t vertex_count, uint32_t index_count, bool with_uvs)
{
	memset(m, 0, sizeof(*m));
	m->positions = malloc((size_t)vertex_count * 3 * sizeof(float) + 1);
	m->normals = malloc((size_t)vertex_count * 3 * sizeof(float) + 1);
	m->uvs = with_uvs ? malloc((size_t)vertex_count * 2 * sizeof(float) + 1) : NULL;
	m->indices = malloc((size_t)index_count * sizeof(uint32_t) + 1);
	if (!m->positions || !m->normals || !m->indices || (with_uvs && !m->uvs)) {
		mesh_release(m);
		return -ENOMEM;
	}
	m->vertex_count = vertex_count;
	m->index_count = index_count;
	return 0;
}

int mesh_alloc_tangents(struct mesh *m)
{
	free(m->tangents);
	m->tangents = malloc((size_t)m->vertex_count * 4 * sizeof(float) + 1);
	return m->tangents ? 0 : -ENOMEM;
}

int mesh_alloc_colors(struct mesh *m)
{
	free(m->colors);
	m->colors = malloc((size_t)m->vertex_count * 4 * sizeof(float) + 1);
	return m->colors ? 0 : -ENOMEM;
}

int mesh_alloc_uv1(struct mesh *m, const float *from)
{
	free(m->uv1);
	m->uv1 = malloc((size_t)m->vertex_count * 2 * sizeof(float) + 1);
	if (m->uv1 && from)
		memcpy(m->uv1, from, (size_t)m->vertex_count * 2 * sizeof(float));
	return m->uv1 ? 0 : -ENOMEM;
}

void mesh_release(struct mesh *m)
{
	free(m->positions);
	free(m->normals);
	free(m->uvs);
	free(m->uv1);
	free(m->tangents);
	free(m->colors);
	free(m->indices);
	free(m->flat);
	for (uint32_t i = 0; m->materials && i < m->material_count; i++)
		mesh_material_release(&m->materials[i]);
	free(m->materials);
	free(m->ranges);
	mesh_variants_release(m);
	memset(m, 0, sizeof(*m));
}

void mesh_material_release(struct mesh_material *mat)
{
	image_release(&mat->normal_map);
	image_release(&mat->occlusion_map);
	image_release(&mat->thickness_map);
	image_release(&mat->base_map);
	image_release(&mat->emissive_map);
}

int mesh_alloc_ranges(struct mesh *m, uint32_t n, uint32_t k)
{
	struct mesh_range *r = calloc(n ? n : 1, sizeof(*r));
	struct mesh_material *mats = calloc(k ? k : 1, sizeof(*mats));

	if (!r || !mats) {
		free(r);
		free(mats);
		return -ENOMEM;
	}
	for (uint32_t i = 0; m->materials && i < m->material_count; i++)
		mesh_material_release(&m->materials[i]);
	free(m->materials);
	free(m->ranges);
	for (uint32_t i = 0; i < k; i++)
		mesh_material_default(&mats[i]);
	m->ranges = r;
	m->range_count = n;
	m->materials = mats;
	m->material_count = k;
	return 0;
}

void mesh_range_centers(struct mesh *m)
{
	for (uint32_t r = 0; r < m->range_count; r++) {
		struct mesh_range *g = &m->ranges[r];
		float lo[3] = {INFINITY, INFINITY, INFINITY},
		      hi[3] = {-INFINITY, -INFINITY, -INFINITY};

		for (uint32_t i = g->first_index; i < g->first_index + g->index_count; i++)
			for (int k = 0; k < 3; k++) {
				float x = m->positions[(size_t)m->indices[i] * 3 + k];

				lo[k] = fminf(lo[k], x);
				hi[k] = fmaxf(hi[k], x);
			}
		for (int k = 0; k < 3; k++)
			g->center[k] = g->index_count ? (lo[k] + hi[k]) * 0.5f : 0.0f;
	}
}

void mesh_fit_of(const double *world, uint32_t count, double fit[4])
{
	double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
	double c[3] = {0, 0, 0}, r2 = 0.0, scale = 1.0;

	for (uint32_t i = 0; i < count; i++)
		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], world[i * 3 + k]);
			hi[k] = fmax(hi[k], world[i * 3 + k]);
		}
	if (count)
		for (int k = 0; k < 3; k++)
			c[k] = lo[k] + (hi[k] - lo[k]) / 2.0;
	for (uint32_t i = 0; i < count; i++) {
		double d2 = 0.0;

		for (int k = 0; k < 3; k++)
			d2 += (world[i * 3 + k] - c[k]) * (world[i * 3 + k] - c[k]);
		r2 = fmax(r2, d2);
	}
	if (r2 > 0.0 && isfinite(r2))
		scale = 1.0 / sqrt(r2);
	for (int k = 0; k < 3; k++)
		fit[k] = c[k];
	fit[3] = scale;
}

void mesh_fit_positions(const double *world, uint32_t count, float *out)
{
	double fit[4];

	mesh_fit_of(world, count, fit);
	for (uint32_t i = 0; i < count; i++)
		for (int k = 0; k < 3; k++)
			out[i * 3 + k] = (float)((world[i * 3 + k] - fit[k]) * fit[3]);
}

void mesh_box(const double *world, uint32_t count, const double *center, double box[6], double *r2)
{
	*r2 = 0.0;
	for (int k = 0; k < 3; k++) {
		box[k] = INFINITY;
		box[3 + k] = -INFINITY;
	}
	for (uint32_t i = 0; i < count; i++) {
		double d2 = 0.0;

		for (int k = 0; k < 3; k++) {
			double v = world[i * 3 + k];

			box[k] = fmin(box[k], v);
			box[3 + k] = fmax(box[3 + k], v);
			if (center)
				d2 += (v - center[k]) * (v - center[k]);
		}
		*r2 = fmax(*r2, d2);
	}
}

void mesh_fit_to(const double *world, uint32_t count, const double center[3], double scale,
		 float *out)
{
	for (uint32_t i = 0; i < count; i++)
		for (int k = 0; k < 3; k++)
			out[i * 3 + k] = (float)((world[i * 3 + k] - center[k]) * scale);
}

struct weld_key {
	const float *p;
	uint32_t v;
};

/* By value, so -0.0 and 0.0 (a pole, a seam) are one position. */
static int position_compare(const float *a, const float *b)
{
	for (int k = 0; k < 3; k++)
		if (a[k] != b[k])
			return a[k] < b[k] ? -1 : 1;
	return 0;
}

static int weld_compare(const void *a, const void *b)
{
	const struct weld_key *x = a, *y = b;
	int c = position_compare(x->p, y->p);

	if (c)
		return c;
	return x->v < y->v ? -1 : x->v > y->v;
}

/* The triangle's (b - a) x (c - a) in double: its length is twice the
 * area. One place for the smooth normals' weights and the flat ones. */
static void face_cross(const float *a, const float *b, const float *c, double n[3])
{
	double e1[3], e2[3];

	for (int k = 0; k < 3; k++) {
		e1[k] = (double)b[k] - a[k];
		e2[k] = (double)c[k] - a[k];
	}
	n[0] = e1[1] * e2[2] - e1[2] * e2[1];
	n[1] = e1[2] * e2[0] - e1[0] * e2[2];
	n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

static void accumulate_faces(const float *pos, const uint32_t *idx, uint32_t index_count,
			     const uint32_t *rep, uint32_t first, double *acc)
{
	for (uint32_t t = 0; t + 2 < index_count; t += 3) {
		double n[3];

		/* The cross product's length is twice the area: the weight. */
		face_cross(pos + (size_t)idx[t] * 3, pos + (size_t)idx[t + 1] * 3,
			   pos + (size_t)idx[t + 2] * 3, n);
		for (int j = 0; j < 3; j++)
			for (int k = 0; k < 3; k++)
				acc[(size_t)rep[idx[t + j] - first] * 3 + k] += n[k];
	}
}

int mesh_weld(const float *positions, uint32_t count, uint32_t *rep)
{
	struct weld_key *keys = malloc((size_t)count * sizeof(*keys) + 1);

	if (!keys)
		return -ENOMEM;
	for (uint32_t i = 0; i < count; i++)
		keys[i] = (struct weld_key){positions + (size_t)i * 3, i};
	qsort(keys, count, sizeof(*keys), weld_compare);
	for (uint32_t i = 0; i < count; i++) {
		bool same = i > 0 && position_compare(keys[i].p, keys[i - 1].p) == 0;

		rep[keys[i].v] = same ? rep[keys[i - 1].v] : keys[i].v;
	}
	free(keys);
	return 0;
}

int mesh_generate_normals(const float *positions, const uint32_t *idx, uint32_t index_count,
			  uint32_t first, uint32_t count, float *normals)
{
	uint32_t *rep = malloc((size_t)count * sizeof(*rep) + 1);
	double *acc = calloc((size_t)count * 3 + 1, sizeof(double));
	int ret = -ENOMEM;

	/* Each vertex accumulates into the first vertex at its position. */
	if (!rep || !acc || mesh_weld(positions + (size_t)first * 3, count, rep))
		goto out;
	accumulate_faces(positions, idx, index_count, rep, first, acc);
	for (uint32_t i = 0; i < count; i++) {
		const double *n = acc + (size_t)rep[i] * 3;
		double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		float *out = normals + (size_t)(first + i) * 3;

		for (int k = 0; k < 3; k++)
			out[k] = len > 0.0 && isfinite(len) ? (float)(n[k] / len) : (k == 2);
	}
	ret = 0;
out:
	free(rep);
	free(acc);
	return ret;
}

void mesh_face_normal(const float *a, const float *b, const float *c, float out[3])
{
	double n[3], len;

	face_cross(a, b, c, n);
	len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	for (int k = 0; k < 3; k++)
		out[k] = len > 0.0 && isfinite(len) ? (float)(n[k] / len) : (k == 2);
}

void mesh_flat_normals(const float *positions, const uint32_t *idx, uint32_t index_count,
		       float *normals)
{
	for (uint32_t t = 0; t + 2 < index_count; t += 3) {
		float n[3];

		mesh_face_normal(positions + (size_t)idx[t] * 3, positions + (size_t)idx[t + 1] * 3,
				 positions + (size_t)idx[t + 2] * 3, n);
		for (int j = 0; j < 3; j++)
			memcpy(normals + (size_t)idx[t + j] * 3, n, sizeof(n));
	}
}

/* Every image a material holds, in one list: a map added to struct
 * mesh_material and not here would be copied by a copy of the factors
 * and, worse, missed by mesh_material_decoded, so that a model whose only
 * texture it is would be cached as if it had none and drawn without it
 * from the cache (as the emissive map was). */
#define MATERIAL_IMAGES 5
static void material_images(const struct mesh_material *m, const struct image *out[])
{
	out[0] = &m->normal_map, out[1] = &m->occlusion_map, out[2] = &m->thickness_map;
	out[3] = &m->base_map, out[4] = &m->emissive_map;
}

bool mesh_material_decoded(const struct mesh_material *m)
{
	const struct image *images[MATERIAL_IMAGES];

	material_images(m, images);
	for (int i = 0; i < MATERIAL_IMAGES; i++)
		if (images[i]->width)
			return true;
	return false;
}

/* An image left out of a copy of the factors. */
static void drop_images(struct mesh_material *m)
{
	const struct image *images[MATERIAL_IMAGES];

	material_images(m, images);
	for (int i = 0; i < MATERIAL_IMAGES; i++)
		memset((struct image *)images[i], 0, sizeof(*images[i]));
}

int mesh_copy_factors(struct mesh *to, const struct mesh *from)
{
	size_t n = from->material_count;

	to->has_colors = from->has_colors;
	memcpy(to->fit, from->fit, sizeof(to->fit));
	memcpy(to->vertex_color, from->vertex_color, sizeof(to->vertex_color));
	to->node_count = from->node_count;
	memcpy(to->nodes, from->nodes, sizeof(to->nodes));
	to->materials = n ? malloc(n * sizeof(*to->materials)) : NULL;
	to->material_count = 0;
	if (n && !to->materials)
		return -ENOMEM;
	for (size_t k = 0; k < n; k++) {
		to->materials[k] = from->materials[k];
		drop_images(&to->materials[k]);
	}
	to->material_count = (uint32_t)n;
	return 0;
}

void mesh_material_vertex_color(const struct mesh_material *mat, float rgba[4])
{
	for (int k = 0; k < 3; k++)
		rgba[k] = mat->base_color[k];
	rgba[3] = 1.0f;
}

const struct mesh_material *mesh_material_at(const struct mesh *m, uint32_t k)
{
	return k < m->material_count ? &m->materials[k] : &material_default;
}

bool mesh_materials_any(const struct mesh *m, bool (*pred)(const struct mesh_material *))
{
	for (uint32_t k = 0; k < m->material_count; k++)
		if (pred(&m->materials[k]))
			return true;
	return false;
}

const struct mesh_material *mesh_material_first(const struct mesh *m)
{
	for (uint32_t k = 0; k < m->material_count; k++)
		if (m->materials[k].present)
			return &m->materials[k];
	return mesh_material_at(m, m->material_count);
}

unsigned mesh_images_decoded(const struct mesh *m)
{
	unsigned n = 0;

	for (uint32_t k = 0; k < m->material_count; k++)
		n += m->materials[k].images_decoded;
	return n;
}

int mesh_variant_find(const struct mesh *m, const char *name)
{
	for (uint32_t v = 0; name && v < m->variant_count; v++)
		if (!strcmp(m->variant_names[v], name))
			return (int)v;
	return -1;
}

uint32_t mesh_range_material(const struct mesh *m, int v, uint32_t r)
{
	if (v < 0 || (uint32_t)v >= m->variant_count || !m->variant_materials ||
	    r >= m->variant_ranges)
		return m->ranges[r].material;
	return m->variant_materials[(size_t)v * m->range_count + r];
}

void mesh_variants_release(struct mesh *m)
{
	for (uint32_t v = 0; m->variant_names && v < m->variant_count; v++)
		free(m->variant_names[v]);
	free(m->variant_names);
	free(m->variant_materials);
	m->variant_names = NULL;
	m->variant_materials = NULL;
	m->variant_count = 0;
	m->variant_ranges = 0;
	m->colors_by_material = false;
}

void mesh_variants_move(struct mesh *to, struct mesh *from)
{
	mesh_variants_release(to);
	to->variant_count = from->variant_count;
	to->variant_ranges = from->variant_ranges;
	to->variant_names = from->variant_names;
	to->variant_materials = from->variant_materials;
	to->colors_by_material = from->colors_by_material;
	from->variant_names = NULL;
	from->variant_materials = NULL;
	mesh_variants_release(from);
}
