/* A content's prepared-mesh cache (scene/mesh_cache.h): the entry looked
 * up before a parse, the prepared mesh packed (with live playback's data
 * for a model that plays) and stored once uploaded. */
#include "content/content.h"
#include "scene/mesh/lod_split.h"
#include "scene/mesh/mesh_cache_anim.h"
#include "util/log.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

/* A shell says what the prepared mesh holds (vertex and index counts),
 * with no array: the renderer is given the packed mesh or the entry. */
static void shell_counts(struct content *s, const struct mesh_packed *m)
{
	s->mesh.vertex_count = m->vertex_count;
	s->mesh.index_count = m->index_count;
}

/* An entry of a model that plays: its mesh gets arrays of its own again
 * (the poses write them). An entry whose mesh is not float32 (not what
 * a live model's is written as) is a miss: the parse writes it again. */
static int content_cache_live(struct content *s, const char *path)
{
	int ret = mesh_cache_unpack_live(mesh_cache_entry_mesh(s->cached), &s->mesh);

	if (ret == -EBADMSG)
		log_warn("%s: its cache entry is not a live model's; the model is prepared again",
			 path);
	if (!ret)
		return 0;
	content_play_release(s);
	mesh_cache_entry_free(s->cached);
	s->cached = NULL;
	mesh_release(&s->mesh);
	return ret;
}

int content_cache_lookup(struct content *s, const struct content_config *c, const char *path,
			 const void *data, size_t size)
{
	char dir[PATH_MAX];
	int ret = mesh_cache_scene_key(path, data, size, c->lod_pixels, c->normals, &c->material,
				       &s->cache_key);

	/* Another of the file's scenes is another mesh. */
	if (!ret && c->model_scene)
		s->cache_key.settings =
		    mesh_cache_hash(c->model_scene, strlen(c->model_scene), s->cache_key.settings);
	/* A pose (--time) is another mesh, and so is the live kiosk's (its
	 * entry holds the play's data as well: a still's must never be
	 * taken for it, nor it for a still's). */
	if (!ret && (c->anim_time >= 0 || c->anim_live)) {
		double t[4] = {c->anim_time, c->anim_speed, c->anim_loop, c->anim_live};
		const char *a = c->animation ? c->animation : "auto";

		s->cache_key.settings = mesh_cache_hash(t, sizeof(t), s->cache_key.settings);
		s->cache_key.settings = mesh_cache_hash(a, strlen(a), s->cache_key.settings);
	}
	/* The level of detail on several threads is another mesh (the
	 * clusters follow the count: scene/lod.h); one thread's key is as
	 * it was. */
	if (!ret && lod_threads(c->prepare_threads) > 1) {
		int threads = lod_threads(c->prepare_threads);

		s->cache_key.settings =
		    mesh_cache_hash(&threads, sizeof(threads), s->cache_key.settings);
	}
	/* The fit's zoom (or --zoom) sets the level of detail's pixels. */
	if (!ret)
		s->cache_key.settings =
		    mesh_cache_hash(&c->fit, sizeof(c->fit), s->cache_key.settings);
	if (!ret)
		s->cache_key.settings =
		    mesh_cache_hash(&c->zoom, sizeof(c->zoom), s->cache_key.settings);

	if (!ret)
		ret = mesh_cache_dir(dir, sizeof(dir));
	s->cacheable = !ret;
	if (!ret)
		ret = mesh_cache_open(dir, &s->cache_key, &s->cached);
	if (ret)
		return ret;
	/* An entry is written only for a model whose material decodes no
	 * texture: its factors are all material_load needs. */
	ret = mesh_copy_factors(&s->mesh, mesh_cache_entry_materials(s->cached));
	if (ret)
		return ret;
	shell_counts(s, mesh_cache_entry_mesh(s->cached));
	s->play = mesh_cache_entry_take_play(s->cached);
	if (s->play)
		ret = content_cache_live(s, path);
	if (ret)
		return ret;
	/* Said by content_prepare, once it is known to be used. */
	log_debug("%s: a prepared mesh in the cache", path);
	return 0;
}

bool content_cache_fits(const struct content *s, int width, int height)
{
	const struct mesh_cache_key *k = s->cached ? mesh_cache_entry_key(s->cached) : NULL;

	return k && k->width == (uint32_t)width && k->height == (uint32_t)height;
}

/* An entry holds no image: a model with one is prepared at each start. */
static bool decoded_images(const struct mesh *mesh)
{
	return mesh_materials_any(mesh, mesh_material_decoded);
}

/* A model that plays keeps its arrays: its entry gets a copy, and the
 * play's data (made here, on the worker, not on the frame thread that
 * uploads and then stores). */
static void content_cache_pack_live(struct content *s, int width, int height)
{
	if (mesh_cache_pack_live(&s->mesh, &s->packed))
		return;
	if (mesh_cache_anim_encode(s->play, &s->play_bytes, &s->play_size)) {
		mesh_packed_release(&s->packed);
		return;
	}
	s->cache_key.width = (uint32_t)width;
	s->cache_key.height = (uint32_t)height;
}

/* The prepared mesh packed as the GPU and the cache take it; the mesh's
 * own arrays are given back (its materials and colour facts stay:
 * material_load and a reload read them; they hold no image here). */
void content_cache_pack(struct content *s, int width, int height)
{
	/* What stays: the materials and the colour facts, no array. */
	struct mesh shell = {0};

	if (!s->cacheable || decoded_images(&s->mesh))
		return;
	if (s->play) {
		content_cache_pack_live(s, width, height);
		return;
	}
	if (mesh_pack(&s->mesh, VERTEX_COMPACT, &s->packed))
		return;
	s->cache_key.width = (uint32_t)width;
	s->cache_key.height = (uint32_t)height;
	shell.materials = s->mesh.materials, shell.material_count = s->mesh.material_count;
	shell.has_colors = s->mesh.has_colors;
	memcpy(shell.fit, s->mesh.fit, sizeof(shell.fit));
	shell.node_count = s->mesh.node_count;
	memcpy(shell.nodes, s->mesh.nodes, sizeof(shell.nodes));
	memcpy(shell.vertex_color, s->mesh.vertex_color, sizeof(shell.vertex_color));
	s->mesh.materials = NULL, s->mesh.material_count = 0;
	mesh_release(&s->mesh);
	s->mesh = shell;
	shell_counts(s, &s->packed);
}

/* Once uploaded, the packed mesh goes to the cache on a thread of its
 * own (the first frame does not wait for the disk), which frees it. */
void content_cache_store(struct content *s)
{
	char dir[PATH_MAX];

	if (!s->packed.vertex_count || mesh_cache_dir(dir, sizeof(dir)))
		return;
	s->writer = mesh_cache_write_async_play(dir, &s->cache_key, &s->packed, &s->mesh,
						s->play_bytes, s->play_size, MESH_CACHE_MAX_BYTES);
	s->play_bytes = NULL;
}

/* A shell whose packed mesh went to the cache: uploaded again (a reload
 * that failed), it is read back from the entry. */
int content_cache_reopen(struct content *s)
{
	char dir[PATH_MAX];
	int ret;

	if (s->cached || s->packed.vertex_count || s->mesh.positions || !s->mesh.index_count)
		return 0;
	mesh_cache_writer_join(s->writer);
	s->writer = NULL;
	ret = mesh_cache_dir(dir, sizeof(dir));
	if (!ret)
		ret = mesh_cache_open(dir, &s->cache_key, &s->cached);
	if (ret)
		log_err("the prepared mesh is neither in memory nor in the cache");
	return ret;
}
