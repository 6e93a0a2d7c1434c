// tinygltf's file callbacks for the glTF loader: a model's external files
// are read only from its own folder (or below), and what was refused or
// missing is kept, to name it when tinygltf gives up.
#include "scene/gltf/gltf_fs.h"
#include "scene/gltf/gltf_ext.h"
#include "util/file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

bool gltf_path_allowed(const GltfFiles &c, const std::string &path)
{
	std::string prefix = c.dir.empty() ? "" : c.dir + "/";
	if (path.compare(0, prefix.size(), prefix) != 0)
		return false;
	std::string rel = path.substr(prefix.size());
	if (rel.empty() || rel[0] == '/')
		return false;
	size_t start = 0;
	while (start <= rel.size()) {
		size_t end = rel.find('/', start);
		if (end == std::string::npos)
			end = rel.size();
		if (rel.compare(start, end - start, "..") == 0 && end - start == 2)
			return false;
		start = end + 1;
	}
	return true;
}

// Why path cannot be read, from file_open_read's code.
static std::string open_fault(const std::string &path, int ret)
{
	const char *why = file_refusal(ret);
	return why ? path + " " + why : "cannot open " + path + ": " + std::strerror(-ret);
}

// The whole file, refused when larger than max; opened by file_open_read,
// which refuses a FIFO (it would hang the load) or a device node.
bool gltf_read_file(const std::string &path, size_t max, std::vector<unsigned char> *out,
		    std::string *err)
{
	struct stat st;
	int fd = file_open_read(path.c_str(), 0, &st);
	bool ok = false;
	if (fd < 0) {
		*err = open_fault(path, fd);
		return false;
	}
	if ((unsigned long long)st.st_size > max) {
		*err = path + " is larger than the limit";
	} else {
		out->resize((size_t)st.st_size);
		ssize_t n = file_read_at(fd, out->data(), out->size(), 0);
		if (n < 0)
			*err = "read error in " + path + ": " + std::strerror((int)-n);
		else
			out->resize((size_t)n);
		ok = n >= 0;
	}
	close(fd);
	return ok;
}

std::string gltf_uri_fault(const GltfFiles &c, const std::string &uri)
{
	struct stat st;
	std::string path = (c.dir.empty() ? "" : c.dir + "/") + gltf_ext::percent_decoded(uri);
	if (!gltf_path_allowed(c, path))
		return "lies outside the model's folder (absolute paths and \"..\" are refused)";
	int fd = file_open_read(path.c_str(), 0, &st);
	if (fd >= 0)
		close(fd);
	if (fd == -ENOENT || fd == -ENOTDIR)
		return "is not in the model's folder (no such file)";
	if (file_refusal(fd))
		return file_refusal(fd);
	if (fd < 0)
		return std::string("cannot be read: ") + std::strerror(-fd);
	if ((unsigned long long)st.st_size > c.max_size)
		return "is larger than the limit (" + std::to_string(c.max_size >> 20) + " MiB)";
	return "could not be read";
}

namespace
{

// tinygltf looks for a buffer in more than one folder; remember the first
// refused path and any allowed one that was missing, to say which it was.
bool fs_exists(const std::string &path, void *user)
{
	GltfFiles *c = static_cast<GltfFiles *>(user);
	size_t skip = c->dir.empty() ? 0 : c->dir.size() + 1;
	std::string shown = path.size() > skip ? path.substr(skip) : path;
	if (!gltf_path_allowed(*c, path)) {
		if (c->refused.empty())
			c->refused = shown;
		return false;
	}
	// stat, not open: opening a FIFO blocks (the read refuses it, saying so).
	struct stat st;
	bool found = stat(path.c_str(), &st) == 0;
	if (!found && c->missing.empty())
		c->missing = shown;
	return found;
}

std::string fs_expand(const std::string &path, void *)
{
	return path; // no "~" or variables: a URI means what it says
}

bool fs_read(std::vector<unsigned char> *out, std::string *err, const std::string &path, void *user)
{
	GltfFiles *c = static_cast<GltfFiles *>(user);
	if (!gltf_path_allowed(*c, path)) {
		*err = "URI leaves the model's folder: " + path;
		return false;
	}
	return gltf_read_file(path, c->max_size, out, err);
}

bool fs_write(std::string *err, const std::string &, const std::vector<unsigned char> &, void *)
{
	*err = "writing is not allowed";
	return false;
}

// tinygltf 2.9 (Debian 13) asks for a file's size before reading it, and
// takes no callbacks at all unless this one is given too; 2.7 has no such
// member.
[[maybe_unused]] bool fs_size(size_t *size, std::string *err, const std::string &path, void *user)
{
	GltfFiles *c = static_cast<GltfFiles *>(user);
	if (!gltf_path_allowed(*c, path)) {
		*err = "URI leaves the model's folder: " + path;
		return false;
	}
	struct stat st;
	int fd = file_open_read(path.c_str(), 0, &st);
	if (fd < 0) {
		*err = open_fault(path, fd);
		return false;
	}
	close(fd);
	*size = (size_t)st.st_size;
	return true;
}

template <typename T, typename = void> struct HasFileSize : std::false_type {
};
template <typename T>
struct HasFileSize<T, std::void_t<decltype(&T::GetFileSizeInBytes)>> : std::true_type {
};

// Members by name: 2.9 added one before user_data, so a brace list that
// fits one version does not fit the other.
template <typename T> T fs_callbacks(GltfFiles *ctx)
{
	T fs{};
	fs.FileExists = fs_exists;
	fs.ExpandFilePath = fs_expand;
	fs.ReadWholeFile = fs_read;
	fs.WriteWholeFile = fs_write;
	if constexpr (HasFileSize<T>::value)
		fs.GetFileSizeInBytes = fs_size;
	fs.user_data = ctx;
	return fs;
}

} // namespace

tinygltf::FsCallbacks gltf_fs_callbacks(GltfFiles *files)
{
	return fs_callbacks<tinygltf::FsCallbacks>(files);
}
