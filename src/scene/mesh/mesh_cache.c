#include "scene/mesh/mesh_cache.h"
#include "scene/mesh/mesh_cache_anim.h"
#include "scene/mesh/mesh_cache_nest.h"
#include "util/file.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* Changed whenever the layout or the preparation changes: an entry of
 * another version is stale. */
#define CACHE_VERSION 12
#define CACHE_SUFFIX  ".mkmesh"

static const char cache_magic[8] = {'M', 'K', 'M', 'E', 'S', 'H', '\r', '\n'};

/* On disk, in the host's byte order (an entry is never moved between
 * machines; one of another order fails the header's checksum). */
struct cache_header {
	char magic[8];
	uint32_t version, header_size;
	uint64_t content, settings;
	uint32_t vertex_count, index_count;
	uint32_t format; /* enum vertex_format */
	uint32_t arrays; /* bit a: array a is present */
	float position_scale;
	uint32_t range_count, material_count;
	uint32_t width, height;
	uint32_t node_count, unused; /* the named nodes' records (mesh.h's MESH_NODES at most) */
	uint64_t payload_size, payload_hash;
	/* The live playback's section (mesh_cache_anim.c) at the payload's
	 * end, in bytes; 0: a still. */
	uint64_t anim_size;
	uint64_t header_hash; /* of every byte before it */
};

/* The payload starts 8-aligned, so its arrays can be read in place. */
_Static_assert(sizeof(struct cache_header) % 8 == 0, "the header keeps the payload aligned");

struct mesh_cache_entry {
	void *map;
	size_t size;
	struct mesh_packed mesh;
	/* No arrays: what only it holds, the materials' factors and the
	 * model's colour facts (its ranges are mesh's). */
	struct mesh materials;
	struct mesh_cache_key key;
	struct anim_play *play; /* read from the anim section; NULL: a still */
};

static size_t padded(size_t n)
{
	return (n + 7) & ~(size_t)7;
}

/* The records after the indices: the model's colour facts, each range
 * material, each range (mesh_cache_fields.c's tables), in bytes. */
static uint64_t record_bytes(const struct cache_header *h)
{
	return (uint64_t)mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_COLORS)) +
	       (uint64_t)h->material_count *
		   mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_MATERIAL)) +
	       (uint64_t)h->range_count * mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_RANGE)) +
	       (uint64_t)h->node_count * mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_NODE));
}

/* The payload's layout: each present array, then the indices, then the
 * records, then the anim section, each starting on 8 bytes. Returns its
 * size. */
static uint64_t payload_layout(const struct cache_header *h, uint64_t offset[MESH_ARRAYS + 3])
{
	uint64_t total = 0;

	for (int a = 0; a < MESH_ARRAYS; a++) {
		offset[a] = total;
		if (h->arrays & (1u << a))
			total += padded(
			    (uint64_t)h->vertex_count *
			    mesh_array_stride((enum vertex_format)h->format, (enum mesh_array)a));
	}
	offset[MESH_ARRAYS] = total;
	offset[MESH_ARRAYS + 1] = total + padded((uint64_t)h->index_count * 4);
	offset[MESH_ARRAYS + 2] = offset[MESH_ARRAYS + 1] + padded(record_bytes(h));
	return offset[MESH_ARRAYS + 2] + padded(h->anim_size);
}

static bool header_sane(const struct cache_header *h, size_t size)
{
	return size >= sizeof(*h) && !memcmp(h->magic, cache_magic, 8) &&
	       h->version == CACHE_VERSION && h->header_size == sizeof(*h) &&
	       h->header_hash ==
		   mesh_cache_hash(h, offsetof(struct cache_header, header_hash), 0) &&
	       h->format <= VERTEX_COMPACT && (h->arrays & 3u) == 3u &&
	       !(h->arrays >> MESH_ARRAYS) && h->index_count % 3 == 0 && h->index_count &&
	       h->vertex_count && h->position_scale > 0.0f && h->position_scale <= 1e30f &&
	       h->range_count <= h->index_count / 3 && h->material_count <= h->index_count / 3 &&
	       h->anim_size <= size && (h->range_count == 0) == (h->material_count == 0) &&
	       h->node_count <= MESH_NODES;
}

