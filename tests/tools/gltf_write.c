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

/* Where each part lies in the buffer. */
struct layout {
	size_t nrm, idx, uv, tan, col, skin, img[4], img_len[4], size;
	const char *img_path[4]; /* normal, occlusion, thickness, base: NULL when absent */
};

static unsigned char *read_file(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	unsigned char *data = NULL;
	long n;

	if (!f)
		return NULL;
	if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 && fseek(f, 0, SEEK_SET) == 0) {
		data = malloc((size_t)n);
		*len = data ? fread(data, 1, (size_t)n, f) : 0;
	}
	fclose(f);
	return data;
}

static int has_material(const struct gltf_write_opts *o)
{
	return o->normal_png || o->occlusion_png || o->thickness_png || o->iridescence_factor > 0 ||
	       o->base_color_png || o->base_factor;
}

static size_t color_bytes(const struct mesh *m, const struct gltf_write_opts *o)
{
	size_t c = o->color_type == 5126 ? 4 : o->color_type == 5123 ? 2 : 1;

	return o->color_type ? pad4(c * (size_t)o->color_components) * m->vertex_count : 0;
}

/* One vertex's colour as the accessor stores it, each element padded to 4
 * bytes as glTF asks of vertex attributes. */
static void put_color(const struct mesh *m, const struct gltf_write_opts *o, uint32_t v,
		      unsigned char *out)
{
	size_t c = o->color_type == 5126 ? 4 : o->color_type == 5123 ? 2 : 1;

	for (int k = 0; k < o->color_components; k++) {
		float x = m->colors[v * 4 + k];
		uint16_t s = (uint16_t)(x * 65535.0f + 0.5f);
		uint8_t b = (uint8_t)(x * 255.0f + 0.5f);

		memcpy(out + k * c, c == 4 ? (void *)&x : c == 2 ? (void *)&s : (void *)&b, c);
	}
}

/* Joints 0 and 1 (bytes) for every vertex, then weights (floats) that
 * move from the first to the second along x, smoothly. */
static void put_skin(const struct mesh *m, uint32_t v, unsigned char *skin)
{
	static const unsigned char joints[4] = {0, 1, 0, 0};
	float t = (m->positions[v * 3] + 1.0f) / 2.0f, w[4] = {0, 0, 0, 0};

	t = t < 0 ? 0 : t > 1 ? 1 : t;
	w[1] = t * t * (3 - 2 * t);
	w[0] = 1 - w[1];
	memcpy(skin + (size_t)v * 4, joints, 4);
	memcpy(skin + (size_t)m->vertex_count * 4 + (size_t)v * 16, w, 16);
}

/* positions | normals | indices | uvs | tangents | embedded images, each
 * padded to 4 bytes. */
static unsigned char *pack(const struct mesh *m, const struct gltf_write_opts *o, struct layout *l)
{
	size_t stride = o->byte_stride ? (size_t)o->byte_stride : 12;
	size_t npos = stride * m->vertex_count, nnrm = 12 * (size_t)m->vertex_count;
	size_t nidx = (size_t)o->index_bytes * m->index_count;
	unsigned char *buf, *img[4] = {NULL, NULL, NULL, NULL};
	size_t ncol = color_bytes(m, o);

	l->img_path[0] = o->normal_png;
	l->img_path[1] = o->occlusion_png;
	l->img_path[2] = o->thickness_png;
	l->img_path[3] = o->base_color_png;
	l->nrm = pad4(npos);
	l->idx = l->nrm + (o->with_normals ? nnrm : 0);
	l->uv = pad4(l->idx + nidx);
	l->tan = l->uv + (o->with_uvs ? 8 * (size_t)m->vertex_count : 0);
	l->col = l->tan + (o->with_tangents ? 16 * (size_t)m->vertex_count : 0);
	l->skin = l->col + ncol;
	l->size = l->skin + (o->skin_joints ? 20 * (size_t)m->vertex_count : 0);
	for (int i = 0; i < 4; i++) {
		l->img_len[i] = 0;
		if (l->img_path[i] && o->embed_images)
			img[i] = read_file(l->img_path[i], &l->img_len[i]);
		l->img[i] = l->size;
		l->size = pad4(l->size + l->img_len[i]);
	}
	buf = calloc(1, l->size + 1);
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		memcpy(buf + v * stride, m->positions + v * 3, 12);
		if (o->with_normals)
			memcpy(buf + l->nrm + v * 12, m->normals + v * 3, 12);
		if (o->with_uvs)
			memcpy(buf + l->uv + v * 8, m->uvs + v * 2, 8);
		if (o->with_tangents)
			memcpy(buf + l->tan + v * 16, m->tangents + v * 4, 16);
		if (o->color_type)
			put_color(m, o, v, buf + l->col + v * (ncol / m->vertex_count));
		if (o->skin_joints)
			put_skin(m, v, buf + l->skin);
	}
	for (uint32_t i = 0; i < m->index_count && o->index_bytes; i++) {
		uint32_t x = m->indices[i];

		if (i == 0 && o->bad_index >= 0)
			x = (uint32_t)o->bad_index;
		memcpy(buf + l->idx + (size_t)i * o->index_bytes, &x, (size_t)o->index_bytes);
	}
	for (int i = 0; i < 4; i++) {
		if (img[i])
			memcpy(buf + l->img[i], img[i], l->img_len[i]);
		free(img[i]);
	}
	return buf;
}

