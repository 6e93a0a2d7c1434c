/* The prepared-mesh cache: what is written reads back the same, and an
 * entry that is truncated, flipped, stale or of another key is never
 * trusted. Also the compact vertex format it stores, and the entry of a
 * model that plays live (its playback data read back, or refused). */
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

/* OSMesa leaks a fixed few hundred bytes per process; see
 * tests/unit/test_camera_texture.c. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
	return "leak:libOSMesa\nleak:libLLVM\nleak:display_osmesa_new\n";
}

struct fixture {
	char dir[64];
	struct mesh mesh;
	struct mesh_packed packed;
	struct mesh_cache_key key;
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	assert_non_null(f);
	snprintf(f->dir, sizeof(f->dir), "/tmp/mk-cache-XXXXXX");
	assert_non_null(mkdtemp(f->dir));
	assert_int_equal(mesh_uv_sphere(&f->mesh, 24, 12), 0);
	f->mesh.material.present = true;
	f->mesh.material.base_color[1] = 0.25f;
	/* Two parts: the upper half opaque, the lower blended, double sided. */
	assert_int_equal(mesh_alloc_ranges(&f->mesh, 2, 2), 0);
	f->mesh.ranges[0] = (struct mesh_range){0, f->mesh.index_count / 6 * 3, 0, {0, 0, 0}};
	f->mesh.ranges[1] = (struct mesh_range){f->mesh.ranges[0].index_count,
						f->mesh.index_count - f->mesh.ranges[0].index_count,
						1,
						{0, 0, 0}};
	mesh_range_centers(&f->mesh);
	f->mesh.materials[1].alpha_mode = MESH_ALPHA_BLEND;
	f->mesh.materials[1].base_alpha = 0.5f;
	f->mesh.materials[1].double_sided = true;
	assert_int_equal(mesh_pack(&f->mesh, VERTEX_COMPACT, &f->packed), 0);
	f->key = (struct mesh_cache_key){.content = 0x1234, .settings = 0x5678};
	log_set_level(LOG_ERR);
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fixture *f = *state;
	char cmd[128];

	snprintf(cmd, sizeof(cmd), "rm -rf %s", f->dir);
	assert_int_equal(system(cmd), 0);
	mesh_packed_release(&f->packed);
	mesh_release(&f->mesh);
	free(f);
	return 0;
}

static void *read_path(const char *path, size_t *size)
{
	FILE *file;
	void *data;
	long n;

	file = fopen(path, "rb");
	assert_non_null(file);
	fseek(file, 0, SEEK_END);
	n = ftell(file);
	rewind(file);
	data = malloc((size_t)n);
	assert_int_equal(fread(data, 1, (size_t)n, file), (size_t)n);
	fclose(file);
	*size = (size_t)n;
	return data;
}

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
	assert_true(mesh_cache_entry_materials(e)->material.base_color[1] == 0.25f);
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
	m.material.emissive_uv1 = true;
	assert_int_equal(mesh_pack(&m, VERTEX_COMPACT, &p), 0);
	assert_int_equal(mesh_cache_write(f->dir, &f->key, &p, &m, MESH_CACHE_MAX_BYTES), 0);
	assert_int_equal(mesh_cache_open(f->dir, &f->key, &e), 0);
	assert_non_null(mesh_cache_entry_mesh(e)->arrays[MESH_UV1]);
	assert_memory_equal(mesh_cache_entry_mesh(e)->arrays[MESH_UV1], m.uv1, m.vertex_count * 8);
	assert_true(mesh_cache_entry_materials(e)->material.emissive_uv1);
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
	/* The records (materials, then ranges) end the payload, 8-aligned;
	 * the last index is before them. */
	size_t records = (3 * mesh_cache_record_words(MESH_CACHE_MATERIAL) +
			  2 * mesh_cache_record_words(MESH_CACHE_RANGE)) *
			 4;
	size_t last_index =
	    size - ((records + 7) & ~(size_t)7) - 4 - (f->packed.index_count % 2 ? 4 : 0);
	size_t range1 = size - ((records + 7) & ~(size_t)7) + records -
			mesh_cache_record_words(MESH_CACHE_RANGE) * 4;

	bad = f->packed.vertex_count;
	memcpy(data + last_index, &bad, 4);
	mesh_cache_reseal(data, size);
	assert_int_equal(mesh_cache_parse(data, size, NULL, &out, NULL, NULL), -EBADMSG);
	memcpy(data + last_index, f->packed.indices + f->packed.index_count - 1, 4);
	mesh_cache_reseal(data, size);
	assert_int_equal(mesh_cache_parse(data, size, NULL, &out, NULL, NULL), 0);
	/* The second range starting one triangle late (a gap), then with a
	 * material that does not exist: refused. */
	memcpy(&bad, data + range1, 4);
	bad += 3;
	memcpy(data + range1, &bad, 4);
	mesh_cache_reseal(data, size);
	assert_int_equal(mesh_cache_parse(data, size, NULL, &out, NULL, NULL), -EBADMSG);
	bad -= 3;
	memcpy(data + range1, &bad, 4);
	bad = 2;
	memcpy(data + range1 + 8, &bad, 4);
	mesh_cache_reseal(data, size);
	assert_int_equal(mesh_cache_parse(data, size, NULL, &out, NULL, NULL), -EBADMSG);
	/* A size that does not match the layout, resealed. */
	mesh_cache_reseal(data, size - 8);
	assert_int_equal(mesh_cache_parse(data, size - 8, NULL, &out, NULL, NULL), -EBADMSG);
	free(data);
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

