/* What the level-of-detail tests share (test_lod.c, one thread;
 * test_lod_threads.c, the clusters on several): meshes copied, a flat-shaded
 * knot, a sphere of four parts, and the surface error measured. Each unit
 * test is a program of its own: this header defines what it needs once
 * per test. */
#ifndef MK_TEST_LOD_FIXTURE_H
#define MK_TEST_LOD_FIXTURE_H

#include "scene/mesh/lod.h"
#include "scene/mesh/mesh.h"
#include "util/math3d.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

static inline const float *vec_at(const float *a, uint32_t i, int n)
{
	return a + (size_t)i * (size_t)n;
}

static inline void sub3(const float *a, const float *b, double out[3])
{
	for (int k = 0; k < 3; k++)
		out[k] = (double)a[k] - (double)b[k];
}

static inline double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The point of triangle abc nearest p, as barycentric weights (Ericson,
 * Real-Time Collision Detection, 5.1.5). */
static inline void closest_on_triangle(const float *p, const float *a, const float *b,
				       const float *c, double w[3])
{
	double ab[3], ac[3], ap[3], bp[3], cp[3];
	double d1, d2, d3, d4, d5, d6, va, vb, vc, denom, v, t;

	sub3(b, a, ab), sub3(c, a, ac), sub3(p, a, ap);
	d1 = dot3(ab, ap), d2 = dot3(ac, ap);
	w[0] = 1, w[1] = 0, w[2] = 0;
	if (d1 <= 0 && d2 <= 0)
		return;
	sub3(p, b, bp);
	d3 = dot3(ab, bp), d4 = dot3(ac, bp);
	if (d3 >= 0 && d4 <= d3) {
		w[0] = 0, w[1] = 1;
		return;
	}
	vc = d1 * d4 - d3 * d2;
	if (vc <= 0 && d1 >= 0 && d3 <= 0) {
		v = d1 / (d1 - d3);
		w[0] = 1 - v, w[1] = v;
		return;
	}
	sub3(p, c, cp);
	d5 = dot3(ab, cp), d6 = dot3(ac, cp);
	if (d6 >= 0 && d5 <= d6) {
		w[0] = 0, w[2] = 1;
		return;
	}
	vb = d5 * d2 - d1 * d6;
	if (vb <= 0 && d2 >= 0 && d6 <= 0) {
		t = d2 / (d2 - d6);
		w[0] = 1 - t, w[2] = t;
		return;
	}
	va = d3 * d6 - d5 * d4;
	if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
		t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
		w[0] = 0, w[1] = 1 - t, w[2] = t;
		return;
	}
	denom = 1.0 / (va + vb + vc);
	w[1] = vb * denom, w[2] = vc * denom, w[0] = 1 - w[1] - w[2];
}

struct surface_error {
	double distance;   /* the farthest original vertex from the new surface */
	double normal_max; /* degrees between a vertex's normal and the new surface's there */
	double normal_mean;
};

/* Every vertex of the original against the simplified surface (brute
 * force: the meshes here are small): the distance to it, and the angle
 * between the vertex's normal and the simplified mesh's interpolated
 * normal at the nearest point, which is what the shader would use. */
static inline struct surface_error measure(const struct mesh *orig, const struct mesh *s)
{
	struct surface_error e = {0, 0, 0};

	for (uint32_t v = 0; v < orig->vertex_count; v++) {
		const float *p = vec_at(orig->positions, v, 3);
		double best = INFINITY, bw[3] = {1, 0, 0}, n[3] = {0, 0, 0}, len, cosang;
		uint32_t bt = 0;

		for (uint32_t t = 0; t < s->index_count; t += 3) {
			const float *a = vec_at(s->positions, s->indices[t], 3);
			const float *b = vec_at(s->positions, s->indices[t + 1], 3);
			const float *c = vec_at(s->positions, s->indices[t + 2], 3);
			double w[3], d2 = 0;

			closest_on_triangle(p, a, b, c, w);
			for (int k = 0; k < 3; k++) {
				double q = w[0] * a[k] + w[1] * b[k] + w[2] * c[k] - p[k];

				d2 += q * q;
			}
			if (d2 < best)
				best = d2, bt = t, memcpy(bw, w, sizeof(w));
		}
		for (int j = 0; j < 3; j++)
			for (int k = 0; k < 3; k++)
				n[k] += bw[j] * vec_at(s->normals, s->indices[bt + j], 3)[k];
		len = sqrt(dot3(n, n));
		cosang = (n[0] * orig->normals[v * 3] + n[1] * orig->normals[v * 3 + 1] +
			  n[2] * orig->normals[v * 3 + 2]) /
			 len;
		e.distance = fmax(e.distance, sqrt(best));
		e.normal_max = fmax(e.normal_max, acos(fmin(cosang, 1.0)) * 180.0 / M_PI);
		e.normal_mean += acos(fmin(cosang, 1.0)) * 180.0 / M_PI / orig->vertex_count;
	}
	return e;
}

