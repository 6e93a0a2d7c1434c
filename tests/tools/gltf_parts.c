#include "gltf_parts.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_IMAGES 64

static size_t pad4(size_t n)
{
	return (n + 3) & ~(size_t)3;
}

static unsigned char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	unsigned char *p = NULL;
	long n;

	if (!f)
		return NULL;
	if (!fseek(f, 0, SEEK_END) && (n = ftell(f)) > 0 && !fseek(f, 0, SEEK_SET)) {
		p = malloc((size_t)n);
		if (p && fread(p, 1, (size_t)n, f) != (size_t)n) {
			free(p);
			p = NULL;
		}
		*len = (size_t)n;
	}
	fclose(f);
	return p;
}

struct blob {
	unsigned char *data;
	size_t size;
};

/* Appends bytes 4-aligned; returns their offset. */
static size_t put(struct blob *b, const void *p, size_t n)
{
	size_t at = b->size;

	b->data = realloc(b->data, pad4(at + n));
	memcpy(b->data + at, p, n);
	memset(b->data + at + n, 0, pad4(at + n) - at - n);
	b->size = pad4(at + n);
	return at;
}

/* A part's four views (positions, normals, uvs, indices) and accessors,
 * numbered 4 k .. 4 k + 3. */
static void part_views(FILE *views, FILE *accessors, struct blob *b, const struct mesh *m, int k)
{
	size_t nv = m->vertex_count, off[4],
	       len[4] = {nv * 12, nv * 12, nv * 8, m->index_count * 4};
	float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};

	off[0] = put(b, m->positions, len[0]);
	off[1] = put(b, m->normals, len[1]);
	off[2] = put(b, m->uvs, len[2]);
	off[3] = put(b, m->indices, len[3]);
	for (size_t i = 0; i < nv * 3; i++) {
		lo[i % 3] = m->positions[i] < lo[i % 3] ? m->positions[i] : lo[i % 3];
		hi[i % 3] = m->positions[i] > hi[i % 3] ? m->positions[i] : hi[i % 3];
	}
	for (int v = 0; v < 4; v++)
		fprintf(views, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}",
			k || v ? "," : "", off[v], len[v]);
	fprintf(accessors,
		"%s{\"bufferView\":%d,\"componentType\":5126,\"count\":%zu,\"type\":\"VEC3\","
		"\"min\":[%g,%g,%g],\"max\":[%g,%g,%g]}",
		k ? "," : "", 4 * k, nv, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
	fprintf(accessors,
		",{\"bufferView\":%d,\"componentType\":5126,\"count\":%zu,\"type\":\"VEC3\"}"
		",{\"bufferView\":%d,\"componentType\":5126,\"count\":%zu,\"type\":\"VEC2\"}"
		",{\"bufferView\":%d,\"componentType\":5125,\"count\":%u,\"type\":\"SCALAR\"}",
		4 * k + 1, nv, 4 * k + 2, nv, 4 * k + 3, m->index_count);
}

/* One PNG into the buffer and the images; returns its texture's index,
 * or -1. */
static int embed(const char *path, struct blob *b, FILE *imgs, int first_view, int *images,
		 size_t *img_off, size_t *img_len)
{
	size_t len = 0;
	unsigned char *png = slurp(path, &len);

	if (!png || *images == MAX_IMAGES) {
		free(png);
		return -1;
	}
	img_off[*images] = put(b, png, len);
	img_len[*images] = len;
	free(png);
	fprintf(imgs, "%s{\"bufferView\":%d,\"mimeType\":\"image/png\"}", *images ? "," : "",
		first_view + *images);
	return (*images)++;
}

static char *stream_text(FILE *f, char **buf)
{
	fclose(f);
	return *buf;
}

/* glTF asks every extension a file uses to be named in extensionsUsed
 * (three.js's loader refuses an unlit material without it): the names
 * that are keys in the materials' text, each once. */
static void put_extensions_used(FILE *out, const char *mats)
{
	char seen[1024] = "";
	const char *p = mats;
	int n = 0;

	while ((p = strchr(p, '"')) != NULL) {
		const char *name = ++p, *end = strchr(p, '"');

		if (!end)
			break;
		p = end + 1;
		if ((strncmp(name, "KHR_", 4) && strncmp(name, "EXT_", 4)) || *p != ':' ||
		    end - name > 64)
			continue;
		char key[70];
		snprintf(key, sizeof(key), "\"%.*s\"", (int)(end - name), name);
		if (strstr(seen, key) || strlen(seen) + strlen(key) + 2 > sizeof(seen))
			continue;
		strcat(seen, n++ ? "," : "");
		strcat(seen, key);
	}
	if (n)
		fprintf(out, ",\"extensionsUsed\":[%s]", seen);
}

int gltf_write_parts(const char *path, const struct gltf_part *parts, int n)
{
	return gltf_write_parts_more(path, parts, NULL, n);
}