static void the_key_follows_the_bytes(void **state)
{
	struct fixture *f = *state;
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
	const struct mesh_cache_field *x = a, *y = b;

	return (x->offset > y->offset) - (x->offset < y->offset);
}

/* Every byte of the struct is a field of the table or the padding the
 * next field's alignment makes: a field added to the struct and not to
 * the table (stored, or named as not stored) leaves a hole and fails. */
static void check_table(enum mesh_cache_table t, size_t struct_size, size_t struct_align)
{
	size_t n, end = 0;
	const struct mesh_cache_field *table = mesh_cache_fields(t, &n);
	struct mesh_cache_field *f = malloc(n * sizeof(*f));

	memcpy(f, table, n * sizeof(*f));
	qsort(f, n, sizeof(*f), by_offset);
	for (size_t i = 0; i < n; i++) {
		size_t expected = (end + f[i].align - 1) / f[i].align * f[i].align;

		if (f[i].offset != expected)
			fail_msg("%s: a field of %zu bytes before it has no entry in the cache's "
				 "table (src/scene/mesh/mesh_cache_fields.c)",
				 f[i].name, f[i].offset - end);
		end = f[i].offset + f[i].size;
	}
	if ((end + struct_align - 1) / struct_align * struct_align != struct_size)
		fail_msg("a field after %s has no entry in the cache's table", f[n - 1].name);
	free(f);
}

