/* Inside the renderer (render.c: state, uploads, programs; render_draw.c:
 * the draws of a frame): its state, shared by the two files only. */
#ifndef MK_RENDER_PRIV_H
#define MK_RENDER_PRIV_H

#include "render/background.h"
#include "render/caption.h"
#include "render/draw_list.h"
#include "render/gl.h"
#include "render/shader.h"
#include "render/shading.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh_pack.h"

enum { UNIT_MATCAP, UNIT_DETAIL, UNIT_RAMP, UNIT_BASE, UNIT_EMISSIVE };

/* The vertex shader's vectors besides the bone palette: the model-view
 * and projection (4 each), the normal matrix and the base and emissive
 * maps' transforms (3 each), and the morph targets' weights (2). */
#define RENDER_SKIN_RESERVED 19

/* A range's program variant (draw_item_variant): its alphaMode, its sides,
 * the model's features its material lacks, and its emission and unlit. */
enum { VARIANTS = DRAW_VARIANTS };

struct program {
	GLuint id;
	unsigned features; /* enum material_feature and material_variant bits */
	GLint modelview, projection, normal_matrix, matcap, detail, ramp, base_map, base_transform;
	GLint reads_base_map; /* u_reads_base_map: this draw's material has a base map */
	GLint iridescence, hsv, light, base_color, shininess, alpha;
	GLint emissive, emissive_map, emissive_transform; /* a range that emits */
	GLint bones;	     /* u_bones: a skinning program's palette; else -1 */
	GLint morph_weights; /* u_morph_weights: a program that morphs; else -1 */
};

/* Which material each range draws in each variant; defaults: the
 * ranges' own; colors: each material's vertex colour (rgba) where the
 * mesh's base colours are by material (mesh colors_by_material), or NULL. */
struct render_variants {
	uint32_t count, ranges, surfaces;
	uint32_t *materials; /* [variant * ranges + range] */
	uint32_t *defaults;
	float *colors;
};

struct renderer {
	const struct gl *gl;
	const char *shader_dir;
	/* [mode][ortho][lit][variant] */
	struct program programs[SHADING_MODE_COUNT][2][2][VARIANTS];
	struct program *current; /* the matcap program, or the lit one alone */
	struct program *beside;	 /* lit = beside: the lit program, drawn right */
	/* The variants of each, [0] the opaque one (current, beside). */
	struct program *variants[2][VARIANTS];
	enum shading_mode mode;
	bool ortho, mode_set;
	bool highp;	     /* every float highp (PRECISION_HIGHP): see renderer_new */
	struct material mat; /* the features and their numbers; no images, no surfaces */
	GLuint vbo[SHADER_ATTR_COUNT], ibo, matcap, detail, ramp;
	/* Per material (surfaces): its base map and its own detail map (0:
	 * none; detail: the model's, r->detail) and the rest. */
	uint32_t surface_count;
	GLuint *base_maps, *detail_maps, *emissive_maps;
	struct material_surface *surfaces; /* their images left empty */
	bool variant_used[VARIANTS];	   /* by some range */
	struct draw_list list;
	GLuint matcap_override; /* another's texture as the matcap (the camera's); 0: none */
	long attr_bytes[SHADER_ATTR_COUNT]; /* 0: not uploaded */
	GLenum index_type;
	enum vertex_format format;     /* for the next renderer_set_mesh */
	enum vertex_format drawn;      /* of the arrays uploaded */
	float position_scale;	       /* int16 positions: the model units of 1.0 */
	int matcap_filter;	       /* enum matcap_filter (render.h) */
	bool matcap_mippable;	       /* the image texture's size can have a chain */
	bool matcap_has_mips;	       /* it has its mipmap chain */
	int matcap_side;	       /* its shorter side, texels */
	bool matcap_mipmapped;	       /* its minifying filter now reads the chain */
	struct background *background; /* NULL: the view's clear colour */
	struct caption_gl *caption;    /* NULL: none */
	unsigned caption_serial;       /* its picture's; 0: none */
	/* The pictures of [frame] stops' texts; NULL: that stop shows the
	 * caption. */
	struct caption_gl *stop_caption[CAPTION_STOPS];
	unsigned stop_serial[CAPTION_STOPS];
	int stop;	  /* the stop shown (renderer_show_stop); -1: none */
	unsigned serials; /* the last picture's serial: each picture set has its own */
	/* A mesh that plays live (renderer_set_mesh_live): float32 arrays its
	 * poses replace; live_scratch: room for a pose gathered into chunks. */
	bool live, live_next;
	float *live_scratch;
	/* Skinned on the GPU (render_skin.c): the palette's bones (0: no
	 * skinning, today's programs), its rows (12 floats a bone), the
	 * bone limit (GL_MAX_VERTEX_UNIFORM_VECTORS' palette, or less for the
	 * bench), the bones' indices and weights arrays. */
	uint32_t bones, bones_next, bone_limit;
	unsigned mesh_serial; /* bumped with each mesh set */
	float *bone_rows;
	GLuint skin_vbo[2];
	/* A palette split into draws (renderer_set_palettes): the bones of
	 * all (bone_total rows in bone_rows), each range's palette in them,
	 * and the rows of the one drawn (bones of them at most). */
	uint32_t bone_total, range_count;
	uint32_t *palette_first, *palette_count;
	uint16_t *palette_bones;
	float *palette_rows;
	/* Morph targets on the GPU (render_morph.c): targets a vertex (0:
	 * none, programs without MORPH_TARGETS), whether they move normals,
	 * as set for the next mesh; their arrays one after another in
	 * morph_vbo (morph_array bytes each), each array's location, the
	 * weights set a frame; the attributes allowed (0: the GPU's). */
	uint32_t morph_targets, morph_next, attribute_limit;
	bool morph_normals, morph_normals_next;
	GLuint morph_vbo;
	size_t morph_array;
	GLuint morph_location[SHADER_MAX_ATTRIBUTES];
	float morph_weights[8];
	/* KHR_materials_variants (render_variant.c): the mesh's table (none:
	 * count 0), the next mesh's until it is set, and the variant shown
	 * (-1: the file's default materials). */
	struct render_variants looks, looks_next;
	int look;
	/* Hotspots (render_hotspot.c): drawn after the model, against its
	 * depth; the program built with the first set. */
	struct hotspot_gl *hotspot_gl;
	struct render_hotspot hotspots[RENDER_HOTSPOTS];
	int hotspot_count;
	/* The hotspot each stop's picture labels (-1: none): its text is
	 * drawn beside that badge. */
	int stop_hotspot[CAPTION_STOPS];
};

