// The model's name from its glTF JSON: read apart from the model (the
// caption is drawn on the worker beside it), and only when asked.
#include "scene/gltf/gltf_name.h"
#include "scene/gltf/gltf_json_depth.h"
#include "util/file.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <unistd.h>

namespace
{

// Enough for any model's JSON; a larger one names nothing.
const size_t max_json = 64u << 20;

uint32_t read_u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

// The JSON text: a .gltf whole, or a GLB's JSON chunk alone (its
// binary chunk may be hundreds of megabytes).
std::string read_json(const char *path)
{
	unsigned char head[20];
	std::string text;
	int fd = file_open_read(path, 0, nullptr);

	if (fd < 0)
		return text;
	if (file_read_at(fd, head, sizeof(head), 0) == (ssize_t)sizeof(head) &&
	    !std::memcmp(head, "glTF", 4)) {
		uint32_t len = read_u32(head + 12);

		if (read_u32(head + 16) == 0x4E4F534Au && len <= max_json) {
			text.resize(len);
			if (file_read_at(fd, &text[0], len, 20) != (ssize_t)len)
				text.clear();
		}
		close(fd);
		return text;
	}
	close(fd);
	unsigned char *data = nullptr;
	size_t size = 0;

	if (!file_read_all(path, max_json, &data, &size))
		text.assign((const char *)data, size);
	free(data);
	return text;
}

std::string string_at(const nlohmann::json &j, const char *key)
{
	auto it = j.is_object() ? j.find(key) : j.end();

	return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::string scene_name(const nlohmann::json &j, const char *want)
{
	auto scenes = j.find("scenes");
	long index = 0;
	char *end = nullptr;

	if (scenes == j.end() || !scenes->is_array() || scenes->empty())
		return std::string();
	if (want && *want) {
		index = std::strtol(want, &end, 10);
		if (*end) // a name: the scene is shown by it
			return want;
	} else if (j.contains("scene") && j["scene"].is_number_integer()) {
		index = j["scene"].get<long>();
	}
	if (index < 0 || (size_t)index >= scenes->size())
		return std::string();
	return string_at((*scenes)[(size_t)index], "name");
}

} // namespace

char *gltf_model_name(const char *path, const char *scene)
{
	std::string text = read_json(path);
	struct gltf_json_depth d;
	std::string name;

	// The model loader refused it already (gltf_json_depth.h); the
	// caption's own parse must not recurse that deep either.
	if (!gltf_json_depth_within(text.data(), text.size(), GLTF_JSON_MAX_DEPTH, &d))
		return nullptr;
	nlohmann::json j = nlohmann::json::parse(text, nullptr, false);

	if (!j.is_object())
		return nullptr;
	auto asset = j.find("asset");
	if (asset != j.end() && asset->is_object() && asset->contains("extras"))
		name = string_at((*asset)["extras"], "title");
	if (name.empty())
		name = scene_name(j, scene);
	return name.empty() ? nullptr : strdup(name.c_str());
}
