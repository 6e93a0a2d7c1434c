#include "scene/gltf/gltf_json_depth.h"

#include <string.h>

/* GLB: a 12-byte header, then the first chunk's length and type. */
#define GLB_JSON_CHUNK	0x4E4F534Au
#define GLB_JSON_OFFSET 20u

static uint32_t read_u32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

bool gltf_json_depth_within(const char *text, size_t size, unsigned max,
			    struct gltf_json_depth *out)
{
	unsigned depth = 0;
	size_t line = 1;
	bool in_string = false;

	memset(out, 0, sizeof(*out));
	for (size_t i = 0; i < size; i++) {
		char c = text[i];

		if (c == '\n')
			line++;
		if (in_string) {
			/* An escape's next byte never ends the string. */
			if (c == '\\' && i + 1 < size && text[++i] == '\n')
				line++;
			else if (c == '"')
				in_string = false;
		} else if (c == '"') {
			in_string = true;
		} else if (c == '{' || c == '[') {
			if (++depth > out->depth)
				out->depth = depth;
			if (depth > max) {
				out->offset = i;
				out->line = line;
				return false;
			}
		} else if ((c == '}' || c == ']') && depth > 0) {
			depth--;
		}
	}
	return true;
}

bool gltf_json_depth_file_within(const uint8_t *data, size_t size, unsigned max,
				 struct gltf_json_depth *out)
{
	size_t len;
	bool ok;

	if (size < 4 || memcmp(data, "glTF", 4) != 0)
		return gltf_json_depth_within((const char *)data, size, max, out);
	if (size < GLB_JSON_OFFSET || read_u32(data + 16) != GLB_JSON_CHUNK) {
		memset(out, 0, sizeof(*out));
		out->glb = true;
		return true;
	}
	/* A chunk that claims more than the file holds is refused by the
	 * parser; what the file holds is scanned all the same. */
	len = read_u32(data + 12);
	if (len > size - GLB_JSON_OFFSET)
		len = size - GLB_JSON_OFFSET;
	ok = gltf_json_depth_within((const char *)data + GLB_JSON_OFFSET, len, max, out);
	out->glb = true;
	if (!ok)
		out->offset += GLB_JSON_OFFSET;
	return ok;
}