static void every_field_is_in_the_cache_table(void **state)
{
	(void)state;
	check_table(MESH_CACHE_MATERIAL, sizeof(struct mesh_material),
		    _Alignof(struct mesh_material));
	check_table(MESH_CACHE_RANGE, sizeof(struct mesh_range), _Alignof(struct mesh_range));
	/* Stored: every field but the five images (34 words, and 14 for
	 * unlit and emission). */
	assert_int_equal(mesh_cache_record_words(MESH_CACHE_RANGE), 6);
	assert_int_equal(mesh_cache_record_words(MESH_CACHE_MATERIAL), 49);
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

/* The kiosk's content: the first start prepares the model and writes its
 * entry, the next maps it (no parse) with the same counts, and another
 * display prepares it again from the file. */
static void content_maps_a_model_prepared_before(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = {.index_bytes = 4, .with_normals = 1, .bad_index = -1};
	struct content_config c = {.lod_pixels = 4.0};
	struct display_config dc = {.width = 16, .height = 16};
	struct display *d = display_osmesa_new(&dc);
	struct renderer *r;
	struct renderer_stats st;
	struct content s;
	char model[128];
	uint32_t triangles;

	assert_non_null(d);
	d->begin_frame(d);
	r = renderer_new(&d->gl, NULL);
	assert_non_null(r);
	snprintf(model, sizeof(model), "%s/sphere.glb", f->dir);
	assert_int_equal(gltf_write(model, &f->mesh, &o), 0);
	setenv("XDG_CACHE_HOME", f->dir, 1);
	material_config_defaults(&c.material);
	c.model = model;
	assert_int_equal(content_load(&s, &c, true), 0);
	assert_null(s.cached);
	assert_non_null(s.mesh.positions);
	assert_int_equal(content_prepare(&s, &c, 64, 64), 0);
	assert_null(s.mesh.positions); /* packed, the mesh's arrays given back */
	triangles = s.mesh.index_count / 3;
	assert_int_equal(s.packed.index_count / 3, triangles);
	assert_int_equal(content_upload(&s, r), 0);
	assert_int_equal(s.packed.vertex_count, 0); /* to the cache's writer */
	assert_null(s.matcap.rgba);		    /* a texture now: the image given back */
	/* A failed reload uploads it again (the model; the matcap is
	 * decoded again on the worker): from the entry. */
	assert_int_equal(content_upload_model(&s, r), 0);
	assert_non_null(s.cached);
	renderer_get_stats(r, &st);
	assert_int_equal(st.vertex_bytes, (long)s.mesh.vertex_count * 12);
	content_release(&s);

	assert_int_equal(content_load(&s, &c, true), 0);
	assert_non_null(s.cached);
	assert_null(s.mesh.positions);
	assert_int_equal(s.mesh.index_count / 3, triangles);
	assert_int_equal(content_prepare(&s, &c, 64, 64), 0);
	assert_int_equal(mesh_cache_entry_key(s.cached)->width, 64);
	assert_int_equal(content_upload(&s, r), 0);
	/* Another display: prepared again from the file. */
	assert_int_equal(content_prepare(&s, &c, 640, 480), 0);
	assert_null(s.cached);
	assert_int_equal(s.cache_key.width, 640);
	content_release(&s);
	unsetenv("XDG_CACHE_HOME");
	renderer_free(r);
	/* The display is left open: see __lsan_default_suppressions. */
}

#define KHRONOS "tests/corpus/khronos/"

/* The live kiosk's settings for model (as tests/unit/test_kiosk_anim.c). */
static struct content_config live_config(const char *model)
{
	struct options o;

	option_defaults(&o);
	o.content.model = (char *)model;
	o.content.anim_time = -1;
	o.content.anim_live = true;
	o.content.zoom = 1.0;
	return o.content;
}

static struct renderer *live_renderer(void)
{
	static struct display *d;
	struct display_config dc = {.width = 16, .height = 16};
	struct renderer *r;

	/* One display for the process: see __lsan_default_suppressions. */
	if (!d) {
		d = display_osmesa_new(&dc);
		assert_non_null(d);
	}
	d->begin_frame(d);
	r = renderer_new(&d->gl, NULL);
	assert_non_null(r);
	return r;
}

/* The play's CPU frame at clip time t of its first clip: positions,
 * then normals, as the live kiosk poses them. */
static float *frame_at(struct anim_play *p, double t)
{
	struct anim_pose *pose = anim_pose_new(p->anim);
	float *out = malloc((size_t)p->vertex_count * 6 * sizeof(float));

	assert_non_null(pose);
	assert_non_null(out);
	anim_pose_rest(p->anim, pose);
	if (p->anim->clip_count)
		anim_pose_apply(p->anim, &p->anim->clips[0], t, pose);
	anim_play_pose(p, pose, out, out + (size_t)p->vertex_count * 3);
	anim_pose_free(pose);
	return out;
}

/* Loaded, prepared and shown the live kiosk's way: from the cache
 * (s->cached, its entry) or parsed. */
static void show_live(struct content *s, const struct content_config *c, struct renderer *r)
{
	assert_int_equal(content_load(s, c, true), 0);
	assert_non_null(s->play);
	assert_int_equal(content_prepare(s, c, 64, 64), 0);
	assert_int_equal(content_upload(s, r), 0);
}

/* A skin, morph targets, node animation, eight joints a vertex
 * (JOINTS_1): the second start maps the entry (no parse) and plays
 * exactly what the parse gave, every byte of its playback data and its
 * frame at a time. */
static void a_live_model_starts_from_the_cache(void **state)
{
	struct fixture *f = *state;
	char capsule[96];
	const char *const models[] = {KHRONOS "RiggedSimple.gltf", KHRONOS "SimpleMorph.gltf",
				      KHRONOS "BoxAnimated.gltf", capsule};
	struct renderer *r = live_renderer();

	snprintf(capsule, sizeof(capsule), "%s/capsule.glb", f->dir);
	assert_int_equal(gltf_write_joints(capsule, &f->mesh, 2), 0);
	setenv("XDG_CACHE_HOME", f->dir, 1);
	for (size_t m = 0; m < sizeof(models) / sizeof(models[0]); m++) {
		struct content_config c = live_config(models[m]);
		struct content parsed, cached;
		void *a, *b;
		size_t na, nb;
		double t;
		float *fa, *fb;
		size_t floats;

		show_live(&parsed, &c, r);
		assert_null(parsed.cached);
		mesh_cache_writer_join(parsed.writer); /* the entry on disk */
		parsed.writer = NULL;
		show_live(&cached, &c, r);
		assert_non_null(cached.cached);
		assert_int_equal(cached.mesh.vertex_count, parsed.mesh.vertex_count);
		assert_int_equal(cached.mesh.index_count, parsed.mesh.index_count);
		assert_memory_equal(cached.mesh.indices, parsed.mesh.indices,
				    parsed.mesh.index_count * 4);
		assert_int_equal(mesh_cache_anim_encode(parsed.play, &a, &na), 0);
		assert_int_equal(mesh_cache_anim_encode(cached.play, &b, &nb), 0);
		assert_int_equal(na, nb);
		assert_memory_equal(a, b, na);
		assert_int_equal(cached.play->influences, parsed.play->influences);
		if (m == 3)
			assert_int_equal(cached.play->influences, 8);
		free(a);
		free(b);
		t = parsed.play->anim->clips[0].duration * 7 / 16;
		fa = frame_at(parsed.play, t);
		fb = frame_at(cached.play, t);
		floats = (size_t)parsed.play->vertex_count * 6;
		assert_memory_equal(fa, fb, floats * sizeof(float));
		free(fa);
		free(fb);
		content_release(&parsed);
		content_release(&cached);
	}
	unsetenv("XDG_CACHE_HOME");
	renderer_free(r);
}

static size_t padded8(size_t n)
{
	return (n + 7) & ~(size_t)7;
}

static void put_file(const char *path, const void *data, size_t size)
{
	FILE *file = fopen(path, "wb");

	assert_non_null(file);
	assert_int_equal(fwrite(data, 1, size, file), size);
	fclose(file);
}

/* The playback section, damaged: every truncation and a wrong word at
 * every place are refused or read as something in range (never a crash,
 * ASan watching); the entry flipped there, truncated, or resealed over
 * a wrong field is refused and removed, and the next start parses and
 * writes it again. */
static void a_damaged_live_entry_is_rebuilt(void **state)
{
	struct fixture *f = *state;
	struct content_config c = live_config(KHRONOS "RiggedSimple.gltf");
	struct renderer *r = live_renderer();
	struct content s;
	struct anim_play *p;
	struct mesh_cache_entry *e;
	char dir[96], path[160];
	unsigned char *data, *blob;
	size_t size, n, at;
	uint32_t word, vc;
	void *own;

	setenv("XDG_CACHE_HOME", f->dir, 1);
	snprintf(dir, sizeof(dir), "%s/matcap-kiosk", f->dir);
	show_live(&s, &c, r);
	assert_int_equal(mesh_cache_anim_encode(s.play, &own, &n), 0);
	vc = s.play->vertex_count;
	f->key = s.cache_key;
	content_release(&s); /* the entry written */
	snprintf(path, sizeof(path), "%s/%016llx-%016llx.mkmesh", dir,
		 (unsigned long long)f->key.content, (unsigned long long)f->key.settings);
	data = read_path(path, &size);
	/* The section ends the entry, as encoded. */
	at = size - padded8(n);
	assert_memory_equal(data + at, own, n);
	blob = own;
	assert_int_equal(mesh_cache_anim_decode(blob, n, vc, &p), 0);
	anim_play_free(p);
	assert_int_equal(mesh_cache_anim_decode(blob, n, vc + 1, &p), -EBADMSG); /* another mesh */
	for (size_t k = 0; k < n; k += k < 256 ? 1 : 4)
		assert_int_equal(mesh_cache_anim_decode(blob, k, vc, &p), -EBADMSG);
	for (size_t k = 0; k + 4 <= n; k += 4) {
		uint32_t was;

		memcpy(&was, blob + k, 4);
		word = 0xffffffffu;
		memcpy(blob + k, &word, 4);
		if (mesh_cache_anim_decode(blob, n, vc, &p) == 0)
			anim_play_free(p);
		word = was + 1;
		memcpy(blob + k, &word, 4);
		if (mesh_cache_anim_decode(blob, n, vc, &p) == 0)
			anim_play_free(p);
		memcpy(blob + k, &was, 4);
	}
	free(own);

	/* A flipped byte in the section: the checksum refuses it. */
	data[at + n / 2] ^= 0x10;
	put_file(path, data, size);
	assert_int_equal(mesh_cache_open(dir, &f->key, &e), -EBADMSG);
	assert_int_not_equal(access(path, F_OK), 0); /* removed */
	/* Resealed over a wrong magic word: the checksums pass, the
	 * section's own checks refuse it. */
	data[at + n / 2] ^= 0x10;
	word = 0;
	memcpy(data + at, &word, 4);
	mesh_cache_reseal(data, size);
	put_file(path, data, size);
	assert_int_equal(mesh_cache_open(dir, &f->key, &e), -EBADMSG);
	assert_int_not_equal(access(path, F_OK), 0);
	/* Truncated by 8 bytes. */
	put_file(path, data, size - 8);
	assert_int_equal(mesh_cache_open(dir, &f->key, &e), -EBADMSG);
	assert_int_not_equal(access(path, F_OK), 0);
	/* Flipped on disk: the next start parses and writes it again. */
	memcpy(data + at, "MKAN", 4);
	data[at + n / 2] ^= 0x10;
	put_file(path, data, size);
	show_live(&s, &c, r);
	assert_null(s.cached);
	content_release(&s);
	show_live(&s, &c, r);
	assert_non_null(s.cached);
	content_release(&s);
	free(data);
	unsetenv("XDG_CACHE_HOME");
	renderer_free(r);
}

/* Decoding bytes, what the journal says of them (log into log). */
static int decode_logged(const void *blob, size_t n, uint32_t vc, char *log, size_t size)
{
	char path[] = "/tmp/mk-anim-log-XXXXXX";
	int fd = mkstemp(path), saved = dup(2), ret;
	struct anim_play *p = NULL;
	ssize_t got;

	assert_true(fd >= 0 && saved >= 0);
	log_set_level(LOG_WARN);
	fflush(stderr);
	dup2(fd, 2);
	ret = mesh_cache_anim_decode(blob, n, vc, &p);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	log_set_level(LOG_ERR);
	got = pread(fd, log, size - 1, 0);
	log[got > 0 ? got : 0] = '\0';
	close(fd);
	unlink(path);
	anim_play_free(p);
	return ret;
}

/* A forged section (the checksums resealed over it) that names a node, a
 * joint or a vertex count that is not there: refused (a part's node or a
 * joint past the nodes would index the worlds out of bounds each frame),
 * and the journal says at which struct, element and field. */
static void a_forged_rig_is_refused_where_it_lies(void **state)
{
	struct fixture *f = *state;
	struct content_config c = live_config(KHRONOS "RiggedSimple.gltf");
	struct renderer *r = live_renderer();
	struct content s;
	char log[1024];
	void *blob;
	size_t n;
	uint32_t vc, word = 0;
	int node, joint;

	setenv("XDG_CACHE_HOME", f->dir, 1);
	show_live(&s, &c, r);
	vc = s.play->vertex_count;
	assert_int_equal(mesh_cache_anim_encode(s.play, &blob, &n), 0);
	assert_int_equal(decode_logged(blob, n, vc + 1, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "refused at the rig: its vertex count is not the mesh's"));
	assert_int_equal(decode_logged(blob, n - 4, vc, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "refused at parts: more elements than the bytes left hold"));
	memcpy(blob, &word, 4);
	assert_int_equal(decode_logged(blob, n, vc, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "refused at its first word: not MKAN"));
	free(blob);

	node = s.play->parts[0].node;
	s.play->parts[0].node = (int)s.play->anim->node_count;
	assert_int_equal(mesh_cache_anim_encode(s.play, &blob, &n), 0);
	s.play->parts[0].node = node;
	assert_int_equal(decode_logged(blob, n, vc, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "refused at parts[0]: its node is not a node"));
	free(blob);

	joint = s.play->skins[0].joints[1];
	s.play->skins[0].joints[1] = -7;
	assert_int_equal(mesh_cache_anim_encode(s.play, &blob, &n), 0);
	s.play->skins[0].joints[1] = joint;
	assert_int_equal(decode_logged(blob, n, vc, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "refused at skins[0]: a joint that is not a node"));
	free(blob);

	s.play->anim->nodes[0].parent = 0; /* its own parent: a cycle */
	assert_int_equal(mesh_cache_anim_encode(s.play, &blob, &n), 0);
	s.play->anim->nodes[0].parent = -1;
	assert_int_equal(decode_logged(blob, n, vc, log, sizeof(log)), -EBADMSG);
	assert_non_null(strstr(log, "refused at anim: the parents make a cycle"));
	free(blob);
	content_release(&s);
	unsetenv("XDG_CACHE_HOME");
	renderer_free(r);
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
	    cmocka_unit_test_setup_teardown(content_maps_a_model_prepared_before, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_live_model_starts_from_the_cache, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_damaged_live_entry_is_rebuilt, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_forged_rig_is_refused_where_it_lies, setup, teardown),
	    cmocka_unit_test(the_directory_is_named_as_systemd_and_xdg_say),
	    cmocka_unit_test(every_field_is_in_the_cache_table),
	    cmocka_unit_test(a_nearly_full_disk_is_full),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
