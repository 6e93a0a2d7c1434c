#include "scene/mesh/tangent.h"
#include "util/math3d.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NO_TWIN UINT32_MAX

/* A triangle's UV frame: unit tangent (+u) and bitangent (-v, the image's
 * up), and its handedness, 0 when the UVs or the triangle are degenerate
 * and it has no frame to give. */
struct face {
	double t[3], b[3];
	int sign;
};

static void corner_edges(const struct mesh *m, uint32_t t, int k, double e1[3], double e2[3])
{
	const float *p = m->positions + (size_t)m->indices[t * 3 + k] * 3;
	const float *a = m->positions + (size_t)m->indices[t * 3 + (k + 1) % 3] * 3;
	const float *b = m->positions + (size_t)m->indices[t * 3 + (k + 2) % 3] * 3;

	for (int c = 0; c < 3; c++) {
		e1[c] = (double)a[c] - p[c];
		e2[c] = (double)b[c] - p[c];
	}
}

/* Each triangle counts at a vertex by its angle there, as MikkTSpace
 * does, so the result does not depend on how a surface is triangulated. */
static double corner_angle(const struct mesh *m, uint32_t t, int k)
{
	double e1[3], e2[3], c[3];

	corner_edges(m, t, k, e1, e2);
	vec3_cross(e1, e2, c);
	double a = atan2(sqrt(vec3_dot(c, c)), vec3_dot(e1, e2));

	return isfinite(a) ? a : 0.0;
}

/* Solve dP = T du + S dv over the triangle's two edges: T = dP/du, and
 * the glTF bitangent is -S (v runs down the image). The handedness is
 * -sign(r): r < 0 for UVs laid out like the image seen from the front. */
static void face_frame(const struct mesh *m, uint32_t t, struct face *f)
{
	const uint32_t *ix = m->indices + (size_t)t * 3;
	const float *uv0 = m->uvs + (size_t)ix[0] * 2, *uv1 = m->uvs + (size_t)ix[1] * 2,
		    *uv2 = m->uvs + (size_t)ix[2] * 2;
	double e1[3], e2[3], area[3];
	double du1 = (double)uv1[0] - uv0[0], dv1 = (double)uv1[1] - uv0[1];
	double du2 = (double)uv2[0] - uv0[0], dv2 = (double)uv2[1] - uv0[1];
	double r = du1 * dv2 - du2 * dv1, s = hypot(du1, dv1) * hypot(du2, dv2);

	f->sign = 0;
	/* Relative to the UV edges' lengths, so tiny UV islands still count. */
	if (!(s > 0.0) || !(fabs(r) > 1e-9 * s) || !isfinite(r))
		return;
	corner_edges(m, t, 0, e1, e2);
	vec3_cross(e1, e2, area);
	/* A zero-area triangle (collinear corners) has no surface to follow. */
	if (!(sqrt(vec3_dot(area, area)) > 1e-12 * sqrt(vec3_dot(e1, e1) * vec3_dot(e2, e2))))
		return;
	for (int c = 0; c < 3; c++) {
		f->t[c] = (e1[c] * dv2 - e2[c] * dv1) / r;
		f->b[c] = -(e2[c] * du1 - e1[c] * du2) / r;
	}
	if (vec3_normalize(f->t) && vec3_normalize(f->b))
		f->sign = r < 0 ? 1 : -1;
}

/* Any unit vector normal to n (n unit): from the axis least along n. */
static void any_perpendicular(const double n[3], double out[3])
{
	int k = fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0
		: fabs(n[1]) <= fabs(n[2])			     ? 1
								     : 2;
	double axis[3] = {k == 0, k == 1, k == 2};
	double d = vec3_dot(n, axis);

	for (int c = 0; c < 3; c++)
		out[c] = axis[c] - n[c] * d;
	vec3_normalize(out);
}

/* Gram-Schmidt of the accumulated tangent against the normal. When it
 * cancelled out (a pole, where the frame turns all the way round), the
 * bitangent gives it (T = B x N), and failing that any perpendicular.
 * The handedness is read from the bitangent; fallback is used when that
 * is lost too. */
