#include "scene/mesh/mesh_cache.h"
#include "util/file.h"

#include <elf.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

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
 * runs them side by side) over every whole 32-byte stripe, then the tail,
 * then a final avalanche. Several GB/s, so a 30 MB model costs a few
 * milliseconds. In steps, so that a file is hashed as it is read. */
static const uint64_t p1 = 0x9E3779B185EBCA87ull, p2 = 0xC2B2AE3D27D4EB4Full;

static void lanes_start(uint64_t lane[4], uint64_t seed)
{
	lane[0] = seed + p1 + p2, lane[1] = seed + p2, lane[2] = seed, lane[3] = seed - p1;
}

static void lanes_add(uint64_t lane[4], const unsigned char *b, size_t stripes)
{
	uint64_t w;

	for (size_t i = 0; i < stripes * 32; i += 32)
		for (int k = 0; k < 4; k++) {
			memcpy(&w, b + i + 8 * k, 8);
			lane[k] = round64(lane[k], w);
		}
}

/* tail: the last size % 32 bytes. */
static uint64_t lanes_finish(const uint64_t lane[4], const unsigned char *tail, uint64_t size)
{
	uint64_t h = rotl(lane[0], 1) + rotl(lane[1], 7) + rotl(lane[2], 12) + rotl(lane[3], 18);
	size_t i = 0, n = (size_t)(size % 32);
	uint64_t w;

	for (int k = 0; k < 4; k++)
		h = (h ^ round64(0, lane[k])) * p1 + p2;
	h += size;
	for (; i + 8 <= n; i += 8) {
		memcpy(&w, tail + i, 8);
		h = rotl(h ^ round64(0, w), 27) * p1 + p2;
	}
	for (w = 0; i < n; i++)
		w = (w << 8) | tail[i];
	h = rotl(h ^ round64(0, w), 27) * p1 + p2;
	h ^= h >> 33;
	h *= p2;
	h ^= h >> 29;
	return h;
}

uint64_t mesh_cache_hash(const void *data, size_t size, uint64_t seed)
{
	uint64_t lane[4];

	lanes_start(lane, seed);
	lanes_add(lane, data, size / 32);
	return lanes_finish(lane, (const unsigned char *)data + size / 32 * 32, size);
}

/* Files are read in pieces of this many bytes (a multiple of 32), each
 * hashed while it is warm in the cache: a warm start hashes a 30 MB model
 * with no 30 MB buffer. Read, never mapped: a file cut short while mapped
 * raises SIGBUS, which would take the kiosk down. */
#define PIECE (256u << 10)

/* The file's hash, and its first 20 bytes (zeros past its end). */
static int hash_fd(int fd, uint64_t seed, uint64_t *out, unsigned char head[20])
{
	unsigned char *buf = malloc(PIECE);
	uint64_t lane[4], size = 0;
	ssize_t n = PIECE;
	int ret = 0;

	if (!buf)
		return -ENOMEM;
	lanes_start(lane, seed);
	memset(head, 0, 20);
	while (n == PIECE) {
		n = file_read_at(fd, buf, PIECE, (off_t)size);
		if (n < 0) {
			ret = (int)n;
			goto out;
		}
		if (!size)
			memcpy(head, buf, n < 20 ? (size_t)n : 20);
		lanes_add(lane, buf, (size_t)n / 32);
		size += (uint64_t)n;
	}
	*out = lanes_finish(lane, buf + (size_t)n / 32 * 32, size);
out:
	free(buf);
	return ret;
}

