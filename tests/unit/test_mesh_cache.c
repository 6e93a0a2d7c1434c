/* The prepared-mesh cache: what is written reads back the same, and an
 * entry that is truncated, flipped, stale or of another key is never
 * trusted. Also the compact vertex format it stores, the key, and the
 * folder's name, bound and free space (the kiosk's content through the
 * cache: test_mesh_cache_content.c). */
#include "config/settings.h"
#include "content/content.h"
#include "display/display.h"
#include "gltf_joints.h"
#include "gltf_write.h"
#include "scene/mesh/mesh.h"
#include "scene/anim/anim.h"
#include "scene/anim/anim_play.h"
#include "scene/mesh/mesh_cache.h"
#include "scene/mesh/mesh_cache_anim.h"
#include "scene/mesh/mesh_cache_nest.h"
#include "scene/mesh/mesh_pack.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>
#include "mesh_cache_fixture.h"

static void *read_entry(const struct fixture *f, size_t *size)
{
	char path[128];

	snprintf(path, sizeof(path), "%s/%016llx-%016llx.mkmesh", f->dir,
		 (unsigned long long)f->key.content, (unsigned long long)f->key.settings);
	return read_path(path, size);
}

static void compact_vertices_are_within_a_step(void **state)
{
	struct fixture *f = *state;
	const int16_t *p = f->packed.arrays[MESH_POSITIONS], *n = f->packed.arrays[MESH_NORMALS];
	float s = f->packed.position_scale;

	assert_true(s > 0.9f && s <= 1.0f);
	assert_int_equal(mesh_array_stride(VERTEX_COMPACT, MESH_POSITIONS), 6);
	assert_int_equal(mesh_array_stride(VERTEX_FLOAT32, MESH_POSITIONS), 12);
	for (uint32_t i = 0; i < f->mesh.vertex_count * 3; i++) {
		assert_true(fabsf(p[i] / 32767.0f * s - f->mesh.positions[i]) <= s / 32767.0f);
		assert_true(fabsf(n[i] / 32767.0f - f->mesh.normals[i]) <= 1.0f / 32767.0f);
	}
}

static void an_entry_reads_back_as_written(void **state)
{
	struct fixture *f = *state;
	struct mesh_cache_entry *e;
	const struct mesh_packed *m;
	size_t bytes = f->mesh.vertex_count * mesh_array_stride(VERTEX_COMPACT, MESH_POSITIONS);

	assert_int_equal(mesh_cache_open(f->dir, &f->key, &e), -ENOENT);
	assert_int_equal(
	    mesh_cache_write(f->dir, &f->key, &f->packed, &f->mesh, MESH_CACHE_MAX_BYTES), 0);
	assert_int_equal(mesh_cache_open(f->dir, &f->key, &e), 0);
	m = mesh_cache_entry_mesh(e);
	assert_int_equal(m->vertex_count, f->packed.vertex_count);
	assert_int_equal(m->index_count, f->packed.index_count);
	assert_true(m->position_scale == f->packed.position_scale);
	assert_memory_equal(m->arrays[MESH_POSITIONS], f->packed.arrays[MESH_POSITIONS], bytes);
	assert_memory_equal(m->indices, f->packed.indices, f->packed.index_count * 4);
	assert_null(m->arrays[MESH_TANGENTS]);
	assert_true(mesh_cache_entry_materials(e)->materials[0].present);
	assert_true(mesh_cache_entry_materials(e)->materials[0].base_color[1] == 0.25f);
	/* The model's colour facts, which no material and no array hold. */
	assert_true(mesh_cache_entry_materials(e)->has_colors);
	assert_memory_equal(mesh_cache_entry_materials(e)->vertex_color, f->mesh.vertex_color,
			    sizeof(f->mesh.vertex_color));
	/* The ranges and their materials, as written. */
	assert_int_equal(m->range_count, 2);
	assert_memory_equal(m->ranges, f->mesh.ranges, 2 * sizeof(struct mesh_range));
	assert_int_equal(mesh_cache_entry_materials(e)->material_count, 2);
	{
		const struct mesh_material *b = &mesh_cache_entry_materials(e)->materials[1];

		assert_int_equal(b->alpha_mode, MESH_ALPHA_BLEND);
		assert_true(b->base_alpha == 0.5f && b->double_sided && b->alpha_cutoff == 0.5f);
	}
	mesh_cache_entry_free(e);
}

