#include "scene/mesh/subdivide.h"
#include "scene/mesh/texture.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Boubekeur and Alexa's shape factor. 1/2 puts the middle of an edge
 * between two points with exact normals on a circle where the circle is,
 * to second order (their 3/4 inflates low-poly silhouettes on purpose). */
#define PHONG_ALPHA 0.5

/* Edges by their two vertex indices, lower first: open addressing. */
struct edge_map {
	uint64_t *keys;	 /* (lo << 32 | hi) + 1; 0 marks an empty slot */
	uint32_t *first; /* the edge's first inner vertex */
	size_t mask;
	uint32_t count;
};

struct subdiv {
	const struct mesh *in;
	struct mesh *out;
	struct edge_map edges;
	int n;
};

static int edges_init(struct edge_map *e, size_t max_edges)
{
	size_t cap = 16;

	while (cap < max_edges * 2)
		cap *= 2;
	e->keys = calloc(cap, sizeof(*e->keys));
	e->first = malloc(cap * sizeof(*e->first));
	e->mask = cap - 1;
	e->count = 0;
	return e->keys && e->first ? 0 : -ENOMEM;
}

static void edges_release(struct edge_map *e)
{
	free(e->keys);
	free(e->first);
}

static size_t edge_slot(const struct edge_map *e, uint32_t a, uint32_t b)
{
	uint64_t key = ((uint64_t)(a < b ? a : b) << 32 | (a < b ? b : a)) + 1;
	/* A multiplicative hash spreads the sequential indices of a grid. */
	size_t i = (size_t)((key * 0x9E3779B97F4A7C15ull) >> 20) & e->mask;

	while (e->keys[i] && e->keys[i] != key)
		i = (i + 1) & e->mask;
	return i;
}

static void edges_insert(struct edge_map *e, uint32_t a, uint32_t b, uint32_t base, int n)
{
	size_t i = edge_slot(e, a, b);

	if (e->keys[i])
		return;
	e->keys[i] = ((uint64_t)(a < b ? a : b) << 32 | (a < b ? b : a)) + 1;
	e->first[i] = base + e->count++ * (uint32_t)(n - 1);
}

/* The vertex k segments from a towards b (0 < k < n). */
static uint32_t edge_vertex(const struct subdiv *s, uint32_t a, uint32_t b, int k)
{
	uint32_t first = s->edges.first[edge_slot(&s->edges, a, b)];

	return first + (uint32_t)(a < b ? k - 1 : s->n - k - 1);
}

/* Orders an edge's ends by what they are (position, then normal), not by
 * index, so a seam's two copies of an edge compute identical points. */
static int corner_compare(const struct mesh *m, uint32_t a, uint32_t b)
{
	const float *x[2] = {m->positions + (size_t)a * 3, m->normals + (size_t)a * 3};
	const float *y[2] = {m->positions + (size_t)b * 3, m->normals + (size_t)b * 3};

	for (int i = 0; i < 2; i++)
		for (int k = 0; k < 3; k++)
			if (x[i][k] != y[i][k])
				return x[i][k] < y[i][k] ? -1 : 1;
	return 0;
}

/* Phong tessellation: q = sum w_i p_i, each p_i's tangent plane pulls q
 * to itself, and the result moves alpha of the way to the weighted mean
 * of those projections: q - alpha sum w_i ((q - p_i).n_i) n_i. */
