#include "scene/mesh_cache.h"
#include "util/file.h"

#include <elf.h>
#include <errno.h>
#include <limits.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Part of every content hash: a change of what the entries hold or how
 * the key is made makes every older entry a miss. */
#define KEY_VERSION 1

static uint64_t rotl(uint64_t x, int r)
{
	return (x << r) | (x >> (64 - r));
}

static uint64_t round64(uint64_t acc, uint64_t w)
{
	const uint64_t p1 = 0x9E3779B185EBCA87ull, p2 = 0xC2B2AE3D27D4EB4Full;

	return rotl(acc + w * p2, 31) * p1;
}

/* xxHash64's shape: four independent lanes of eight bytes each (the CPU
 * runs them side by side), then the tail, then a final avalanche. Several
 * GB/s, so a 30 MB model costs a few milliseconds. */
uint64_t mesh_cache_hash(const void *data, size_t size, uint64_t seed)
{
	const uint64_t p1 = 0x9E3779B185EBCA87ull, p2 = 0xC2B2AE3D27D4EB4Full;
	const unsigned char *b = data;
	uint64_t lane[4] = {seed + p1 + p2, seed + p2, seed, seed - p1}, h, w;
	size_t i = 0;

	for (; i + 32 <= size; i += 32)
		for (int k = 0; k < 4; k++) {
			memcpy(&w, b + i + 8 * k, 8);
			lane[k] = round64(lane[k], w);
		}
	h = rotl(lane[0], 1) + rotl(lane[1], 7) + rotl(lane[2], 12) + rotl(lane[3], 18);
	for (int k = 0; k < 4; k++)
		h = (h ^ round64(0, lane[k])) * p1 + p2;
	h += size;
	for (; i + 8 <= size; i += 8) {
		memcpy(&w, b + i, 8);
		h = rotl(h ^ round64(0, w), 27) * p1 + p2;
	}
	for (w = 0; i < size; i++)
		w = (w << 8) | b[i];
	h = rotl(h ^ round64(0, w), 27) * p1 + p2;
	h ^= h >> 33;
	h *= p2;
	h ^= h >> 29;
	return h;
}

/* Files the key reads: no model beyond what the loader takes. */
#define KEY_MAX_FILE (1ull << 30)

/* A file's bytes, read (not mapped: see file_read_all). */
static int hash_file(const char *path, uint64_t seed, uint64_t *out)
{
	unsigned char *data;
	size_t size;
	int ret = file_read_all(path, KEY_MAX_FILE, &data, &size);

	if (!ret)
		*out = mesh_cache_hash(data, size, seed);
	free(data);
	return ret;
}

/* glTF names its buffers and images by "uri": each file beside it
 * joins the hash (a data: URI is in the file's own bytes already). A name
 * that does not resolve adds only itself: the loader reports it. */
static uint64_t hash_references(const char *path, const char *text, size_t size, uint64_t h)
{
	const char *end = text + size, *p = text, *slash = strrchr(path, '/');
	int dir_len = slash ? (int)(slash - path) : 1;
	const char *dir = slash ? path : ".";

	while ((p = memmem(p, (size_t)(end - p), "\"uri\"", 5))) {
		const char *q = p + 5, *close;
		char file[PATH_MAX];
		uint64_t fh = 0;

		p = q;
		while (q < end &&
		       (*q == ' ' || *q == '\t' || *q == '\n' || *q == '\r' || *q == ':'))
			q++;
		if (q >= end || *q != '"' || !(close = memchr(q + 1, '"', (size_t)(end - q - 1))))
			continue;
		q++;
		h = mesh_cache_hash(q, (size_t)(close - q), h);
		if ((size_t)(close - q) >= 5 && !memcmp(q, "data:", 5))
			continue;
		if (snprintf(file, sizeof(file), "%.*s/%.*s", dir_len, dir, (int)(close - q), q) <
			(int)sizeof(file) &&
		    !hash_file(file, h, &fh))
			h ^= fh;
	}
	return h;
}

/* A .glb's JSON is its first chunk (after a 12-byte header and the
 * chunk's length and type); a .gltf is all JSON. */