/* A mesh with a second UV set (an emissive map on its own TEXCOORD_n)
 * stores it, and the material's emissive_uv1, and reads both back. */
static void a_second_uv_set_reads_back(void **state)
{
	struct fixture *f = *state;
	struct mesh_cache_entry *e;
	struct mesh m;
	struct mesh_packed p;

	assert_int_equal(mesh_uv_sphere(&m, 12, 8), 0);
	assert_int_equal(mesh_alloc_uv1(&m, m.uvs), 0);
	m.uv1[3] = 7.5f; /* a repeated map's UVs leave [0, 1]: stored as float */
	assert_int_equal(mesh_alloc_ranges(&m, 1, 1), 0);
	m.ranges[0] = (struct mesh_range){0, m.index_count, 0, {0, 0, 0}};
	m.materials[0].emissive_uv1 = true;
	assert_int_equal(mesh_pack(&m, VERTEX_COMPACT, &p), 0);
	assert_int_equal(mesh_cache_write(f->dir, &f->key, &p, &m, MESH_CACHE_MAX_BYTES), 0);
	assert_int_equal(mesh_cache_open(f->dir, &f->key, &e), 0);
	assert_non_null(mesh_cache_entry_mesh(e)->arrays[MESH_UV1]);
	assert_memory_equal(mesh_cache_entry_mesh(e)->arrays[MESH_UV1], m.uv1, m.vertex_count * 8);
	assert_true(mesh_cache_entry_materials(e)->materials[0].emissive_uv1);
	mesh_cache_entry_free(e);
	mesh_packed_release(&p);
	mesh_release(&m);
}

/* Every truncation and every single-bit flip of the header, and flips
 * spread over the payload: each is refused, none crashes. */
static void a_damaged_entry_is_refused(void **state)
{
	struct fixture *f = *state;
	struct mesh_packed out;
	struct mesh mat;
	size_t size;
	unsigned char *data;

	assert_int_equal(
	    mesh_cache_write(f->dir, &f->key, &f->packed, &f->mesh, MESH_CACHE_MAX_BYTES), 0);
	data = read_entry(f, &size);
	assert_int_equal(mesh_cache_parse(data, size, &f->key, &out, &mat, NULL), 0);
	mesh_release(&mat);
	for (size_t n = 0; n < size; n += n < 512 ? 1 : 97)
		assert_int_equal(mesh_cache_parse(data, n, &f->key, &out, &mat, NULL), -EBADMSG);
	for (size_t i = 0; i < size; i += i < 256 ? 1 : 13)
		for (int bit = 0; bit < 8; bit++) {
			data[i] ^= (unsigned char)(1u << bit);
			assert_int_equal(mesh_cache_parse(data, size, &f->key, &out, &mat, NULL),
					 -EBADMSG);
			data[i] ^= (unsigned char)(1u << bit);
		}
	free(data);
}

/* Parsing bytes resealed, what the journal says of them (into log). */
static int parse_logged(unsigned char *data, size_t size, char *log, size_t log_size)
{
	struct journal_capture c;
	struct mesh_packed out;
	int ret;

	mesh_cache_reseal(data, size);
	journal_capture_begin(&c);
	ret = mesh_cache_parse(data, size, NULL, &out, NULL, NULL);
	journal_capture_end(&c, log, log_size);
	return ret;
}

/* Checksums made right over a wrong field (a forgery, or a bug in the
 * writer): the index range and the layout are still checked. */