static inline void copy_mesh(const struct mesh *src, struct mesh *dst)
{
	assert_int_equal(mesh_alloc(dst, src->vertex_count, src->index_count, src->uvs != NULL), 0);
	memcpy(dst->positions, src->positions, src->vertex_count * 12);
	memcpy(dst->normals, src->normals, src->vertex_count * 12);
	if (src->uvs)
		memcpy(dst->uvs, src->uvs, src->vertex_count * 8);
	if (src->tangents) {
		assert_int_equal(mesh_alloc_tangents(dst), 0);
		memcpy(dst->tangents, src->tangents, src->vertex_count * 16);
	}
	memcpy(dst->indices, src->indices, src->index_count * 4);
}

/* The knot as a flat-shaded export has it: every triangle its own three
 * vertices with the face's normal, so that every vertex lies on a crease
 * and meshoptimizer alone could collapse none. */
static inline void split_flat(const struct mesh *src, struct mesh *out)
{
	assert_int_equal(mesh_alloc(out, src->index_count, src->index_count, true), 0);
	for (uint32_t i = 0; i < src->index_count; i++) {
		uint32_t v = src->indices[i], t = i - i % 3;
		double e1[3], e2[3], n[3], len;

		sub3(src->positions + src->indices[t + 1] * 3, src->positions + src->indices[t] * 3,
		     e1);
		sub3(src->positions + src->indices[t + 2] * 3, src->positions + src->indices[t] * 3,
		     e2);
		n[0] = e1[1] * e2[2] - e1[2] * e2[1];
		n[1] = e1[2] * e2[0] - e1[0] * e2[2];
		n[2] = e1[0] * e2[1] - e1[1] * e2[0];
		len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		for (int k = 0; k < 3; k++) {
			out->positions[i * 3 + k] = src->positions[v * 3 + k];
			out->normals[i * 3 + k] = len > 0 ? (float)(n[k] / len) : (float)(k == 2);
		}
		memcpy(out->uvs + i * 2, src->uvs + v * 2, 8);
		out->indices[i] = i;
	}
}

/* The sphere as four parts (quarters by longitude), each with vertices of
 * its own, as four glTF primitives are: range k, material k, every vertex
 * of part k coloured k / 4. */
static inline void four_parts(const struct mesh *s, struct mesh *m)
{
	uint32_t *local = malloc(s->vertex_count * sizeof(uint32_t));
	uint32_t nv = 0, ni = 0, tris = s->index_count / 3, *part = malloc(tris * 4);

	for (uint32_t t = 0; t < tris; t++) {
		double x = 0, z = 0;

		for (int k = 0; k < 3; k++)
			x += s->positions[s->indices[t * 3 + k] * 3],
			    z += s->positions[s->indices[t * 3 + k] * 3 + 2];
		part[t] = (uint32_t)((atan2(x, z) + M_PI) / (M_PI / 2)) % 4;
	}
	assert_int_equal(mesh_alloc(m, s->index_count, s->index_count, true), 0);
	assert_int_equal(mesh_alloc_colors(m), 0);
	assert_int_equal(mesh_alloc_ranges(m, 4, 4), 0);
	for (uint32_t k = 0; k < 4; k++) {
		memset(local, 0xff, s->vertex_count * sizeof(uint32_t));
		m->ranges[k].first_index = ni;
		m->ranges[k].material = k;
		for (uint32_t t = 0; t < tris; t++)
			for (int j = 0; j < 3 && part[t] == k; j++) {
				uint32_t v = s->indices[t * 3 + j];

				if (local[v] == UINT32_MAX) {
					local[v] = nv;
					memcpy(m->positions + nv * 3, s->positions + v * 3, 12);
					memcpy(m->normals + nv * 3, s->normals + v * 3, 12);
					memcpy(m->uvs + nv * 2, s->uvs + v * 2, 8);
					for (int c = 0; c < 4; c++)
						m->colors[nv * 4 + c] = k / 4.0f;
					nv++;
				}
				m->indices[ni++] = local[v];
			}
		m->ranges[k].index_count = ni - m->ranges[k].first_index;
	}
	m->vertex_count = nv;
	m->index_count = ni;
	free(local);
	free(part);
}

/* four_parts' ranges, simplified: each in order, material k, not empty,
 * every triangle of it still of part k (its vertices' colour), together
 * every index once. */
static inline void assert_four_parts_in_order(const struct mesh *m)
{
	uint32_t at = 0;

	for (uint32_t k = 0; k < 4; k++) {
		assert_int_equal(m->ranges[k].first_index, at);
		assert_int_equal(m->ranges[k].material, k);
		assert_true(m->ranges[k].index_count > 0);
		for (uint32_t i = at; i < at + m->ranges[k].index_count; i++)
			assert_true(m->colors[m->indices[i] * 4] == k / 4.0f);
		at += m->ranges[k].index_count;
	}
	assert_int_equal(at, m->index_count);
}

#endif
