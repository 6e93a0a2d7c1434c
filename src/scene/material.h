/* The optional shading features of a scene: an
 * iridescent hue layer, a packed detail map, displacement and a lit mode.
 * Which are on, and with what, comes from [material] in kiosk.ini and from
 * the model's glTF material. A feature that is off costs nothing: no code
 * in the compiled program, no vertex attribute uploaded, no texture. */
#ifndef MK_MATERIAL_H
#define MK_MATERIAL_H

#include "util/image.h"
#include "scene/mesh.h"

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
};

enum material_switch { MATERIAL_AUTO, MATERIAL_OFF, MATERIAL_ON };
enum material_lit { LIT_OFF, LIT_ON, LIT_BESIDE };

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
};

/* What the renderer reads: resolved, with every texture decoded. */
struct material {
	unsigned features; /* enum material_feature */
	int lit;	   /* enum material_lit */
	float hue_range, hue_average, hue_shift;
	float opacity, saturation, value;
	float base_color[3], shininess;
	float displacement_scale, displacement_pixels;
	uint32_t displacement_triangles;
	struct image detail; /* rg normal xy, b occlusion, a hue shift; power-of-two sides */
	struct image ramp;
	struct image height;
	struct image base_map;	 /* sRGB as stored; power-of-two sides */
	float base_transform[6]; /* mesh_material.base_transform */
	float vertex_color[4];	 /* mesh_material.color: every vertex's without a colour array */
};

void material_config_defaults(struct material_config *cfg);
void material_config_release(struct material_config *cfg);

/* Which of the model's glTF textures these settings can use (enum
 * gltf_texture bits), so that no other is decoded. */
unsigned material_gltf_textures(const struct material_config *cfg);

/* Settings plus the model's glTF material (mesh->material) into out, with
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

/* The vertex attributes a program with these features reads. */
bool material_needs_uvs(unsigned features);
bool material_needs_tangents(unsigned features);
bool material_needs_colors(unsigned features);

#endif