static size_t json_length(const unsigned char *data, size_t size, size_t *start)
{
	uint32_t len;

	*start = 0;
	if (size < 20 || memcmp(data, "glTF", 4))
		return size;
	memcpy(&len, data + 12, 4);
	*start = 20;
	return len <= size - 20 ? len : size - 20;
}

void mesh_cache_hash_model_bytes(const char *path, const unsigned char *data, size_t size,
				 uint64_t *out)
{
	size_t start, json = json_length(data, size, &start);

	*out = hash_references(path, (const char *)data + start, json,
			       mesh_cache_hash(data, size, KEY_VERSION));
}

int mesh_cache_hash_model(const char *path, uint64_t *out)
{
	unsigned char *data;
	size_t size;
	int ret = file_read_all(path, KEY_MAX_FILE, &data, &size);

	if (!ret)
		mesh_cache_hash_model_bytes(path, data, size, out);
	free(data);
	return ret;
}

int mesh_cache_dir(char *buf, size_t size)
{
	const char *systemd = getenv("CACHE_DIRECTORY"), *xdg = getenv("XDG_CACHE_HOME");
	const char *home = getenv("HOME");
	int n;

	if (systemd && *systemd)
		n = snprintf(buf, size, "%.*s", (int)strcspn(systemd, ":"), systemd);
	else if (xdg && *xdg == '/')
		n = snprintf(buf, size, "%s/matcap-kiosk", xdg);
	else if (home && *home == '/')
		n = snprintf(buf, size, "%s/.cache/matcap-kiosk", home);
	else
		return -ENOENT;
	return n < 0 || (size_t)n >= size ? -ENAMETOOLONG : 0;
}

/* The program's GNU build ID (gcc and Debian write one), from its own
 * ELF notes: what the kiosk was built from, without reading its bytes. */
static int build_id_note(struct dl_phdr_info *info, size_t size, void *data)
{
	uint64_t *out = data;

	(void)size;
	for (int i = 0; i < info->dlpi_phnum; i++) {
		const char *p = (const char *)(info->dlpi_addr + info->dlpi_phdr[i].p_vaddr);
		const char *end = p + info->dlpi_phdr[i].p_memsz;

		if (info->dlpi_phdr[i].p_type != PT_NOTE)
			continue;
		while (p + sizeof(ElfW(Nhdr)) <= end) {
			const ElfW(Nhdr) *n = (const ElfW(Nhdr) *)(const void *)p;
			const char *desc = p + sizeof(*n) + ((n->n_namesz + 3) & ~3u);

			if (n->n_type == NT_GNU_BUILD_ID && n->n_namesz == 4 &&
			    desc + n->n_descsz <= end) {
				*out = mesh_cache_hash(desc, n->n_descsz, 0);
				return 1;
			}
			p = desc + ((n->n_descsz + 3) & ~3u);
		}
	}
	return 1; /* the first object is the program itself: no further */
}

/* A scene is kept when nothing but the model file and these settings
 * shape its mesh: no displacement (a height map reshapes it), no detail
 * map or detail = on (their tangents need the UVs, which a cached scene's
 * material_load does not see), and, checked when writing, no texture
 * decoded from the model (an entry holds no images). The program's build
 * is part of the key: a rebuilt kiosk (another loader, another
 * simplifier) prepares again rather than trust what an older one wrote;
 * without a build ID, the program's bytes are. */
int mesh_cache_scene_key(const char *model, const unsigned char *data, size_t size,
			 double lod_pixels, const struct material_config *m,
			 struct mesh_cache_key *out)
{
	const double values[] = {lod_pixels, m->detail, m->iridescence, VERTEX_COMPACT,
				 m->base_color};
	uint64_t program = 0;
	int ret = 0;

	memset(out, 0, sizeof(*out));
	if (!model || m->height_map || m->detail_map || m->detail == MATERIAL_ON)
		return -ENOENT;
	dl_iterate_phdr(build_id_note, &program);
	if (!program)
		ret = mesh_cache_hash_model("/proc/self/exe", &program);
	if (!ret)
		mesh_cache_hash_model_bytes(model, data, size, &out->content);
	out->settings = mesh_cache_hash(values, sizeof(values), program);
	return ret;
}