static void a_resealed_entry_is_still_checked(void **state)
{
	struct fixture *f = *state;
	struct mesh_packed out;
	size_t size;
	unsigned char *data;
	uint32_t bad;

	assert_int_equal(
	    mesh_cache_write(f->dir, &f->key, &f->packed, &f->mesh, MESH_CACHE_MAX_BYTES), 0);
	data = read_entry(f, &size);
	/* The records (colours, materials, then ranges) end the payload,
	 * 8-aligned; the last index is before them. */
	size_t range_bytes = mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_RANGE));
	size_t records = mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_COLORS)) +
			 2 * mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_MATERIAL)) +
			 2 * range_bytes;
	size_t last_index =
	    size - ((records + 7) & ~(size_t)7) - 4 - (f->packed.index_count % 2 ? 4 : 0);
	size_t range1 = size - ((records + 7) & ~(size_t)7) + records - range_bytes;
	size_t material0 = size - ((records + 7) & ~(size_t)7) +
			   mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_COLORS));
	char log[512];

	bad = f->packed.vertex_count;
	memcpy(data + last_index, &bad, 4);
	mesh_cache_reseal(data, size);
	assert_int_equal(mesh_cache_parse(data, size, NULL, &out, NULL, NULL), -EBADMSG);
	memcpy(data + last_index, f->packed.indices + f->packed.index_count - 1, 4);
	mesh_cache_reseal(data, size);
	assert_int_equal(mesh_cache_parse(data, size, NULL, &out, NULL, NULL), 0);
	/* The second range starting one triangle late (a gap), then with a
	 * material that does not exist, the first material's alpha mode
	 * past the last: refused, the journal saying which record and why. */
	memcpy(&bad, data + range1, 4);
	bad += 3;
	memcpy(data + range1, &bad, 4);
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "records are refused at ranges[1]: it does not start where the "
				    "range before it ends"));
	bad -= 3;
	memcpy(data + range1, &bad, 4);
	bad = 2;
	memcpy(data + range1 + 8, &bad, 4);
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "at ranges[1]: its material is not one the entry holds"));
	bad = 1;
	memcpy(data + range1 + 8, &bad, 4);
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), 0);
	bad = MESH_ALPHA_BLEND + 1; /* words: colours 5, then present, base colour 3, alpha */
	memcpy(data + material0 + 5 * 4, &bad, 4);
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "at materials[0].alpha_mode: out of its range"));
	/* A size that does not match the layout, resealed. */
	mesh_cache_reseal(data, size - 8);
	assert_int_equal(mesh_cache_parse(data, size - 8, NULL, &out, NULL, NULL), -EBADMSG);
	free(data);
}

/* A model's named nodes (a hotspot's node = NAME) read back as written;
 * a name that is not printable UTF-8, or fills its bytes without a NUL,
 * is refused with its place, checksums resealed over it. */
static void named_nodes_read_back_and_bad_names_are_refused(void **state)
{
	struct fixture *f = *state;
	struct mesh_cache_entry *e;
	size_t size, node_bytes = mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_NODE));
	unsigned char *data;
	char log[512];

	f->mesh.node_count = 2;
	snprintf(f->mesh.nodes[0].name, MESH_NODE_NAME, "arm");
	snprintf(f->mesh.nodes[1].name, MESH_NODE_NAME,
		 "Ventil \xc3\xb6"
		 "ffnet");
	f->mesh.nodes[1].index = 7;
	f->mesh.nodes[1].origin[0] = 1.5, f->mesh.nodes[1].origin[2] = -2;
	assert_int_equal(
	    mesh_cache_write(f->dir, &f->key, &f->packed, &f->mesh, MESH_CACHE_MAX_BYTES), 0);
	assert_int_equal(mesh_cache_open(f->dir, &f->key, &e), 0);
	assert_int_equal(mesh_cache_entry_materials(e)->node_count, 2);
	assert_memory_equal(mesh_cache_entry_materials(e)->nodes, f->mesh.nodes,
			    2 * sizeof(struct mesh_node));
	mesh_cache_entry_free(e);
	data = read_entry(f, &size);
	/* The nodes' records end the records, which end the payload (8-aligned). */
	size_t records = mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_COLORS)) +
			 2 * mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_MATERIAL)) +
			 2 * mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_RANGE)) +
			 2 * node_bytes;
	size_t node1 = size - ((records + 7) & ~(size_t)7) + records - node_bytes;

	data[node1 + 3] = 0x07; /* a control character inside */
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "at nodes[1]: its name is not printable UTF-8"));
	data[node1 + 3] = 0xc3; /* half a character */
	data[node1 + 4] = 'x';
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "at nodes[1]: its name is not printable UTF-8"));
	memset(data + node1, 'a', MESH_NODE_NAME);
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "nodes[1].name: no NUL within its bytes"));
	data[node1 + MESH_NODE_NAME - 1] = 0;
	assert_int_equal(parse_logged(data, size, log, sizeof(log)), 0);
	free(data);
	f->mesh.node_count = 0;
}

