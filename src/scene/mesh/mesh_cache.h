/* The prepared-mesh cache: a mesh loaded, given its normals, tangents and
 * level of detail, fitted, and packed in the GPU's vertex format, kept on
 * disk so that the next start maps it and uploads it as it is, with no
 * parse and no preparation. An entry is keyed by the model's content and
 * by every setting that changes the result, written atomically, and
 * checked (header, sizes, checksums, index range) before it is used: a
 * truncated, stale or corrupt entry is a miss, removed and rebuilt. */
#ifndef MK_MESH_CACHE_H
#define MK_MESH_CACHE_H

#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/mesh_pack.h"

#include <stddef.h>
#include <stdint.h>

/* Entries beyond this, oldest first, are removed after each write. */
#define MESH_CACHE_MAX_BYTES (256ull << 20)

struct mesh_cache_key {
	uint64_t content;  /* mesh_cache_hash_model */
	uint64_t settings; /* the caller's settings, through mesh_cache_hash */
	/* The display the mesh was prepared for (its level of detail). Not
	 * in the entry's name: a model has one entry per settings, replaced
	 * when the display changes. 0 x 0 in a lookup: any display
	 * (mesh_cache_entry_key says which). */
	uint32_t width, height;
};

/* A fast 64-bit hash (not a cryptographic one: the cache trusts its own
 * directory, and checks what it reads for damage, not for malice). */
uint64_t mesh_cache_hash(const void *data, size_t size, uint64_t seed);

/* The model file's bytes and, for a .gltf, those of every file its "uri"s
 * name beside it (buffers, images). Returns 0 or a negative errno code. */
int mesh_cache_hash_model(const char *path, uint64_t *out);
/* The same of the model's bytes, read by the caller (the parser reads the
 * same bytes: the model is read once, and what is parsed is what was
 * keyed); path names it and the folder its "uri"s are in. */
uint64_t mesh_cache_hash_model_bytes(const char *path, const void *data, size_t size);

/* The key of a scene showing model (its size bytes at data, as read) with
 * these settings, for any display (width, height 0). Returns 0, -ENOENT
 * for a scene the cache does not keep (one its settings reshape beyond the
 * model: src/scene/mesh/mesh_cache_key.c), or another negative errno code
 * when the program cannot be read. normals: [scene] normals (enum
 * mesh_normals). */
int mesh_cache_scene_key(const char *model, const void *data, size_t size, double lod_pixels,
			 int normals, const struct material_config *m, struct mesh_cache_key *out);

/* $CACHE_DIRECTORY (systemd's CacheDirectory=, the first when it lists
 * several), else $XDG_CACHE_HOME/matcap-kiosk, else ~/.cache/matcap-kiosk.
 * Returns 0, or -ENOENT when none can be named, -ENAMETOOLONG. */
int mesh_cache_dir(char *buf, size_t size);

/* Whether a cache file system with bytes_free of bytes_total is too full
 * to write to: under 16 MiB free (total 0: unknown, not full). Not a
 * share: 5 % of a 32 GB card is 1.6 GB, and would turn the caches off on
 * a card with room; 16 MiB holds Mesa's shader-cache index (mapped whole,
 * about 1.3 MB: a page it cannot back is SIGBUS) and a model's entry. */
bool mesh_cache_space_low(uint64_t bytes_free, uint64_t bytes_total);
/* The same for dir's file system (dir or the nearest folder above it that
 * exists); *bytes_free (may be NULL) is what is free. False when it
 * cannot be told. */
bool mesh_cache_dir_full(const char *dir, uint64_t *bytes_free);

struct mesh_cache_entry;

/* Map dir's entry for key and check it. Returns 0, -ENOENT when there is
 * none, or -EBADMSG when it is damaged or stale (it is then removed). */
int mesh_cache_open(const char *dir, const struct mesh_cache_key *key,
		    struct mesh_cache_entry **out);
/* The entry's mesh, its arrays pointing into the mapping. */
const struct mesh_packed *mesh_cache_entry_mesh(const struct mesh_cache_entry *e);
/* What the entry keeps that its packed mesh does not: each range's
 * material (no images: an entry is written only for a scene that decodes
 * none) and the model's colour facts (has_colors, vertex_color), in a
 * mesh with no arrays; its ranges are the entry mesh's. */