static void write_material(FILE *f, const struct gltf_write_opts *o, const struct layout *l)
{
	static const char *const keys[2] = {"normalTexture", "occlusionTexture"};
	static const double factor[4] = {0.8, 0.7, 0.6, 1};
	const double *b = o->base_factor ? o->base_factor : factor;
	int texture = 0, sep = 0;

	fprintf(f, "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[%g,%g,%g,%g]",
		b[0], b[1], b[2], b[3]);
	if (l->img_path[3]) {
		int index = !!l->img_path[0] + !!l->img_path[1] + !!l->img_path[2];

		fprintf(f, ",\"baseColorTexture\":{\"index\":%d", index);
		if (o->texture_transform)
			fprintf(f, ",\"extensions\":{\"KHR_texture_transform\":{%s}}",
				o->texture_transform);
		fprintf(f, "}");
	}
	fprintf(f, "}");
	for (int i = 0; i < 2; i++)
		if (l->img_path[i])
			fprintf(f, ",\"%s\":{\"index\":%d}", keys[i], texture++);
	if (o->iridescence_factor > 0) {
		fprintf(f,
			",\"extensions\":{\"KHR_materials_iridescence\":{\"iridescenceFactor\":%g,"
			"\"iridescenceThicknessMinimum\":%g,\"iridescenceThicknessMaximum\":%g",
			o->iridescence_factor, o->thickness_range[0], o->thickness_range[1]);
		if (l->img_path[2])
			fprintf(f, ",\"iridescenceThicknessTexture\":{\"index\":%d}", texture);
		fprintf(f, "}}");
	}
	fprintf(f, "}],\"extensionsUsed\":[\"KHR_materials_iridescence\"%s],\"textures\":[",
		o->texture_transform ? ",\"KHR_texture_transform\"" : "");
	for (int i = 0, n = 0; i < 4; i++)
		if (l->img_path[i]) {
			fprintf(f, "%s{\"source\":%d}", n ? "," : "", n);
			n++;
		}
	fprintf(f, "],\"images\":[");
	for (int i = 0, view = 6; i < 4; i++) {
		const char *name = l->img_path[i] ? strrchr(l->img_path[i], '/') : NULL;

		if (!l->img_path[i])
			continue;
		name = name ? name + 1 : l->img_path[i];
		if (o->embed_images)
			fprintf(f, "%s{\"bufferView\":%d,\"mimeType\":\"image/png\"}",
				sep++ ? "," : "", view++);
		else
			fprintf(f, "%s{\"uri\":\"%s\"}", sep++ ? "," : "",
				o->image_uri ? o->image_uri : name);
	}
	fprintf(f, "],");
}

/* The skin's views follow the images': their numbers stay as they were. */
static void skin_accessors(FILE *f, const struct mesh *m, const struct gltf_write_opts *o,
			   const struct layout *l)
{
	int view = 6;

	for (int i = 0; i < 4; i++)
		view += l->img_path[i] && o->embed_images;
	fprintf(f,
		",{\"bufferView\":%d,\"componentType\":5121,\"count\":%u,\"type\":\"VEC4\"}"
		",{\"bufferView\":%d,\"componentType\":5126,\"count\":%u,\"type\":\"VEC4\"}",
		view, m->vertex_count, view + 1, m->vertex_count);
}

/* The turn of with_anim: key times and rotations, as a data: URI. */
static void write_anim_buffer(FILE *f)
{
	float keys[15] = {0, 1, 2, 0, 0, 0, 1, 0, 0, 0.38268343f, 0.92387953f, 0, 0, 0, 1};
	char *b = base64((const unsigned char *)keys, sizeof(keys));

	fprintf(f, ",{\"byteLength\":%zu,\"uri\":\"data:application/octet-stream;base64,%s\"}",
		sizeof(keys), b);
	free(b);
}

