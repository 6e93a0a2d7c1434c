/* JSON nested too deep for the parsers' recursion (scene/gltf_json_depth.h):
 * the attack that killed the kiosk (30,000 levels of "extras", SIGSEGV in
 * tinygltf), refused with one line before any parser; a file at the bound
 * still loads; and the stack a parse at the bound takes, measured, is far
 * below the worker's (content/worker.h). */
#include "content/worker.h"
#include "gltf_write.h"
#include "scene/gltf/gltf.h"
#include "scene/gltf/gltf_json_depth.h"
#include "scene/mesh/mesh.h"
#include "util/log.h"

#include <errno.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include <cmocka.h>

/* {"asset":{"version":"2.0","extras":[[...]]}}: depth levels in all, as
 * tests/fuzz/deep_json.sh writes it. Malloc'd, its length in *len. */
static char *deep_text(unsigned depth, size_t *len)
{
	static const char head[] = "{\"asset\":{\"version\":\"2.0\",\"extras\":";
	size_t n = depth - 2, h = sizeof(head) - 1;
	char *t = malloc(h + 2 * n + 3);

	assert_non_null(t);
	memcpy(t, head, h);
	memset(t + h, '[', n);
	memset(t + h + n, ']', n);
	memcpy(t + h + 2 * n, "}}", 3);
	*len = h + 2 * n + 2;
	return t;
}

static void put_u32(uint8_t *p, uint32_t v)
{
	for (int k = 0; k < 4; k++)
		p[k] = (uint8_t)(v >> (8 * k));
}

/* The same text as a GLB's JSON chunk (padded with spaces), no BIN chunk. */
static uint8_t *deep_glb(unsigned depth, size_t *len)
{
	size_t n;
	char *text = deep_text(depth, &n);
	size_t chunk = (n + 3) & ~(size_t)3;
	uint8_t *g = malloc(20 + chunk);

	assert_non_null(g);
	memcpy(g, "glTF", 4);
	put_u32(g + 4, 2);
	put_u32(g + 8, (uint32_t)(20 + chunk));
	put_u32(g + 12, (uint32_t)chunk);
	memcpy(g + 16, "JSON", 4);
	memset(g + 20, ' ', chunk);
	memcpy(g + 20, text, n);
	free(text);
	*len = 20 + chunk;
	return g;
}

static void counts_brackets_outside_strings(void **state)
{
	/* Brackets in strings, escaped quotes and a backslash before the
	 * closing quote: only the 3 real levels count. */
	static const char t[] = "{\"a\":\"[[[[\\\"[{[\",\"b\\\\\":[[\"]]]\\\\\"]],\"c\":\"\\\\\"}";
	struct gltf_json_depth d;

	(void)state;
	assert_true(gltf_json_depth_within(t, sizeof(t) - 1, 3, &d));
	assert_int_equal(d.depth, 3);
	assert_false(gltf_json_depth_within(t, sizeof(t) - 1, 2, &d));
	assert_int_equal(d.offset, strchr(t + 20, '[') + 1 - t);
	assert_int_equal(d.line, 1);
}

static void says_where_the_first_bracket_too_deep_is(void **state)
{
	static const char t[] = "{\n \"a\": [\n  [\n   {\"b\": \"\\n[\"}, [\n[]]]]}";
	struct gltf_json_depth d;

	(void)state;
	assert_false(gltf_json_depth_within(t, sizeof(t) - 1, 4, &d));
	assert_int_equal(d.offset, strrchr(t, '[') - t);
	assert_int_equal(d.line, 5);
	assert_int_equal(d.depth, 5);
	/* Closing brackets past the opening ones (bad JSON, for the parser
	 * to name) count nothing. */
	assert_true(gltf_json_depth_within("]]]]{[]}", 8, 2, &d));
	assert_int_equal(d.depth, 2);
}

/* The attack and the first depth past the bound, in both containers: one
 * error naming the file, the byte and the bound; no crash. */
