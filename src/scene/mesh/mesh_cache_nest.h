/* The one field table of a cache entry: the material, range and colour
 * records (scene/mesh/mesh_cache_fields.c) and live playback's rig, with
 * its arrays and structs (scene/mesh/mesh_cache_anim.c). Each member of a
 * struct is described once (its place, its kind, how many elements an array has),
 * and one writer and one reader walk the description, the reader
 * checking every word against what it may hold and every count against
 * the bytes left before it allocates. What ties members together (an
 * index into another table) is the struct's check, after its members. */
#ifndef MK_MESH_CACHE_NEST_H
#define MK_MESH_CACHE_NEST_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

enum mesh_nest_kind {
	MESH_NEST_NONE,	   /* not stored: scratch, or made again on reading */
	MESH_NEST_U32,	   /* uint32_t, at most n (0: any) */
	MESH_NEST_INT,	   /* int: an index (-1: none), checked by the struct's check */
	MESH_NEST_SIZE,	   /* size_t, stored in 32 bits: a count */
	MESH_NEST_BOOL,	   /* bool: 0 or 1 */
	MESH_NEST_ENUM,	   /* an enum: 0 to n */
	MESH_NEST_FLOATS,  /* n floats in the struct, each finite */
	MESH_NEST_DOUBLES, /* n doubles in the struct, each finite */
	MESH_NEST_STRING,  /* char *, NUL-free; NULL allowed */
	MESH_NEST_F32S,	   /* float *: count() of them, each finite */
	MESH_NEST_U16S,	   /* uint16_t *: count() */
	MESH_NEST_U32S,	   /* uint32_t *: count() */
	MESH_NEST_INTS,	   /* int *: count() */
	MESH_NEST_STRUCTS, /* count() structs of sub, their count the member at count_at */
	MESH_NEST_STRUCT,  /* a pointer to one struct of sub */
	MESH_NEST_CHARS,   /* char[n] in the struct: a string cut to fit, NUL within n */
};

struct mesh_nest;

struct mesh_nest_member {
	const char *name;
	size_t offset, size; /* size: sizeof the member, for the table's test */
	int kind;	     /* enum mesh_nest_kind */
	uint32_t n;
	/* Arrays: NULL allowed (a word says whether it is there). */
	bool optional;
	/* Arrays: how many elements, from the members before it (a product
	 * in 64 bits: a damaged count is refused, never wrapped). */
	uint64_t (*count)(const void *obj);
	const struct mesh_nest *sub;
	/* MESH_NEST_STRUCTS: the count member (a size_t or, count_u32, a
	 * uint32_t), set to 0 when the array is refused so that freeing
	 * the half-read struct walks no elements it lacks. */
	size_t count_at;
	bool count_u32;
};

struct mesh_nest {
	const char *name;
	size_t size; /* sizeof the struct */
	const struct mesh_nest_member *members;
	size_t member_count;
	/* After its members: NULL when they hold together, against ctx
	 * (what the caller read before), else what is wrong. */
	const char *(*check)(void *obj, void *ctx);
};

/* A member of struct s, every member of s described (stored, or NONE with
 * a comment saying why): tests/unit/test_mesh_cache.c fails on a field of
 * s in no table. */
#define MESH_NEST_MEMBER(s, f, k, ...)                                                             \
	{                                                                                          \
		.name = #f, .offset = offsetof(struct s, f), .size = sizeof(((struct s *)0)->f),   \
		.kind = k, __VA_ARGS__                                                             \
	}
/* A float or an array of floats in the struct. */
#define MESH_NEST_FLOATS_OF(s, f)                                                                  \
	MESH_NEST_MEMBER(s, f, MESH_NEST_FLOATS, .n = sizeof(((struct s *)0)->f) / sizeof(float))
#define MESH_NEST_TABLE(s, members, check)                                                         \
	{                                                                                          \
#s, sizeof(struct s), members, sizeof(members) / sizeof(members[0]), check         \
	}

/* A growing buffer of 32-bit words. */
struct mesh_nest_out {
	char *data;
	size_t size, cap;
	bool failed; /* out of memory */
};

/* The reader: every take checks the bytes left; the first failure stays,
 * its place and reason in why (e.g. "parts[3].first_vertex: ..."). */
struct mesh_nest_in {
	const char *p;
	size_t left;
	bool ok;
	void *ctx;
	char why[160];
};

void mesh_nest_put_u32(struct mesh_nest_out *b, uint32_t v);
uint32_t mesh_nest_get_u32(struct mesh_nest_in *g);
void mesh_nest_write(struct mesh_nest_out *b, const struct mesh_nest *t, const void *obj);
/* obj zeroed by the caller; on failure it holds what was read, for the
 * caller's own free. */
bool mesh_nest_read(struct mesh_nest_in *g, const struct mesh_nest *t, void *obj);
/* The bytes a struct of t takes with every array empty: those of a
 * struct of no arrays (a record). */
size_t mesh_nest_min_bytes(const struct mesh_nest *t);
/* The failure of an element (index i; SIZE_MAX: the one a pointer
 * holds, or a record alone) said at its place: "nodes[3].parent: ...". */
void mesh_nest_prefix(struct mesh_nest_in *g, const char *name, size_t i);
/* false, with why, at the place the reader is in. */
bool mesh_nest_fail(struct mesh_nest_in *g, const char *where, const char *why);

#endif