/* Its views, accessors (after views and accessors of their own numbers)
 * and the animation. */
static void write_anim(FILE *f, const struct gltf_write_opts *o, int view, int accessor, int part)
{
	if (part == 0)
		fprintf(f, ",{\"buffer\":1,\"byteOffset\":0,\"byteLength\":12}"
			   ",{\"buffer\":1,\"byteOffset\":12,\"byteLength\":48}");
	else if (part == 1)
		fprintf(f,
			",{\"bufferView\":%d,\"componentType\":5126,\"count\":3,\"type\":"
			"\"SCALAR\",\"min\":[0],\"max\":[2]},{\"bufferView\":%d,"
			"\"componentType\":5126,\"count\":3,\"type\":\"VEC4\"}",
			view, view + 1);
	else
		fprintf(f,
			"\"animations\":[{\"name\":\"turn\",\"samplers\":[{\"input\":%d,"
			"\"output\":%d%s}],\"channels\":[{\"sampler\":0,\"target\":{\"node\":%d,"
			"\"path\":\"rotation\"}}]}],",
			accessor, accessor + 1, o->anim_step ? ",\"interpolation\":\"STEP\"" : "",
			o->anim_node);
}

static void write_json(FILE *f, const struct mesh *m, const struct gltf_write_opts *o,
		       const struct layout *l, const char *uri)
{
	static const int ctype[5] = {0, 5121, 5123, 0, 5125};
	long count = o->position_count ? o->position_count : (long)m->vertex_count;

	fprintf(f, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[%s],",
		o->scenes ? o->scenes : "{\"nodes\":[0]}");
	fprintf(f, "\"nodes\":[");
	if (o->parent)
		fprintf(f, "{\"children\":[1]%s%s},", o->parent[0] ? "," : "", o->parent);
	fprintf(f, "{\"mesh\":0%s%s}%s%s],", o->node ? "," : "", o->node ? o->node : "",
		o->extra_nodes ? "," : "", o->extra_nodes ? o->extra_nodes : "");
	fprintf(f, "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0");
	if (o->with_normals)
		fprintf(f, ",\"NORMAL\":1");
	if (o->with_uvs)
		fprintf(f, ",\"TEXCOORD_%d\":3", o->uv_set);
	if (o->with_tangents)
		fprintf(f, ",\"TANGENT\":4");
	if (o->color_type)
		fprintf(f, ",\"COLOR_0\":5");
	if (o->skin_joints)
		fprintf(f, ",\"JOINTS_0\":%d,\"WEIGHTS_0\":%d", 5 + !!o->color_type,
			6 + !!o->color_type);
	fprintf(f, "}%s%s}]}],", o->index_bytes ? ",\"indices\":2" : "",
		has_material(o) ? ",\"material\":0" : "");
	if (has_material(o))
		write_material(f, o, l);
	if (o->skin_joints)
		fprintf(f, "\"skins\":[{\"joints\":[%s]}],", o->skin_joints);
	int views = 6 + 2 * !!o->skin_joints,
	    accessors = 5 + !!o->color_type + 2 * !!o->skin_joints;

	for (int i = 0; i < 4; i++)
		views += l->img_path[i] && o->embed_images;
	if (o->with_anim)
		write_anim(f, o, views, accessors, 2);
	fprintf(f, "\"buffers\":[{\"byteLength\":%zu%s%s%s}", l->size, uri ? ",\"uri\":\"" : "",
		uri ? uri : "", uri ? "\"" : "");
	if (o->with_anim)
		write_anim_buffer(f);
	fprintf(f, "],");
	fprintf(f, "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":%zu", l->nrm);
	if (o->byte_stride)
		fprintf(f, ",\"byteStride\":%d", o->byte_stride);
	fprintf(f, "},");
	/* An absent attribute's view is 4 bytes at the start, inside the buffer. */
	fprintf(f, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu},",
		o->with_normals ? l->nrm : 0, o->with_normals ? (size_t)m->vertex_count * 12 : 4);
	fprintf(f, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu},", l->idx,
		(size_t)m->index_count * (size_t)(o->index_bytes ? o->index_bytes : 1));
	fprintf(f, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu},", o->with_uvs ? l->uv : 0,
		o->with_uvs ? (size_t)m->vertex_count * 8 : 4);
	fprintf(f, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}",
		o->with_tangents ? l->tan : 0, o->with_tangents ? (size_t)m->vertex_count * 16 : 4);
	fprintf(f, ",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu",
		o->color_type ? l->col : 0, o->color_type ? color_bytes(m, o) : 4);
	if (o->color_type)
		fprintf(f, ",\"byteStride\":%zu", color_bytes(m, o) / m->vertex_count);
	fprintf(f, "}");
	for (int i = 0; i < 4; i++)
		if (l->img_path[i] && o->embed_images)
			fprintf(f, ",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}",
				l->img[i], l->img_len[i]);
	if (o->skin_joints)
		fprintf(f,
			",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}"
			",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}",
			l->skin, (size_t)m->vertex_count * 4, l->skin + (size_t)m->vertex_count * 4,
			(size_t)m->vertex_count * 16);
	if (o->with_anim)
		write_anim(f, o, views, accessors, 0);
	fprintf(f, "],");
	fprintf(f,
		"\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%ld,"
		"\"type\":\"VEC3\",\"min\":[-1,-1,-1],\"max\":[1,1,1]},",
		count);
	/* An attribute left out keeps its accessor number, as one element of
	 * the positions: valid for validators such as cgltf (gltfpack). */
	fprintf(f, "{\"bufferView\":%d,\"componentType\":5126,\"count\":%u,\"type\":\"VEC3\"},",
		o->with_normals ? 1 : 0, o->with_normals ? m->vertex_count : 1);
	fprintf(f, "{\"bufferView\":2,\"componentType\":%d,\"count\":%u,\"type\":\"SCALAR\"},",
		ctype[o->index_bytes > 0 ? o->index_bytes : 1], m->index_count);
	fprintf(f, "{\"bufferView\":%d,\"componentType\":5126,\"count\":%u,\"type\":\"VEC2\"},",
		o->with_uvs ? 3 : 0, o->with_uvs ? m->vertex_count : 1);
	fprintf(f, "{\"bufferView\":%d,\"componentType\":5126,\"count\":%u,\"type\":\"VEC4\"}",
		o->with_tangents ? 4 : 0, o->with_tangents ? m->vertex_count : 1);
	if (o->color_type)
		fprintf(
		    f, ",{\"bufferView\":5,\"componentType\":%d,\"count\":%u,\"type\":\"VEC%d\"%s}",
		    o->color_type, m->vertex_count, o->color_components,
		    o->color_type == 5126 ? "" : ",\"normalized\":true");
	if (o->skin_joints)
		skin_accessors(f, m, o, l);
	if (o->with_anim)
		write_anim(f, o, views, accessors, 1);
	fprintf(f, "]}");
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

