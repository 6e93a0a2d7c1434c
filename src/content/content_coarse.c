/* The live kiosk's first picture of a large model before its last
 * triangle is simplified (issue 34): on a cache miss, a model over [kiosk]
 * coarse_above triangles is cut sloppily to a few thousand
 * (scene/mesh/lod_coarse.h) once its fit is known, and that is what the
 * content's first upload shows; a second job of the worker
 * (content/refine_job.h) prepares the whole mesh as a still would, and
 * the loop swaps it in. The coarse picture is framed by the fit of the
 * whole mesh (a sloppy cut's outline is not the model's:
 * content_coarse_frame); the swap then takes the fit a still and a start
 * from the cache compute on the prepared mesh (content_frame, with the
 * caption's box), which its level of detail keeps within its pixel error
 * of the whole one's. */
#include "content/content.h"
#include "config/settings.h"
#include "scene/mesh/lod.h"
#include "scene/mesh/lod_coarse.h"
#include "scene/mesh/lod_split.h"
#include "util/clock.h"
#include "util/log.h"

#include <errno.h>
#include <malloc.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* The coarse picture's triangles at most: a few thousand draw in a frame
 * on a Pi and read as the model's shape; fewer where the level of detail
 * itself keeps few (a small screen), an eighth of those, so that the
 * coarse picture is always the cruder one. */
#define COARSE_TRIANGLES 4000
#define COARSE_SHARE	 8

struct content_refine {
	/* The model's side of a content: the whole mesh, then prepared and
	 * packed, with its fit (zoom); its cache key. */
	struct content part;
	struct content_config config; /* the model's settings, for the fit at the swap */
	double pixels;
	int width, height, threads;
	uint32_t coarse_triangles;
	uint64_t began_ns;
	bool prepared; /* content_refine_run is done with it */
};

/* The journal's name of s's model. */
const char *content_name(const struct content *s)
{
	return s->model_path ? s->model_path : "the built-in knot";
}

static double seconds_since(uint64_t ns)
{
	return (double)(monotonic_ns() - ns) / 1e9;
}

/* Whether s is one to show coarse first, and with how many triangles. */
static uint32_t coarse_target(const struct content *s, const struct content_config *o,
			      double pixels, int width, int height)
{
	uint32_t triangles = s->mesh.index_count / 3;
	double wanted;

	if (!o->coarse_first || o->coarse_above <= 0 || triangles <= (uint32_t)o->coarse_above ||
	    s->play || s->cached || pixels <= 0.0 || s->mesh.variant_count)
		return 0;
	wanted = lod_triangles_wanted(&s->mesh, pixels, width, height) / COARSE_SHARE;
	if (wanted > COARSE_TRIANGLES)
		wanted = COARSE_TRIANGLES;
	/* Already about as few: the level of detail is quick. */
	return wanted < triangles / 2 ? (uint32_t)(wanted > 1 ? wanted : 1) : 0;
}

int content_coarse_begin(struct content *s, const struct content_config *o, double pixels,
			 int width, int height)
{
	uint32_t target = coarse_target(s, o, pixels, width, height);
	struct content_refine *f = target ? calloc(1, sizeof(*f)) : NULL;
	struct mesh coarse;
	int ret;

	if (!f)
		return 0; /* none wanted, or no memory: prepared whole */
	ret = content_config_copy(&f->config, o);
	if (!ret)
		ret = lod_coarse_mesh(&s->mesh, target, &coarse);
	if (ret) {
		content_config_release(&f->config);
		free(f);
		return ret == -EINVAL ? 0 : ret;
	}
	f->part.mesh = s->mesh;
	f->part.cache_key = s->cache_key;
	f->part.cacheable = s->cacheable;
	f->pixels = pixels;
	f->width = width;
	f->height = height;
	f->threads = lod_threads(o->prepare_threads);
	f->coarse_triangles = coarse.index_count / 3;
	f->began_ns = s->began_ns ? s->began_ns : monotonic_ns();
	s->mesh = coarse;
	s->cacheable = false; /* the whole one is cached, at its swap */
	s->refine = f;
	s->coarse = true;
	log_debug("%s: %u triangles, over [kiosk] coarse_above = %d: a coarse picture of %u first",
		  content_name(s), f->part.mesh.index_count / 3, o->coarse_above,
		  f->coarse_triangles);
	return 1;
}