const struct mesh *mesh_cache_entry_materials(const struct mesh_cache_entry *e);
/* Once its mesh is on the GPU: the mapping's pages leave the process
 * (the file keeps them; a later read maps them in again). */
void mesh_cache_entry_evict(const struct mesh_cache_entry *e);
/* The key the entry was written with (its display's size included). */
const struct mesh_cache_key *mesh_cache_entry_key(const struct mesh_cache_entry *e);
/* An entry of a model that plays live: what playback needs, read back
 * and checked when the entry was opened, handed to the caller (to
 * anim_play_free); NULL for a still's entry (or once taken). */
struct anim_play *mesh_cache_entry_take_play(struct mesh_cache_entry *e);
void mesh_cache_entry_free(struct mesh_cache_entry *e);

/* Check an entry's bytes (what mesh_cache_open does once mapped): 0 and
 * out's arrays pointing into data, or -EBADMSG (or -ENOMEM). key may be
 * NULL (any); found (may be NULL) gets the entry's own key. materials
 * gets the materials and ranges (mesh_release frees them), and out's
 * ranges point at its. */
int mesh_cache_parse(const void *data, size_t size, const struct mesh_cache_key *key,
		     struct mesh_packed *out, struct mesh *materials, struct mesh_cache_key *found);

/* The anim section of an entry's bytes (mesh_cache_anim.h), checked:
 * 0 with *out NULL (a still) or the playback data, -EBADMSG or -ENOMEM.
 * mesh_cache_open calls it after mesh_cache_parse. */
struct anim_play;
int mesh_cache_parse_play(const void *data, size_t size, struct anim_play **out);

/* For the fuzzer: recompute an entry's checksums in place (what a
 * deliberate forgery would do), so that the fields behind them are what
 * mesh_cache_parse then checks. Does nothing to fewer bytes than a header. */
void mesh_cache_reseal(void *data, size_t size);

/* Write m and material's factors as key's entry: a temporary file,
 * fsync, rename, so that a reader sees the whole entry or none; then the
 * directory is trimmed to max_bytes, oldest entries first. The directory
 * is made when missing. Returns 0 or a negative errno code. */
int mesh_cache_write(const char *dir, const struct mesh_cache_key *key, const struct mesh_packed *m,
		     const struct mesh *materials, uint64_t max_bytes);

/* mesh_cache_write with a model's live playback data: the bytes of
 * mesh_cache_anim_encode (anim NULL: a still's entry). */
int mesh_cache_write_play(const char *dir, const struct mesh_cache_key *key,
			  const struct mesh_packed *m, const struct mesh *materials,
			  const void *anim, size_t anim_size, uint64_t max_bytes);

/* mesh_cache_write on a thread of its own, so that the first frame does
 * not wait for the disk: m's arrays are taken over (m is left empty) and
 * freed once written. When no thread can start, the entry is written
 * before this returns. Returns NULL then, or the writer to join. */
struct mesh_cache_writer;
struct mesh_cache_writer *mesh_cache_write_async(const char *dir, const struct mesh_cache_key *key,
						 struct mesh_packed *m,
						 const struct mesh *materials, uint64_t max_bytes);
/* The same with the anim section's bytes (malloc'd), taken over too. */
struct mesh_cache_writer *mesh_cache_write_async_play(const char *dir,
						      const struct mesh_cache_key *key,
						      struct mesh_packed *m,
						      const struct mesh *materials, void *anim,
						      size_t anim_size, uint64_t max_bytes);
/* Waits for the entry to be written, and frees w (NULL: nothing). */
void mesh_cache_writer_join(struct mesh_cache_writer *w);

/* The member tables (scene/mesh/mesh_cache_nest.h) of the records an
 * entry keeps (src/scene/mesh/mesh_cache_fields.c): each field of struct
 * mesh_material and struct mesh_range, and struct mesh's colour facts
 * (has_colors, vertex_color), and each named node (struct mesh_node),
 * stored as 32-bit words, checked when read, or NONE: named, not stored. */
enum mesh_cache_table { MESH_CACHE_MATERIAL, MESH_CACHE_RANGE, MESH_CACHE_COLORS, MESH_CACHE_NODE };
struct mesh_nest;
const struct mesh_nest *mesh_cache_table(enum mesh_cache_table t);
/* What the range table's check reads against (the reader's ctx): the
 * index a range must start at (moved past each), the entry's counts. */
struct mesh_cache_ranges {
	uint32_t at, index_count, material_count;
};

#endif
