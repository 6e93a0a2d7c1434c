#include "app/content_cache.h"
#include "scene/mesh_cache.h"
#include "util/log.h"

#include <errno.h>
#include <limits.h>
#include <string.h>

/* A scene is kept when nothing but the model file and these settings
 * shape its mesh: no displacement (a height map reshapes it), no detail
 * map (its tangents need UVs that the shell does not show material_load),
 * and no texture decoded from the model (the entry holds no images). */
static bool keeps(const struct content_config *c)
{
	const struct material_config *m = &c->material;

	return c->model && !m->height_map && !m->detail_map && m->detail != MATERIAL_ON;
}

/* The settings that change the prepared mesh, and the program's own
 * bytes: a rebuilt kiosk (another loader, another simplifier) prepares
 * again rather than trust what an older one wrote. */
static int settings_key(const struct content_config *c, uint64_t *out)
{
	const double values[] = {c->lod_pixels, c->material.detail, c->material.iridescence,
				 VERTEX_COMPACT};
	uint64_t program;
	int ret = mesh_cache_hash_model("/proc/self/exe", &program);

	*out = mesh_cache_hash(values, sizeof(values), program);
	return ret;
}

int content_cache_lookup(struct content *s, const struct content_config *c)
{
	char dir[PATH_MAX];
	int ret = keeps(c) ? mesh_cache_dir(dir, sizeof(dir)) : -ENOENT;

	if (!ret)
		ret = mesh_cache_hash_model(c->model, &s->cache_key.content);
	if (!ret)
		ret = settings_key(c, &s->cache_key.settings);
	s->cacheable = !ret;
	if (!ret)
		ret = mesh_cache_open(dir, &s->cache_key, &s->cached);
	if (ret)
		return ret;
	/* An entry is written only for a model whose material decodes no
	 * texture: its factors are all material_load needs. */
	s->mesh.material = *mesh_cache_entry_material(s->cached);
	log_info("%s: the prepared mesh from the cache (%u triangles)", c->model,
		 mesh_cache_entry_mesh(s->cached)->index_count / 3);
	return 0;
}

bool content_cache_fits(const struct content *s, int width, int height)
{
	const struct mesh_cache_key *k = s->cached ? mesh_cache_entry_key(s->cached) : NULL;

	return k && k->width == (uint32_t)width && k->height == (uint32_t)height;
}

static bool decoded_images(const struct mesh_material *m)
{
	return m->normal_map.width || m->occlusion_map.width || m->thickness_map.width;
}

/* The material stays: material_load and a reload read it. It holds no
 * image here (decoded_images). */
static void drop_arrays(struct mesh *m)
{
	struct mesh_material material = m->material;

	mesh_material_default(&m->material);
	mesh_release(m);
	m->material = material;
}

void content_cache_store(struct content *s, const struct content_config *c, int width, int height)
{
	struct mesh_packed packed;
	char dir[PATH_MAX];

	if (!s->cacheable || decoded_images(&s->mesh.material) || !keeps(c) ||
	    mesh_cache_dir(dir, sizeof(dir)))
		return;
	s->cache_key.width = (uint32_t)width;
	s->cache_key.height = (uint32_t)height;
	if (mesh_pack(&s->mesh, VERTEX_COMPACT, &packed))
		return;
	if (!mesh_cache_write(dir, &s->cache_key, &packed, &s->mesh.material, MESH_CACHE_MAX_BYTES))
		log_info("%s: the prepared mesh cached in %s", c->model, dir);
	mesh_packed_release(&packed);
	/* Uploaded from the entry, as the next start will be: the mesh's own
	 * arrays are given back now, before the first frame. */
	if (!mesh_cache_open(dir, &s->cache_key, &s->cached))
		drop_arrays(&s->mesh);
}
