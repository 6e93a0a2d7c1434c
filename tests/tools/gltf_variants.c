#include "gltf_variants.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* A unit cube's 24 vertices (4 a face, each face its own normal). */
static void cube(float pos[72], float nrm[72], uint16_t idx[36])
{
	static const float n[6][3] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},
				      {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};

	for (int f = 0; f < 6; f++) {
		int a = f % 3, u = (a + 1) % 3, w = (a + 2) % 3;
		float s = n[f][a];
		static const float c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

		for (int k = 0; k < 4; k++) {
			float *p = pos + (f * 4 + k) * 3;

			p[a] = 0.5f * s;
			p[u] = 0.5f * c[k][0];
			p[w] = 0.5f * c[k][1] * s; /* counter-clockwise seen from outside */
			memcpy(nrm + (f * 4 + k) * 3, n[f], sizeof(n[f]));
		}
		static const uint16_t q[6] = {0, 1, 2, 0, 2, 3};
		for (int k = 0; k < 6; k++)
			idx[f * 6 + k] = (uint16_t)(f * 4 + q[k]);
	}
}

static void base64(FILE *f, const unsigned char *p, size_t n)
{
	static const char t[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

	for (size_t i = 0; i < n; i += 3) {
		unsigned v = (unsigned)p[i] << 16 | (i + 1 < n ? (unsigned)p[i + 1] << 8 : 0) |
			     (i + 2 < n ? p[i + 2] : 0);

		fputc(t[v >> 18 & 63], f);
		fputc(t[v >> 12 & 63], f);
		fputc(i + 1 < n ? t[v >> 6 & 63] : '=', f);
		fputc(i + 2 < n ? t[v & 63] : '=', f);
	}
}

static const char *mappings(enum gltf_variants_fault fault, int prim)
{
	switch (fault) {
	case VARIANTS_MISSING_MATERIAL:
		return prim ? "{\"material\":7,\"variants\":[1]}"
			    : "{\"material\":1,\"variants\":[1]}";
	case VARIANTS_MISSING_VARIANT:
		return "{\"material\":1,\"variants\":[5]}";
	case VARIANTS_SPLIT:
		return prim ? "{\"material\":1,\"variants\":[1]}"
			    : "{\"material\":0,\"variants\":[0]}";
	default:
		return "{\"material\":0,\"variants\":[0]},{\"material\":1,\"variants\":[1]}";
	}
}

int gltf_write_variants(const char *path, enum gltf_variants_fault fault)
{
	struct {
		float pos[72], nrm[72];
		uint16_t idx[36];
	} b;
	FILE *f = fopen(path, "w");

	if (!f)
		return -1;
	cube(b.pos, b.nrm, b.idx);
	fprintf(f,
		"{\"asset\":{\"version\":\"2.0\"},\"extensionsUsed\":[\"KHR_materials_variants\"],"
		"\"extensionsRequired\":[\"KHR_materials_variants\"],"
		"\"extensions\":{\"KHR_materials_variants\":{\"variants\":"
		"[{\"name\":\"red\"},{\"name\":\"blue\"}");
	for (int k = 2; fault == VARIANTS_TOO_MANY && k < 257; k++)
		fprintf(f, ",{\"name\":\"v%d\"}", k);
	fprintf(f, "]}},"
		   "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
		   "\"nodes\":[{\"mesh\":0,\"rotation\":[0.2,0.3,0,0.9327379]}],\"meshes\":[{"
		   "\"primitives\":[");
	for (int p = 0; p < 2; p++)
		fprintf(
		    f,
		    "%s{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":%d,\"material\":0,"
		    "\"extensions\":{\"KHR_materials_variants\":{\"mappings\":[%s]}}}",
		    p ? "," : "", 2 + p, mappings(fault, p));
	fprintf(f,
		"]}],\"materials\":["
		"{\"name\":\"red\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]}},"
		"{\"name\":\"blue\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,1,1]}}],"
		"\"accessors\":["
		"{\"bufferView\":0,\"componentType\":5126,\"count\":24,\"type\":\"VEC3\","
		"\"min\":[-0.5,-0.5,-0.5],\"max\":[0.5,0.5,0.5]},"
		"{\"bufferView\":1,\"componentType\":5126,\"count\":24,\"type\":\"VEC3\"},"
		"{\"bufferView\":2,\"componentType\":5123,\"count\":18,\"type\":\"SCALAR\"},"
		"{\"bufferView\":2,\"byteOffset\":36,\"componentType\":5123,\"count\":18,"
		"\"type\":\"SCALAR\"}],"
		"\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":288},"
		"{\"buffer\":0,\"byteOffset\":288,\"byteLength\":288},"
		"{\"buffer\":0,\"byteOffset\":576,\"byteLength\":72}],"
		"\"buffers\":[{\"byteLength\":648,\"uri\":\"data:application/octet-stream;base64,");
	base64(f, (const unsigned char *)&b, sizeof(b));
	fprintf(f, "\"}]}\n");
	return fclose(f) ? -1 : 0;
}
