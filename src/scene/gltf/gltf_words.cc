// Our words for a file the parser refused, before its own: what a user
// brings is most often an empty file, a copy cut short, a glTF 1.0 export or
// a hand-edited JSON, and tinygltf names them in its terms ("JSON string too
// short", "asset object not found"). Read only after tinygltf failed, so a
// good file costs nothing more.
#include "scene/gltf/gltf_ext.h"

#include <nlohmann/json.hpp>

#include <cstring>

namespace gltf_ext
{

const char *const gltf1_words = "glTF 1.0 is not supported; re-export it as glTF 2.0";

namespace
{

const uint32_t glb_json = 0x4E4F534Au, glb_header = 12, chunk_header = 8;

uint32_t u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

std::string bytes(size_t n)
{
	return std::to_string(n) + (n == 1 ? " byte" : " bytes");
}

// Line and column (both from 1) of the byte at offset `at`.
std::string line_column(const unsigned char *text, size_t size, size_t at)
{
	size_t line = 1, start = 0;
	if (at > size)
		at = size;
	for (size_t i = 0; i < at; i++)
		if (text[i] == '\n')
			line++, start = i + 1;
	return "line " + std::to_string(line) + ", column " + std::to_string(at - start + 1);
}

// nlohmann's own words without its prefix: "[json.exception.parse_error.101]
// parse error at line 3, column 24: syntax error while parsing ...".
std::string parser_detail(const char *what)
{
	std::string s = what;
	size_t col = s.find("column ");
	size_t colon = col == std::string::npos ? std::string::npos : s.find(": ", col);
	return colon == std::string::npos ? s : s.substr(colon + 2);
}

// glTF 1.0 kept its lists as objects keyed by name; 2.0 has arrays.
bool keyed_lists(const nlohmann::json &j)
{
	for (const char *key : {"meshes", "accessors", "nodes", "buffers", "bufferViews"}) {
		auto it = j.find(key);
		if (it != j.end() && it->is_object())
			return true;
	}
	return false;
}

std::string json_fault(const unsigned char *text, size_t size, const std::string &where)
{
	nlohmann::json j;
	try {
		j = nlohmann::json::parse(text, text + size);
	} catch (const nlohmann::json::parse_error &e) {
		// e.byte counts the characters read, the one at fault included.
		size_t at = e.byte ? e.byte - 1 : 0;
		return "JSON syntax error" + where + " at " + line_column(text, size, at) + ": " +
		       parser_detail(e.what());
	}
	if (!j.is_object())
		return "the JSON" + where + " is not an object: not a glTF 2.0 model";
	auto asset = j.find("asset");
	if (asset == j.end() || !asset->is_object())
		return keyed_lists(j) ? gltf1_words
				      : "no \"asset\" object, expected \"asset\": {\"version\": "
					"\"2.0\"}: not a glTF 2.0 model";
	auto version = asset->find("version");
	if (version != asset->end() && version->is_string()) {
		std::string v = version->get<std::string>();
		if (v == "1" || v.compare(0, 2, "1.") == 0)
			return std::string(gltf1_words) + " (asset.version \"" + v + "\")";
	}
	return keyed_lists(j) ? gltf1_words : "";
}

std::string glb_fault(const unsigned char *data, size_t size)
{
	uint32_t version = size >= 8 ? u32(data + 4) : 2;
	if (version == 1)
		return std::string(gltf1_words) + " (a GLB of version 1)";
	if (version != 2)
		return "GLB version " + std::to_string(version) + ", expected 2 (glTF 2.0)";
	if (size < glb_header)
		return "GLB cut short: " + bytes(size) + ", less than its 12-byte header";
	uint32_t declared = u32(data + 8);
	if (declared > size)
		return "GLB cut short: its header declares " + bytes(declared) + ", the file has " +
		       std::to_string(size);
	if (size < glb_header + chunk_header)
		return "GLB cut short: " + bytes(size) + ", no room for its JSON chunk";
	size_t json_len = u32(data + 12), room = size - glb_header - chunk_header;
	if (u32(data + 16) != glb_json)
		return "GLB's first chunk is not JSON (its type is not \"JSON\")";
	if (json_len > room)
		return "GLB cut short: its JSON chunk declares " + bytes(json_len) +
		       ", the file has " + std::to_string(room) + " after the chunk's header";
	size_t bin = glb_header + chunk_header + json_len;
	if (size - bin >= chunk_header && u32(data + bin) > size - bin - chunk_header)
		return "GLB cut short: its binary chunk declares " + bytes(u32(data + bin)) +
		       ", the file has " + std::to_string(size - bin - chunk_header) +
		       " after the chunk's header";
	return json_fault(data + glb_header + chunk_header, json_len, " in the GLB's JSON chunk");
}

} // namespace

std::string file_fault(const unsigned char *data, size_t size)
{
	if (size == 0)
		return "the file is empty (0 bytes), expected a glTF 2.0 model (.gltf or .glb)";
	if (size >= 4 && std::memcmp(data, "glTF", 4) == 0)
		return glb_fault(data, size);
	return json_fault(data, size, "");
}

} // namespace gltf_ext
