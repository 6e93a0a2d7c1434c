#include "gltf_write.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

static char *base64(const unsigned char *p, size_t n)
{
	char *out = malloc(n / 3 * 4 + 8), *q = out;

	for (size_t i = 0; i < n; i += 3) {
		unsigned v =
		    p[i] << 16 | (i + 1 < n ? p[i + 1] << 8 : 0) | (i + 2 < n ? p[i + 2] : 0);

		*q++ = b64[v >> 18 & 63];
		*q++ = b64[v >> 12 & 63];
		*q++ = i + 1 < n ? b64[v >> 6 & 63] : '=';
		*q++ = i + 2 < n ? b64[v & 63] : '=';
	}
	*q = '\0';
	return out;
}

static size_t pad4(size_t n)
{
	return (n + 3) & ~(size_t)3;
}

/* positions | normals | indices, each padded to 4 bytes. */
static unsigned char *pack(const struct mesh *m, const struct gltf_write_opts *o, size_t *size,
			   size_t *off_nrm, size_t *off_idx)
{
	size_t stride = o->byte_stride ? (size_t)o->byte_stride : 12;
	size_t npos = stride * m->vertex_count, nnrm = 12 * (size_t)m->vertex_count;
	size_t nidx = (size_t)o->index_bytes * m->index_count;
	unsigned char *buf;

	*off_nrm = pad4(npos);
	*off_idx = *off_nrm + (o->with_normals ? nnrm : 0);
	*size = pad4(*off_idx + nidx);
	buf = calloc(1, *size + 1);
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		memcpy(buf + v * stride, m->positions + v * 3, 12);
		if (o->with_normals)
			memcpy(buf + *off_nrm + v * 12, m->normals + v * 3, 12);
	}
	for (uint32_t i = 0; i < m->index_count && o->index_bytes; i++) {
		uint32_t x = m->indices[i];

		if (i == 0 && o->bad_index >= 0)
			x = (uint32_t)o->bad_index;
		memcpy(buf + *off_idx + (size_t)i * o->index_bytes, &x, (size_t)o->index_bytes);
	}
	return buf;
}

static void write_json(FILE *f, const struct mesh *m, const struct gltf_write_opts *o, size_t size,
		       size_t off_nrm, size_t off_idx, const char *uri)
{
	static const int ctype[5] = {0, 5121, 5123, 0, 5125};
	long count = o->position_count ? o->position_count : (long)m->vertex_count;

	fprintf(f, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],");
	fprintf(f, "\"nodes\":[");
	if (o->parent)
		fprintf(f, "{\"children\":[1]%s%s},", o->parent[0] ? "," : "", o->parent);
	fprintf(f, "{\"mesh\":0%s%s}],", o->node ? "," : "", o->node ? o->node : "");
	fprintf(f, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0");
	if (o->with_normals)
		fprintf(f, ",\"NORMAL\":1");
	fprintf(f, "}%s}]}],", o->index_bytes ? ",\"indices\":2" : "");
	fprintf(f, "\"buffers\":[{\"byteLength\":%zu%s%s%s}],", size, uri ? ",\"uri\":\"" : "",
		uri ? uri : "", uri ? "\"" : "");
	fprintf(f, "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":%zu", off_nrm);
	if (o->byte_stride)
		fprintf(f, ",\"byteStride\":%d", o->byte_stride);
	fprintf(f, "},");
	fprintf(f, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu},", off_nrm,
		o->with_normals ? (size_t)m->vertex_count * 12 : 4);
	fprintf(f, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}],", off_idx,
		(size_t)m->index_count * (size_t)(o->index_bytes ? o->index_bytes : 1));
	fprintf(f,
		"\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%ld,"
		"\"type\":\"VEC3\",\"min\":[-1,-1,-1],\"max\":[1,1,1]},",
		count);
	fprintf(f, "{\"bufferView\":1,\"componentType\":5126,\"count\":%u,\"type\":\"VEC3\"},",
		m->vertex_count);
	fprintf(f, "{\"bufferView\":2,\"componentType\":%d,\"count\":%u,\"type\":\"SCALAR\"}]}",
		ctype[o->index_bytes > 0 ? o->index_bytes : 1], m->index_count);
}

static int write_glb(FILE *f, const char *json, size_t jlen, const unsigned char *bin, size_t blen)
{
	uint32_t jpad = (uint32_t)pad4(jlen), total = 12 + 8 + jpad + 8 + (uint32_t)blen;
	uint32_t hdr[3] = {0x46546C67, 2, total}, jc[2] = {jpad, 0x4E4F534A},
		 bc[2] = {(uint32_t)blen, 0x004E4942};

	fwrite(hdr, 4, 3, f);
	fwrite(jc, 4, 2, f);
	fwrite(json, 1, jlen, f);
	for (size_t i = jlen; i < jpad; i++)
		fputc(' ', f);
	fwrite(bc, 4, 2, f);
	fwrite(bin, 1, blen, f);
	return 0;
}

static char *json_text(const struct mesh *m, const struct gltf_write_opts *o, size_t size,
		       size_t off_nrm, size_t off_idx, const char *uri, size_t *len)
{
	char *text = NULL;
	FILE *mem = open_memstream(&text, len);

	write_json(mem, m, o, size, off_nrm, off_idx, uri);
	fclose(mem);
	return text;
}

int gltf_write(const char *path, const struct mesh *m, const struct gltf_write_opts *o)
{
	size_t size, off_nrm, off_idx, jlen;
	unsigned char *bin = pack(m, o, &size, &off_nrm, &off_idx);
	char bin_path[4096], *uri = NULL, *json;
	FILE *f;

	if (o->container == GLTF_DATA_URI) {
		char *b = base64(bin, size);

		uri = malloc(strlen(b) + 64);
		sprintf(uri, "data:application/octet-stream;base64,%s", b);
		free(b);
	} else if (o->container == GLTF_EXTERNAL_BIN) {
		snprintf(bin_path, sizeof(bin_path), "%.*s.bin", (int)(strlen(path) - 5), path);
		const char *name = strrchr(bin_path, '/') ? strrchr(bin_path, '/') + 1 : bin_path;

		uri = strdup(o->bin_uri ? o->bin_uri : name);
		f = fopen(bin_path, "wb");
		fwrite(bin, 1, size, f);
		fclose(f);
	}
	json = json_text(m, o, size, off_nrm, off_idx, uri, &jlen);
	f = fopen(path, "wb");
	if (o->container == GLTF_GLB)
		write_glb(f, json, jlen, bin, size);
	else
		fwrite(json, 1, jlen, f);
	fclose(f);
	if (o->truncate_to > 0 && truncate(path, o->truncate_to))
		return -1;
	free(json);
	free(uri);
	free(bin);
	return 0;
}