static void put_vertex(const struct subdiv *s, uint32_t out, const uint32_t *v, const double *w,
		       int k)
{
	const struct mesh *in = s->in;
	struct mesh *o = s->out;
	double q[3] = {0, 0, 0}, p[3], nrm[3] = {0, 0, 0}, len;

	for (int i = 0; i < k; i++)
		for (int c = 0; c < 3; c++) {
			q[c] += w[i] * in->positions[(size_t)v[i] * 3 + c];
			nrm[c] += w[i] * in->normals[(size_t)v[i] * 3 + c];
		}
	memcpy(p, q, sizeof(p));
	for (int i = 0; i < k; i++) {
		const float *pi = in->positions + (size_t)v[i] * 3,
			    *ni = in->normals + (size_t)v[i] * 3;
		double d = (q[0] - pi[0]) * ni[0] + (q[1] - pi[1]) * ni[1] + (q[2] - pi[2]) * ni[2];

		for (int c = 0; c < 3; c++)
			p[c] -= PHONG_ALPHA * w[i] * d * ni[c];
	}
	len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
	for (int c = 0; c < 3; c++) {
		o->positions[(size_t)out * 3 + c] = (float)p[c];
		/* Opposed normals cancel: the first corner's stands in. */
		o->normals[(size_t)out * 3 + c] = len > 1e-12 && isfinite(len)
						      ? (float)(nrm[c] / len)
						      : in->normals[(size_t)v[0] * 3 + c];
	}
	for (int c = 0; in->uvs && c < 2; c++) {
		double u = 0;

		for (int i = 0; i < k; i++)
			u += w[i] * in->uvs[(size_t)v[i] * 2 + c];
		o->uvs[(size_t)out * 2 + c] = (float)u;
	}
	for (int c = 0; in->uv1 && c < 2; c++) {
		double u = 0;

		for (int i = 0; i < k; i++)
			u += w[i] * in->uv1[(size_t)v[i] * 2 + c];
		o->uv1[(size_t)out * 2 + c] = (float)u;
	}
	for (int c = 0; in->colors && c < 4; c++) {
		double u = 0;

		for (int i = 0; i < k; i++)
			u += w[i] * in->colors[(size_t)v[i] * 4 + c];
		o->colors[(size_t)out * 4 + c] = (float)u;
	}
	for (int c = 0; in->tangents && c < 4; c++) {
		double t = 0;

		/* Handedness is not interpolated: it is the first corner's. */
		for (int i = 0; i < k && c < 3; i++)
			t += w[i] * in->tangents[(size_t)v[i] * 4 + c];
		o->tangents[(size_t)out * 4 + c] =
		    c < 3 ? (float)t : in->tangents[(size_t)v[0] * 4 + 3];
	}
}

static void put_edge(const struct subdiv *s, uint32_t a, uint32_t b, uint32_t first)
{
	bool swap = corner_compare(s->in, a, b) > 0;
	uint32_t v[2] = {swap ? b : a, swap ? a : b};

	for (int k = 1; k < s->n; k++) {
		int j = swap ? s->n - k : k;
		double w[2] = {(double)(s->n - j) / s->n, (double)j / s->n};

		put_vertex(s, first + (uint32_t)k - 1, v, w, 2);
	}
}

/* Vertex (i, j) of a triangle's grid: i segments towards its second
 * corner, j towards its third. */
static uint32_t grid_vertex(const struct subdiv *s, const uint32_t *tri, uint32_t inner, int i,
			    int j)
{
	int n = s->n;

	if (i == 0 && j == 0)
		return tri[0];
	if (j == 0)
		return i == n ? tri[1] : edge_vertex(s, tri[0], tri[1], i);
	if (i == 0)
		return j == n ? tri[2] : edge_vertex(s, tri[0], tri[2], j);
	if (i + j == n)
		return edge_vertex(s, tri[1], tri[2], j);
	return inner + (uint32_t)((j - 1) * (n - 1) - (j - 1) * j / 2 + (i - 1));
}

