// The model's file as tinygltf reads it: the JSON rewritten where tinygltf
// refuses what the spec allows, and, after it refused a file, which buffer
// was at fault, by its URI as written.
#include "scene/gltf/gltf_ext.h"
#include "util/file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <unistd.h>

namespace gltf_ext
{

namespace
{

uint32_t read_u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

void put_u32(std::vector<unsigned char> &out, uint32_t v)
{
	for (int k = 0; k < 4; k++)
		out.push_back((unsigned char)(v >> (8 * k)));
}

// Where the JSON text lies: the whole file, or a GLB's first chunk.
bool json_span(const unsigned char *data, size_t size, size_t *begin, size_t *len, bool *glb)
{
	*glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
	if (!*glb) {
		*begin = 0;
		*len = size;
		return true;
	}
	if (size < 20 || read_u32(data + 16) != 0x4E4F534Au)
		return false;
	*begin = 20;
	*len = read_u32(data + 12);
	return *len <= size - 20;
}

bool parse_json(const unsigned char *data, size_t size, nlohmann::json *j, bool *glb, size_t *end)
{
	size_t begin, len;
	if (!json_span(data, size, &begin, &len, glb))
		return false;
	*j = nlohmann::json::parse(data + begin, data + begin + len, nullptr, false);
	*end = begin + len;
	return j->is_object();
}

std::vector<unsigned char> glb_with_json(const unsigned char *data, size_t size, size_t json_end,
					 std::string text)
{
	std::vector<unsigned char> out;
	while (text.size() % 4)
		text.push_back(' ');
	size_t rest = size - json_end;
	out.insert(out.end(), data, data + 8);
	put_u32(out, (uint32_t)(12 + 8 + text.size() + rest));
	put_u32(out, (uint32_t)text.size());
	put_u32(out, 0x4E4F534Au);
	out.insert(out.end(), text.begin(), text.end());
	out.insert(out.end(), data + json_end, data + size);
	return out;
}

} // namespace

std::string percent_decoded(const std::string &uri)
{
	std::string out;
	for (size_t i = 0; i < uri.size(); i++) {
		unsigned v;
		if (uri[i] == '%' && i + 2 < uri.size() + 0 &&
		    std::sscanf(uri.c_str() + i + 1, "%2x", &v) == 1) {
			out.push_back((char)v);
			i += 2;
		} else {
			out.push_back(uri[i]);
		}
	}
	return out;
}

namespace
{

// In the JSON only: a GLB's binary chunk (30 MB for a 1M-triangle model)
// holds no extension names, and searching it cost 215M instructions, 8 % of
// a cold start.
bool mentions(const unsigned char *data, size_t size, const char *key)
{
	size_t begin, len;
	bool glb;
	if (!json_span(data, size, &begin, &len, &glb))
		return false;
	const unsigned char *end = data + begin + len;
	return std::search(data + begin, end, key, key + std::strlen(key)) != end;
}

bool has_view(const nlohmann::json &j, const nlohmann::json &index)
{
	if (!index.is_number_unsigned() || !j.contains("accessors") || !j["accessors"].is_array() ||
	    index.get<size_t>() >= j["accessors"].size())
		return true; // not ours to judge: the accessor checks name it
	const nlohmann::json &a = j["accessors"][index.get<size_t>()];
	return !a.is_object() || a.contains("bufferView");
}

bool move_indices(nlohmann::json &j)
{
	bool changed = false;
	if (!j.contains("meshes") || !j["meshes"].is_array())
		return false;
	for (nlohmann::json &mesh : j["meshes"]) {
		if (!mesh.is_object() || !mesh.contains("primitives") ||
		    !mesh["primitives"].is_array())
			continue;
		for (nlohmann::json &p : mesh["primitives"]) {
			if (!p.is_object() || !p.contains("indices") || has_view(j, p["indices"]))
				continue;
			if (!p.contains("extras") || !p["extras"].is_object())
				p["extras"] = nlohmann::json::object();
			p["extras"][moved_indices] = p["indices"];
			p.erase("indices");
			changed = true;
		}
	}
	return changed;
}

bool empty_fallbacks(nlohmann::json &j)
{
	static const char key[] = "EXT_meshopt_compression";
	bool changed = false;
	if (!j.contains("buffers") || !j["buffers"].is_array())
		return false;
	for (nlohmann::json &b : j["buffers"]) {
		if (!b.is_object() || !b.contains("extensions") || !b["extensions"].is_object())
			continue;
		const nlohmann::json &e = b["extensions"];
		if (!e.contains(key) || !e[key].is_object() || !e[key].value("fallback", false))
			continue;
		// tinygltf insists on bytes for every buffer; a fallback has none.
		b["uri"] = "data:application/octet-stream;base64,AA==";
		b["byteLength"] = 1;
		changed = true;
	}
	return changed;
}

} // namespace

std::vector<unsigned char> tinygltf_compatible(const unsigned char *data, size_t size, bool all)
{
	if (!all && !mentions(data, size, "EXT_meshopt_compression") &&
	    !mentions(data, size, "KHR_draco_mesh_compression"))
		return {};
	nlohmann::json j;
	bool glb;
	size_t json_end;
	if (!parse_json(data, size, &j, &glb, &json_end))
		return {};
	bool moved = move_indices(j), emptied = empty_fallbacks(j);
	if (!moved && !emptied)
		return {};
	std::string text = j.dump();
	if (glb)
		return glb_with_json(data, size, json_end, text);
	return std::vector<unsigned char>(text.begin(), text.end());
}

bool buffer_uris(const unsigned char *data, size_t size, std::vector<std::string> *uris, bool *glb)
{
	nlohmann::json j;
	size_t json_end;
	if (!parse_json(data, size, &j, glb, &json_end))
		return false;
	if (!j.contains("buffers") || !j["buffers"].is_array())
		return true;
	for (const nlohmann::json &b : j["buffers"]) {
		const nlohmann::json *u = b.is_object() && b.contains("uri") ? &b["uri"] : nullptr;
		uris->push_back(u && u->is_string() ? u->get<std::string>() : "");
	}
	return true;
}

namespace
{

// The first buffer whose URI (as written) names no file in dir that
// `allowed` accepts; empty when every buffer is there.
std::string buffer_fault(const std::string &dir,
			 const std::function<bool(const std::string &)> &allowed,
			 const unsigned char *data, size_t size)
{
	std::vector<std::string> uris;
	bool glb;
	if (!gltf_ext::buffer_uris(data, size, &uris, &glb))
		return "";
	for (size_t i = 0; i < uris.size(); i++) {
		const std::string &u = uris[i];
		std::string what = "buffers[" + std::to_string(i) + "]";
		if (u.empty() && !(glb && i == 0))
			return what + ": has no uri, expected a file name or a data: URI (only a "
				      ".glb's first buffer may leave it out)";
		if (u.empty() || u.compare(0, 5, "data:") == 0)
			continue;
		std::string path = (dir.empty() ? "" : dir + "/") + percent_decoded(u);
		if (!allowed(path))
			return what + ".uri \"" + u +
			       "\": lies outside the model's folder (absolute paths and \"..\" "
			       "are refused)";
		// Opened as the loader does: a FIFO named here would block an open.
		int fd = file_open_read(path.c_str(), 0, nullptr);
		if (fd >= 0)
			close(fd);
		else if (file_refusal(fd))
			return what + ".uri \"" + u + "\": " + file_refusal(fd);
		else
			return what + ".uri \"" + u + "\": no such file in the model's folder";
	}
	return "";
}

} // namespace

std::string parse_fault(const FileFault &c, const tinygltf::Model &m, const unsigned char *data,
			size_t size, std::string err)
{
	std::string required = unsupported(m.extensionsRequired);
	std::string buffer = buffer_fault(c.dir, c.allowed, data, size);
	if (!required.empty())
		return "extensionsRequired: " + required + " not supported";
	if (!buffer.empty())
		return buffer;
	if (!c.missing.empty())
		return "buffer file \"" + c.missing + "\" does not exist in the model's folder";
	if (size >= 8 && std::memcmp(data, "glTF", 4) == 0 && data[4] != 2)
		return "GLB version " + std::to_string(data[4]) + ", expected 2 (glTF 2.0)";
	if (!c.refused.empty())
		return "buffer URI \"" + c.refused +
		       "\" lies outside the model's folder (absolute paths and \"..\" are refused)";
	if (err.empty())
		return "not a glTF 2.0 file";
	for (char &ch : err)
		if (ch == '\n')
			ch = ' ';
	while (!err.empty() && err.back() == ' ')
		err.pop_back();
	return err;
}

} // namespace gltf_ext
