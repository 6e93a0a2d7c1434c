#include "content/content.h"
#include "content/load_guard.h"
#include "util/file.h"
#include "content/model_list.h"
#include "config/model_settings.h"
#include "scene/gltf/gltf.h"
#include "scene/mesh/lod.h"
#include "scene/mesh/lod_split.h"
#include "scene/mesh/texture.h"
#include "util/clock.h"
#include "util/log.h"

#include <limits.h>
#include <malloc.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define KNOT_TUBULAR 256
#define KNOT_RADIAL  32

/* The bytes of path, as gltf_read gives them; path NULL (the built-in
 * knot) or none read: data NULL. */
struct model_bytes {
	uint8_t *data;
	size_t size;
};

/* path NULL: the built-in knot. The live kiosk keeps what playback needs
 * in *play (posed at 0 s, fitted over its clip); NULL: a still. b: the
 * file's bytes, read by the caller to key the cache with them; the parse
 * reads them, not the file again. */
static int load_model(const char *path, struct model_bytes *b, const struct content_config *o,
		      struct mesh *mesh, struct anim_play **play)
{
	if (path) {
		struct gltf_options g = {.textures = material_gltf_textures(&o->material),
					 .texture_memory = texture_memory_budget(o->texture_memory),
					 .scene = o->model_scene,
					 .scene_setting = "[scene] model_scene",
					 .play = o->anim_live ? play : NULL,
					 .animation_optional = o->anim_live && !o->anim_strict,
					 .pose = o->anim_time >= 0 || o->anim_live,
					 .animation = o->animation,
					 .animation_setting = "[scene] animation",
					 .time = o->anim_time >= 0 ? o->anim_time : 0,
					 .speed = o->anim_speed,
					 .loop = o->anim_loop,
					 .normals = o->normals};

		/* The bytes go once parsed (gltf.h): the caller frees NULL. */
		return b->data ? gltf_load_bytes_owned(path, &b->data, b->size, &g, mesh)
			       : gltf_load_options(path, &g, mesh);
	}
	return mesh_torus_knot(mesh, KNOT_TUBULAR, KNOT_RADIAL);
}

static void free_own(struct content *s)
{
	if (s->own)
		content_config_release(s->own);
	free(s->own);
	s->own = NULL;
}

/* o with the model's NAME.ini over it (read here, on the worker where a
 * model is loaded). A file with errors (each logged with its line) is
 * left out: the model is shown with o as it is. */
static int own_settings(struct content *s, const struct content_config *o, const char *path)
{
	struct content_config *c = calloc(1, sizeof(*c));

	if (!c || content_config_copy(c, o)) {
		free(c);
		return -ENOMEM;
	}
	/* A model the import brought: its NAME.ini is a stick's, whoever
	 * put it there (the import refused it otherwise). */
	if ((file_in_content(path) ? model_settings_read_stick(c, path)
				   : model_settings_read(c, path)) != OPTIONS_OK)
		log_err("%s: its own settings are ignored for the errors above", path);
	free_own(s);
	s->own = c;
	return 0;
}

const struct content_config *content_settings(const struct content *s,
					      const struct content_config *c)
{
	return s->own ? s->own : c;
}

/* The model of one file, from the cache or parsed; strict: no knot. The
 * file is read once: the cache's key is of the bytes a miss then parses
 * (a file replaced meanwhile cannot be stored under the old one's key). */
static int load_mesh_file(struct content *s, const struct content_config *o, const char *path)
{
	struct model_bytes b = {NULL, 0};
	int ret = own_settings(s, o, path);
	unsigned warned;

	if (ret)
		return ret;
	o = s->own;
	if (!path || o->anim_strict) /* the knot, or never cached */
		return load_model(path, &b, o, &s->mesh, &s->play);
	ret = gltf_read(path, &b.data, &b.size);
	if (ret)
		return ret;
	if (!content_cache_lookup(s, o, path, b.data, b.size))
		goto out;
	warned = log_warnings(); /* the parse's (a damaged entry is one) */
	ret = load_model(path, &b, o, &s->mesh, &s->play);
	/* A model that warned (a clip it lacks, animations it cannot read) is
	 * not cached: a start from the cache would show it as it falls back
	 * and no longer say why. */
	if (!ret && s->cacheable && log_warnings() != warned) {
		log_info("%s: not cached: each start says its warnings (above)", path);
		s->cacheable = false;
	}
	/* The cache's entry holds one set of materials' factors and no
	 * variant table: a model with variants is loaded each start. */
	if (!ret && s->cacheable && s->mesh.variant_count) {
		log_info("%s: not cached: it has material variants", path);
		s->cacheable = false;
	}
out:
	free(b.data);
	return ret;
}