/* One record of table t into obj; what is wrong said at its place,
 * name[i] ("ranges[1].material: ..."), or name alone (i UINT32_MAX). */
static bool read_record(struct mesh_nest_in *g, enum mesh_cache_table t, void *obj,
			const char *name, uint32_t i)
{
	if (mesh_nest_read(g, mesh_cache_table(t), obj))
		return true;
	mesh_nest_prefix(g, name, i == UINT32_MAX ? SIZE_MAX : i);
	return false;
}

/* The records (size bytes at data) into materials (allocated), each
 * checked by its table (the ranges': in order, covering every index
 * once, each a whole number of triangles with a material that exists). */
static int read_records(const struct cache_header *h, const void *data, size_t size,
			struct mesh *materials)
{
	struct mesh_cache_ranges ranges = {0, h->index_count, h->material_count};
	struct mesh_nest_in g = {data, size, true, &ranges, ""};

	memset(materials, 0, sizeof(*materials));
	if (h->range_count && mesh_alloc_ranges(materials, h->range_count, h->material_count))
		return -ENOMEM;
	read_record(&g, MESH_CACHE_COLORS, materials, "colours", UINT32_MAX);
	for (uint32_t k = 0; g.ok && k < h->material_count; k++)
		read_record(&g, MESH_CACHE_MATERIAL, &materials->materials[k], "materials", k);
	for (uint32_t r = 0; g.ok && r < h->range_count; r++)
		read_record(&g, MESH_CACHE_RANGE, &materials->ranges[r], "ranges", r);
	if (g.ok && h->range_count && ranges.at != h->index_count)
		mesh_nest_fail(&g, "ranges", "they leave indices uncovered");
	for (uint32_t k = 0; g.ok && k < h->node_count; k++)
		read_record(&g, MESH_CACHE_NODE, &materials->nodes[k], "nodes", k);
	materials->node_count = g.ok ? h->node_count : 0;
	if (g.ok)
		return 0;
	log_warn("a cache entry's records are refused at %s", g.why);
	mesh_release(materials);
	return -EBADMSG;
}

int mesh_cache_parse(const void *data, size_t size, const struct mesh_cache_key *key,
		     struct mesh_packed *out, struct mesh *materials, struct mesh_cache_key *found)
{
	struct cache_header h;
	struct mesh shell;
	uint64_t offset[MESH_ARRAYS + 3];
	int ret;
	const char *payload = (const char *)data + sizeof(h);
	const uint32_t *idx;

	memset(out, 0, sizeof(*out));
	if (size < sizeof(h))
		return -EBADMSG;
	memcpy(&h, data, sizeof(h));
	if (!header_sane(&h, size) ||
	    (key && (h.content != key->content || h.settings != key->settings)))
		return -EBADMSG;
	if (payload_layout(&h, offset) != h.payload_size || h.payload_size != size - sizeof(h) ||
	    mesh_cache_hash(payload, (size_t)h.payload_size, h.content) != h.payload_hash)
		return -EBADMSG;
	/* The checksum finds damage; the index range is what keeps the GPU
	 * inside the arrays, so it is checked as well. */
	idx = (const uint32_t *)(const void *)(payload + offset[MESH_ARRAYS]);
	for (uint32_t i = 0; i < h.index_count; i++)
		if (idx[i] >= h.vertex_count)
			return -EBADMSG;
	out->format = (enum vertex_format)h.format;
	out->vertex_count = h.vertex_count;
	out->index_count = h.index_count;
	out->position_scale = h.position_scale;
	for (int a = 0; a < MESH_ARRAYS; a++)
		out->arrays[a] = h.arrays & (1u << a) ? payload + offset[a] : NULL;
	out->indices = idx;
	ret = read_records(&h, payload + offset[MESH_ARRAYS + 1], (size_t)record_bytes(&h), &shell);
	if (ret) {
		memset(out, 0, sizeof(*out));
		return ret;
	}
	out->ranges = shell.ranges;
	out->range_count = shell.range_count;
	if (materials)
		*materials = shell;
	else
		mesh_release(&shell);
	if (!materials)
		out->ranges = NULL, out->range_count = 0;
	if (found)
		*found = (struct mesh_cache_key){h.content, h.settings, h.width, h.height};
	return 0;
}