int gltf_write_parts_more(const char *path, const struct gltf_part *parts,
			  const struct gltf_part_more *more, int n)
{
	static const struct gltf_part_more none = {NULL, NULL, 0, 0, NULL, 0};
	char *vbuf = NULL, *abuf = NULL, *mbuf = NULL, *pbuf = NULL, *ibuf = NULL, *json = NULL;
	size_t vs = 0, as = 0, ms = 0, ps = 0, is = 0, js = 0;
	FILE *views = open_memstream(&vbuf, &vs), *acc = open_memstream(&abuf, &as),
	     *mats = open_memstream(&mbuf, &ms), *prims = open_memstream(&pbuf, &ps),
	     *imgs = open_memstream(&ibuf, &is), *out;
	struct blob b = {NULL, 0};
	int material = -1, images = 0, ret = -1;
	size_t img_off[MAX_IMAGES], img_len[MAX_IMAGES];
	/* Second UV sets: their views and accessors after the parts' (4 n + j),
	 * the images' views after those. */
	size_t uv1_off[MAX_IMAGES], uv1_count[MAX_IMAGES];
	int uv1s = 0, first_image = 4 * n;

	for (int k = 0; more && k < n; k++)
		first_image += more[k].uv1 != NULL;
	for (int k = 0; k < n; k++) {
		const struct gltf_part_more *x = more ? &more[k] : &none;

		part_views(views, acc, &b, parts[k].mesh, k);
		if (parts[k].own_material || material < 0) {
			material++;
			fprintf(mats, "%s{%s", material ? "," : "",
				x->spec_gloss ? "\"extensions\":{\"KHR_materials_"
						"pbrSpecularGlossiness\":{\"diffuseFactor\""
					      : "\"pbrMetallicRoughness\":{\"baseColorFactor\"");
			fprintf(mats, ":[%g,%g,%g,%g]", parts[k].factor[0], parts[k].factor[1],
				parts[k].factor[2], parts[k].factor[3]);
			if (parts[k].png) {
				int t = embed(parts[k].png, &b, imgs, first_image, &images, img_off,
					      img_len);

				if (t < 0)
					goto out;
				fprintf(mats, ",\"%s\":{\"index\":%d%s%s}",
					x->spec_gloss ? "diffuseTexture" : "baseColorTexture", t,
					parts[k].texture_info ? "," : "",
					parts[k].texture_info ? parts[k].texture_info : "");
			}
			fprintf(mats, x->spec_gloss ? ",\"glossinessFactor\":0.5}}"
						    : ",\"metallicFactor\":0}");
			if (x->emissive_png) {
				int t = embed(x->emissive_png, &b, imgs, first_image, &images,
					      img_off, img_len);

				if (t < 0)
					goto out;
				fprintf(mats, ",\"emissiveTexture\":{\"index\":%d%s%s}", t,
					x->emissive_info ? "," : "",
					x->emissive_info ? x->emissive_info : "");
			}
			if (parts[k].normal_png) {
				int t = embed(parts[k].normal_png, &b, imgs, first_image, &images,
					      img_off, img_len);

				if (t < 0)
					goto out;
				fprintf(mats, ",\"normalTexture\":{\"index\":%d}", t);
			}
			fprintf(mats, "%s%s}", parts[k].material ? "," : "",
				parts[k].material ? parts[k].material : "");
		}
		fprintf(prims,
			"%s{\"attributes\":{\"POSITION\":%d,\"NORMAL\":%d,\"TEXCOORD_%d\":%d",
			k ? "," : "", 4 * k, 4 * k + 1, x->uv_set, 4 * k + 2);
		if (x->uv1) {
			uv1_count[uv1s] = parts[k].mesh->vertex_count;
			uv1_off[uv1s] = put(&b, x->uv1, uv1_count[uv1s] * 8);
			fprintf(prims, ",\"TEXCOORD_%d\":%d", x->uv1_set, 4 * n + uv1s++);
		}
		fprintf(prims, "},\"indices\":%d,\"material\":%d}", 4 * k + 3, material);
	}
	for (int j = 0; j < uv1s; j++) {
		fprintf(views, ",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", uv1_off[j],
			uv1_count[j] * 8);
		fprintf(acc,
			",{\"bufferView\":%d,\"componentType\":5126,\"count\":%zu,"
			"\"type\":\"VEC2\"}",
			4 * n + j, uv1_count[j]);
	}
	/* The images' views after every part's. */
	for (int i = 0; i < images; i++)
		fprintf(views, ",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", img_off[i],
			img_len[i]);
	out = open_memstream(&json, &js);
	fprintf(out,
		"{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
		"\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[%s]}],\"materials\":[%s],"
		"\"accessors\":[%s],\"bufferViews\":[%s],\"buffers\":[{\"byteLength\":%zu}]",
		stream_text(prims, &pbuf), stream_text(mats, &mbuf), stream_text(acc, &abuf),
		stream_text(views, &vbuf), b.size);
	prims = mats = acc = views = NULL;
	stream_text(imgs, &ibuf);
	imgs = NULL;
	if (images) {
		fprintf(out, ",\"images\":[%s],\"textures\":[", ibuf);
		for (int i = 0; i < images; i++)
			fprintf(out, "%s{\"source\":%d}", i ? "," : "", i);
		fprintf(out, "]");
	}
	put_extensions_used(out, mbuf);
	fprintf(out, "}");
	fclose(out);
	{
		FILE *f = fopen(path, "wb");
		uint32_t jpad = (uint32_t)pad4(js), total = 12 + 8 + jpad + 8 + (uint32_t)b.size;
		uint32_t hdr[3] = {0x46546C67, 2, total}, jc[2] = {jpad, 0x4E4F534A},
			 bc[2] = {(uint32_t)b.size, 0x004E4942};

		if (!f)
			goto out;
		fwrite(hdr, 4, 3, f);
		fwrite(jc, 4, 2, f);
		fwrite(json, 1, js, f);
		for (size_t i = js; i < jpad; i++)
			fputc(' ', f);
		fwrite(bc, 4, 2, f);
		fwrite(b.data, 1, b.size, f);
		ret = fclose(f) ? -1 : 0;
	}
out:
	if (views)
		fclose(views);
	if (acc)
		fclose(acc);
	if (mats)
		fclose(mats);
	if (prims)
		fclose(prims);
	if (imgs)
		fclose(imgs);
	free(vbuf);
	free(abuf);
	free(mbuf);
	free(pbuf);
	free(ibuf);
	free(json);
	free(b.data);
	return ret;
}