int content_variant_names(const struct mesh *m, char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (uint32_t v = 0; v < m->variant_count && len < n; v++)
		len += (size_t)snprintf(buf + len, n - len, "%s\"%s\"", v ? ", " : "",
					m->variant_names[v]);
	if (!m->variant_count)
		snprintf(buf, n, "none");
	return (int)m->variant_count;
}

int content_variant_find(const struct content *s, const char *name)
{
	return mesh_variant_find(&s->mesh, name);
}

/* [scene] variant against the model's: a still stops (it was asked for
 * that variant), the live kiosk shows the default materials and says so;
 * --check-config says it itself, with the file and line. */
static int check_variant(const struct content *s, const struct content_config *o, const char *path)
{
	const char *want = content_settings(s, o)->variant;
	char names[512];

	if (!want || o->anim_strict || mesh_variant_find(&s->mesh, want) >= 0)
		return 0;
	content_variant_names(&s->mesh, names, sizeof(names));
	if (o->anim_live) {
		log_warn("%s: [scene] variant = '%s': no such variant (it has: %s); its default "
			 "materials shown",
			 path, want, names);
		return 0;
	}
	log_err("%s: [scene] variant = '%s': no such variant, expected one of its: %s", path, want,
		names);
	return -EINVAL;
}

/* The live kiosk's loads are remembered while they run: one that kills
 * the process is skipped after the restart. (No path: the built-in knot,
 * nothing to remember.) */
static int load_mesh(struct content *s, const struct content_config *o, const char *path)
{
	char dir[PATH_MAX];
	bool guard = path && o->crash_memory && !load_guard_dir(dir, sizeof(dir));
	int ret = guard ? load_guard_enter(dir, path) : 0;

	if (ret)
		return ret;
	ret = load_mesh_file(s, o, path);
	if (!ret)
		ret = check_variant(s, o, path);
	if (guard)
		load_guard_leave(dir);
	return ret;
}

struct try_ctx {
	struct content *s;
	const struct content_config *o;
};

static int try_mesh(void *ctx, const char *path)
{
	struct try_ctx *t = ctx;

	memset(&t->s->mesh, 0, sizeof(t->s->mesh));
	return load_mesh(t->s, t->o, path);
}

/* A folder or a list: the first model in it that loads; the others that
 * fail say so, one line each. */
static int load_first_model(struct content *s, const struct content_config *o, bool strict)
{
	struct try_ctx t = {s, o};
	struct model_list *l = model_list_new(o->model);
	int i = l ? model_list_pick(l, 0, 1, -1, try_mesh, &t) : -1;

	if (i >= 0)
		s->model_path = strdup(model_list_path(l, i));
	model_list_free(l);
	if (i >= 0)
		return s->model_path ? 0 : -ENOMEM;
	if (strict)
		return -ENOENT;
	log_warn("%s: showing the built-in torus knot: no model there loads", o->model);
	free_own(s);
	return mesh_torus_knot(&s->mesh, KNOT_TUBULAR, KNOT_RADIAL);
}

static int load_the_model(struct content *s, const struct content_config *o, bool strict)
{
	int ret;

	if (model_spec_is_many(o->model))
		return load_first_model(s, o, strict);
	if (o->model && !(s->model_path = strdup(o->model)))
		return -ENOMEM;
	/* A model prepared before is mapped from the cache, not parsed. */
	ret = load_mesh(s, o, s->model_path);
	if (ret && !strict) {
		log_warn("showing the built-in torus knot instead of %s", o->model);
		free(s->model_path);
		s->model_path = NULL;
		free_own(s);
		ret = mesh_torus_knot(&s->mesh, KNOT_TUBULAR, KNOT_RADIAL);
	}
	return ret;
}

int content_load(struct content *s, const struct content_config *o, bool strict)
{
	int ret;

	memset(s, 0, sizeof(*s));
	s->began_ns = monotonic_ns();
	ret = load_the_model(s, o, strict);
	/* The first model's own matcaps and background, where it names them. */
	if (!ret)
		ret = content_load_background(content_settings(s, o), strict, &s->background,
					      &s->background_image);
	if (!ret)
		ret = content_load_matcap(content_settings(s, o), strict, s);
	if (!ret)
		ret = content_look_set(&s->look, content_settings(s, o));
	if (!ret)
		ret = material_load(&s->material, &content_settings(s, o)->material, &s->mesh,
				    strict);
	if (!ret)
		ret = content_load_captions(s, content_settings(s, o), strict);
	if (!ret)
		content_load_hotspots(s, content_settings(s, o));
	if (!ret)
		content_load_hotspot_captions(s, content_settings(s, o));
	if (ret)
		content_release(s);
	return ret;
}

