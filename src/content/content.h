/* What the kiosk shows, loaded from the settings: the mesh, the matcaps
 * and the first matcap decoded. The start and a reload (SIGHUP) both build
 * complete new content here; a reload swaps it in only once every part of
 * it loaded and uploaded, so a broken model or folder keeps the old one. */
#ifndef MK_CONTENT_H
#define MK_CONTENT_H

#include "config/content_config.h"
#include "util/image.h"
#include "content/matcap_set.h"
#include "render/background.h"
#include "scene/mesh/material.h"
#include "scene/anim/anim_play.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/mesh_cache.h"
#include "render/render.h"
#include "render/shading.h"

#include <stdbool.h>

struct content;
struct content_refine; /* content_coarse.c: a coarse picture's full level of detail, to come */

/* How a content that plays is posed a frame (src/content/content_deform.c):
 * chosen once a model, at upload (content_play_upload, which says which
 * and why in the journal), so that the frame calls pose and nothing else
 * asks which path it is on. */
struct content_deform_ops {
	const char *name;
	/* The pose to the renderer: its vertices, or its bones and morph
	 * weights, as the upload set the mesh up for. */
	void (*pose)(struct content *s, struct renderer *r, const struct anim_pose *pose);
};

/* Every vertex posed on the CPU (anim_play_pose) and its arrays replaced. */
extern const struct content_deform_ops content_deform_cpu;
/* Bones (one palette, or one a draw once cut) and the morph targets'
 * weights to the vertex shader: a few uniforms a frame. */
extern const struct content_deform_ops content_deform_gpu;
/* Bones in the vertex shader, the morph targets that do not fit it moved
 * on the CPU (the arrays replaced a frame), in the mesh's order or a
 * split's. */
extern const struct content_deform_ops content_deform_gpu_cpu_morphs;
extern const struct content_deform_ops content_deform_gpu_split_cpu_morphs;

/* The settings' text a content's matcaps and background came from
 * ([scene] matcap, matcap_first, [display] background; NULL: the
 * default): another model's that differs is decoded with it. */
struct content_look {
	char *matcap, *matcap_first, *background;
};

/* content.own_look: what of a model's content is its own, to be shown
 * with it in place of the one on screen. */
enum { CONTENT_OWN_MATCAP = 1u << 0, CONTENT_OWN_BACKGROUND = 1u << 1 };

/* The hotspots a content draws: every one a model's settings may hold. */
#define CONTENT_HOTSPOTS RENDER_HOTSPOTS
_Static_assert(HOTSPOTS <= CONTENT_HOTSPOTS, "every hotspot drawn");
/* Hotspot i's text picture is stop_caption[CONTENT_HOTSPOT_CAPTION + i]. */
#define CONTENT_HOTSPOT_CAPTION FRAME_STOPS
_Static_assert(FRAME_STOPS + HOTSPOTS <= CAPTION_STOPS, "a picture for every hotspot");