static void another_key_or_version_is_a_miss(void **state)
{
	struct fixture *f = *state;
	struct mesh_cache_key other = {.content = f->key.content, .settings = 1};
	struct mesh_cache_entry *e;
	struct mesh_packed out;
	size_t size;
	unsigned char *data;

	assert_int_equal(
	    mesh_cache_write(f->dir, &f->key, &f->packed, &f->mesh, MESH_CACHE_MAX_BYTES), 0);
	data = read_entry(f, &size);
	assert_int_equal(mesh_cache_parse(data, size, &other, &out, NULL, NULL), -EBADMSG);
	assert_int_equal(mesh_cache_open(f->dir, &other, &e), -ENOENT);
	/* An entry renamed under another key is stale: refused and removed. */
	{
		char from[128], to[128];

		snprintf(from, sizeof(from), "%s/%016llx-%016llx.mkmesh", f->dir, 0x1234ull,
			 0x5678ull);
		snprintf(to, sizeof(to), "%s/%016llx-%016llx.mkmesh", f->dir, 0x1234ull, 1ull);
		assert_int_equal(rename(from, to), 0);
		assert_int_equal(mesh_cache_open(f->dir, &other, &e), -EBADMSG);
		assert_int_equal(access(to, F_OK), -1);
	}
	free(data);
}

static void the_directory_stays_under_its_bound(void **state)
{
	struct fixture *f = *state;
	struct mesh_cache_entry *e;
	size_t size;
	void *data;

	assert_int_equal(
	    mesh_cache_write(f->dir, &f->key, &f->packed, &f->mesh, MESH_CACHE_MAX_BYTES), 0);
	data = read_entry(f, &size);
	free(data);
	/* Room for two: the third write removes the oldest. */
	for (uint64_t k = 1; k <= 3; k++) {
		struct mesh_cache_key key = {.content = k, .settings = 0};

		assert_int_equal(
		    mesh_cache_write(f->dir, &key, &f->packed, &f->mesh, 2 * size + size / 2), 0);
		usleep(20000); /* distinct times, coarse file systems too */
	}
	{
		struct mesh_cache_key first = {.content = 1}, last = {.content = 3};

		assert_int_equal(mesh_cache_open(f->dir, &first, &e), -ENOENT);
		assert_int_equal(mesh_cache_open(f->dir, &last, &e), 0);
		mesh_cache_entry_free(e);
	}
}

/* The key of a model's bytes in memory is the key of its file. */
static void same_key_of_bytes(const char *path)
{
	size_t n;
	unsigned char *bytes = read_path(path, &n);
	uint64_t key;

	assert_int_equal(mesh_cache_hash_model(path, &key), 0);
	assert_true(mesh_cache_hash_model_bytes(path, bytes, n) == key);
	free(bytes);
}

static void the_key_follows_the_bytes(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts glb = {.index_bytes = 4, .bad_index = -1};
	char model[128], buffer[128];
	uint64_t a, b, c;
	FILE *file;

	assert_int_not_equal(mesh_cache_hash("abc", 3, 0), mesh_cache_hash("abd", 3, 0));
	assert_int_not_equal(mesh_cache_hash("abc", 3, 0), mesh_cache_hash("abc", 3, 1));
	snprintf(model, sizeof(model), "%s/m.gltf", f->dir);
	snprintf(buffer, sizeof(buffer), "%s/m.bin", f->dir);
	file = fopen(model, "w");
	fputs("{\"buffers\": [{\"uri\" : \"m.bin\", \"byteLength\": 4}]}", file);
	fclose(file);
	file = fopen(buffer, "w");
	fputs("abcd", file);
	fclose(file);
	assert_int_equal(mesh_cache_hash_model(model, &a), 0);
	file = fopen(buffer, "w");
	fputs("abce", file);
	fclose(file);
	assert_int_equal(mesh_cache_hash_model(model, &b), 0);
	assert_int_equal(mesh_cache_hash_model(model, &c), 0);
	assert_int_not_equal(a, b); /* the buffer beside it counts */
	assert_int_equal(b, c);
	/* The key of the bytes content.c read (and parses) is the file's:
	 * an entry written before still hits; a .glb's JSON is its chunk. */
	same_key_of_bytes(model);
	snprintf(model, sizeof(model), "%s/m.glb", f->dir);
	assert_int_equal(gltf_write(model, &f->mesh, &glb), 0);
	same_key_of_bytes(model);
	assert_int_equal(mesh_cache_hash_model("/nonexistent/m.glb", &a), -ENOENT);
	/* Hashed in 256 KiB pieces as it is read: the same as the bytes at
	 * once (seed 1: KEY_VERSION in src/scene/mesh/mesh_cache_key.c), across
	 * the pieces' edges and with every length of tail. */
	for (size_t n = (512u << 10) - 33; n < (512u << 10) + 33; n++) {
		unsigned char *bytes = malloc(n);

		for (size_t i = 0; i < n; i++)
			bytes[i] = (unsigned char)(i * 2654435761u >> 13);
		file = fopen(buffer, "wb");
		fwrite(bytes, 1, n, file);
		fclose(file);
		assert_int_equal(mesh_cache_hash_model(buffer, &a), 0);
		assert_true(a == mesh_cache_hash(bytes, n, 1));
		free(bytes);
	}
}