static void put_triangle(const struct subdiv *s, uint32_t t, uint32_t inner, uint32_t *idx)
{
	const uint32_t *tri = s->in->indices + (size_t)t * 3;
	int n = s->n;

	for (int j = 1; j < n; j++)
		for (int i = 1; i + j < n; i++) {
			double w[3] = {(double)(n - i - j) / n, (double)i / n, (double)j / n};

			put_vertex(s, grid_vertex(s, tri, inner, i, j), tri, w, 3);
		}
	/* Each cell's two triangles, wound as the original. */
	for (int j = 0; j < n; j++)
		for (int i = 0; i + j < n; i++) {
			*idx++ = grid_vertex(s, tri, inner, i, j);
			*idx++ = grid_vertex(s, tri, inner, i + 1, j);
			*idx++ = grid_vertex(s, tri, inner, i, j + 1);
			if (i + j + 1 < n) {
				*idx++ = grid_vertex(s, tri, inner, i + 1, j);
				*idx++ = grid_vertex(s, tri, inner, i + 1, j + 1);
				*idx++ = grid_vertex(s, tri, inner, i, j + 1);
			}
		}
}

static int alloc_out(struct subdiv *s, uint64_t nv, uint64_t ni)
{
	if (nv > UINT32_MAX || ni > UINT32_MAX)
		return -EINVAL;
	if (mesh_alloc(s->out, (uint32_t)nv, (uint32_t)ni, s->in->uvs != NULL))
		return -ENOMEM;
	if (s->in->tangents && mesh_alloc_tangents(s->out))
		return -ENOMEM;
	if (s->in->colors && mesh_alloc_colors(s->out))
		return -ENOMEM;
	if (s->in->uv1 && mesh_alloc_uv1(s->out, NULL))
		return -ENOMEM;
	return 0;
}

int subdivide_mesh(const struct mesh *in, int n, struct mesh *out)
{
	struct subdiv s = {.in = in, .out = out, .n = n};
	uint32_t nt = in->index_count / 3, inner_per_tri = (uint32_t)((n - 1) * (n - 2) / 2);
	uint64_t nv;
	int ret = -EINVAL;

	memset(out, 0, sizeof(*out));
	if (n < 1 || n > SUBDIVIDE_MAX_SEGMENTS)
		return -EINVAL;
	ret = edges_init(&s.edges, (size_t)nt * 3);
	for (uint32_t t = 0; t < nt && !ret; t++)
		for (int k = 0; k < 3; k++)
			edges_insert(&s.edges, in->indices[t * 3 + k],
				     in->indices[t * 3 + (k + 1) % 3], in->vertex_count, n);
	nv = in->vertex_count + (uint64_t)s.edges.count * (uint64_t)(n - 1) +
	     (uint64_t)nt * inner_per_tri;
	if (!ret)
		ret = alloc_out(&s, nv, (uint64_t)nt * 3 * (uint64_t)n * (uint64_t)n);
	if (ret)
		goto out;
	memcpy(out->positions, in->positions, (size_t)in->vertex_count * 12);
	memcpy(out->normals, in->normals, (size_t)in->vertex_count * 12);
	if (in->uvs)
		memcpy(out->uvs, in->uvs, (size_t)in->vertex_count * 8);
	if (in->tangents)
		memcpy(out->tangents, in->tangents, (size_t)in->vertex_count * 16);
	if (in->colors)
		memcpy(out->colors, in->colors, (size_t)in->vertex_count * 16);
	if (in->uv1)
		memcpy(out->uv1, in->uv1, (size_t)in->vertex_count * 8);
	for (size_t i = 0; i <= s.edges.mask; i++)
		if (s.edges.keys[i]) {
			uint64_t key = s.edges.keys[i] - 1;

			put_edge(&s, (uint32_t)(key >> 32), (uint32_t)key, s.edges.first[i]);
		}
	for (uint32_t t = 0; t < nt; t++)
		put_triangle(
		    &s, t, in->vertex_count + s.edges.count * (uint32_t)(n - 1) + t * inner_per_tri,
		    out->indices + (size_t)t * 3 * (size_t)n * (size_t)n);
out:
	edges_release(&s.edges);
	if (ret)
		mesh_release(out);
	return ret;
}

static int compare_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* The 90th percentile of up to 3 x 4096 sampled edges: by model length
 * and by the height-map texels they span. */
