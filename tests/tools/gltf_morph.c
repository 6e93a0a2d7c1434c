#include "gltf_morph.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The buffer's views in order, one accessor each. */
enum { POS, NRM, IDX, T0P, T0N, T1P, T1N, TIMES, WEIGHTS, VIEWS };

static void deltas(const struct mesh *m, float *buf, const size_t *at)
{
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		const float *p = m->positions + (size_t)v * 3, *n = m->normals + (size_t)v * 3;
		float *s0 = buf + at[T0P] / 4 + v * 3, *s1 = buf + at[T1P] / 4 + v * 3;
		float *n1 = buf + at[T1N] / 4 + v * 3;

		for (int k = 0; k < 3; k++)
			s0[k] = 0.15f * n[k]; /* its normals stay: zeros at T0N */
		s1[0] = 0.3f * p[1];
		n1[0] = -0.3f * n[1];
		n1[1] = 0.3f * n[0];
	}
}

/* One accessor's min and max (positions): 3 floats each. */
static void bounds(const float *a, uint32_t n, float lo[3], float hi[3])
{
	for (int k = 0; k < 3; k++)
		lo[k] = hi[k] = n ? a[k] : 0;
	for (uint32_t i = 0; i < n; i++)
		for (int k = 0; k < 3; k++) {
			lo[k] = a[i * 3 + k] < lo[k] ? a[i * 3 + k] : lo[k];
			hi[k] = a[i * 3 + k] > hi[k] ? a[i * 3 + k] : hi[k];
		}
}

static void accessor(FILE *f, int view, uint32_t count, const char *type, const float *data)
{
	float lo[3], hi[3];

	fprintf(f, "%s{\"bufferView\":%d,\"componentType\":%d,\"count\":%u,\"type\":\"%s\"",
		view ? "," : "", view, view == IDX ? 5125 : 5126, count, type);
	if (data) {
		bounds(data, count, lo, hi);
		fprintf(f, ",\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]", lo[0], lo[1],
			lo[2], hi[0], hi[1], hi[2]);
	}
	if (view == TIMES)
		fprintf(f, ",\"min\":[0],\"max\":[2]");
	fprintf(f, "}");
}

static void json(FILE *f, const struct mesh *m, const float *buf, const size_t *at,
		 const size_t *len, int nodes)
{
	uint32_t n = m->vertex_count;

	fprintf(f, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0%s]}],",
		nodes > 1 ? ",1" : "");
	fprintf(f, "\"nodes\":[{\"mesh\":0%s}%s],", nodes > 1 ? ",\"translation\":[-1.6,0,0]" : "",
		nodes > 1 ? ",{\"mesh\":0,\"translation\":[1.6,0,0]}" : "");
	fprintf(f, "\"meshes\":[{\"weights\":[0,0],\"primitives\":[{\"attributes\":{\"POSITION\":0,"
		   "\"NORMAL\":1},\"indices\":2,\"targets\":[{\"POSITION\":3,\"NORMAL\":4},"
		   "{\"POSITION\":5,\"NORMAL\":6}]}]}],");
	fprintf(f,
		"\"animations\":[{\"name\":\"breathe\",\"samplers\":[{\"input\":7,\"output\":8}],"
		"\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}}");
	if (nodes > 1)
		fprintf(f, ",{\"sampler\":0,\"target\":{\"node\":1,\"path\":\"weights\"}}");
	fprintf(f, "]}],\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":[",
		at[WEIGHTS] + len[WEIGHTS]);
	for (int v = 0; v < VIEWS; v++)
		fprintf(f, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", v ? "," : "",
			at[v], len[v]);
	fprintf(f, "],\"accessors\":[");
	for (int v = 0; v < VIEWS; v++)
		accessor(f, v,
			 v == IDX	? m->index_count
			 : v == TIMES	? 3
			 : v == WEIGHTS ? 6
					: n,
			 v == IDX || v >= TIMES ? "SCALAR" : "VEC3",
			 v == POS || v == T0P || v == T1P ? buf + at[v] / 4 : NULL);
	fprintf(f, "]}");
}

int gltf_write_glb(const char *path, const char *text, size_t tlen, const void *bin, size_t blen)
{
	uint32_t jpad = (uint32_t)((tlen + 3) & ~(size_t)3);
	uint32_t hdr[5] = {0x46546C67, 2, (uint32_t)(12 + 8 + jpad + 8 + blen), jpad, 0x4E4F534A};
	uint32_t bc[2] = {(uint32_t)blen, 0x004E4942};
	FILE *f = fopen(path, "wb");
	int bad;

	if (!f)
		return -1;
	fwrite(hdr, 4, 5, f);
	fwrite(text, 1, tlen, f);
	for (size_t i = tlen; i < jpad; i++)
		fputc(' ', f);
	fwrite(bc, 4, 2, f);
	fwrite(bin, 1, blen, f);
	bad = ferror(f);
	return fclose(f) || bad ? -1 : 0;
}

int gltf_write_morph(const char *path, const struct mesh *m, int nodes)
{
	static const float keys[9] = {0, 1, 2, 0, 0, 1, 0.5f, 0, 1};
	size_t vec = (size_t)m->vertex_count * 12, at[VIEWS], len[VIEWS] = {vec, vec};
	char *text = NULL;
	size_t tlen = 0;
	float *buf;
	FILE *mem;
	int ret;

	len[IDX] = (size_t)m->index_count * 4;
	len[T0P] = len[T0N] = len[T1P] = len[T1N] = vec;
	len[TIMES] = 12;
	len[WEIGHTS] = 24;
	at[0] = 0;
	for (int v = 1; v < VIEWS; v++)
		at[v] = at[v - 1] + len[v - 1]; /* every length a multiple of 4 */
	buf = calloc(1, at[WEIGHTS] + len[WEIGHTS]);
	if (!buf || !m->normals)
		return free(buf), -1;
	memcpy(buf + at[POS] / 4, m->positions, vec);
	memcpy(buf + at[NRM] / 4, m->normals, vec);
	memcpy(buf + at[IDX] / 4, m->indices, len[IDX]);
	memcpy(buf + at[TIMES] / 4, keys, sizeof(keys));
	deltas(m, buf, at);
	mem = open_memstream(&text, &tlen);
	if (!mem)
		return free(buf), -1;
	json(mem, m, buf, at, len, nodes);
	fclose(mem);
	ret = gltf_write_glb(path, text, tlen, buf, at[WEIGHTS] + len[WEIGHTS]);
	free(text);
	free(buf);
	return ret;
}