struct content {
	char *model_path; /* the file the mesh came from; NULL: the built-in knot */
	/* The mesh as loaded and prepared; once prepared for the cache
	 * (packed, then cached), a shell: its counts and material, no array. */
	struct mesh mesh;
	struct mesh_cache_entry *cached;  /* the prepared mesh, mapped; or NULL */
	struct mesh_packed packed;	  /* the prepared mesh, packed, until stored */
	struct mesh_cache_writer *writer; /* storing it; NULL: none */
	struct mesh_cache_key cache_key;
	bool cacheable;		  /* the key is known and the cache directory named */
	struct image matcap;	  /* the first one shown */
	struct matcap_set *set;	  /* NULL: the built-in clay only */
	char *matcap_path;	  /* the file or folder set came from; NULL with set */
	char *matcap_first;	  /* where set's cycle starts (a rescan too); NULL: the first */
	struct material material; /* the optional features ([material]) */
	struct background_spec background; /* its path is NULL once decoded */
	struct image background_image;	   /* decoded once, when it is an image */
	double zoom; /* the fit (render/framing.h) on the display prepared for; 0: none */
	/* The outline's centre at the start view (NDC at zoom 1) and the
	 * room's the fit puts it at: the frame less the caption's box. */
	double outline[2], room[2];
	/* The caption's picture (scene/caption.h), this model's; empty: none.
	 * Kept after the upload: the overlay plane is filled from it. */
	struct image caption;
	/* The picture of each of [frame] stops' texts, in the caption's
	 * style; empty: a stop without text (the caption is shown). */
	struct image stop_caption[CAPTION_STOPS];
	/* The same of each other language of [caption] languages, drawn
	 * with these: language lang_shown's are the two above (its slot
	 * here is empty), so a switch swaps pictures and draws none. */
	struct content_lang {
		struct image caption, stop[CAPTION_STOPS];
	} lang_spare[LANG_MAX];
	int lang_shown, lang_count; /* lang_count 0: no languages named */
	int caption_frame[2];	    /* the frame the pictures were laid out in; 0: none yet */
	struct caption_config caption_place; /* its position, padding, drift; no strings */
	/* Its hotspots as the renderer draws them (content_hotspot.c). */
	struct render_hotspot hotspots[CONTENT_HOTSPOTS];
	int hotspot_source[CONTENT_HOTSPOTS]; /* each one's index in the settings' set */
	/* The file's node each follows (node = NAME), -1: a point; a model
	 * that plays moves it each frame (content_hotspots_follow). */
	int hotspot_node[CONTENT_HOTSPOTS];
	int hotspot_count;
	/* The drawn hotspot each stop's picture labels (-1: none): a stop's
	 * hotspot=NAME, and next-hotspot's views after FRAME_STOPS. */
	int stop_hotspot[CAPTION_STOPS];
	/* The model's settings: the caller's with its NAME.ini over them
	 * (config/model_settings.h); NULL: the caller's (the built-in knot). */
	struct content_config *own;
	/* What live playback needs beside the mesh (scene/anim_play.h); NULL:
	 * a still. Its mesh keeps its arrays (the poses write them; the
	 * cache's entry holds a float32 copy, and the play's data in a
	 * section of its own: scene/mesh_cache_anim.h) and has no level of
	 * detail: the poses write its vertices by number, and a simplified
	 * skin would need its joints and weights carried through each
	 * collapse. */
	struct anim_play *play;
	void *play_bytes; /* the play's data for the cache entry, until stored */
	size_t play_size;
	/* How it is posed a frame, set by content_play_upload; NULL: not
	 * uploaded to play. */
	const struct content_deform_ops *play_ops;
	/* Its palette cut into draws (more bones than one holds); NULL: one. */
	struct anim_play_split *play_split;
	struct content_look look; /* what matcaps and background came from */
	unsigned own_look;	  /* CONTENT_OWN_*: set by content_load_model */
	/* A large model prepared from scratch for the live kiosk: mesh is a
	 * coarse stand-in (coarse), and refine holds the whole mesh until a
	 * job prepares it (content_refine_take) and the loop swaps it in
	 * (content_refine_swap). began_ns: when its load began (the
	 * journal's times). */
	struct content_refine *refine;
	bool coarse;
	uint64_t began_ns;
};

/* strict: every file the settings name must load (a one-shot render is
 * useless with a substitute, and a reload keeps the old scene instead).
 * Otherwise a model or matcap that fails is replaced by the built-in one,
 * and the journal says so. On failure s is left empty. */
int content_load(struct content *s, const struct content_config *c, bool strict);
void content_release(struct content *s);
/* Fit the mesh to the display it will be drawn on: subdivided for a
 * displacement map at this display's density, then simplified to no more
 * triangles than the display shows (a displaced mesh is only reordered).
 * The start and a reload do the same, so a reload shows what a restart
 * would. */
int content_prepare(struct content *s, const struct content_config *c, int width, int height);
/* Hand the mesh, the background and the first matcap to the renderer;
 * the matcap's and the background's decoded images are then given back
 * (left empty), so a second upload of s is content_upload_model's. */
int content_upload(struct content *s, struct renderer *r);
/* Another model of a folder or list, for a worker thread: the model of
 * path, loaded strictly and prepared for a width x height display, with
 * no GL call; with its matcaps and background only where they differ
 * from shown's (its NAME.ini names its own, or the model on screen had
 * its own and this one goes back to c's): s->own_look says which. On
 * failure s is left empty. */
int content_load_model(struct content *s, const struct content_config *c, const char *path,
		       const struct content_look *shown, int width, int height);
/* The model of fresh (from content_load_model) into shown, whose own
 * model goes to old (for content_release, where waiting for its cache
 * write costs nothing: the worker); shown keeps its matcaps and
 * background unless fresh brought its own (own_look, left set: the
 * caller uploads them with content_upload_look). fresh is left empty. */
void content_take_model(struct content *shown, struct content *fresh, struct content *old);
/* On the worker: s's matcaps and background from c where they differ
 * from shown's (content_load_model); a file that fails is replaced by
 * the default, and the journal says so. 0 or -ENOMEM. */
int content_load_look(struct content *s, const struct content_config *c,
		      const struct content_look *shown);
