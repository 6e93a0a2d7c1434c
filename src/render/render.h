/* The GLES2 renderer: knows shading, nothing of where the pixels go. */
#ifndef MK_RENDER_H
#define MK_RENDER_H

#include "render/background.h"
#include "scene/text/caption.h"
#include "render/gl.h"
#include "render/hotspot_gl.h"
#include "util/image.h"
#include "scene/mesh/material.h"
#include "util/math3d.h"
#include "scene/mesh/mesh.h"
#include "scene/mesh/mesh_pack.h"
#include "render/shading.h"
#include "render/wall.h"

#include <stdbool.h>

struct view {
	struct quat orientation; /* of the model */
	bool ortho;		 /* orthographic: the unit sphere fills the short side */
	int rotation;		 /* of the panel: 0, 90, 180 or 270 degrees */
	float zoom;		 /* the picture's scale about its centre; 0 or 1: as fitted */
	/* The model's outline's centre at the start view, in NDC at zoom 1,
	 * put at room (the centre of the frame less the caption's box): the
	 * picture is shifted so (render/framing.h). Both 0: not shifted. */
	float outline[2], room[2];
	float background[3];   /* the clear colour, without renderer_set_background */
	bool plain_background; /* that colour alone, even with renderer_set_background's */
	/* [wall]: the camera frames the whole wall, this frame shows its
	 * slice (render/wall.h). Zeroed: no wall. */
	struct wall_layout wall;
};

struct renderer;

struct renderer *renderer_new(const struct gl *gl, const char *shader_dir);
void renderer_free(struct renderer *r);

/* The scene's optional features: their textures are uploaded and their
 * programs compiled; a feature that is off adds nothing. Call it before
 * renderer_set_mesh, which uploads only the attributes these features
 * read. Without it the renderer draws the plain matcap. */
int renderer_set_material(struct renderer *r, const struct material *m);
int renderer_set_mesh(struct renderer *r, const struct mesh *m);
/* A mesh whose poses replace its positions and normals (live playback,
 * scene/anim_play.h): float32 arrays, whatever the vertex format set. */
int renderer_set_mesh_live(struct renderer *r, const struct mesh *m);
/* The live mesh's positions and normals (xyz per vertex of the mesh set)
 * from now on; nothing for a mesh not set live. */
void renderer_set_vertices(struct renderer *r, const float *positions, const float *normals);
/* A mesh skinned on the GPU: its positions and normals the parts' own
 * (scene/anim_play.h), each vertex's four bones (indices as floats) and
 * weights, a palette of `bones` (no more than renderer_bone_palette):
 * programs that skin are built for it. Float32 arrays, replaced where its
 * morph targets move them (renderer_set_vertices). */
struct skin_palettes {
	uint32_t total; /* the bones renderer_set_bones sets */
	uint32_t range_count;
	const uint32_t *first, *count; /* per range of the mesh, into bones */
	const uint16_t *bones;	       /* each range's palette, numbers among total */
};
/* split: the palette cut into draws (scene/anim_play.h anim_play_split):
 * each of m's ranges draws with its own bones, `bones` the largest
 * draw's; NULL: one palette of `bones` for every draw. */
/* morphs: the morph targets added in the vertex shader before the skin
 * (targets of no more than renderer_morph_room's attributes): deltas of
 * xyz per vertex of m, `targets` arrays of positions, then as many of
 * normals where normals; NULL: none (programs without MORPH_TARGETS). */
struct skin_morphs {
	uint32_t targets;
	bool normals;
	const float *deltas;
};
int renderer_set_mesh_skinned(struct renderer *r, const struct mesh *m, const float *joints,
			      const float *weights, uint32_t bones,
			      const struct skin_palettes *split, const struct skin_morphs *morphs);
/* The morph targets' weights from now on (8 floats, those past the
 * mesh's targets unread). */