static void frame_finish(const float *normal, const double tan[3], const double bit[3],
			 int fallback, float out[4])
{
	double n[3] = {normal[0], normal[1], normal[2]}, t[3], nb[3];
	double d = 0.0;

	if (!vec3_normalize(n))
		n[0] = n[1] = 0.0, n[2] = 1.0;
	d = vec3_dot(n, tan);
	for (int c = 0; c < 3; c++)
		t[c] = tan[c] - n[c] * d;
	if (!vec3_normalize(t)) {
		vec3_cross(bit, n, t);
		d = vec3_dot(n, t);
		for (int c = 0; c < 3; c++)
			t[c] -= n[c] * d;
		if (!vec3_normalize(t))
			any_perpendicular(n, t);
	}
	vec3_cross(n, t, nb);
	d = vec3_dot(nb, bit);
	for (int c = 0; c < 3; c++)
		out[c] = (float)t[c];
	out[3] = d < 0.0 ? -1.0f : d > 0.0 ? 1.0f : fallback < 0 ? -1.0f : 1.0f;
}

static int grow(float **a, size_t n)
{
	float *p = realloc(*a, n * sizeof(float) + 1);

	if (!p)
		return -ENOMEM;
	*a = p;
	return 0;
}

/* Add a twin for every vertex used by both handednesses (heavier side
 * keeps the original). twin[v] is its index, or NO_TWIN. */
static int split_mirrored(struct mesh *m, const double *weight, uint32_t *twin)
{
	uint32_t n = m->vertex_count, extra = 0;

	for (uint32_t v = 0; v < n; v++) {
		twin[v] = NO_TWIN;
		if (weight[v * 2] > 0.0 && weight[v * 2 + 1] > 0.0)
			twin[v] = n + extra++;
	}
	if (!extra)
		return 0;
	/* Every per-vertex array grows with the twins, the colours too. */
	if (grow(&m->positions, (size_t)(n + extra) * 3) ||
	    grow(&m->normals, (size_t)(n + extra) * 3) || grow(&m->uvs, (size_t)(n + extra) * 2) ||
	    (m->colors && grow(&m->colors, (size_t)(n + extra) * 4)) ||
	    (m->uv1 && grow(&m->uv1, (size_t)(n + extra) * 2)))
		return -ENOMEM;
	for (uint32_t v = 0; v < n; v++)
		if (twin[v] != NO_TWIN) {
			memcpy(m->positions + (size_t)twin[v] * 3, m->positions + (size_t)v * 3,
			       12);
			memcpy(m->normals + (size_t)twin[v] * 3, m->normals + (size_t)v * 3, 12);
			memcpy(m->uvs + (size_t)twin[v] * 2, m->uvs + (size_t)v * 2, 8);
			if (m->colors)
				memcpy(m->colors + (size_t)twin[v] * 4, m->colors + (size_t)v * 4,
				       16);
			if (m->uv1)
				memcpy(m->uv1 + (size_t)twin[v] * 2, m->uv1 + (size_t)v * 2, 8);
		}
	m->vertex_count = n + extra;
	return 0;
}

/* weight[v * 2 + side]: side 1 for right-handed faces, 0 for mirrored. */
static void sum_sides(const struct mesh *m, const struct face *faces, double *weight)
{
	for (uint32_t t = 0; t < m->index_count / 3; t++)
		for (int k = 0; k < 3 && faces[t].sign; k++)
			weight[(size_t)m->indices[t * 3 + k] * 2 + (faces[t].sign > 0)] +=
			    corner_angle(m, t, k) + 1e-30;
}

static void move_to_twins(struct mesh *m, const struct face *faces, const double *weight,
			  const uint32_t *twin)
{
	for (uint32_t t = 0; t < m->index_count / 3; t++)
		for (int k = 0; k < 3 && faces[t].sign; k++) {
			uint32_t *v = &m->indices[t * 3 + k];
			int side = faces[t].sign > 0;
			int kept = weight[*v * 2 + 1] >= weight[*v * 2]; /* ties: right-handed */

			if (twin[*v] != NO_TWIN && side != kept)
				*v = twin[*v];
		}
}

static bool has_frame(const double *a)
{
	return vec3_dot(a, a) > 0.0;
}

/* Whether copies of one point (a UV seam splits them) may share a frame:
 * same normal, same handedness, tangents within 60 degrees. Across a
 * wrapping seam (u = 0 | u = 1) they do, and averaging both sides keeps
 * a detail map from showing the seam; across a mirror seam they do not.
 * A copy with no frame of its own (only zero-area triangles use it, as at
 * a pole) takes the group's when its normal is the same. */
static bool same_frame(const struct mesh *m, const double *a, const double *b, uint32_t va,
		       uint32_t vb)
{
	const float *na = m->normals + (size_t)va * 3, *nb = m->normals + (size_t)vb * 3;

	if (na[0] != nb[0] || na[1] != nb[1] || na[2] != nb[2])
		return false;
	return !has_frame(b) || ((a[6] < 0) == (b[6] < 0) &&
				 vec3_dot(a, b) > 0.5 * sqrt(vec3_dot(a, a) * vec3_dot(b, b)));
}

