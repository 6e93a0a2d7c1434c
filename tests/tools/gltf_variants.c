#include "gltf_variants.h"

#include <stdbool.h>
#include <stddef.h>
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

/* The skin's arrays after the cube's: faces 0-2 on joint 0, 3-5 on
 * joint 1 (each triangle on one joint, so that a palette of one bone
 * splits the draws), and a clip of 1 s that holds both joints still. */
struct skin_part {
	uint8_t joints[24][4];
	float weights[24][4];
	float times[2];
	float rotations[2][4];
};

static void skin_part(struct skin_part *s)
{
	memset(s, 0, sizeof(*s));
	for (int v = 0; v < 24; v++) {
		s->joints[v][0] = v < 12 ? 0 : 1;
		s->weights[v][0] = 1.0f;
	}
	s->times[1] = 1.0f;
	s->rotations[0][3] = s->rotations[1][3] = 1.0f;
}

/* The skin, its joints' nodes and the clip, and the accessors and views
 * of its arrays (at `at` in the buffer, accessors from 4, views from 3). */
static const char skin_nodes[] =
    ",{\"name\":\"j0\"},{\"name\":\"j1\"}],\"skins\":[{\"joints\":[1,2]}],"
    "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":2,"
    "\"path\":\"rotation\"}}],\"samplers\":[{\"input\":6,\"output\":7}]}]";

static void skin_accessors(FILE *f)
{
	fprintf(f, ",{\"bufferView\":3,\"componentType\":5121,\"count\":24,\"type\":\"VEC4\"},"
		   "{\"bufferView\":4,\"componentType\":5126,\"count\":24,\"type\":\"VEC4\"},"
		   "{\"bufferView\":5,\"componentType\":5126,\"count\":2,\"type\":\"SCALAR\","
		   "\"min\":[0],\"max\":[1]},"
		   "{\"bufferView\":6,\"componentType\":5126,\"count\":2,\"type\":\"VEC4\"}");
}

static void skin_views(FILE *f, size_t at)
{
	fprintf(f,
		",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":96},"
		"{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":384},"
		"{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":8},"
		"{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":32}",
		at, at + 96, at + 480, at + 488);
}

static int write_cube(const char *path, enum gltf_variants_fault fault, bool skinned)
{
	struct {
		float pos[72], nrm[72];
		uint16_t idx[36];
		struct skin_part skin;
	} b;
	size_t bytes = skinned ? 648 + sizeof(b.skin) : 648;
	FILE *f = fopen(path, "w");

	if (!f)
		return -1;
	cube(b.pos, b.nrm, b.idx);
	skin_part(&b.skin);
	fprintf(f,
		"{\"asset\":{\"version\":\"2.0\"},\"extensionsUsed\":[\"KHR_materials_variants\"],"
		"\"extensionsRequired\":[\"KHR_materials_variants\"],"
		"\"extensions\":{\"KHR_materials_variants\":{\"variants\":"
		"[{\"name\":\"red\"},{\"name\":\"blue\"}");
	for (int k = 2; fault == VARIANTS_TOO_MANY && k < 257; k++)
		fprintf(f, ",{\"name\":\"v%d\"}", k);
	fprintf(f,
		"]}},"
		"\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
		"\"nodes\":[{\"mesh\":0,\"rotation\":[0.2,0.3,0,0.9327379]%s}%s,\"meshes\":[{"
		"\"primitives\":[",
		skinned ? ",\"skin\":0,\"children\":[1,2]" : "", skinned ? skin_nodes : "]");
	for (int p = 0; p < 2; p++)
		fprintf(f,
			"%s{\"attributes\":{\"POSITION\":0,\"NORMAL\":1%s},\"indices\":%d,"
			"\"material\":0,"
			"\"extensions\":{\"KHR_materials_variants\":{\"mappings\":[%s]}}}",
			p ? "," : "", skinned ? ",\"JOINTS_0\":4,\"WEIGHTS_0\":5" : "", 2 + p,
			mappings(fault, p));
	fprintf(f, "]}],\"materials\":["
		   "{\"name\":\"red\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]}},"
		   "{\"name\":\"blue\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,1,1]}}],"
		   "\"accessors\":["
		   "{\"bufferView\":0,\"componentType\":5126,\"count\":24,\"type\":\"VEC3\","
		   "\"min\":[-0.5,-0.5,-0.5],\"max\":[0.5,0.5,0.5]},"
		   "{\"bufferView\":1,\"componentType\":5126,\"count\":24,\"type\":\"VEC3\"},"
		   "{\"bufferView\":2,\"componentType\":5123,\"count\":18,\"type\":\"SCALAR\"},"
		   "{\"bufferView\":2,\"byteOffset\":36,\"componentType\":5123,\"count\":18,"
		   "\"type\":\"SCALAR\"}");
	if (skinned)
		skin_accessors(f);
	fprintf(f, "],\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":288},"
		   "{\"buffer\":0,\"byteOffset\":288,\"byteLength\":288},"
		   "{\"buffer\":0,\"byteOffset\":576,\"byteLength\":72}");
	if (skinned)
		skin_views(f, 648);
	fprintf(f,
		"],\"buffers\":[{\"byteLength\":%zu,\"uri\":\"data:application/"
		"octet-stream;base64,",
		bytes);
	base64(f, (const unsigned char *)&b, bytes);
	fprintf(f, "\"}]}\n");
	return fclose(f) ? -1 : 0;
}

int gltf_write_variants(const char *path, enum gltf_variants_fault fault)
{
	return write_cube(path, fault, false);
}

int gltf_write_variants_skinned(const char *path, enum gltf_variants_fault fault)
{
	return write_cube(path, fault, true);
}