int mesh_cache_parse_play(const void *data, size_t size, struct anim_play **out)
{
	struct cache_header h;
	uint64_t offset[MESH_ARRAYS + 3];

	*out = NULL;
	if (size < sizeof(h))
		return -EBADMSG;
	memcpy(&h, data, sizeof(h));
	if (!header_sane(&h, size) || payload_layout(&h, offset) != size - sizeof(h))
		return -EBADMSG;
	if (!h.anim_size)
		return 0;
	return mesh_cache_anim_decode((const char *)data + sizeof(h) + offset[MESH_ARRAYS + 2],
				      (size_t)h.anim_size, h.vertex_count, out);
}

void mesh_cache_reseal(void *data, size_t size)
{
	struct cache_header h;

	if (size < sizeof(h))
		return;
	memcpy(&h, data, sizeof(h));
	h.payload_hash =
	    mesh_cache_hash((const char *)data + sizeof(h), size - sizeof(h), h.content);
	h.header_hash = mesh_cache_hash(&h, offsetof(struct cache_header, header_hash), 0);
	memcpy(data, &h, sizeof(h));
}

static int entry_path(const char *dir, const struct mesh_cache_key *key, char *buf, size_t size)
{
	int n = snprintf(buf, size, "%s/%016llx-%016llx" CACHE_SUFFIX, dir,
			 (unsigned long long)key->content, (unsigned long long)key->settings);

	return n < 0 || (size_t)n >= size ? -ENAMETOOLONG : 0;
}

static int map_entry(const char *path, struct mesh_cache_entry *e)
{
	struct stat st;
	/* The cache writes no links: one there (or a FIFO) is not its own. */
	int fd = file_open_read(path, FILE_NOFOLLOW, &st), ret = 0;

	if (fd < 0)
		return file_refusal(fd) ? -EBADMSG : fd;
	if (st.st_size < (off_t)sizeof(struct cache_header)) {
		ret = -EBADMSG;
		goto out;
	}
	e->size = (size_t)st.st_size;
	e->map = mmap(NULL, e->size, PROT_READ, MAP_PRIVATE, fd, 0);
	if (e->map == MAP_FAILED) {
		e->map = NULL;
		ret = -errno;
		goto out;
	}
	/* Read once, front to back: ask for it all now. */
	madvise(e->map, e->size, MADV_WILLNEED);
	/* Used now: the trimming removes the entries used least lately. */
	futimens(fd, NULL);
out:
	close(fd);
	return ret;
}

int mesh_cache_open(const char *dir, const struct mesh_cache_key *key,
		    struct mesh_cache_entry **out)
{
	struct mesh_cache_entry *e = calloc(1, sizeof(*e));
	char path[PATH_MAX];
	int ret = e ? entry_path(dir, key, path, sizeof(path)) : -ENOMEM;

	*out = NULL;
	if (!ret)
		ret = map_entry(path, e);
	if (!ret)
		ret = mesh_cache_parse(e->map, e->size, key, &e->mesh, &e->materials, &e->key);
	if (!ret)
		ret = mesh_cache_parse_play(e->map, e->size, &e->play);
	if (ret == -EBADMSG) {
		log_warn("%s: a damaged or stale cache entry, removed; the model is prepared again",
			 path);
		unlink(path);
	}
	if (ret) {
		mesh_cache_entry_free(e);
		return ret;
	}
	*out = e;
	return 0;
}