static int hash_file(const char *path, uint64_t seed, uint64_t *out)
{
	unsigned char head[20];
	int fd = file_open_read(path, 0, NULL), ret;

	if (fd < 0)
		return fd;
	ret = hash_fd(fd, seed, out, head);
	close(fd);
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

/* The text "uri"s are looked for in: a .glb's JSON is its first chunk
 * (after a 12-byte header and the chunk's length and type), a .gltf is
 * all JSON. Into *json (malloc'd), *size bytes. */
static int read_json(int fd, const unsigned char head[20], char **json, size_t *size)
{
	struct stat st;
	uint32_t len;
	off_t start = 0;
	ssize_t n;

	*json = NULL;
	*size = 0;
	if (fstat(fd, &st))
		return -errno;
	*size = (size_t)st.st_size;
	if (!memcmp(head, "glTF", 4) && st.st_size >= 20) {
		memcpy(&len, head + 12, 4);
		start = 20;
		*size = len <= st.st_size - 20 ? len : (size_t)(st.st_size - 20);
	}
	*json = malloc(*size + 1);
	if (!*json)
		return -ENOMEM;
	n = file_read_at(fd, (unsigned char *)*json, *size, start);
	*size = n > 0 ? (size_t)n : 0;
	return n < 0 ? (int)n : 0;
}

int mesh_cache_hash_model(const char *path, uint64_t *out)
{
	unsigned char head[20];
	char *json = NULL;
	size_t size = 0;
	int fd = file_open_read(path, 0, NULL), ret;

	if (fd < 0)
		return fd;
	ret = hash_fd(fd, KEY_VERSION, out, head);
	if (!ret)
		ret = read_json(fd, head, &json, &size);
	if (!ret)
		*out = hash_references(path, json, size, *out);
	free(json);
	close(fd);
	return ret;
}

/* The same key as mesh_cache_hash_model's, from bytes already read: the
 * whole file hashed at once is what its pieces give (PIECE is a multiple
 * of the stripe), and the JSON is a slice of it, as read_json reads it. */
uint64_t mesh_cache_hash_model_bytes(const char *path, const void *data, size_t size)
{
	const unsigned char *b = data;
	const char *json = data;
	size_t len = size;
	uint32_t n;

	if (size >= 20 && !memcmp(b, "glTF", 4)) {
		memcpy(&n, b + 12, 4);
		json = (const char *)b + 20;
		len = n <= size - 20 ? n : size - 20;
	}
	return hash_references(path, json, len, mesh_cache_hash(data, size, KEY_VERSION));
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

#define CACHE_MARGIN ((uint64_t)16 << 20)

bool mesh_cache_space_low(uint64_t bytes_free, uint64_t bytes_total)
{
	return bytes_total > 0 && bytes_free < CACHE_MARGIN;
}

bool mesh_cache_dir_full(const char *dir, uint64_t *bytes_free)
{
	char path[PATH_MAX];
	struct statvfs st;
	int n = snprintf(path, sizeof(path), "%s", dir);

	if (n < 0 || (size_t)n >= sizeof(path))
		return false;
	/* A cache folder not made yet: its file system is its parent's. */
	while (statvfs(path, &st)) {
		char *slash = strrchr(path, '/');

		if (errno != ENOENT || !slash || slash == path)
			return false;
		*slash = '\0';
	}
	if (bytes_free)
		*bytes_free = (uint64_t)st.f_bavail * st.f_frsize;
	return mesh_cache_space_low((uint64_t)st.f_bavail * st.f_frsize,
				    (uint64_t)st.f_blocks * st.f_frsize);
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
int mesh_cache_scene_key(const char *model, const void *data, size_t size, double lod_pixels,
			 int normals, const struct material_config *m, struct mesh_cache_key *out)
{
	/* normals: [scene] normals splits (flat) or averages (smooth) a
	 * primitive's vertices, another mesh. */
	const double values[] = {lod_pixels,	 m->detail,	m->iridescence,
				 VERTEX_COMPACT, m->base_color, normals};
	uint64_t program = 0;
	int ret = 0;

	memset(out, 0, sizeof(*out));
	if (!model || m->height_map || m->detail_map || m->detail == MATERIAL_ON)
		return -ENOENT;
	dl_iterate_phdr(build_id_note, &program);
	if (!program)
		ret = mesh_cache_hash_model("/proc/self/exe", &program);
	if (!ret)
		out->content = mesh_cache_hash_model_bytes(model, data, size);
	out->settings = mesh_cache_hash(values, sizeof(values), program);
	return ret;
}