#define SAMPLE_TRIANGLES 4096

static void edge_percentiles(const struct mesh *m, const struct image *height, double *len90,
			     double *texels90)
{
	uint32_t nt = m->index_count / 3, step = nt > SAMPLE_TRIANGLES ? nt / SAMPLE_TRIANGLES : 1;
	double len[SAMPLE_TRIANGLES * 3], tex[SAMPLE_TRIANGLES * 3];
	size_t n = 0;

	for (uint32_t t = 0; t < nt && n + 3 <= SAMPLE_TRIANGLES * 3; t += step)
		for (int k = 0; k < 3; k++, n++) {
			uint32_t a = m->indices[t * 3 + k], b = m->indices[t * 3 + (k + 1) % 3];
			const float *pa = m->positions + (size_t)a * 3,
				    *pb = m->positions + (size_t)b * 3;

			len[n] = sqrt(((double)pa[0] - pb[0]) * ((double)pa[0] - pb[0]) +
				      ((double)pa[1] - pb[1]) * ((double)pa[1] - pb[1]) +
				      ((double)pa[2] - pb[2]) * ((double)pa[2] - pb[2]));
			tex[n] = INFINITY;
			if (height && height->width && m->uvs)
				tex[n] =
				    hypot((m->uvs[a * 2] - m->uvs[b * 2]) * height->width,
					  (m->uvs[a * 2 + 1] - m->uvs[b * 2 + 1]) * height->height);
		}
	qsort(len, n, sizeof(double), compare_double);
	qsort(tex, n, sizeof(double), compare_double);
	*len90 = n ? len[n * 9 / 10] : 0.0;
	*texels90 = n ? tex[n * 9 / 10] : 0.0;
}

int subdivide_segments(const struct mesh *m, double px_per_unit, double target_px,
		       const struct image *height, uint64_t max_triangles)
{
	uint64_t nt = m->index_count / 3;
	double len90, tex90, want;
	int n = 1;

	if (!nt || !(target_px > 0))
		return 1;
	edge_percentiles(m, height, &len90, &tex90);
	want = fmin(len90 * px_per_unit / target_px, tex90);
	while (n < SUBDIVIDE_MAX_SEGMENTS && n < want &&
	       nt * (uint64_t)(n + 1) * (uint64_t)(n + 1) <= max_triangles)
		n++;
	return n;
}

int displace_mesh(struct mesh *m, const struct image *height, double scale)
{
	uint32_t nv = m->vertex_count;
	uint32_t *rep = malloc((size_t)nv * sizeof(*rep) + 1);
	double *acc = calloc((size_t)nv * 5 + 1, sizeof(double)); /* normal, height, count */
	int ret = -ENOMEM;

	if (!m->uvs || !height->width) {
		ret = -EINVAL;
		goto out;
	}
	if (!rep || !acc || mesh_weld(m->positions, nv, rep))
		goto out;
	for (uint32_t v = 0; v < nv; v++) {
		double *a = acc + (size_t)rep[v] * 5;

		for (int c = 0; c < 3; c++)
			a[c] += m->normals[(size_t)v * 3 + c];
		a[3] += texture_height(height, m->uvs[(size_t)v * 2], m->uvs[(size_t)v * 2 + 1]);
		a[4] += 1.0;
	}
	for (uint32_t v = 0; v < nv; v++) {
		const double *a = acc + (size_t)rep[v] * 5;
		double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
		double d = a[3] / a[4] * scale;

		for (int c = 0; c < 3; c++) {
			double dir = len > 1e-12 ? a[c] / len : m->normals[(size_t)v * 3 + c];
			float *p = m->positions + (size_t)v * 3 + c;

			*p = (float)(*p + dir * d);
		}
	}
	ret = mesh_generate_normals(m->positions, m->indices, m->index_count, 0, nv, m->normals);
out:
	free(rep);
	free(acc);
	return ret;
}
