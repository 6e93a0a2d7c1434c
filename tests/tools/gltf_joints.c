#include "gltf_joints.h"
#include "gltf_morph.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The buffer's views in order, one accessor each: positions, normals,
 * indices, JOINTS_n and WEIGHTS_n of each set, the inverse bind matrices,
 * the key times and the rotations. */
enum { POS, NRM, IDX, SETS };
#define J(s)	    (SETS + 2 * (s))
#define W(s)	    (SETS + 2 * (s) + 1)
#define IBM(sets)   (SETS + 2 * (sets))
#define TIMES(sets) (IBM(sets) + 1)
#define ROT(sets)   (IBM(sets) + 2)
#define VIEWS(sets) (IBM(sets) + 3)
#define VIEWS_MAX   VIEWS(GLTF_JOINTS_SETS)

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

/* Each vertex's weights, a Gaussian of its distance in y to each joint,
 * summing to 1; joints 4s to 4s + 3 in set s. */
static void skin(const float *pos, uint32_t n, int sets, char *buf, const size_t *at)
{
	int count = 4 * sets;

	for (uint32_t v = 0; v < n; v++) {
		double w[GLTF_JOINTS_MAX], total = 0;

		for (int k = 0; k < count; k++) {
			double d = (pos[v * 3 + 1] - GLTF_JOINTS_Y(k, count)) / 1.2;

			w[k] = exp(-d * d);
			total += w[k];
		}
		for (int k = 0; k < count; k++) {
			uint16_t *j = (uint16_t *)(buf + at[J(k / 4)]);
			float *wt = (float *)(buf + at[W(k / 4)]);

			j[v * 4 + k % 4] = (uint16_t)k;
			wt[v * 4 + k % 4] = (float)(w[k] / total);
		}
	}
}

static void keys(int count, float *ibm, float *times, float *rot)
{
	const double half = 15.0 * M_PI / 360.0;

	for (int k = 0; k < count; k++) {
		float *m = ibm + k * 16;

		memset(m, 0, 16 * sizeof(float));
		m[0] = m[5] = m[10] = m[15] = 1;
		m[13] = (float)-GLTF_JOINTS_Y(k, count);
	}
	for (int i = 0; i < 3; i++)
		times[i] = (float)i;
	memset(rot, 0, 12 * sizeof(float));
	rot[3] = rot[11] = 1;
	rot[6] = (float)sin(half);
	rot[7] = (float)cos(half);
}

static void accessor(FILE *f, int v, int sets, uint32_t n, uint32_t index_count, const float *pos)
{
	bool joints = v >= SETS && v < IBM(sets) && (v - SETS) % 2 == 0;
	bool vec4 = v >= SETS && v < IBM(sets);
	int type = v == IDX ? 5125 : joints ? 5123 : 5126;
	uint32_t count = v == IDX	    ? index_count
			 : v == IBM(sets)   ? 4u * (uint32_t)sets
			 : v >= TIMES(sets) ? 3
					    : n;
	const char *kind = v <= NRM		    ? "VEC3"
			   : vec4 || v == ROT(sets) ? "VEC4"
			   : v == IBM(sets)	    ? "MAT4"
						    : "SCALAR";

	fprintf(f, "%s{\"bufferView\":%d,\"componentType\":%d,\"count\":%u,\"type\":\"%s\"",
		v ? "," : "", v, type, count, kind);
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
	if (v == TIMES(sets))
		fprintf(f, ",\"min\":[0],\"max\":[2]");
	fprintf(f, "}");
}

/* Node 0 shows the mesh with skin 0; nodes 1..count are the chain (1 at
 * the root, each next its child one step up). */
static void json(FILE *f, const struct mesh *m, int sets, const float *pos, const size_t *at,
		 const size_t *len)
{
	int count = 4 * sets, views = VIEWS(sets);

	fprintf(f, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}],"
		   "\"nodes\":[{\"mesh\":0,\"skin\":0}");
	for (int k = 0; k < count; k++) {
		fprintf(f, ",{\"translation\":[0,%.9g,0]",
			k ? 4.0 / count : GLTF_JOINTS_Y(0, count));
		if (k + 1 < count)
			fprintf(f, ",\"children\":[%d]", k + 2);
		fprintf(f, "}");
	}
	fprintf(f, "],\"skins\":[{\"inverseBindMatrices\":%d,\"joints\":[", IBM(sets));
	for (int k = 0; k < count; k++)
		fprintf(f, "%s%d", k ? "," : "", k + 1);
	fprintf(f, "]}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
		   "\"NORMAL\":1");
	for (int s = 0; s < sets; s++)
		fprintf(f, ",\"JOINTS_%d\":%d,\"WEIGHTS_%d\":%d", s, J(s), s, W(s));
	fprintf(f, "},\"indices\":2}]}],");
	fprintf(f,
		"\"animations\":[{\"name\":\"curl\",\"samplers\":[{\"input\":%d,\"output\":%d}],"
		"\"channels\":[",
		TIMES(sets), ROT(sets));
	for (int k = 1; k < count; k++)
		fprintf(f, "%s{\"sampler\":0,\"target\":{\"node\":%d,\"path\":\"rotation\"}}",
			k > 1 ? "," : "", k + 1);
	fprintf(f, "]}],\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":[",
		at[views - 1] + len[views - 1]);
	for (int v = 0; v < views; v++)
		fprintf(f, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", v ? "," : "",
			at[v], len[v]);
	fprintf(f, "],\"accessors\":[");
	for (int v = 0; v < views; v++)
		accessor(f, v, sets, m->vertex_count, m->index_count, pos);
	fprintf(f, "]}");
}

int gltf_write_joints(const char *path, const struct mesh *m, int sets)
{
	size_t n = m->vertex_count, at[VIEWS_MAX], len[VIEWS_MAX], size;
	char *text = NULL, *buf;
	size_t tlen = 0;
	FILE *mem;
	int ret, views = VIEWS(sets);

	if (sets < 1 || sets > GLTF_JOINTS_SETS || !m->normals)
		return -1;
	len[POS] = len[NRM] = n * 12;
	len[IDX] = (size_t)m->index_count * 4;
	for (int s = 0; s < sets; s++) {
		len[J(s)] = n * 8;
		len[W(s)] = n * 16;
	}
	len[IBM(sets)] = (size_t)sets * 4 * 64;
	len[TIMES(sets)] = 12;
	len[ROT(sets)] = 48;
	at[0] = 0;
	for (int v = 1; v < views; v++)
		at[v] = at[v - 1] + len[v - 1]; /* every length a multiple of 4 */
	size = at[views - 1] + len[views - 1];
	buf = calloc(1, size);
	if (!buf)
		return -1;
	capsule(m, (float *)(buf + at[POS]), (float *)(buf + at[NRM]));
	memcpy(buf + at[IDX], m->indices, len[IDX]);
	skin((const float *)(buf + at[POS]), m->vertex_count, sets, buf, at);
	keys(4 * sets, (float *)(buf + at[IBM(sets)]), (float *)(buf + at[TIMES(sets)]),
	     (float *)(buf + at[ROT(sets)]));
	mem = open_memstream(&text, &tlen);
	if (!mem)
		return free(buf), -1;
	json(mem, m, sets, (const float *)(buf + at[POS]), at, len);
	fclose(mem);
	ret = gltf_write_glb(path, text, tlen, buf, size);
	free(text);
	free(buf);
	return ret;
}
