/* Procedural models: a torus knot shows off a matcap (curvature in every
 * direction), a sphere makes the mapping checkable analytically. */
#include "util/math3d.h"
#include "scene/mesh/mesh.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#define KNOT_P	  2
#define KNOT_Q	  3
#define KNOT_TUBE 0.4

static void knot_curve(double u, double out[3])
{
	double qu = (double)KNOT_Q / KNOT_P * u;
	double r = 2.0 + cos(qu);

	out[0] = r * cos(u) * 0.5;
	out[1] = r * sin(u) * 0.5;
	out[2] = sin(qu) * 0.5;
}

static void grid_indices(uint32_t *idx, int cols, int rows)
{
	uint32_t *p = idx;

	for (int j = 0; j < cols; j++)
		for (int i = 0; i < rows; i++) {
			uint32_t a = (uint32_t)((rows + 1) * j + i);
			uint32_t b = (uint32_t)((rows + 1) * (j + 1) + i);

			*p++ = a;
			*p++ = b;
			*p++ = a + 1;
			*p++ = b;
			*p++ = b + 1;
			*p++ = a + 1;
		}
}

/* Frenet-like frame as three.js builds it: tangent by finite difference,
 * normal from the sum of the neighbouring points. */
static void knot_ring(double u, int radial, double *pos, double *nrm)
{
	double p1[3], p2[3], t[3], n[3], b[3];

	knot_curve(u, p1);
	knot_curve(u + 0.01, p2);
	for (int k = 0; k < 3; k++) {
		t[k] = p2[k] - p1[k];
		n[k] = p2[k] + p1[k];
	}
	vec3_cross(t, n, b);
	vec3_cross(b, t, n);
	vec3_normalize(b);
	vec3_normalize(n);
	for (int i = 0; i <= radial; i++) {
		double v = (double)(i % radial) / radial * 2.0 * M_PI;
		double cx = -KNOT_TUBE * 0.5 * cos(v), cy = KNOT_TUBE * 0.5 * sin(v);

		for (int k = 0; k < 3; k++) {
			double off = cx * n[k] + cy * b[k];

			pos[i * 3 + k] = p1[k] + off;
			nrm[i * 3 + k] = off / (KNOT_TUBE * 0.5);
		}
	}
}

int mesh_torus_knot(struct mesh *m, int tubular, int radial)
{
	uint32_t nv = (uint32_t)((tubular + 1) * (radial + 1));
	double *world = malloc((size_t)nv * 3 * sizeof(double));
	double *nrm = malloc((size_t)nv * 3 * sizeof(double));
	int ret = -ENOMEM;

	if (!world || !nrm || mesh_alloc(m, nv, (uint32_t)(tubular * radial * 6), true))
		goto out;
	for (int j = 0; j <= tubular; j++) {
		double u = (double)(j % tubular) / tubular * KNOT_P * 2.0 * M_PI;
		size_t base = (size_t)j * (size_t)(radial + 1);

		knot_ring(u, radial, world + base * 3, nrm + base * 3);
		for (int i = 0; i <= radial; i++) {
			m->uvs[(base + (size_t)i) * 2] = (float)j / (float)tubular;
			m->uvs[(base + (size_t)i) * 2 + 1] = (float)i / (float)radial;
		}
	}
	for (size_t i = 0; i < (size_t)nv * 3; i++)
		m->normals[i] = (float)nrm[i];
	mesh_fit_positions(world, nv, m->positions);
	grid_indices(m->indices, tubular, radial);
	ret = 0;
out:
	free(world);
	free(nrm);
	return ret;
}

int mesh_uv_sphere(struct mesh *m, int slices, int stacks)
{
	uint32_t nv = (uint32_t)((slices + 1) * (stacks + 1));
	int ret = mesh_alloc(m, nv, (uint32_t)(slices * stacks * 6), true);

	if (ret)
		return ret;
	for (int j = 0; j <= slices; j++) {
		/* The seam column repeats column 0 exactly, so welding by
		 * position (normal generation) finds it. */
		double phi = (double)(j % slices) / slices * 2.0 * M_PI;

		for (int i = 0; i <= stacks; i++) {
			double theta = (double)i / stacks * M_PI;
			size_t v = (size_t)j * (size_t)(stacks + 1) + (size_t)i;
			/* Longitude runs clockwise seen from +y so the shared grid
			 * winds counter-clockwise seen from outside. */
			/* Exact poles: sin(pi) is not 0 in floating point. */
			double st = i == 0 || i == stacks ? 0.0 : sin(theta);
			double p[3] = {-st * sin(phi),
				       i == 0	     ? 1.0
				       : i == stacks ? -1.0
						     : cos(theta),
				       st * cos(phi)};

			for (int k = 0; k < 3; k++) {
				m->positions[v * 3 + k] = (float)p[k];
				m->normals[v * 3 + k] = (float)p[k];
			}
			/* u grows eastward seen from outside and v downward, so
			 * a texture reads unmirrored (tangent w = +1). */
			m->uvs[v * 2] = 1.0f - (float)j / (float)slices;
			m->uvs[v * 2 + 1] = (float)i / (float)stacks;
		}
	}
	grid_indices(m->indices, slices, stacks);
	return 0;
}