static void refuses_json_too_deep(void **state)
{
	static const unsigned depths[] = {30002, GLTF_JSON_MAX_DEPTH + 1};
	char err[512], want[256];
	struct mesh m;

	(void)state;
	for (int i = 0; i < 2; i++) {
		size_t n;
		char *text = deep_text(depths[i], &n);
		uint8_t *glb = deep_glb(depths[i], &n);
		size_t tn = strlen(text);

		log_clear_last_error();
		assert_int_equal(gltf_load_memory("deep.gltf", (uint8_t *)text, tn, "", &m),
				 -EINVAL);
		log_last_error(err, sizeof(err));
		snprintf(want, sizeof(want),
			 "deep.gltf: JSON nested deeper than %d levels at byte %d (line 1); a glTF "
			 "file needs far fewer, refused",
			 GLTF_JSON_MAX_DEPTH, 35 + GLTF_JSON_MAX_DEPTH - 2);
		assert_string_equal(err, want);
		assert_int_equal(gltf_load_memory("deep.glb", glb, n, "", &m), -EINVAL);
		log_last_error(err, sizeof(err));
		snprintf(want, sizeof(want),
			 "deep.glb: JSON chunk nested deeper than %d levels at byte %d (line 1 of "
			 "the chunk); a glTF file needs far fewer, refused",
			 GLTF_JSON_MAX_DEPTH, 20 + 35 + GLTF_JSON_MAX_DEPTH - 2);
		assert_string_equal(err, want);
		assert_null(m.positions);
		free(text);
		free(glb);
	}
}

/* A real model (a sphere) whose node's extras nest to the bound exactly. */
static void write_at_bound(const char *path, char *node, size_t size)
{
	struct gltf_write_opts o = {.index_bytes = 2, .with_normals = 1, .bad_index = -1};
	struct mesh sphere;
	/* The node lies 3 deep (file, "nodes", the node): extras' arrays add
	 * the rest. */
	int arrays = GLTF_JSON_MAX_DEPTH - 3, n;

	assert_true((size_t)(2 * arrays + 16) < size);
	n = sprintf(node, "\"extras\":");
	memset(node + n, '[', (size_t)arrays);
	memset(node + n + arrays, ']', (size_t)arrays);
	node[n + 2 * arrays] = '\0';
	o.node = node;
	assert_int_equal(mesh_uv_sphere(&sphere, 12, 8), 0);
	assert_int_equal(gltf_write(path, &sphere, &o), 0);
	mesh_release(&sphere);
}

static void file_depth(const char *path, struct gltf_json_depth *d)
{
	uint8_t buf[8192];
	FILE *f = fopen(path, "rb");
	size_t n;

	assert_non_null(f);
	n = fread(buf, 1, sizeof(buf), f);
	fclose(f);
	assert_true(gltf_json_depth_file_within(buf, n, 100000, d));
}

static void loads_a_model_at_the_bound(void **state)
{
	char dir[] = "/tmp/mk-depth-XXXXXX", path[64], node[256];
	struct gltf_json_depth d;
	struct mesh m;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/bound.glb", dir);
	write_at_bound(path, node, sizeof(node));
	file_depth(path, &d);
	assert_int_equal(d.depth, GLTF_JSON_MAX_DEPTH);
	assert_int_equal(gltf_load(path, &m), 0);
	assert_true(m.index_count > 0);
	mesh_release(&m);
	unlink(path);
	rmdir(dir);
}

/* The bytes of a stack a function used: the thread runs on a stack painted
 * with a pattern (a guard page below it), and the bytes left as painted
 * from its far end are those never touched. */
struct painted {
	void (*fn)(void *arg);
	void *arg;
};

static void *run_painted(void *arg)
{
	struct painted *p = arg;

	p->fn(p->arg);
	return NULL;
}

static size_t stack_used(size_t size, void (*fn)(void *arg), void *arg)
{
	size_t page = (size_t)sysconf(_SC_PAGESIZE), untouched = 0;
	uint8_t *base = mmap(NULL, size + page, PROT_READ | PROT_WRITE,
			     MAP_PRIVATE | MAP_ANONYMOUS | MAP_STACK, -1, 0);
	struct painted p = {fn, arg};
	pthread_attr_t attr;
	pthread_t t;

	assert_true(base != MAP_FAILED);
	assert_int_equal(mprotect(base, page, PROT_NONE), 0);
	memset(base + page, 0xa5, size);
	assert_int_equal(pthread_attr_init(&attr), 0);
	assert_int_equal(pthread_attr_setstack(&attr, base + page, size), 0);
	assert_int_equal(pthread_create(&t, &attr, run_painted, &p), 0);
	assert_int_equal(pthread_join(t, NULL), 0);
	pthread_attr_destroy(&attr);
	while (untouched < size && base[page + untouched] == 0xa5)
		untouched++;
	munmap(base, size + page);
	return size - untouched;
}

