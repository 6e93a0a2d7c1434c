/* The kiosk's content through the prepared-mesh cache: a model prepared
 * before is mapped, not parsed, and one that is not is read once (keyed and
 * parsed from the same bytes); a model that plays live starts from its
 * entry (its playback data read back), and a damaged playback section is
 * refused and written again. */
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
#include <sys/inotify.h>
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

#include "mesh_cache_fixture.h"

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

/* The opens of the file watched by fd (inotify) since the last call. */
static int opens(int fd)
{
	char buf[4096] __attribute__((aligned(__alignof__(struct inotify_event))));
	int count = 0;
	ssize_t n;

	while ((n = read(fd, buf, sizeof(buf))) > 0)
		for (char *p = buf; p < buf + n;) {
			const struct inotify_event *e = (const struct inotify_event *)(void *)p;

			count += (e->mask & IN_OPEN) != 0;
			p += sizeof(*e) + e->len;
		}
	return count;
}

/* A cache miss opens the model once: its key is of the bytes the parser
 * then reads (it was opened twice, once to hash it for the key, once to
 * parse it, and a file replaced in between was stored under the other's
 * key). A hit opens it once too, to hash it, as before. The kernel counts
 * the opens (inotify), not the code under test. */
static void a_miss_reads_the_model_once(void **state)
{
	struct fixture *f = *state;
	struct gltf_write_opts o = {.index_bytes = 4, .with_normals = 1, .bad_index = -1};
	struct content_config c = {.lod_pixels = 4.0};
	struct display_config dc = {.width = 16, .height = 16};
	struct display *d = display_osmesa_new(&dc);
	struct renderer *r;
	struct content s;
	char model[128];
	int fd = inotify_init1(IN_NONBLOCK);

	assert_non_null(d);
	d->begin_frame(d);
	r = renderer_new(&d->gl, NULL);
	assert_non_null(r);
	assert_true(fd >= 0);
	snprintf(model, sizeof(model), "%s/sphere.glb", f->dir);
	assert_int_equal(gltf_write(model, &f->mesh, &o), 0);
	/* The closes too: inotify folds an event into the same one unread
	 * before it, two opens in a row would read as one. */
	assert_true(inotify_add_watch(fd, model, IN_OPEN | IN_CLOSE_NOWRITE) >= 0);
	setenv("XDG_CACHE_HOME", f->dir, 1);
	material_config_defaults(&c.material);
	c.model = model;
	assert_int_equal(content_load(&s, &c, true), 0);
	assert_null(s.cached); /* a miss: parsed */
	assert_non_null(s.mesh.positions);
	assert_int_equal(opens(fd), 1);
	assert_int_equal(content_prepare(&s, &c, 64, 64), 0);
	assert_int_equal(content_upload(&s, r), 0);
	content_release(&s); /* the entry written */
	assert_int_equal(opens(fd), 0);
	assert_int_equal(content_load(&s, &c, true), 0);
	assert_non_null(s.cached); /* a hit: mapped */
	assert_int_equal(opens(fd), 1);
	content_release(&s);
	unsetenv("XDG_CACHE_HOME");
	close(fd);
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
	struct journal_capture c;
	struct anim_play *p = NULL;
	int ret;

	journal_capture_begin(&c);
	ret = mesh_cache_anim_decode(blob, n, vc, &p);
	journal_capture_end(&c, log, size);
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

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test_setup_teardown(content_maps_a_model_prepared_before, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_miss_reads_the_model_once, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_live_model_starts_from_the_cache, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_damaged_live_entry_is_rebuilt, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_forged_rig_is_refused_where_it_lies, setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