static char *json_text(const struct mesh *m, const struct gltf_write_opts *o,
		       const struct layout *l, const char *uri, size_t *len)
{
	char *text = NULL;
	FILE *mem = open_memstream(&text, len);

	write_json(mem, m, o, l, uri);
	fclose(mem);
	return text;
}

int gltf_write(const char *path, const struct mesh *m, const struct gltf_write_opts *o)
{
	struct layout l;
	size_t jlen;
	unsigned char *bin = pack(m, o, &l);
	char bin_path[4096], *uri = NULL, *json;
	FILE *f;

	if (o->container == GLTF_DATA_URI) {
		char *b = base64(bin, l.size);

		uri = malloc(strlen(b) + 64);
		sprintf(uri, "data:application/octet-stream;base64,%s", b);
		free(b);
	} else if (o->container == GLTF_EXTERNAL_BIN) {
		snprintf(bin_path, sizeof(bin_path), "%.*s.bin", (int)(strlen(path) - 5), path);
		const char *name = strrchr(bin_path, '/') ? strrchr(bin_path, '/') + 1 : bin_path;

		uri = strdup(o->bin_uri ? o->bin_uri : name);
		f = fopen(bin_path, "wb");
		fwrite(bin, 1, l.size, f);
		fclose(f);
	}
	json = json_text(m, o, &l, uri, &jlen);
	f = fopen(path, "wb");
	if (o->container == GLTF_GLB)
		write_glb(f, json, jlen, bin, l.size);
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

int gltf_test_cube(struct mesh *m)
{
	/* Corner i at x = bit 0, y = bit 1, z = bit 2 (-0.5 or 0.5); each
	 * side two triangles, counter-clockwise seen from outside. */
	static const uint32_t sides[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
					   2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

	if (mesh_alloc(m, 8, 36, false))
		return -1;
	for (uint32_t v = 0; v < 8; v++)
		for (int k = 0; k < 3; k++) {
			m->positions[v * 3 + k] = (v >> k) & 1 ? 0.5f : -0.5f;
			m->normals[v * 3 + k] = 0.0f;
		}
	memcpy(m->indices, sides, sizeof(sides));
	return 0;
}
