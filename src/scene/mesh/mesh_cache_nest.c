/* One writer and one reader for a struct described by a member table
 * (mesh_cache_nest.h). Words are 32 bits, a double two; an array is its
 * elements padded to a word, after a presence word when optional; a
 * string is its length (NO_STRING for NULL) and its bytes, padded. */
#include "scene/mesh/mesh_cache_nest.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NO_STRING 0xffffffffu

static void put_bytes(struct mesh_nest_out *b, const void *data, size_t size)
{
	size_t padded = (size + 3) & ~(size_t)3, cap = b->cap ? b->cap : 4096;
	char *grown;

	if (b->failed)
		return;
	if (b->size + padded > b->cap) {
		while (cap < b->size + padded)
			cap *= 2;
		grown = realloc(b->data, cap);
		b->failed = !grown;
		if (!grown)
			return;
		b->data = grown;
		b->cap = cap;
	}
	if (size)
		memcpy(b->data + b->size, data, size);
	memset(b->data + b->size + size, 0, padded - size);
	b->size += padded;
}

void mesh_nest_put_u32(struct mesh_nest_out *b, uint32_t v)
{
	put_bytes(b, &v, 4);
}

bool mesh_nest_fail(struct mesh_nest_in *g, const char *where, const char *why)
{
	if (g->ok)
		snprintf(g->why, sizeof(g->why), "%s: %s", where, why);
	return g->ok = false;
}

static bool get_bytes(struct mesh_nest_in *g, void *out, size_t size)
{
	size_t padded = (size + 3) & ~(size_t)3;

	if (!g->ok)
		return false;
	if (size > SIZE_MAX - 3 || padded > g->left)
		return mesh_nest_fail(g, "", "the section ends early");
	if (size)
		memcpy(out, g->p, size);
	g->p += padded;
	g->left -= padded;
	return true;
}

uint32_t mesh_nest_get_u32(struct mesh_nest_in *g)
{
	uint32_t v = 0;

	get_bytes(g, &v, 4);
	return v;
}

static size_t elem_size(int kind)
{
	switch (kind) {
	case MESH_NEST_U16S:
		return 2;
	case MESH_NEST_STRUCTS:
	case MESH_NEST_STRUCT:
		return 0;
	default:
		return 4;
	}
}

static void write_member(struct mesh_nest_out *b, const struct mesh_nest_member *m,
			 const void *obj);

void mesh_nest_write(struct mesh_nest_out *b, const struct mesh_nest *t, const void *obj)
{
	for (size_t i = 0; i < t->member_count; i++)
		write_member(b, &t->members[i], obj);
}

static void write_array(struct mesh_nest_out *b, const struct mesh_nest_member *m, const void *obj,
			const void *a)
{
	size_t n = (size_t)m->count(obj);

	if (m->optional)
		mesh_nest_put_u32(b, a != NULL);
	if (!a)
		return;
	if (m->kind != MESH_NEST_STRUCTS) {
		put_bytes(b, a, n * elem_size(m->kind));
		return;
	}
	for (size_t i = 0; i < n; i++)
		mesh_nest_write(b, m->sub, (const char *)a + i * m->sub->size);
}

static void write_member(struct mesh_nest_out *b, const struct mesh_nest_member *m, const void *obj)
{
	const char *at = (const char *)obj + m->offset;
	const void *ptr;

	switch (m->kind) {
	case MESH_NEST_NONE:
		return;
	case MESH_NEST_SIZE:
		mesh_nest_put_u32(b, (uint32_t) * (const size_t *)(const void *)at);
		return;
	case MESH_NEST_BOOL:
		mesh_nest_put_u32(b, *(const bool *)(const void *)at);
		return;
	case MESH_NEST_FLOATS:
		put_bytes(b, at, (size_t)m->n * 4);
		return;
	case MESH_NEST_DOUBLES:
		put_bytes(b, at, (size_t)m->n * 8);
		return;
	case MESH_NEST_CHARS:
		put_bytes(b, at, m->n);
		return;
	case MESH_NEST_U32:
	case MESH_NEST_INT:
	case MESH_NEST_ENUM:
		put_bytes(b, at, 4);
		return;
	}
	memcpy(&ptr, at, sizeof(ptr));
	if (m->kind == MESH_NEST_STRUCT) {
		mesh_nest_write(b, m->sub, ptr);
	} else if (m->kind == MESH_NEST_STRING) {
		mesh_nest_put_u32(b, ptr ? (uint32_t)strlen(ptr) : NO_STRING);
		if (ptr)
			put_bytes(b, ptr, strlen(ptr));
	} else {
		write_array(b, m, obj, ptr);
	}
}