const struct mesh_packed *mesh_cache_entry_mesh(const struct mesh_cache_entry *e)
{
	return &e->mesh;
}

const struct mesh *mesh_cache_entry_materials(const struct mesh_cache_entry *e)
{
	return &e->materials;
}

void mesh_cache_entry_evict(const struct mesh_cache_entry *e)
{
	/* A private mapping never written: dropping its pages loses nothing. */
	madvise(e->map, e->size, MADV_DONTNEED);
}

const struct mesh_cache_key *mesh_cache_entry_key(const struct mesh_cache_entry *e)
{
	return &e->key;
}

struct anim_play *mesh_cache_entry_take_play(struct mesh_cache_entry *e)
{
	struct anim_play *p = e->play;

	e->play = NULL;
	return p;
}

void mesh_cache_entry_free(struct mesh_cache_entry *e)
{
	if (!e)
		return;
	if (e->map)
		munmap(e->map, e->size);
	mesh_release(&e->materials);
	anim_play_free(e->play);
	free(e);
}

/* The records in layout order (record_bytes of them: a table of arrays
 * would write more, and is refused); false when out of memory. */
static bool write_records(const struct cache_header *h, const struct mesh_packed *m,
			  const struct mesh *materials, char *to)
{
	struct mesh_nest_out b = {NULL, 0, 0, false};
	bool ok;

	mesh_nest_write(&b, mesh_cache_table(MESH_CACHE_COLORS), materials);
	for (uint32_t k = 0; k < h->material_count; k++)
		mesh_nest_write(&b, mesh_cache_table(MESH_CACHE_MATERIAL),
				&materials->materials[k]);
	for (uint32_t r = 0; r < h->range_count; r++)
		mesh_nest_write(&b, mesh_cache_table(MESH_CACHE_RANGE), &m->ranges[r]);
	for (uint32_t k = 0; k < h->node_count; k++)
		mesh_nest_write(&b, mesh_cache_table(MESH_CACHE_NODE), &materials->nodes[k]);
	ok = !b.failed && b.size == record_bytes(h);
	if (ok)
		memcpy(to, b.data, b.size);
	free(b.data);
	return ok;
}

/* The payload in layout order, hashed as it goes. */
static int write_payload(int fd, const struct cache_header *h, const struct mesh_packed *m,
			 const struct mesh *materials, const void *anim, uint64_t *hash_out)
{
	uint64_t offset[MESH_ARRAYS + 3];
	size_t size = (size_t)payload_layout(h, offset);
	char *buf = malloc(size + 1);
	int ret;

	if (!buf)
		return -ENOMEM;
	memset(buf, 0, size);
	for (int a = 0; a < MESH_ARRAYS; a++)
		if (m->arrays[a])
			memcpy(buf + offset[a], m->arrays[a],
			       (size_t)m->vertex_count *
				   mesh_array_stride(m->format, (enum mesh_array)a));
	memcpy(buf + offset[MESH_ARRAYS], m->indices, (size_t)m->index_count * 4);
	if (!write_records(h, m, materials, buf + offset[MESH_ARRAYS + 1])) {
		free(buf);
		return -ENOMEM;
	}
	if (h->anim_size)
		memcpy(buf + offset[MESH_ARRAYS + 2], anim, (size_t)h->anim_size);
	*hash_out = mesh_cache_hash(buf, size, h->content);
	ret = file_write_all(fd, buf, size);
	free(buf);
	return ret;
}