void renderer_set_morph_weights(struct renderer *r, const float *weights);
/* The vertex attributes (GL_MAX_VERTEX_ATTRIBS, or fewer as set by
 * renderer_set_attribute_limit: the tests and the bench; 0: the GPU's)
 * that a skinned model's program leaves for morph targets: less the
 * mesh's arrays its material reads and the skin's bones and weights. */
uint32_t renderer_morph_room(const struct renderer *r);
void renderer_set_attribute_limit(struct renderer *r, uint32_t attributes);
/* The palette's rows from now on: 12 floats a bone (rows of 3x4), every
 * bone of a split's total. */
void renderer_set_bones(struct renderer *r, const float *rows);
/* Which mesh is set, 1, 2, ... (a new one each set): a player knows its
 * model's arrays are the ones on the GPU. */
unsigned renderer_mesh_serial(const struct renderer *r);
/* The bones a palette holds on this GPU (from GL_MAX_VERTEX_UNIFORM_VECTORS),
 * or fewer as set (0: every model skins on the CPU; the bench and tests). */
uint32_t renderer_bone_palette(const struct renderer *r);
void renderer_set_bone_limit(struct renderer *r, uint32_t bones);
/* The same from arrays already in the GPU's format (a mapped cache entry),
 * uploaded as they are; m may be unmapped once it returns. */
int renderer_set_packed(struct renderer *r, const struct mesh_packed *m);

/* What is drawn behind the model from now on (img: s's image, decoded;
 * uploaded here, once). Returns 0, or a negative errno after logging, and
 * then the one before stays. */
int renderer_set_background(struct renderer *r, const struct background_spec *s,
			    const struct image *img);

/* The caption drawn over every frame from now on (img: its picture from
 * caption_render, uploaded here once; NULL or empty: none). Returns 0, or
 * a negative errno after logging, and then the one before stays. */
int renderer_set_caption(struct renderer *r, const struct image *img,
			 const struct caption_config *c);
/* The pictures of [frame] stops' texts (imgs[i]: stop i's; empty: that
 * stop shows the caption), uploaded here once, as renderer_set_caption's.
 * Returns 0, or -EINVAL after logging (the old ones kept). */
int renderer_set_stop_captions(struct renderer *r, const struct image *imgs, int count,
			       const struct caption_config *c);
/* Which picture the caption calls below use from now on: stop's (the app
 * state's stop; -1: none) where it has one, else the caption. Picking is
 * all the loop thread does: every picture is uploaded already. */
void renderer_show_stop(struct renderer *r, int stop);

/* The hotspots drawn over the model from now on (count 0: none), their
 * points in the mesh's unit sphere; stop_hotspot (CAPTION_STOPS of them,
 * or NULL): the hotspot each stop's picture labels, drawn beside its
 * badge (-1: in the caption's place). Returns 0, or -EINVAL after
 * logging (none drawn). */
int renderer_set_hotspots(struct renderer *r, const struct render_hotspot *hs, int count,
			  const int *stop_hotspot);
/* Where hotspot i is drawn on a width x height frame of view v; false:
 * there is no hotspot i. */
bool renderer_hotspot_at(const struct renderer *r, const struct view *v, int width, int height,
			 int i, struct hotspot_place *out);
/* The drawn hotspot whose badge a touch at (fx, fy) (fractions of the
 * turned screen) is on, the nearest; -1: none. A badge another part of
 * the model hides (the GPU's depth) still answers. */
int renderer_hotspot_hit(const struct renderer *r, const struct view *v, int width, int height,
			 double fx, double fy);

/* KHR_materials_variants: draw the mesh's ranges with variant `variant`'s
 * materials (-1, or one the mesh lacks: the file's default ones). Every
 * material was uploaded with the mesh: this changes the draw list only,
 * on the loop thread, no upload. Returns whether the picture changed. */
bool renderer_show_variant(struct renderer *r, int variant);
/* The variants of the mesh set (0: none, or a mesh drawn without them). */
int renderer_variant_count(const struct renderer *r);
/* Blend the caption over the frame, at seconds of its drift: call it last,
 * after the scene (and after any scaling of it: full resolution). */