static int by_offset(const void *a, const void *b)
{
	const struct mesh_nest_member *x = a, *y = b;

	return (x->offset > y->offset) - (x->offset < y->offset);
}

/* A member's alignment, from its kind; one not stored is only sized, so
 * the most its size allows (lenient: never a hole that is not there). */
static size_t align_of(const struct mesh_nest_member *m)
{
	size_t a = _Alignof(max_align_t);

	switch (m->kind) {
	case MESH_NEST_BOOL:
		return _Alignof(bool);
	case MESH_NEST_U32:
	case MESH_NEST_INT:
	case MESH_NEST_ENUM:
	case MESH_NEST_FLOATS:
		return 4;
	case MESH_NEST_SIZE:
		return _Alignof(size_t);
	case MESH_NEST_DOUBLES:
		return _Alignof(double);
	case MESH_NEST_NONE:
		while (m->size % a)
			a /= 2;
		return a;
	default:
		return _Alignof(void *);
	}
}

/* Every byte of t's struct is a member of the table or the padding the
 * next member's alignment makes: a field added to the struct and not to
 * the table (stored, or named as not stored) leaves a hole. Returns NULL,
 * or a member that a hole comes before ("" : one at the end). */
static const char *table_hole(const struct mesh_nest_member *members, size_t n, size_t size)
{
	struct mesh_nest_member *m = malloc(n * sizeof(*m));
	size_t end = 0, align = 1;
	const char *hole = NULL;

	memcpy(m, members, n * sizeof(*m));
	qsort(m, n, sizeof(*m), by_offset);
	for (size_t i = 0; !hole && i < n; i++) {
		if (m[i].offset < end || m[i].offset - end >= align_of(&m[i]))
			hole = m[i].name;
		end = m[i].offset + m[i].size;
		align = align_of(&m[i]) > align ? align_of(&m[i]) : align;
	}
	if (!hole && (end > size || size - end >= align))
		hole = "";
	free(m);
	return hole;
}

/* t and the tables under it (the rig's), once each, into all. */
static size_t collect(const struct mesh_nest *t, const struct mesh_nest **all, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (all[i] == t)
			return n;
	assert_true(n < 16);
	all[n++] = t;
	for (size_t i = 0; i < t->member_count; i++)
		if (t->members[i].sub)
			n = collect(t->members[i].sub, all, n);
	return n;
}

/* One mechanism describes the whole entry: every field of the material,
 * the range and every struct of the rig is in its member table (stored or
 * named as not stored); a table with a member taken out (what a field
 * added to the struct and not to the table looks like) is caught. */
