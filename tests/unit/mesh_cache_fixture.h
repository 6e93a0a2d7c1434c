/* What the prepared-mesh cache's tests share (test_mesh_cache.c, the entry
 * itself; test_mesh_cache_content.c, the kiosk's content through it): a
 * folder of their own, a sphere of two parts packed, a key, and a file read
 * whole. Each unit test is a program of its own: this header defines what
 * it needs once per test. */
#ifndef MK_TEST_MESH_CACHE_FIXTURE_H
#define MK_TEST_MESH_CACHE_FIXTURE_H

#include "scene/mesh/mesh.h"
#include "scene/mesh/mesh_cache.h"
#include "scene/mesh/mesh_pack.h"
#include "util/log.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <cmocka.h>

struct fixture {
	char dir[64];
	struct mesh mesh;
	struct mesh_packed packed;
	struct mesh_cache_key key;
};

static inline int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	assert_non_null(f);
	snprintf(f->dir, sizeof(f->dir), "/tmp/mk-cache-XXXXXX");
	assert_non_null(mkdtemp(f->dir));
	assert_int_equal(mesh_uv_sphere(&f->mesh, 24, 12), 0);
	/* A model of one colour: no array, the colour kept as a fact. */
	f->mesh.has_colors = true;
	f->mesh.vertex_color[1] = 0.75f;
	f->mesh.vertex_color[3] = 0.5f;
	/* Two parts: the upper half opaque, the lower blended, double sided. */
	assert_int_equal(mesh_alloc_ranges(&f->mesh, 2, 2), 0);
	f->mesh.ranges[0] = (struct mesh_range){0, f->mesh.index_count / 6 * 3, 0, {0, 0, 0}};
	f->mesh.ranges[1] = (struct mesh_range){f->mesh.ranges[0].index_count,
						f->mesh.index_count - f->mesh.ranges[0].index_count,
						1,
						{0, 0, 0}};
	mesh_range_centers(&f->mesh);
	f->mesh.materials[0].present = true;
	f->mesh.materials[0].base_color[1] = 0.25f;
	f->mesh.materials[1].alpha_mode = MESH_ALPHA_BLEND;
	f->mesh.materials[1].base_alpha = 0.5f;
	f->mesh.materials[1].double_sided = true;
	assert_int_equal(mesh_pack(&f->mesh, VERTEX_COMPACT, &f->packed), 0);
	f->key = (struct mesh_cache_key){.content = 0x1234, .settings = 0x5678};
	log_set_level(LOG_ERR);
	*state = f;
	return 0;
}

static inline int teardown(void **state)
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

static inline void *read_path(const char *path, size_t *size)
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

/* What the journal says between the two calls (warnings and up), into
 * log: stderr goes to a file meanwhile. */
struct journal_capture {
	char path[32];
	int fd, saved;
};

static inline void journal_capture_begin(struct journal_capture *c)
{
	snprintf(c->path, sizeof(c->path), "/tmp/mk-cache-log-XXXXXX");
	c->fd = mkstemp(c->path);
	c->saved = dup(2);
	assert_true(c->fd >= 0 && c->saved >= 0);
	log_set_level(LOG_WARN);
	fflush(stderr);
	dup2(c->fd, 2);
}

static inline void journal_capture_end(struct journal_capture *c, char *log, size_t size)
{
	ssize_t got;

	fflush(stderr);
	dup2(c->saved, 2);
	close(c->saved);
	log_set_level(LOG_ERR);
	got = pread(c->fd, log, size - 1, 0);
	log[got > 0 ? got : 0] = '\0';
	close(c->fd);
	unlink(c->path);
}

#endif