void renderer_draw_caption(struct renderer *r, const struct view *v, double seconds, int width,
			   int height);
/* Where the caption's top-left corner is at seconds; false: no caption.
 * The loop redraws when it moved. */
bool renderer_caption_at(const struct renderer *r, const struct view *v, double seconds, int width,
			 int height, int out[2]);
/* Which caption picture is shown, 1, 2, ... (each picture set has its
 * own; a stop's too); 0: none.
 * An overlay plane is tested once per picture. */
unsigned renderer_caption_serial(const struct renderer *r);

/* How renderer_set_mesh stores the vertices (scene/mesh_pack.h); the
 * default: compact. */
void renderer_set_vertex_format(struct renderer *r, enum vertex_format format);
/* How the matcap is sampled where it is minified. AUTO, the default:
 * mipmapped while the model's disc on screen is no wider than the matcap,
 * where a pixel reads a texel or more and a thin part shimmers; linear
 * when the model is larger, where a mipmap would only blur the silhouette
 * (the normal turns fast there) and bleed SEM's rim. MIPMAP and LINEAR
 * force one, for the bench. Mipmaps need a power-of-two size in GLES2:
 * MIPMAP resamples another size to one, AUTO leaves it linear. */
enum matcap_filter { MATCAP_FILTER_AUTO, MATCAP_FILTER_MIPMAP, MATCAP_FILTER_LINEAR };
void renderer_set_matcap_filter(struct renderer *r, enum matcap_filter filter);
/* Whether filter reads the mipmaps of a matcap side texels wide (a power
 * of two) drawn in a width x height viewport: the renderer's choice. */
bool matcap_filter_mipmaps(enum matcap_filter filter, int side, int width, int height);
int renderer_set_matcap(struct renderer *r, const struct image *img);
/* Draw with tex (owned by the caller, e.g. the live camera's) as the
 * matcap; 0: back to the renderer's own image texture. */
void renderer_use_matcap_texture(struct renderer *r, GLuint tex);
/* highp: every float of the fragment stage highp where the GPU has it;
 * else mediump, with highp only for the values that need it
 * (shaders/mapping.glsl). The default is highp on a CPU rasteriser, where
 * it is faster, else mediump. Rebuilds the programs. */
int renderer_set_precision(struct renderer *r, bool highp);
/* Compiles the variant on first use; on failure the previous one stays. */
int renderer_set_mode(struct renderer *r, enum shading_mode mode, bool ortho);
void renderer_draw(struct renderer *r, const struct view *v, int width, int height);

/* What the renderer holds now, for tests and the bench. */
struct renderer_stats {
	int attributes;			  /* vertex arrays uploaded and enabled when drawing */
	long vertex_bytes;		  /* their size in GPU memory */
	int textures;			  /* bound when drawing: the matcap, detail map, ramp */
	GLuint program;			  /* the matcap program (0: none), or the lit one alone */
	GLuint lit_program;		  /* when lit = beside, the second one; else 0 */
	bool highp;			  /* every float highp (renderer_set_precision) */
	enum matcap_filter matcap_filter; /* renderer_set_matcap_filter */
	bool matcap_mipmapped;		  /* the last frame read the matcap's mipmaps */
	enum vertex_format format;	  /* of the arrays uploaded */
	uint32_t draws;			  /* draw calls a frame makes (per half, lit = beside) */
	/* The programs the draws use (the matcap's, or the lit one alone), the
	 * first few in draw order, each with the surface it first draws. */
	uint32_t program_count;
	struct {
		GLuint program;
		uint32_t surface;
	} drawn[4];
};
void renderer_get_stats(const struct renderer *r, struct renderer_stats *out);

/* The model-view and projection matrices the renderer uses (for tests). */
void render_matrices(const struct view *v, int width, int height, float modelview[16],
		     float projection[16]);

#endif