/* The look's text of c, copied into l (released first). 0 or -ENOMEM. */
int content_look_set(struct content_look *l, const struct content_config *c);
int content_look_copy(struct content_look *to, const struct content_look *from);
void content_look_release(struct content_look *l);
/* Hand s's own matcap and background (own_look) to the renderer; their
 * images are given back. */
int content_upload_look(struct content *s, struct renderer *r);
/* Open the matcaps c names (c's default folder when none); strict: a
 * named one that fails fails, else the built-in clay replaces it. */
int content_load_matcap(const struct content_config *c, bool strict, struct content *s);
/* src/content/content_cache.c, for content.c: the entry of path with
 * c's settings into s (0), else a miss (s->cacheable: one can be
 * written); whether it was prepared for this display; the prepared mesh
 * packed for the cache; stored once uploaded; read back when a shell is
 * uploaded again. */
int content_cache_lookup(struct content *s, const struct content_config *c, const char *path,
			 const void *data, size_t size);
bool content_cache_fits(const struct content *s, int width, int height);
void content_cache_pack(struct content *s, int width, int height);
void content_cache_store(struct content *s);
int content_cache_reopen(struct content *s);
/* src/content/content_coarse.c: the live kiosk's first picture of a large
 * model before its level of detail (config: coarse_first and [kiosk]
 * coarse_above). content_coarse_begin, from content_prepare once the fit
 * is known, on the full mesh: its mesh becomes the coarse stand-in and
 * s->refine the rest of the preparation; 1 when it did, 0 when the model
 * is prepared whole as before (a still, small, animated, displaced, with
 * variants), or a negative errno. */
int content_coarse_begin(struct content *s, const struct content_config *o, double pixels,
			 int width, int height);
/* On the worker, once s's captions are fitted (content_fit_captions): s's
 * fit (content_frame) over its whole mesh, not the coarse cut's outline. */
void content_coarse_frame(struct content *s, const struct content_config *o, int width, int height);
/* The refine of s, taken for a job (s->refine left NULL, s still shown
 * coarse); the journal says when the coarse picture came. */
struct content_refine *content_refine_take(struct content *s);
/* On the worker: the level of detail and the packing of f's mesh; then
 * it is prepared (a refine put back, to swap in without a job). */
void content_refine_run(struct content_refine *f);
bool content_refine_prepared(const struct content_refine *f);
/* On the loop: f's mesh to the renderer in place of shown's coarse one
 * (the fit stays: it was of the whole mesh), and its cache entry written;
 * old gets what is to be released (the coarse mesh, or f when it does not
 * fit on the GPU: the coarse one stays). */
int content_refine_swap(struct content *shown, struct content_refine *f, struct renderer *r,
			struct content *old);
void content_refine_free(struct content_refine *f);
/* s's model as the journal names it: its path, or "the built-in knot". */
const char *content_name(const struct content *s);
/* src/content/content_play.c: the material's preparation (a
 * displacement's subdivision, generated tangents) may give the mesh other
 * vertices than those the poses write, or tangents a feature reads (they
 * are not posed): then it shows its first pose and the journal says so.
 * Tangents no feature reads are dropped. */
void content_play_check(struct content *s);
/* The mesh of a content that plays, to the renderer: skinned on the GPU
 * where its bones fit the GPU's palette or each draw's, once cut into
 * draws that fit, else posed on the CPU (the journal says which, and
 * why). content_play_release: what playback holds, given back. */
void content_play_release(struct content *s);
int content_play_upload(struct content *s, struct renderer *r);
/* Hand the mesh alone (and its material) to the renderer. The glTF's
 * decoded maps (mesh.materials' images, copied into material) are given
 * back once on the GPU; the material's own images and the mesh stay, so
 * a failed swap can put this content back. */
int content_upload_model(struct content *s, struct renderer *r);
/* The camera and panel the settings ask for, at the start view ([frame]
 * up and orientation, then its or [scene]'s yaw and pitch), with the
 * clear colour of the background. Its zoom is not set. */
/* KHR_materials_variants: the index of the model's variant `name`, or -1
 * (none named, or the model lacks it); the model's names quoted and
 * comma-separated into buf ("none" without), and how many. */
int content_variant_find(const struct content *s, const char *name);
int content_variant_names(const struct mesh *m, char *buf, size_t n);
struct view content_view(const struct content_config *c);
/* [scene] fit in a width x height frame less s's caption (content_fit.c):
 * s's zoom, outline and room. */
void content_frame(struct content *s, const struct content_config *o, int width, int height);
/* The outline's centre and the room's of s into v (render_matrices
 * shifts the one to the other). */
void content_place_view(const struct content *s, struct view *v);
/* Draw s's caption and its stops' pictures (content_caption.c), c's
 * [caption] and [frame] stops. A picture that fails is left out (the
 * journal says why), unless strict. */