static void every_field_is_in_the_cache_table(void **state)
{
	const struct mesh_nest *all[16] = {mesh_cache_table(MESH_CACHE_MATERIAL),
					   mesh_cache_table(MESH_CACHE_RANGE),
					   mesh_cache_table(MESH_CACHE_NODE)};
	size_t n = collect(mesh_cache_anim_table(), all, 3), caught = 0, big = 0;

	(void)state;
	assert_int_equal(n, 11); /* material, range, node and the rig's eight */
	for (size_t t = 0; t < n; t++) {
		const char *hole = table_hole(all[t]->members, all[t]->member_count, all[t]->size);
		struct mesh_nest_member less[64];

		if (hole)
			fail_msg(
			    "struct %s: a field before '%s' is in no member table of the cache "
			    "(src/scene/mesh/mesh_cache_fields.c, mesh_cache_anim.c)",
			    all[t]->name, hole);
		/* Each member at least as large as the struct's widest
		 * alignment left out is caught (a smaller one may hide in the
		 * padding before the next). Not a fixed 8 bytes: on armhf a
		 * pointer is 4, and most members are 4-byte aligned. */
		size_t widest = 1;

		for (size_t k = 0; k < all[t]->member_count; k++)
			if (align_of(&all[t]->members[k]) > widest)
				widest = align_of(&all[t]->members[k]);
		for (size_t k = 0; k < all[t]->member_count; k++) {
			if (all[t]->members[k].size < widest)
				continue;
			memcpy(less, all[t]->members, k * sizeof(*less));
			memcpy(less + k, all[t]->members + k + 1,
			       (all[t]->member_count - k - 1) * sizeof(*less));
			big++;
			caught += table_hole(less, all[t]->member_count - 1, all[t]->size) != NULL;
		}
	}
	assert_true(big > 20);
	assert_int_equal(caught, big);
	/* Stored: every field but the five images (29 words, and 14 for
	 * unlit and emission); the model's colour facts, 5 words, and the
	 * loader's fit (a hotspot's point lands on the model), 4 doubles. */
	assert_int_equal(mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_RANGE)), 6 * 4);
	assert_int_equal(mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_MATERIAL)), 44 * 4);
	assert_int_equal(mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_COLORS)), 5 * 4 + 4 * 8);
	/* A named node (a hotspot's node = NAME): its name's 64 bytes, its
	 * index and its origin's 3 doubles. */
	assert_int_equal(mesh_nest_min_bytes(mesh_cache_table(MESH_CACHE_NODE)), 64 + 4 + 3 * 8);
}

static void the_directory_is_named_as_systemd_and_xdg_say(void **state)
{
	char dir[256];

	(void)state;
	setenv("CACHE_DIRECTORY", "/var/cache/matcap-kiosk:/var/cache/other", 1);
	assert_int_equal(mesh_cache_dir(dir, sizeof(dir)), 0);
	assert_string_equal(dir, "/var/cache/matcap-kiosk");
	unsetenv("CACHE_DIRECTORY");
	setenv("XDG_CACHE_HOME", "/x/cache", 1);
	assert_int_equal(mesh_cache_dir(dir, sizeof(dir)), 0);
	assert_string_equal(dir, "/x/cache/matcap-kiosk");
	unsetenv("XDG_CACHE_HOME");
	setenv("HOME", "/home/k", 1);
	assert_int_equal(mesh_cache_dir(dir, sizeof(dir)), 0);
	assert_string_equal(dir, "/home/k/.cache/matcap-kiosk");
}

/* A cache file system with under 16 MiB free is full: the shader cache
 * and the mesh cache skip it; an unknown size (total 0) is not. */
static void a_nearly_full_disk_is_full(void **state)
{
	const uint64_t mib = 1u << 20;

	(void)state;
	assert_true(mesh_cache_space_low(0, mib));
	assert_true(mesh_cache_space_low(16 * mib - 1, (uint64_t)32 << 30));
	assert_false(mesh_cache_space_low(16 * mib, (uint64_t)32 << 30));
	assert_false(mesh_cache_space_low((uint64_t)2 << 30, (uint64_t)32 << 30));
	assert_false(mesh_cache_space_low(0, 0));
	/* A folder not made yet is judged by the one above it. */
	assert_false(mesh_cache_dir_full("/nonexistent-mk/a/b", NULL) &&
		     !mesh_cache_dir_full("/", NULL));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test_setup_teardown(compact_vertices_are_within_a_step, setup, teardown),
	    cmocka_unit_test_setup_teardown(an_entry_reads_back_as_written, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_second_uv_set_reads_back, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_damaged_entry_is_refused, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_resealed_entry_is_still_checked, setup, teardown),
	    cmocka_unit_test_setup_teardown(another_key_or_version_is_a_miss, setup, teardown),
	    cmocka_unit_test_setup_teardown(the_directory_stays_under_its_bound, setup, teardown),
	    cmocka_unit_test_setup_teardown(the_key_follows_the_bytes, setup, teardown),
	    cmocka_unit_test(the_directory_is_named_as_systemd_and_xdg_say),
	    cmocka_unit_test(every_field_is_in_the_cache_table),
	    cmocka_unit_test_setup_teardown(named_nodes_read_back_and_bad_names_are_refused, setup,
					    teardown),
	    cmocka_unit_test(a_nearly_full_disk_is_full),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