/* A count of structs that the bytes left cannot hold is refused before
 * it allocates. */
size_t mesh_nest_min_bytes(const struct mesh_nest *t)
{
	size_t n = 0;

	for (size_t i = 0; i < t->member_count; i++) {
		const struct mesh_nest_member *m = &t->members[i];

		if (m->kind == MESH_NEST_FLOATS || m->kind == MESH_NEST_DOUBLES)
			n += (size_t)m->n * (m->kind == MESH_NEST_FLOATS ? 4 : 8);
		else if (m->kind == MESH_NEST_CHARS)
			n += ((size_t)m->n + 3) & ~(size_t)3;
		else if (m->kind == MESH_NEST_STRUCT)
			n += mesh_nest_min_bytes(m->sub);
		else if (m->kind >= MESH_NEST_F32S)
			n += m->optional ? 4 : 0;
		else if (m->kind != MESH_NEST_NONE)
			n += 4;
	}
	return n > 4 ? n : 4;
}

void mesh_nest_prefix(struct mesh_nest_in *g, const char *name, size_t i)
{
	char was[sizeof(g->why)], at[64];

	memcpy(was, g->why, sizeof(was));
	if (i == SIZE_MAX)
		snprintf(at, sizeof(at), "%s", name);
	else
		snprintf(at, sizeof(at), "%s[%zu]", name, i);
	snprintf(g->why, sizeof(g->why), "%.60s%s%.96s", at, was[0] == ':' ? "" : ".", was);
}

static bool all_finite(const float *f, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!isfinite(f[i]))
			return false;
	return true;
}

static bool read_elements(struct mesh_nest_in *g, const struct mesh_nest_member *m, void *a,
			  size_t n)
{
	if (m->kind != MESH_NEST_STRUCTS) {
		if (get_bytes(g, a, n * elem_size(m->kind)) && m->kind == MESH_NEST_F32S &&
		    !all_finite(a, n))
			return mesh_nest_fail(g, m->name, "a value not finite");
		return g->ok;
	}
	for (size_t i = 0; i < n; i++)
		if (!mesh_nest_read(g, m->sub, (char *)a + i * m->sub->size)) {
			mesh_nest_prefix(g, m->name, i);
			return false;
		}
	return true;
}

static void zero_count(const struct mesh_nest_member *m, void *obj)
{
	char *at = (char *)obj + m->count_at;

	if (m->kind != MESH_NEST_STRUCTS)
		return;
	if (m->count_u32)
		*(uint32_t *)(void *)at = 0;
	else
		*(size_t *)(void *)at = 0;
}

static bool read_array(struct mesh_nest_in *g, const struct mesh_nest_member *m, void *obj)
{
	uint32_t present = m->optional ? mesh_nest_get_u32(g) : 1;
	uint64_t n = m->count(obj);
	size_t width =
	    m->kind == MESH_NEST_STRUCTS ? mesh_nest_min_bytes(m->sub) : elem_size(m->kind);
	size_t size = m->kind == MESH_NEST_STRUCTS ? m->sub->size : width;
	void *a = NULL;

	if (g->ok && present > 1)
		return mesh_nest_fail(g, m->name, "its presence is not 0 or 1");
	if (!g->ok || !present || !n)
		return g->ok;
	if (n > g->left / width) {
		zero_count(m, obj);
		return mesh_nest_fail(g, m->name, "more elements than the bytes left hold");
	}
	a = calloc((size_t)n, size);
	memcpy((char *)obj + m->offset, &a, sizeof(a));
	if (!a) {
		zero_count(m, obj);
		return mesh_nest_fail(g, m->name, "out of memory");
	}
	return read_elements(g, m, a, (size_t)n);
}

