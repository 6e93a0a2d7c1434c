#include "gltf_joints.h"
#include "gltf_morph.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The buffer's views in order, one accessor each. */
enum { POS, NRM, IDX, J0, W0, J1, W1, IBM, TIMES, ROT, VIEWS };

/* The capsule's positions and normals (the sphere's, y doubled). */
static void capsule(const struct mesh *m, float *pos, float *nrm)
{
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		const float *p = m->positions + (size_t)v * 3, *n = m->normals + (size_t)v * 3;
		double q[3] = {n[0], n[1] * 0.5, n[2]};
		double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);

		for (int k = 0; k < 3; k++) {
			pos[v * 3 + k] = k == 1 ? 2.0f * p[k] : p[k];
			nrm[v * 3 + k] = (float)(len > 0 ? q[k] / len : k == 1);
		}
	}
}

/* Each vertex's eight weights, a Gaussian of its distance in y to each
 * joint, summing to 1; the first four in set 0, the rest in set 1. */
static void skin(const float *pos, uint32_t n, uint16_t *j0, float *w0, uint16_t *j1, float *w1)
{
	for (uint32_t v = 0; v < n; v++) {
		double w[GLTF_JOINTS_COUNT], total = 0;

		for (int k = 0; k < GLTF_JOINTS_COUNT; k++) {
			double d = (pos[v * 3 + 1] - GLTF_JOINTS_Y(k)) / 1.2;

			w[k] = exp(-d * d);
			total += w[k];
		}
		for (int k = 0; k < 4; k++) {
			j0[v * 4 + k] = (uint16_t)k;
			j1[v * 4 + k] = (uint16_t)(k + 4);
			w0[v * 4 + k] = (float)(w[k] / total);
			w1[v * 4 + k] = (float)(w[k + 4] / total);
		}
	}
}

static void keys(float *ibm, float *times, float *rot)
{
	const double half = 15.0 * M_PI / 360.0;

	for (int k = 0; k < GLTF_JOINTS_COUNT; k++) {
		float *m = ibm + k * 16;

		memset(m, 0, 16 * sizeof(float));
		m[0] = m[5] = m[10] = m[15] = 1;
		m[13] = (float)-GLTF_JOINTS_Y(k);
	}
	for (int i = 0; i < 3; i++)
		times[i] = (float)i;
	memset(rot, 0, 12 * sizeof(float));
	rot[3] = rot[11] = 1;
	rot[6] = (float)sin(half);
	rot[7] = (float)cos(half);
}

static void accessor(FILE *f, int v, uint32_t n, uint32_t index_count, const float *pos)
{
	static const char *types[VIEWS] = {"VEC3", "VEC3", "SCALAR", "VEC4",   "VEC4",
					   "VEC4", "VEC4", "MAT4",   "SCALAR", "VEC4"};
	int type = v == IDX ? 5125 : v == J0 || v == J1 ? 5123 : 5126;
	uint32_t count = v == IDX ? index_count : v == IBM ? GLTF_JOINTS_COUNT : v >= TIMES ? 3 : n;

	fprintf(f, "%s{\"bufferView\":%d,\"componentType\":%d,\"count\":%u,\"type\":\"%s\"",
		v ? "," : "", v, type, count, types[v]);
	if (v == POS) {
		float lo[3], hi[3];

		for (int k = 0; k < 3; k++)
			lo[k] = hi[k] = pos[k];
		for (uint32_t i = 0; i < n; i++)
			for (int k = 0; k < 3; k++) {
				lo[k] = fminf(lo[k], pos[i * 3 + k]);
				hi[k] = fmaxf(hi[k], pos[i * 3 + k]);
			}
		fprintf(f, ",\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]", lo[0], lo[1],
			lo[2], hi[0], hi[1], hi[2]);
	}
	if (v == TIMES)
		fprintf(f, ",\"min\":[0],\"max\":[2]");
	fprintf(f, "}");
}

/* Node 0 shows the mesh with skin 0; nodes 1..8 are the chain (1 at the
 * root, each next its child 0.5 up). */
static void json(FILE *f, const struct mesh *m, const float *pos, const size_t *at,
		 const size_t *len)
{
	fprintf(f, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}],"
		   "\"nodes\":[{\"mesh\":0,\"skin\":0}");
	for (int k = 0; k < GLTF_JOINTS_COUNT; k++) {
		fprintf(f, ",{\"translation\":[0,%g,0]", k ? 0.5 : GLTF_JOINTS_Y(0));
		if (k + 1 < GLTF_JOINTS_COUNT)
			fprintf(f, ",\"children\":[%d]", k + 2);
		fprintf(f, "}");
	}
	fprintf(f, "],\"skins\":[{\"inverseBindMatrices\":%d,\"joints\":[1,2,3,4,5,6,7,8]}],", IBM);
	fprintf(f, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,"
		   "\"JOINTS_0\":3,\"WEIGHTS_0\":4,\"JOINTS_1\":5,\"WEIGHTS_1\":6},"
		   "\"indices\":2}]}],");
	fprintf(f,
		"\"animations\":[{\"name\":\"curl\",\"samplers\":[{\"input\":%d,\"output\":%d}],"
		"\"channels\":[",
		TIMES, ROT);
	for (int k = 1; k < GLTF_JOINTS_COUNT; k++)
		fprintf(f, "%s{\"sampler\":0,\"target\":{\"node\":%d,\"path\":\"rotation\"}}",
			k > 1 ? "," : "", k + 1);
	fprintf(f, "]}],\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":[", at[ROT] + len[ROT]);
	for (int v = 0; v < VIEWS; v++)
		fprintf(f, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", v ? "," : "",
			at[v], len[v]);
	fprintf(f, "],\"accessors\":[");
	for (int v = 0; v < VIEWS; v++)
		accessor(f, v, m->vertex_count, m->index_count, pos);
	fprintf(f, "]}");
}

int gltf_write_joints8(const char *path, const struct mesh *m)
{
	size_t n = m->vertex_count, at[VIEWS];
	size_t len[VIEWS] = {n * 12, n * 12, (size_t)m->index_count * 4, n * 8, n * 16,
			     n * 8,  n * 16, GLTF_JOINTS_COUNT * 64,	 12,	48};
	char *text = NULL;
	size_t tlen = 0;
	char *buf;
	FILE *mem;
	int ret;

	at[0] = 0;
	for (int v = 1; v < VIEWS; v++)
		at[v] = at[v - 1] + len[v - 1]; /* every length a multiple of 4 */
	buf = calloc(1, at[ROT] + len[ROT]);
	if (!buf || !m->normals)
		return free(buf), -1;
	capsule(m, (float *)(buf + at[POS]), (float *)(buf + at[NRM]));
	memcpy(buf + at[IDX], m->indices, len[IDX]);
	skin((const float *)(buf + at[POS]), m->vertex_count, (uint16_t *)(buf + at[J0]),
	     (float *)(buf + at[W0]), (uint16_t *)(buf + at[J1]), (float *)(buf + at[W1]));
	keys((float *)(buf + at[IBM]), (float *)(buf + at[TIMES]), (float *)(buf + at[ROT]));
	mem = open_memstream(&text, &tlen);
	if (!mem)
		return free(buf), -1;
	json(mem, m, (const float *)(buf + at[POS]), at, len);
	fclose(mem);
	ret = gltf_write_glb(path, text, tlen, buf, at[ROT] + len[ROT]);
	free(text);
	free(buf);
	return ret;
}
