/* What the kiosk shows, loaded from the settings: the mesh, the matcaps
 * and the first matcap decoded. The start and a reload (SIGHUP) both build
 * a complete new scene here; a reload swaps it in only once every part of
 * it loaded and uploaded, so a broken model or folder keeps the old one. */
#ifndef MK_SCENE_H
#define MK_SCENE_H

#include "image.h"
#include "matcap_set.h"
#include "mesh.h"
#include "options.h"
#include "render.h"

#include <stdbool.h>

struct scene {
	struct mesh mesh;
	struct image matcap;	  /* the first one shown */
	struct matcap_set *set;	  /* NULL: the built-in clay only */
	char *matcap_path;	  /* the file or folder set came from; NULL with set */
	struct material material; /* the optional features ([material]) */
};

/* strict: every file the settings name must load (a one-shot render is
 * useless with a substitute, and a reload keeps the old scene instead).
 * Otherwise a model or matcap that fails is replaced by the built-in one,
 * and the journal says so. On failure s is left empty. */
int scene_load(struct scene *s, const struct options *o, bool strict);
void scene_release(struct scene *s);
/* Fit the mesh to the display it will be drawn on: subdivided for a
 * displacement map at this display's density, then simplified to no more
 * triangles than the display shows (a displaced mesh is only reordered).
 * The start and a reload do the same, so a reload shows what a restart
 * would. */
int scene_prepare(struct scene *s, const struct options *o, int width, int height);
/* Hand the mesh and the first matcap to the renderer. */
int scene_upload(const struct scene *s, struct renderer *r);
/* The camera and panel the settings ask for, at the resting orientation. */
struct view scene_view(const struct options *o);
/* The matcap folder was changed: open the set again. Returns 0 and
 * replaces s->set, or a negative errno (after logging) and keeps it. */
int scene_rescan_matcaps(struct scene *s);

#endif