int content_load_model(struct content *s, const struct content_config *o, const char *path,
		       const struct content_look *shown, int width, int height)
{
	int ret;

	memset(s, 0, sizeof(*s));
	s->began_ns = monotonic_ns();
	s->model_path = strdup(path);
	ret = s->model_path ? load_mesh(s, o, path) : -ENOMEM;
	if (!ret)
		ret =
		    material_load(&s->material, &content_settings(s, o)->material, &s->mesh, true);
	if (!ret)
		ret = content_prepare(s, o, width, height);
	if (!ret)
		ret = content_load_look(s, content_settings(s, o), shown);
	if (!ret)
		ret = content_load_captions(s, content_settings(s, o), false);
	if (!ret)
		content_fit_captions(s, content_settings(s, o), width, height);
	if (!ret)
		content_load_hotspots(s, content_settings(s, o));
	if (!ret)
		content_load_hotspot_captions(s, content_settings(s, o));
	if (!ret) /* a coarse picture is framed as its whole mesh will be */
		content_coarse_frame(s, content_settings(s, o), width, height);
	if (ret)
		content_release(s);
	return ret;
}

/* The model's parts of a content, as content_release gives them back. */
static void release_model(struct content *s)
{
	mesh_cache_writer_join(s->writer);
	content_refine_free(s->refine);
	mesh_packed_release(&s->packed);
	free(s->play_bytes);
	mesh_cache_entry_free(s->cached);
	mesh_release(&s->mesh);
	content_play_release(s);
	material_release(&s->material);
	free(s->model_path);
	content_release_captions(s);
	free_own(s);
}

void content_take_model(struct content *shown, struct content *fresh, struct content *old)
{
	struct content kept = *shown;

	memset(old, 0, sizeof(*old));
	old->mesh = kept.mesh;
	old->play = kept.play;
	old->play_split = kept.play_split;
	old->play_bytes = kept.play_bytes;
	old->cached = kept.cached;
	old->packed = kept.packed;
	old->writer = kept.writer;
	old->material = kept.material;
	old->model_path = kept.model_path;
	old->caption = kept.caption;
	memcpy(old->stop_caption, kept.stop_caption, sizeof(old->stop_caption));
	memcpy(old->lang_spare, kept.lang_spare, sizeof(old->lang_spare));
	old->own = kept.own;
	old->refine = kept.refine; /* a coarse picture's whole mesh: not wanted now */
	/* The look's text: fresh's equals kept's where it has none of its own. */
	old->look = kept.look;
	*shown = *fresh;
	if (fresh->own_look & CONTENT_OWN_MATCAP) {
		old->matcap = kept.matcap;
		old->set = kept.set;
		old->matcap_path = kept.matcap_path;
		old->matcap_first = kept.matcap_first;
	} else {
		shown->matcap = kept.matcap;
		shown->set = kept.set;
		shown->matcap_path = kept.matcap_path;
		shown->matcap_first = kept.matcap_first;
	}
	if (fresh->own_look & CONTENT_OWN_BACKGROUND) {
		old->background_image = kept.background_image;
	} else {
		shown->background = kept.background;
		shown->background_image = kept.background_image;
	}
	memset(fresh, 0, sizeof(*fresh));
}

void content_release(struct content *s)
{
	release_model(s);
	image_release(&s->matcap);
	image_release(&s->background_image);
	matcap_set_free(s->set);
	free(s->matcap_path);
	free(s->matcap_first);
	content_look_release(&s->look);
	memset(s, 0, sizeof(*s));
}

/* The model of an entry prepared for another display, parsed again: its
 * key's content follows the bytes parsed now, so the entry written after
 * is of what was parsed, whatever the file became since the lookup. */
static int reload_model(struct content *s, const struct content_config *o)
{
	struct model_bytes b = {NULL, 0};
	int ret = gltf_read(s->model_path, &b.data, &b.size);

	if (!ret) {
		s->cache_key.content = mesh_cache_hash_model_bytes(s->model_path, b.data, b.size);
		ret = load_model(s->model_path, &b, o, &s->mesh, &s->play);
	}
	free(b.data);
	return ret;
}

/* A wall's screen magnifies the model as the whole wall does: its level
 * of detail and its displacement's subdivision are judged at the wall's
 * pixels per unit, and kept in the cache under the wall's size (kw x kh:
 * width x height with no wall). */
static double wall_density(const struct content_config *o, int width, int height, int *kw, int *kh)
{
	wall_pixels(&o->wall, o->rotation, width, height, kw, kh);
	if (*kw == width && *kh == height)
		return 1.0;
	return sphere_fit_pixels_per_unit(*kw, *kh) / sphere_fit_pixels_per_unit(width, height);
}

