/* The models [scene] model names: a file, a folder (its .gltf and .glb
 * files in name order) or a comma-separated list of either. They take
 * turns: next and prev step through them, and a model that does not load
 * is passed over, once logged, until its file changes. Nothing here parses
 * a model; the loader is a function the caller gives. */
#ifndef MK_MODEL_LIST_H
#define MK_MODEL_LIST_H

#include <stdbool.h>

struct model_list;

/* True when spec names more than one file: a folder or a list. */
bool model_spec_is_many(const char *spec);
/* NULL after logging: nothing readable, or no model in a folder. */
struct model_list *model_list_new(const char *spec);
void model_list_free(struct model_list *l);
int model_list_count(const struct model_list *l);
const char *model_list_path(const struct model_list *l, int index);
/* The index of path, or -1. */
int model_list_find(const struct model_list *l, const char *path);
/* The same spec read again: files that were there keep their standing
 * (one that did not load stays passed over unless it changed); a file
 * that appeared is taken only when arrived() says it was completely
 * written (closed or moved in), so no half-copied model is loaded. The
 * file that arrived or changed last is returned through *fresh (an
 * index into the new list), or -1. NULL: keep the old list. */
struct model_list *model_list_rescan(const struct model_list *old, const char *spec,
				     bool (*arrived)(void *ctx, const char *path), void *ctx,
				     int *fresh);

/* try loads one model: 0, or a negative errno after logging its one line. */
typedef int (*model_try_fn)(void *ctx, const char *path);
/* From index from, in steps of step (+1 or -1), the first model that
 * loads: its index. Reaching shown (the model on screen; -1: none) ends
 * the walk there, with nothing loaded: every other one failed. -1 when
 * nothing loaded. A model that failed is marked and passed over without a
 * word the next time, until its file changes. */
int model_list_pick(struct model_list *l, int from, int step, int shown, model_try_fn try_load,
		    void *ctx);
/* Mark index as failed (as model_list_pick does), or as loading again. */
void model_list_set_bad(struct model_list *l, int index, bool bad);
bool model_list_bad(const struct model_list *l, int index);

#endif