int content_load_captions(struct content *s, const struct content_config *c, bool strict);
void content_release_captions(struct content *s);
/* The pictures laid out again for a width x height panel (turned by c's
 * rotation): wrapped to its width, cut with an ellipsis; the journal
 * says what was cut, once a picture. Once a frame: the same again draws
 * nothing. */
void content_fit_captions(struct content *s, const struct content_config *c, int width, int height);
/* The picture shown at stop (the app state's; -1: none): the stop's, else
 * the caption (empty: nothing), in the language shown. Its width and
 * height are the caption's box on screen (padding inside it included,
 * the margin outside not), its text wrapped to the frame once
 * content_fit_captions knew the frame: what a fit leaves room for. */
/* s's hotspots from c's [hotspot.NAME] sections, in the mesh's unit
 * sphere (content_hotspot.c); on the worker, after the mesh. */
void content_load_hotspots(struct content *s, const struct content_config *c);
/* A playing model's node hotspots moved to the pose just drawn (its
 * play's node worlds, after play_ops->pose) and handed to r: a few
 * matrix reads, no allocation, on the loop thread. */
void content_hotspots_follow(struct content *s, struct renderer *r);
/* Each hotspot's text as the caption would show it, drawn here on the
 * worker in each language drawn (stop_caption[CONTENT_HOTSPOT_CAPTION + i]
 * and each lang_spare's): a language switch swaps them with the rest. */
void content_load_hotspot_captions(struct content *s, const struct content_config *c);
/* The codes of c's [caption] languages; their count, 0: none named
 * (content_caption.c). */
int content_languages(const struct content_config *c, char codes[LANG_MAX][LANG_CODE_MAX]);
/* Language l's stop and hotspot pictures: the shown slots for the
 * language shown, else its spare ones. */
struct image *content_stop_slots(struct content *s, int l);
/* The offscreen still of the settings' hotspot number (1, 2, ...): v
 * turned to face it (rest: the model's base turn), its text shown
 * (renderer_show_stop). -EINVAL after logging when s has no such hotspot. */
int content_show_hotspot(const struct content *s, const struct content_config *c, int number,
			 struct renderer *r, struct view *v);
/* The badge a tap at (fx, fy) (fractions of the turned screen) is on,
 * as gesture.badge says it: 1 + the settings' hotspot index; 0: none. */
int content_hotspot_tapped(const struct content *s, const struct renderer *r, const struct view *v,
			   int width, int height, double fx, double fy);
/* Which of s's drawn hotspots is the settings' hotspot index; -1: none
 * (a node's, not drawn). */
int content_hotspot_drawn(const struct content *s, int index);
/* The app's yaw and pitch (radians) that turn the settings' hotspot
 * index to face the visitor, the model's base turn rest; false: s does
 * not draw it. */
bool content_hotspot_facing(const struct content *s, int index, struct quat rest, double *yaw,
			    double *pitch);
/* content_app_frame, and each stop that names a hotspot turned to face
 * it (its yaw and pitch replaced): the frame the app state is given. */
void content_app_frame_at(const struct content *s, const struct content_config *c,
			  struct app_frame *f, struct quat *rest);
const struct image *content_caption(const struct content *s, int stop);
/* Show language lang's pictures (an index of [caption] languages, out of
 * range: the first), and give them to the renderer: on the loop thread,
 * an upload of pictures already drawn. 0, or a negative errno after the
 * journal said so (the renderer then keeps the textures it could not
 * replace). */
int content_show_language(struct content *s, struct renderer *r, int lang);
/* The settings s's model is shown with: its own, else c. */
const struct content_config *content_settings(const struct content *s,
					      const struct content_config *c);
/* c's [frame] for the app state (state/view.h): the start view, limits,
 * stops, and the model's own turn. A [frame] that does not hold together
 * (refused when read) frames nothing. */
void content_app_frame(const struct content_config *c, struct app_frame *f, struct quat *rest);
/* Parse c's background and decode its image into spec and img (left
 * empty for a colour or a gradient). strict: a background that does not
 * load fails; otherwise it is replaced by the default, and the journal
 * says so. */
int content_load_background(const struct content_config *c, bool strict,
			    struct background_spec *spec, struct image *img);
/* The matcap folder was changed: open the set again. Returns 0 and
 * replaces s->set, or a negative errno (after logging) and keeps it. */
int content_rescan_matcaps(struct content *s);
/* The matcaps shown when none is named: the installed folder, else
 * ./matcaps (the source tree); NULL: none (the built-in clay). */
const char *content_default_matcaps(void);

#endif