/* render_hotspot.c: the hotspots drawn over the model just drawn (its
 * depth bound). */
void render_draw_hotspots(struct renderer *r, const struct view *v, int width, int height);
/* Where a label of size (pixels) goes beside hotspot i on the turned
 * screen of a width x height frame: false while the hotspot is behind
 * the eye or edge-on. */
bool render_hotspot_label(const struct renderer *r, const struct view *v, int i, const int size[2],
			  int width, int height, int out[2]);
/* render.c: every program dropped (built again on use). */
void render_drop_programs(struct renderer *r);
/* render_skin.c: what the skinning holds, given back (renderer_free); the
 * palette of the mesh being set (bones_next, else none) in place, true
 * when it changed and the programs must be built again (the skinning
 * arrays disabled when none skins); a split's palettes copied (0 or
 * -ENOMEM); the skinning arrays bound from vertex `base`; the palette's
 * rows for a program that skins. */
void render_skin_free(struct renderer *r);
bool render_skin_set(struct renderer *r);
struct skin_palettes; /* render.h */
int render_skin_set_palettes(struct renderer *r, const struct skin_palettes *sp);
void render_skin_bind(const struct renderer *r, uint32_t base);
void render_skin_uniforms(const struct renderer *r, const struct program *p);
/* A split palette's: the rows of the range's bones, when it is another
 * range's palette than *shown (UINT32_MAX: none yet). */
void render_skin_palette(struct renderer *r, const struct program *p, uint32_t range,
			 uint32_t *shown);
/* render_morph.c: the morph targets of the mesh being set in place
 * (morph_next); false when they changed (the programs are built again);
 * a program's source for them; their arrays bound from vertex `base`;
 * their weights for a program; their buffer given back. */
bool render_morph_set(struct renderer *r);
void render_morph_source(const struct renderer *r, struct shader_source *src);
void render_morph_bind(const struct renderer *r, uint32_t base);
void render_morph_uniforms(const struct renderer *r, const struct program *p);
struct skin_morphs; /* render.h */
int render_morph_upload(struct renderer *r, const struct skin_morphs *m, uint32_t vertex_count);
void render_morph_free(struct renderer *r);
/* render_skin.c: a program that skins (r->bones), its palette, attributes
 * and morphs. */
void render_skin_source(const struct renderer *r, struct shader_source *src);
/* The matcap's minifying filter for a viewport (render.c). */
void render_matcap_choose_filter(struct renderer *r, const struct view *v, const int vp[4]);

/* render_variant.c: the mesh's variants taken for the next
 * renderer_set_packed (renderer_set_mesh: 0 or -ENOMEM); made current
 * there, every variant's programs marked used; all dropped; a surface's
 * colour where the colours are by material, else NULL. */
int render_variants_take(struct renderer *r, const struct mesh *m);
void render_variants_mark(struct renderer *r);
void render_variants_drop(struct renderer *r);
const float *render_variant_color(const struct renderer *r, uint32_t surface);

#endif
