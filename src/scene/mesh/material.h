/* The optional shading features of a scene: an
 * iridescent hue layer, a packed detail map, displacement and a lit mode.
 * Which are on, and with what, comes from [material] in kiosk.ini and from
 * the model's glTF material. A feature that is off costs nothing: no code
 * in the compiled program, no vertex attribute uploaded, no texture. */
#ifndef MK_MATERIAL_H
#define MK_MATERIAL_H

#include "util/image.h"
#include "scene/mesh/mesh.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

enum material_feature {
	MATERIAL_IRIDESCENCE = 1u << 0,	  /* hue from the view angle, over the matcap */
	MATERIAL_RAMP = 1u << 1,	  /* ... its colour from a 1-D ramp, not HSV */
	MATERIAL_DETAIL = 1u << 2,	  /* detail map: occlusion (b), hue shift (a) */
	MATERIAL_DETAIL_NORMAL = 1u << 3, /* ... and a tangent-space normal (rg) */
	MATERIAL_DISPLACEMENT = 1u << 4,  /* CPU only: subdivided and displaced */
	/* The matcap times the glTF base colour, as three.js's
	 * MeshMatcapMaterial: per vertex baseColorFactor x COLOR_0 ... */
	MATERIAL_BASE_COLOR = 1u << 5,
	MATERIAL_BASE_MAP = 1u << 6, /* ... x baseColorTexture */
	/* Light added in linear light: emissiveFactor x strength (u_emissive)
	 * ... x emissiveTexture. Per range (material_surface.features): the
	 * model's features say some material has it (its UVs uploaded); only
	 * the ranges whose material emits draw with a program that adds it. */
	MATERIAL_EMISSIVE = 1u << 7,
	MATERIAL_EMISSIVE_MAP = 1u << 11,
	/* KHR_materials_unlit: the base colour as it is, no matcap; per range
	 * as emission. */
	MATERIAL_UNLIT = 1u << 12,
	/* ... the emissive map placed by the mesh's second UVs (uv1): it
	 * reads another TEXCOORD_n than the base map. */
	MATERIAL_EMISSIVE_UV1 = 1u << 13,
};

/* What a range's own program variant adds (draw_variant_adds), never the
 * model's program: a model without them compiles as before. */
#define MATERIAL_PER_RANGE                                                                         \
	(MATERIAL_EMISSIVE | MATERIAL_EMISSIVE_MAP | MATERIAL_EMISSIVE_UV1 | MATERIAL_UNLIT)

/* Not settings: the renderer's program variants for a range's alphaMode
 * (shaders/matcap.frag), never in material.features. */
enum material_variant {
	MATERIAL_ALPHA_MASK = 1u << 8,	  /* discard below the cutoff */
	MATERIAL_ALPHA_BLEND = 1u << 9,	  /* alpha out, blended */
	MATERIAL_DOUBLE_SIDED = 1u << 10, /* a back face's normal turned */
};

enum material_switch { MATERIAL_AUTO, MATERIAL_OFF, MATERIAL_ON };
enum material_lit { LIT_OFF, LIT_ON, LIT_BESIDE };
/* [material] unlit: a KHR_materials_unlit material as the file says
 * (its base colour alone), or shaded by the matcap anyway. */
enum material_unlit { UNLIT_FILE, UNLIT_SHADE };

/* [material] in kiosk.ini (the table in src/config/options.c). A number left NaN
 * was not set: the glTF material, else the built-in default, decides. */
struct material_config {
	int iridescence; /* enum material_switch; auto: when the glTF has it */
	double hue_range, hue_average, hue_shift;
	double opacity, saturation, value;
	char *ramp; /* PNG/JPEG, read along its middle row */
	int detail; /* enum material_switch; auto: when a map is given */
	char *detail_map;
	char *height_map; /* displacement is on when it is set */
	double displacement_scale;
	double displacement_pixels;
	int displacement_triangles;
	int lit; /* enum material_lit */
	double shininess;
	int base_color; /* enum material_switch, auto or off ([model] base_color) */
	int unlit;	/* enum material_unlit */
};

/* What one mesh material (mesh.materials[k]) draws with: its ranges'
 * base map, how they blend and which faces they show, its own detail map
 * and its iridescence. */
