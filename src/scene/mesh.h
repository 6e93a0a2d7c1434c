/* The one plain data model every consumer reads (as cgltf has one): a
 * single indexed triangle list in model space, already centred on the
 * origin and scaled to fit the unit sphere. */
#ifndef MK_MESH_H
#define MK_MESH_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* image.h has no C++ guard of its own; the glTF shim decodes textures. */
#include "util/image.h"

/* What the model's glTF material says about the optional shading features
 * (src/scene/material.c decides which a scene uses). Its textures are decoded
 * only for a feature the scene asked for; an image left out has width 0. */
struct mesh_material {
	bool present;	     /* the model names a material */
	float base_color[3]; /* pbrMetallicRoughness.baseColorFactor */
	/* KHR_materials_iridescence */
	bool iridescence;
	float iridescence_factor, iridescence_ior;
	float thickness_min, thickness_max; /* nanometres */
	/* Which textures the material names, decoded or not. */
	bool has_normal_map, has_occlusion_map, has_thickness_map;
	float normal_scale, occlusion_strength;
	struct image normal_map;    /* normalTexture: tangent-space xyz in rgb */
	struct image occlusion_map; /* occlusionTexture: ambient occlusion in r */
	struct image thickness_map; /* iridescenceThicknessTexture: thickness in g */
	/* pbrMetallicRoughness.baseColorTexture of the model's material, as
	 * stored (sRGB encoded: the shader decodes it), and its
	 * KHR_texture_transform as uv' = (m[0] u + m[2] v + m[4], m[1] u +
	 * m[3] v + m[5]). Its UVs are the mesh's uvs. */
	bool has_base_map;
	bool has_colors; /* the loader gave the mesh colors (kept when they are cached) */
	/* Every vertex's colour (as struct mesh colors) when has_colors and
	 * the mesh has no colour array: a model of one colour. */
	float color[4];
	/* How many images the loader decoded for it: only those a scene asked
	 * for and can place (the tests count them). */
	unsigned images_decoded;
	struct image base_map;
	float base_transform[6];
};

struct mesh {
	uint32_t vertex_count;
	uint32_t index_count; /* three per triangle */
	float *positions;     /* xyz per vertex */
	float *normals;	      /* xyz per vertex, unit length */
	float *uvs;	      /* uv per vertex, NULL when the model has none */
	/* xyz w per vertex: a unit tangent along +u, w = +1 or -1 the
	 * handedness, so that the bitangent is cross(normal, tangent) * w (the
	 * glTF convention). NULL unless the model or a feature provides it. */
	float *tangents;
	/* rgba per vertex, linear: rgb = the primitive's baseColorFactor x
	 * COLOR_0, a = 1 where the primitive reads the material's base map
	 * (mesh_material.base_map), else 0. NULL when the loader was not asked
	 * for base colour, the model has none, or every vertex has the same
	 * (then mesh_material.color holds it). */
	float *colors;
	uint32_t *indices;
	struct mesh_material material;
};

int mesh_alloc(struct mesh *m, uint32_t vertex_count, uint32_t index_count, bool with_uvs);
/* Adds (uninitialised) tangent storage to an allocated mesh. */
int mesh_alloc_tangents(struct mesh *m);
/* Adds (uninitialised) colour storage to an allocated mesh. */
int mesh_alloc_colors(struct mesh *m);
/* Frees the arrays and the material's images. */
void mesh_release(struct mesh *m);
/* The material with every field at the glTF default and no image. */
void mesh_material_default(struct mesh_material *mat);

/* rep[i] = the lowest-numbered vertex with exactly the position of vertex
 * i (by value, so -0.0 and 0.0 are one): seams and poles split vertices
 * that must still move, and shade, as one. */
int mesh_weld(const float *positions, uint32_t count, uint32_t *rep);

/* Centre world-space positions (computed in double, so a model placed far
 * from the origin or at an extreme scale keeps its precision) and scale
 * them into the unit sphere. A degenerate extent leaves the scale at 1. */
void mesh_fit_positions(const double *world, uint32_t count, float *out);

/* Area-weighted smooth normals for the triangles idx[0..index_count) over
 * vertices [first, first + count): vertices at the same position share one
 * normal, so split UV seams shade smoothly. Degenerate areas get +Z. */
int mesh_generate_normals(const float *positions, const uint32_t *idx, uint32_t index_count,
			  uint32_t first, uint32_t count, float *normals);

/* The built-in models, already in the unit sphere. */
int mesh_torus_knot(struct mesh *m, int tubular, int radial);
int mesh_uv_sphere(struct mesh *m, int slices, int stacks);

#ifdef __cplusplus
}
#endif

#endif
