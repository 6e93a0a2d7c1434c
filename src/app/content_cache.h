/* The prepared-mesh cache (scene/mesh_cache.h) for the kiosk's content:
 * which scenes it keeps, and under which key. Only content.c uses it. */
#ifndef MK_CONTENT_CACHE_H
#define MK_CONTENT_CACHE_H

#include "app/content.h"

#include <stdbool.h>

/* A hit: s->cached maps the prepared mesh and s->mesh is a shell holding
 * only the model's material factors (what material_load reads). Returns
 * 0, or a negative errno code on a miss (the model is then loaded). */
int content_cache_lookup(struct content *s, const struct content_config *c);
/* Whether s->cached was prepared for this display. */
bool content_cache_fits(const struct content *s, int width, int height);
/* s->mesh, prepared for width x height, into the cache (when the scene is
 * one it keeps); s->cached then maps the entry written. */
void content_cache_store(struct content *s, const struct content_config *c, int width, int height);

#endif