struct material_surface {
	/* MATERIAL_DETAIL, MATERIAL_DETAIL_NORMAL and MATERIAL_IRIDESCENCE
	 * where this material has them: a range whose material lacks one of
	 * the model's (material.features) draws with a program without it. */
	unsigned features;
	/* Its normal and occlusion maps (and film thickness) packed as
	 * material.detail is; empty: the model's (the settings' detail_map),
	 * or none. */
	struct image detail;
	float hue_range, hue_average, hue_shift, opacity; /* its iridescence */
	struct image base_map;	 /* sRGB as stored; power-of-two sides; empty: none */
	float base_transform[6]; /* mesh_material.base_transform */
	int wrap[2];		 /* mesh_material.base_wrap */
	bool no_mipmaps;	 /* mesh_material.base_no_mipmaps */
	int alpha_mode;		 /* enum mesh_alpha; opaque when base colour is off */
	float alpha, alpha_cutoff;
	bool double_sided;
	/* Its emission (MATERIAL_EMISSIVE in features): linear, and its map
	 * (sRGB as stored, power-of-two sides) with its own transform and
	 * sampler, placed by the mesh's UVs. MATERIAL_UNLIT: shown unlit. */
	float emissive[3];
	struct image emissive_map;
	float emissive_transform[6];
	int emissive_wrap[2];
	bool emissive_no_mipmaps;
};

/* What the renderer reads: resolved, with every texture decoded. */
struct material {
	/* enum material_feature: the model's, every surface's together */
	unsigned features;
	int lit; /* enum material_lit */
	/* The first iridescent surface's numbers (its hue_*, opacity) */
	float hue_range, hue_average, hue_shift;
	float opacity, saturation, value;
	float base_color[3], shininess;
	float displacement_scale, displacement_pixels;
	uint32_t displacement_triangles;
	/* The settings' detail_map, over every part: rg normal xy, b
	 * occlusion, a hue shift; power-of-two sides. Empty: each surface
	 * has its own (or none). */
	struct image detail;
	struct image ramp;
	struct image height;
	float vertex_color[4]; /* mesh.vertex_color: every vertex's without a colour array */
	/* One per mesh material (one for a mesh without ranges): the
	 * renderer draws range r with surfaces[ranges[r].material]. */
	uint32_t surface_count;
	struct material_surface *surfaces;
};

void material_config_defaults(struct material_config *cfg);
void material_config_release(struct material_config *cfg);

/* Which of the model's glTF textures these settings can use (enum
 * gltf_texture bits), so that no other is decoded. */
unsigned material_gltf_textures(const struct material_config *cfg);

/* Settings plus the model's glTF materials (mesh->materials) into out, with
 * the named files decoded. strict: a file that fails is an error (one
 * line, naming it); otherwise its feature is left off and the journal
 * says so. Returns 0 or a negative errno. */
int material_load(struct material *out, const struct material_config *cfg, const struct mesh *mesh,
		  bool strict);
void material_release(struct material *m);

/* Give the mesh what the features need, once the screen's size is known:
 * subdivided and displaced to the screen's density, refitted to the unit
 * sphere, with tangents for a detail normal map. Returns 0 or -ENOMEM. */
int material_prepare_mesh(const struct material *m, struct mesh *mesh, int width, int height);

/* The features of `model` (enum material_feature) that surface s lacks:
 * what its ranges' program leaves out (a ramp goes with iridescence, a
 * detail normal with the detail map). */
static inline unsigned material_surface_missing(unsigned model, const struct material_surface *s)
{
	unsigned missing = 0;

	if ((model & MATERIAL_DETAIL) && !(s->features & MATERIAL_DETAIL))
		missing |= MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL;
	else if ((model & MATERIAL_DETAIL_NORMAL) && !(s->features & MATERIAL_DETAIL_NORMAL))
		missing |= MATERIAL_DETAIL_NORMAL;
	if ((model & MATERIAL_IRIDESCENCE) && !(s->features & MATERIAL_IRIDESCENCE))
		missing |= MATERIAL_IRIDESCENCE | MATERIAL_RAMP;
	return missing & model;
}

/* The vertex attributes a program with these features reads. */
bool material_needs_uvs(unsigned features);
bool material_needs_uv1(unsigned features);
bool material_needs_tangents(unsigned features);
bool material_needs_colors(unsigned features);

#endif