static bool read_string(struct mesh_nest_in *g, const struct mesh_nest_member *m, char *at)
{
	uint32_t len = mesh_nest_get_u32(g);
	char *s;

	if (!g->ok || len == NO_STRING)
		return g->ok;
	if (len > g->left || !(s = calloc(1, (size_t)len + 1)))
		return mesh_nest_fail(g, m->name, "longer than the bytes left");
	memcpy(at, &s, sizeof(s));
	if (get_bytes(g, s, len) && strlen(s) != len)
		return mesh_nest_fail(g, m->name, "a NUL inside");
	return g->ok;
}

static bool read_struct(struct mesh_nest_in *g, const struct mesh_nest_member *m, char *at)
{
	void *s = calloc(1, m->sub->size);

	memcpy(at, &s, sizeof(s));
	if (!s)
		return mesh_nest_fail(g, m->name, "out of memory");
	if (!mesh_nest_read(g, m->sub, s))
		mesh_nest_prefix(g, m->name, SIZE_MAX);
	return g->ok;
}

/* A word of a scalar member into its place, if in range. */
static bool read_word(struct mesh_nest_in *g, const struct mesh_nest_member *m, char *at)
{
	uint32_t v = mesh_nest_get_u32(g);
	size_t z = v;
	bool b = v != 0;

	if (!g->ok)
		return false;
	if ((m->kind == MESH_NEST_U32 && m->n && v > m->n) ||
	    (m->kind == MESH_NEST_ENUM && v > m->n))
		return mesh_nest_fail(g, m->name, "out of its range");
	if (m->kind == MESH_NEST_BOOL && v > 1)
		return mesh_nest_fail(g, m->name, "not 0 or 1");
	if (m->kind == MESH_NEST_SIZE)
		memcpy(at, &z, sizeof(z));
	else if (m->kind == MESH_NEST_BOOL)
		memcpy(at, &b, sizeof(b));
	else
		memcpy(at, &v, 4);
	return true;
}

static bool read_member(struct mesh_nest_in *g, const struct mesh_nest_member *m, void *obj)
{
	char *at = (char *)obj + m->offset;
	double d[16];

	switch (m->kind) {
	case MESH_NEST_NONE:
		return true;
	case MESH_NEST_FLOATS:
		if (get_bytes(g, at, (size_t)m->n * 4) &&
		    !all_finite((const float *)(void *)at, m->n))
			return mesh_nest_fail(g, m->name, "a value not finite");
		return g->ok;
	case MESH_NEST_DOUBLES:
		if (!get_bytes(g, d, (size_t)m->n * 8))
			return false;
		for (uint32_t i = 0; i < m->n; i++)
			if (!isfinite(d[i]))
				return mesh_nest_fail(g, m->name, "a value not finite");
		memcpy(at, d, (size_t)m->n * 8);
		return true;
	case MESH_NEST_STRING:
		return read_string(g, m, at);
	case MESH_NEST_CHARS:
		if (get_bytes(g, at, m->n) && !memchr(at, 0, m->n))
			return mesh_nest_fail(g, m->name, "no NUL within its bytes");
		return g->ok;
	case MESH_NEST_STRUCT:
		return read_struct(g, m, at);
	default:
		return m->kind >= MESH_NEST_F32S ? read_array(g, m, obj) : read_word(g, m, at);
	}
}

bool mesh_nest_read(struct mesh_nest_in *g, const struct mesh_nest *t, void *obj)
{
	const char *why;

	for (size_t i = 0; g->ok && i < t->member_count; i++)
		if (!read_member(g, &t->members[i], obj) && g->why[0] == ':')
			mesh_nest_prefix(g, t->members[i].name,
					 SIZE_MAX); /* the bytes ran out in it */
	if (g->ok && t->check && (why = t->check(obj, g->ctx)))
		mesh_nest_fail(g, "", why);
	return g->ok;
}