void content_coarse_frame(struct content *s, const struct content_config *o, int width, int height)
{
	struct mesh coarse;

	if (!s->refine)
		return;
	coarse = s->mesh;
	s->mesh = s->refine->part.mesh;
	content_frame(s, o, width, height);
	s->refine->part.mesh = s->mesh;
	s->mesh = coarse;
}

struct content_refine *content_refine_take(struct content *s)
{
	struct content_refine *f = s->refine;

	s->refine = NULL;
	if (f)
		log_info("%s: coarse picture (%u triangles) after %.2f s", content_name(s),
			 f->coarse_triangles, seconds_since(f->began_ns));
	return f;
}

/* Test hook: MK_TEST_REFINE_GATE holds the preparation until that file
 * exists (tests/unit/test_kiosk_coarse.c: the coarse frame is read first,
 * however fast the machine), at most a minute. Built into the sanitizer
 * builds of the tests alone (-DMK_TEST_HOOKS). */
static void test_gate(void)
{
#ifdef MK_TEST_HOOKS
	const char *gate = getenv("MK_TEST_REFINE_GATE");
	struct timespec tick = {0, 10 * 1000000};

	for (int i = 0; gate && i < 6000 && access(gate, F_OK); i++)
		nanosleep(&tick, NULL);
#endif
}

void content_refine_run(struct content_refine *f)
{
	struct content *p = &f->part;

	test_gate();
	/* As prepare_mesh does for a still, less the fit: the coarse
	 * picture's stays. Out of memory: the mesh is drawn unsimplified. */
	if (lod_prepare_mesh_threads(&p->mesh, f->pixels, f->width, f->height, f->threads, NULL))
		log_warn("the level of detail has no memory: the model is drawn whole");
	content_cache_pack(p, f->width, f->height);
	f->prepared = true;
}

bool content_refine_prepared(const struct content_refine *f)
{
	return f && f->prepared;
}

/* The glTF's decoded maps are the material's now (content.c's
 * release_decoded_maps, for the whole mesh that kept them till here). */
static void release_maps(struct mesh *m)
{
	for (uint32_t k = 0; k < m->material_count; k++)
		mesh_material_release(&m->materials[k]);
}

int content_refine_swap(struct content *shown, struct content_refine *f, struct renderer *r,
			struct content *old)
{
	struct content *p = &f->part;
	int ret = p->packed.vertex_count ? renderer_set_packed(r, &p->packed)
					 : renderer_set_mesh(r, &p->mesh);

	memset(old, 0, sizeof(*old));
	if (ret) {
		log_err("%s: its full level of detail does not fit on the GPU: the coarse picture "
			"stays",
			content_name(shown));
		old->refine = f;
		return ret;
	}
	old->mesh = shown->mesh;
	shown->mesh = p->mesh;
	shown->packed = p->packed;
	shown->cache_key = p->cache_key;
	shown->cacheable = p->cacheable;
	shown->coarse = false;
	memset(p, 0, sizeof(*p));
	/* The still's fit: over the packed mesh (a few tens of thousands of
	 * vertices: what the display shows), with the caption's box. */
	content_frame(shown, &f->config, f->width, f->height);
	content_cache_store(shown);
	release_maps(&shown->mesh);
	log_info("%s: full level of detail (%u triangles) after %.2f s", content_name(shown),
		 shown->mesh.index_count / 3, seconds_since(f->began_ns));
	content_refine_free(f);
	/* The whole mesh's arrays are gone: back to the system. */
	malloc_trim(0);
	return 0;
}

void content_refine_free(struct content_refine *f)
{
	if (!f)
		return;
	/* Never stored: the swap gives the packed mesh to the content shown. */
	mesh_release(&f->part.mesh);
	mesh_packed_release(&f->part.packed);
	content_config_release(&f->config);
	free(f);
}