static void fill_header(struct cache_header *h, const struct mesh_cache_key *key,
			const struct mesh_packed *m, const struct mesh *materials, size_t anim_size)
{
	uint64_t offset[MESH_ARRAYS + 3];

	memset(h, 0, sizeof(*h));
	memcpy(h->magic, cache_magic, 8);
	h->version = CACHE_VERSION;
	h->header_size = sizeof(*h);
	h->content = key->content;
	h->settings = key->settings;
	h->width = key->width;
	h->height = key->height;
	h->vertex_count = m->vertex_count;
	h->index_count = m->index_count;
	h->format = m->format;
	for (int a = 0; a < MESH_ARRAYS; a++)
		h->arrays |= m->arrays[a] ? 1u << a : 0;
	h->position_scale = m->position_scale;
	h->node_count = materials->node_count < MESH_NODES ? materials->node_count : MESH_NODES;
	/* Ranges and their materials come together, or neither. */
	if (m->range_count && materials->material_count) {
		h->range_count = m->range_count;
		h->material_count = materials->material_count;
	}
	h->anim_size = anim_size;
	h->payload_size = payload_layout(h, offset);
}

static int make_dirs(const char *dir)
{
	char path[PATH_MAX];
	size_t len = strlen(dir);

	if (len >= sizeof(path))
		return -ENAMETOOLONG;
	memcpy(path, dir, len + 1);
	for (char *p = path + 1; *p; p++) {
		if (*p != '/')
			continue;
		*p = '\0';
		if (mkdir(path, 0700) && errno != EEXIST)
			return -errno;
		*p = '/';
	}
	return mkdir(path, 0700) && errno != EEXIST ? -errno : 0;
}

struct cache_file {
	char name[NAME_MAX + 1];
	off_t size;
	struct timespec used;
};

static int oldest_first(const void *a, const void *b)
{
	const struct timespec *x = &((const struct cache_file *)a)->used;
	const struct timespec *y = &((const struct cache_file *)b)->used;

	return x->tv_sec != y->tv_sec ? (x->tv_sec > y->tv_sec) - (x->tv_sec < y->tv_sec)
				      : (x->tv_nsec > y->tv_nsec) - (x->tv_nsec < y->tv_nsec);
}

/* Only the cache's own entries count and go; anything else in the
 * directory is left alone. */
static void trim(const char *dir, uint64_t max_bytes)
{
	DIR *d = opendir(dir);
	struct cache_file *files = NULL;
	size_t count = 0, cap = 0;
	uint64_t total = 0;
	struct dirent *de;

	while (d && (de = readdir(d))) {
		size_t len = strlen(de->d_name);
		struct stat st;
		struct cache_file *grown;

		if (len <= strlen(CACHE_SUFFIX) ||
		    strcmp(de->d_name + len - strlen(CACHE_SUFFIX), CACHE_SUFFIX) ||
		    fstatat(dirfd(d), de->d_name, &st, AT_SYMLINK_NOFOLLOW) || !S_ISREG(st.st_mode))
			continue;
		if (count == cap) {
			cap = cap ? cap * 2 : 16;
			grown = realloc(files, cap * sizeof(*files));
			if (!grown)
				break;
			files = grown;
		}
		snprintf(files[count].name, sizeof(files[count].name), "%s", de->d_name);
		files[count].size = st.st_size;
		files[count].used = st.st_mtim;
		total += (uint64_t)st.st_size;
		count++;
	}
	if (files)
		qsort(files, count, sizeof(*files), oldest_first);
	for (size_t i = 0; d && i < count && total > max_bytes; i++)
		if (!unlinkat(dirfd(d), files[i].name, 0))
			total -= (uint64_t)files[i].size;
	free(files);
	if (d)
		closedir(d);
}

int mesh_cache_write(const char *dir, const struct mesh_cache_key *key, const struct mesh_packed *m,
		     const struct mesh *materials, uint64_t max_bytes)
{
	return mesh_cache_write_play(dir, key, m, materials, NULL, 0, max_bytes);
}

