/* Live playback's data (scene/anim_play.h: the parts, skins, the parts'
 * own arrays, the clip's fit, and the mesh_anim's nodes and clips) as the
 * last section of a prepared-mesh cache entry (scene/mesh_cache.h), so
 * that an animated model starts from the cache as a still does. */
#ifndef MK_MESH_CACHE_ANIM_H
#define MK_MESH_CACHE_ANIM_H

#include "scene/anim/anim_play.h"
#include "scene/mesh/mesh_pack.h"

#include <stddef.h>
#include <stdint.h>

/* The member table of struct anim_play (mesh_cache_nest.h), the rig's
 * other structs under it: for the test that every field is described. */
struct mesh_nest;
const struct mesh_nest *mesh_cache_anim_table(void);

/* p's playback data (not its scratch, nor its GPU arrays: those are
 * made again) as bytes, a multiple of 4, in *out (to free). 0 or
 * -ENOMEM. */
int mesh_cache_anim_encode(const struct anim_play *p, void **out, size_t *size);

/* The bytes back, every count, index and sampler checked, for a mesh of
 * vertex_count vertices; the scratch allocated (anim_play_finish). 0,
 * -EBADMSG (anything out of range, or bytes left over) or -ENOMEM. */
int mesh_cache_anim_decode(const void *data, size_t size, uint32_t vertex_count,
			   struct anim_play **out);

/* The mesh of a model that plays, for its entry: float32 (the live
 * frame poses from what the parse gave, to the last bit), its arrays and
 * indices copied into the packed mesh's own allocation (the frame thread
 * writes the mesh's positions while the entry is written). 0 or -ENOMEM. */
int mesh_cache_pack_live(const struct mesh *m, struct mesh_packed *out);
/* Such an entry's mesh back as a mesh of its own arrays, indices and
 * ranges (out's materials are left as they are). 0, -EBADMSG (not
 * float32: not a live entry) or -ENOMEM. */
int mesh_cache_unpack_live(const struct mesh_packed *p, struct mesh *out);

#endif