static int prepare_mesh(struct content *s, const struct content_config *o, int width, int height)
{
	bool displaced = s->material.features & MATERIAL_DISPLACEMENT;
	int ret = 0, kw, kh;
	double density;

	o = content_settings(s, o);
	density = wall_density(o, width, height, &kw, &kh);
	if (content_cache_fits(s, kw, kh)) {
		log_info("%s: the prepared mesh from the cache (%u triangles)%s", s->model_path,
			 s->mesh.index_count / 3, s->play ? ", with its live playback" : "");
		content_frame(s, o, width, height);
		return 0;
	}
	if (s->cached) {
		/* Cached for another display: its level of detail is another. */
		log_info("%s: the cache holds it prepared for another screen size: prepared again",
			 s->model_path);
		mesh_cache_entry_free(s->cached);
		s->cached = NULL;
		mesh_release(&s->mesh);
		content_play_release(s);
		ret = reload_model(s, o);
	}
	if (!ret)
		ret = material_prepare_mesh(&s->material, &s->mesh, kw, kh);
	/* The fit magnifies the picture: the level of detail judges its
	 * pixels as drawn (the zoom of the whole mesh, then of the simplified
	 * one, which a start from the cache finds too). */
	if (!ret)
		content_frame(s, o, width, height);
	if (!ret)
		content_play_check(s);
	/* The live kiosk's large model: coarse now, whole later (one fit). */
	if (!ret && (ret = content_coarse_begin(
			 s, o, displaced ? 0.0 : o->lod_pixels / s->zoom / density, width, height)))
		return ret < 0 ? ret : 0;
	/* No level of detail for a model that plays (content.h). */
	if (!ret && !s->play)
		ret = lod_prepare_mesh_threads(
		    &s->mesh, displaced ? 0.0 : o->lod_pixels / s->zoom / density, width, height,
		    lod_threads(o->prepare_threads), NULL);
	if (!ret)
		content_cache_pack(s, kw, kh);
	if (!ret)
		content_frame(s, o, width, height);
	return ret;
}

/* The captions drawn at load, before the display's size was known, are
 * fitted to it here (content_caption.c). */
int content_prepare(struct content *s, const struct content_config *o, int width, int height)
{
	int ret = prepare_mesh(s, o, width, height);

	if (!ret)
		content_fit_captions(s, content_settings(s, o), width, height);
	if (!ret)
		content_coarse_frame(s, content_settings(s, o), width, height);
	return ret;
}

/* The glTF's decoded maps were copied into the material's own images
 * (material_load: the detail map, each primitive's base map), which are
 * what the renderer uploads: once on the GPU
 * these CPU copies serve nothing (a reload decodes the file again). */
static void release_decoded_maps(struct mesh *mesh)
{
	for (uint32_t k = 0; k < mesh->material_count; k++)
		mesh_material_release(&mesh->materials[k]);
}

int content_upload_model(struct content *s, struct renderer *r)
{
	/* The material first: it decides which attributes the mesh uploads. */
	int ret = renderer_set_material(r, &s->material);

	if (!ret)
		ret = content_cache_reopen(s);
	/* A model that plays first: its entry or packed copy is for the cache. */
	if (!ret && s->play)
		ret = content_play_upload(s, r);
	else if (!ret && s->cached)
		ret = renderer_set_packed(r, mesh_cache_entry_mesh(s->cached));
	else if (!ret && s->packed.vertex_count)
		ret = renderer_set_packed(r, &s->packed);
	else if (!ret)
		ret = renderer_set_mesh(r, &s->mesh);
	/* On the GPU now: the entry's pages leave the process, the packed
	 * mesh goes to the cache. */
	if (!ret && s->cached)
		mesh_cache_entry_evict(s->cached);
	if (!ret)
		content_cache_store(s);
	if (!ret)
		release_decoded_maps(&s->mesh);
	if (!ret)
		ret = renderer_set_caption(r, &s->caption, &s->caption_place);
	if (!ret)
		ret = renderer_set_stop_captions(r, s->stop_caption, CAPTION_STOPS,
						 &s->caption_place);
	if (!ret)
		ret = renderer_set_hotspots(r, s->hotspots, s->hotspot_count, s->stop_hotspot);
	/* The parse, the preparation and the upload freed far more than the
	 * scene keeps; malloc holds freed heap for reuse, and a kiosk reuses
	 * little: back to the system before the first frame. */
	malloc_trim(0);
	return ret;
}

int content_upload(struct content *s, struct renderer *r)
{
	int ret = content_upload_model(s, r);

	if (!ret)
		ret = renderer_set_background(r, &s->background, &s->background_image);
	if (!ret)
		ret = renderer_set_matcap(r, &s->matcap);
	/* Textures now: the matcap shown next is decoded on the worker, the
	 * background again at a reload. */
	if (!ret) {
		image_release(&s->matcap);
		image_release(&s->background_image);
	}
	return ret;
}