int mesh_cache_write_play(const char *dir, const struct mesh_cache_key *key,
			  const struct mesh_packed *m, const struct mesh *materials,
			  const void *anim, size_t anim_size, uint64_t max_bytes)
{
	char path[PATH_MAX];
	struct cache_header h;
	struct file_atomic a;
	uint64_t left = 0;
	int ret;

	/* A full disk: a write that fails half way is removed, but what it
	 * took meanwhile may be what Mesa or the journal needed. */
	if (mesh_cache_dir_full(dir, &left)) {
		log_warn("%s: %llu KiB free, under 16 MiB: the mesh cache is not written; the next "
			 "start prepares the model again",
			 dir, (unsigned long long)(left >> 10));
		return -ENOSPC;
	}
	ret = make_dirs(dir);
	if (!ret)
		ret = entry_path(dir, key, path, sizeof(path));
	if (!ret)
		ret = file_atomic_begin(&a, path, 0644);
	if (ret)
		goto out;
	fill_header(&h, key, m, materials, anim ? anim_size : 0);
	/* The header last, once the payload's checksum is known. */
	ret = lseek(a.fd, (off_t)sizeof(h), SEEK_SET) < 0 ? -errno : 0;
	if (!ret)
		ret = write_payload(a.fd, &h, m, materials, anim, &h.payload_hash);
	h.header_hash = mesh_cache_hash(&h, offsetof(struct cache_header, header_hash), 0);
	if (!ret)
		ret = pwrite(a.fd, &h, sizeof(h), 0) == (ssize_t)sizeof(h) ? 0 : -EIO;
	ret = file_atomic_end(&a, ret, true);
	if (!ret)
		trim(dir, max_bytes);
out:
	if (ret)
		log_warn("%s: cannot write the mesh cache (%s); the next start prepares the "
			 "model again",
			 dir, strerror(-ret));
	return ret;
}

struct mesh_cache_writer {
	pthread_t thread;
	char dir[PATH_MAX];
	struct mesh_cache_key key;
	struct mesh_packed mesh;
	struct mesh materials; /* a copy: factors only, no arrays, no images */
	void *anim;	       /* the anim section's bytes, taken over; NULL: a still */
	size_t anim_size;
	uint64_t max_bytes;
};

static void *write_entry(void *arg)
{
	struct mesh_cache_writer *w = arg;

	mesh_cache_write_play(w->dir, &w->key, &w->mesh, &w->materials, w->anim, w->anim_size,
			      w->max_bytes);
	mesh_packed_release(&w->mesh);
	free(w->materials.materials);
	free(w->anim);
	return NULL;
}

struct mesh_cache_writer *mesh_cache_write_async(const char *dir, const struct mesh_cache_key *key,
						 struct mesh_packed *m,
						 const struct mesh *materials, uint64_t max_bytes)
{
	return mesh_cache_write_async_play(dir, key, m, materials, NULL, 0, max_bytes);
}

struct mesh_cache_writer *mesh_cache_write_async_play(const char *dir,
						      const struct mesh_cache_key *key,
						      struct mesh_packed *m,
						      const struct mesh *materials, void *anim,
						      size_t anim_size, uint64_t max_bytes)
{
	struct mesh_cache_writer *w = calloc(1, sizeof(*w));

	/* The factors copied: a reload may change the caller's meanwhile. */
	if (w && !mesh_copy_factors(&w->materials, materials) &&
	    snprintf(w->dir, sizeof(w->dir), "%s", dir) < (int)sizeof(w->dir)) {
		w->key = *key;
		w->mesh = *m;
		w->anim = anim;
		w->anim_size = anim_size;
		w->max_bytes = max_bytes;
		memset(m, 0, sizeof(*m));
		if (!pthread_create(&w->thread, NULL, write_entry, w))
			return w;
		*m = w->mesh;
	}
	if (w)
		free(w->materials.materials);
	free(w);
	mesh_cache_write_play(dir, key, m, materials, anim, anim_size, max_bytes);
	mesh_packed_release(m);
	free(anim);
	return NULL;
}

void mesh_cache_writer_join(struct mesh_cache_writer *w)
{
	if (!w)
		return;
	pthread_join(w->thread, NULL);
	free(w);
}