struct parse_job {
	const uint8_t *data;
	size_t size;
	int ret;
};

static void parse(void *arg)
{
	struct parse_job *j = arg;
	struct mesh m;

	j->ret = gltf_load_memory("stack.gltf", j->data, j->size, "", &m);
	mesh_release(&m);
}

static size_t parse_stack(unsigned depth)
{
	struct parse_job j;
	size_t used;
	char *text = deep_text(depth, &j.size);

	j.data = (const uint8_t *)text;
	used = stack_used(WORKER_STACK_SIZE, parse, &j);
	/* Parsed to the end: refused as a model with no mesh, not for depth. */
	assert_int_equal(j.ret, -EINVAL);
	free(text);
	return used;
}

static void load_real(void *arg)
{
	struct mesh m;

	*(int *)arg =
	    gltf_load_textures("tests/fuzz/corpus/gltf/khronos-scenes-draco.glb", ~0u, &m);
	mesh_release(&m);
}

/* The deepest JSON the loader lets through, parsed on a stack of the
 * worker's size: what it used is printed (the figure for worker.h), and it
 * must leave most of that stack free (a sanitizer build's frames are
 * several times larger than a release build's). */
static void a_parse_at_the_bound_fits_the_worker_stack(void **state)
{
	size_t shallow = parse_stack(8), bound = parse_stack(GLTF_JSON_MAX_DEPTH);
	size_t per_level = bound > shallow ? (bound - shallow) / (GLTF_JSON_MAX_DEPTH - 8) : 0;
	int ret = -1;
	size_t real = stack_used(WORKER_STACK_SIZE, load_real, &ret);

	(void)state;
	printf("# stack used by a parse 8 deep: %zu KiB; %d deep: %zu KiB (%zu bytes a level); "
	       "a Draco model's load: %zu KiB; the worker's: %u KiB\n",
	       shallow >> 10, GLTF_JSON_MAX_DEPTH, bound >> 10, per_level, real >> 10,
	       WORKER_STACK_SIZE >> 10);
	assert_int_equal(ret, 0);
	assert_true(bound > shallow);
	assert_true(bound < WORKER_STACK_SIZE / 4);
	assert_true(real < WORKER_STACK_SIZE / 4);
}

struct worker_probe {
	struct worker_job job;
	size_t stack;
};

static void probe_run(struct worker_job *j)
{
	struct worker_probe *p = (struct worker_probe *)j;
	pthread_attr_t attr;

	assert_int_equal(pthread_getattr_np(pthread_self(), &attr), 0);
	assert_int_equal(pthread_attr_getstacksize(&attr, &p->stack), 0);
	pthread_attr_destroy(&attr);
}

static void probe_done(struct worker_job *j)
{
	(void)j;
}

/* The worker's thread has the stack worker.h says, whatever ulimit -s. */
static void the_worker_has_its_own_stack_size(void **state)
{
	struct worker *w = worker_new();
	struct worker_probe p = {{probe_run, probe_done}, 0};

	(void)state;
	assert_non_null(w);
	assert_int_equal(worker_start(w, &p.job), 0);
	while (worker_finish(w) == -EAGAIN)
		usleep(1000);
	worker_free(w);
	assert_true(p.stack >= WORKER_STACK_SIZE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(counts_brackets_outside_strings),
	    cmocka_unit_test(says_where_the_first_bracket_too_deep_is),
	    cmocka_unit_test(refuses_json_too_deep),
	    cmocka_unit_test(loads_a_model_at_the_bound),
	    cmocka_unit_test(a_parse_at_the_bound_fits_the_worker_stack),
	    cmocka_unit_test(the_worker_has_its_own_stack_size),
	};
	return cmocka_run_group_tests_name("gltf_depth", tests, NULL, NULL);
}