/* The first copy of a point that has a frame leads its group; every copy
 * that agrees with it gets the group's sum in acc. */
static int weld_seams(const struct mesh *m, double *acc)
{
	uint32_t n = m->vertex_count;
	uint32_t *rep = malloc((size_t)n * sizeof(*rep) + 1);
	uint32_t *lead = malloc((size_t)n * sizeof(*lead) + 1);	  /* by rep */
	uint32_t *group = malloc((size_t)n * sizeof(*group) + 1); /* v's leader */
	double *sum = calloc((size_t)n * 7 + 1, sizeof(double));
	int ret = -ENOMEM;

	if (!rep || !lead || !group || !sum || mesh_weld(m->positions, n, rep))
		goto out;
	for (uint32_t v = 0; v < n; v++)
		lead[v] = group[v] = NO_TWIN;
	for (uint32_t v = 0; v < n; v++) {
		uint32_t *l = &lead[rep[v]];

		if (!has_frame(acc + (size_t)v * 7))
			continue;
		if (*l == NO_TWIN)
			*l = v;
		else if (!same_frame(m, acc + (size_t)*l * 7, acc + (size_t)v * 7, *l, v))
			continue;
		group[v] = *l;
		for (int c = 0; c < 7; c++)
			sum[(size_t)*l * 7 + c] += acc[(size_t)v * 7 + c];
	}
	for (uint32_t v = 0; v < n; v++) {
		uint32_t l = lead[rep[v]];

		if (!has_frame(acc + (size_t)v * 7) && l != NO_TWIN &&
		    same_frame(m, acc + (size_t)l * 7, acc + (size_t)v * 7, l, v))
			group[v] = l;
	}
	for (uint32_t v = 0; v < n; v++)
		if (group[v] != NO_TWIN)
			memcpy(acc + (size_t)v * 7, sum + (size_t)group[v] * 7, 7 * sizeof(double));
	ret = 0;
out:
	free(rep);
	free(lead);
	free(group);
	free(sum);
	return ret;
}

int tangent_generate(struct mesh *m)
{
	uint32_t nt = m->index_count / 3, n0 = m->vertex_count;
	struct face *faces = malloc((size_t)nt * sizeof(*faces) + 1);
	double *weight = calloc((size_t)n0 * 2 + 1, sizeof(double));
	uint32_t *twin = malloc((size_t)n0 * sizeof(*twin) + 1);
	double *acc = NULL;
	int ret = -ENOMEM;

	if (!m->uvs) {
		ret = -EINVAL;
		goto out;
	}
	if (!faces || !weight || !twin)
		goto out;
	for (uint32_t t = 0; t < nt; t++)
		face_frame(m, t, &faces[t]);
	sum_sides(m, faces, weight);
	if (split_mirrored(m, weight, twin))
		goto out;
	move_to_twins(m, faces, weight, twin);
	acc = calloc((size_t)m->vertex_count * 7 + 1, sizeof(double));
	if (!acc || mesh_alloc_tangents(m))
		goto out;
	/* acc: tangent xyz, bitangent xyz, handedness vote. */
	for (uint32_t t = 0; t < nt; t++)
		for (int k = 0; k < 3 && faces[t].sign; k++) {
			double *a = acc + (size_t)m->indices[t * 3 + k] * 7;
			double w = corner_angle(m, t, k);

			for (int c = 0; c < 3; c++) {
				a[c] += w * faces[t].t[c];
				a[3 + c] += w * faces[t].b[c];
			}
			a[6] += faces[t].sign;
		}
	ret = weld_seams(m, acc);
	if (ret)
		goto out;
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		const double *a = acc + (size_t)v * 7;

		frame_finish(m->normals + (size_t)v * 3, a, a + 3, a[6] < 0 ? -1 : 1,
			     m->tangents + (size_t)v * 4);
	}
	ret = 0;
out:
	free(faces);
	free(weight);
	free(twin);
	free(acc);
	return ret;
}

void tangent_orthonormalize(struct mesh *m)
{
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		float *t = m->tangents + (size_t)v * 4;
		const float *nf = m->normals + (size_t)v * 3;
		double tan[3] = {t[0], t[1], t[2]}, n[3] = {nf[0], nf[1], nf[2]}, bit[3];
		int w = t[3] < 0.0f ? -1 : 1;

		if (!isfinite(tan[0] + tan[1] + tan[2]))
			tan[0] = tan[1] = tan[2] = 0.0;
		vec3_cross(n, tan, bit);
		for (int c = 0; c < 3; c++)
			bit[c] *= w;
		frame_finish(nf, tan, bit, w, t);
	}
}
