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

/* glTF's alphaMode. */
enum mesh_alpha { MESH_ALPHA_OPAQUE, MESH_ALPHA_MASK, MESH_ALPHA_BLEND };
/* A sampler's wrapS or wrapT (glTF's default: repeat). */
enum mesh_wrap { MESH_WRAP_REPEAT, MESH_WRAP_CLAMP, MESH_WRAP_MIRROR };

/* What a glTF material says (src/scene/mesh/material.c decides what a scene
 * uses of it). Its textures are decoded only for a feature the scene asked
 * for; an image left out has width 0. struct mesh has one of these per
 * material its primitives use (materials[]); a question about the whole
 * model is asked of all of them (mesh_materials_any). */
struct mesh_material {
	bool present;	     /* the model names a material */
	float base_color[3]; /* pbrMetallicRoughness.baseColorFactor */
	float base_alpha;    /* ... its alpha */
	int alpha_mode;	     /* enum mesh_alpha */
	float alpha_cutoff;  /* MASK: drawn where alpha >= this (glTF default 0.5) */
	bool double_sided;   /* both faces drawn (no culling) */
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
	/* pbrMetallicRoughness.baseColorTexture of this material, as
	 * stored (sRGB encoded: the shader decodes it), and its
	 * KHR_texture_transform as uv' = (m[0] u + m[2] v + m[4], m[1] u +
	 * m[3] v + m[5]). Its UVs are the mesh's uvs. */
	bool has_base_map;
	/* How many images the loader decoded for it: only those a scene asked
	 * for and can place (the tests count them: mesh_images_decoded). */
	unsigned images_decoded;
	struct image base_map;
	float base_transform[6];
	int base_wrap[2];     /* its sampler's wrapS, wrapT: enum mesh_wrap */
	bool base_no_mipmaps; /* its sampler's minFilter reads one level */
	/* KHR_materials_unlit: the base colour is shown as it is, no matcap. */
	bool unlit;
	/* emissiveFactor x KHR_materials_emissive_strength, linear (0: none),
	 * and emissiveTexture (sRGB as stored, as the base map) with its own
	 * KHR_texture_transform and sampler. Its UVs are the mesh's uvs, or
	 * its uv1 when emissive_uv1 (the map reads another TEXCOORD_n than the
	 * base map: gltf_emissive_uv_set). */
	float emissive[3];
	bool has_emissive_map;
	bool emissive_uv1;
	struct image emissive_map;
	float emissive_transform[6];
	int emissive_wrap[2];
	bool emissive_no_mipmaps;
};

/* A part of the index array drawn with one material. center: the middle
 * of its bounding box in model space, by which blended parts are ordered
 * back to front. */
struct mesh_range {
	uint32_t first_index, index_count;
	uint32_t material; /* into mesh.materials */
	float center[3];
};

/* A named node of the file, for a hotspot that names it ([hotspot.NAME]
 * node = NAME): the first MESH_NODES named nodes, their names printable
 * UTF-8 of at most MESH_NODE_NAME - 1 bytes (others are left out, said
 * by the loader), so that a hotspot follows its node without the file. */
#define MESH_NODES     32
#define MESH_NODE_NAME 64
struct mesh_node {
	char name[MESH_NODE_NAME];
	/* Into the file's nodes: mesh_anim's and anim_play's worlds. */
	uint32_t index;
	/* Its world origin (its world matrix's translation) in the file's
	 * coordinates at the pose the mesh was baked at (rest, or --time). */
	double origin[3];
};

struct mesh {
	uint32_t vertex_count;
	uint32_t index_count; /* three per triangle */
	float *positions;     /* xyz per vertex */
	float *normals;	      /* xyz per vertex, unit length */
	float *uvs;	      /* uv per vertex, NULL when the model has none */
	/* A second uv per vertex, NULL unless an emissive map reads another
	 * set than its base map (mesh_material.emissive_uv1): only the models
	 * that need it carry it. */
	float *uv1;
	/* xyz w per vertex: a unit tangent along +u, w = +1 or -1 the
	 * handedness, so that the bitangent is cross(normal, tangent) * w (the
	 * glTF convention). NULL unless the model or a feature provides it. */
	float *tangents;
	/* rgba per vertex, linear: rgb = the primitive's baseColorFactor x
	 * COLOR_0, a = COLOR_0's alpha (1 where it has none): glTF multiplies
	 * the base colour's alpha by it. Whether a vertex reads a base map is
	 * its range's material's (a uniform per draw), not the array's. NULL
	 * when the loader was not asked for base colour, the model has none,
	 * or every vertex has the same (then vertex_color holds it). */
	float *colors;
	uint32_t *indices;
	/* The loader's fit: positions = (file's world - fit[0..2]) * fit[3],
	 * so that a point the curator gives in the file's coordinates (a
	 * hotspot) lands where the model is; fit[3] 0: unknown (the built-in
	 * models, made in the unit sphere). Kept in the cache's entry. */
	double fit[4];
	/* The loader gave the model colours of its own: colors, or
	 * vertex_color for every vertex (kept when they are cached). */
	bool has_colors;
	/* Every vertex's colour (as colors) when has_colors and colors is
	 * NULL: a model of one colour costs no array. */
	float vertex_color[4];
	/* Draw ranges: indices[first_index .. first_index + index_count)
	 * drawn with materials[material]. Together they cover every index
	 * once, in order. A model of one material has one range. */
	uint32_t range_count;
	struct mesh_range *ranges;
	/* Every material the ranges use, with its maps (decoded when asked
	 * for): base colour factor and texture, normal, occlusion and film
	 * thickness maps, iridescence, alpha, sides. */
	uint32_t material_count;
	struct mesh_material *materials;
	/* KHR_materials_variants: the file's variant names, and which
	 * material each range draws in each: variant v draws range r with
	 * materials[variant_materials[v * range_count + r]] (ranges[r].material
	 * is the file's default). Every material any variant uses is in
	 * materials[], decoded: a switch changes indices, it loads nothing.
	 * No variants: variant_count 0, both NULL. */
	uint32_t variant_count;
	uint32_t variant_ranges; /* the range_count the table was made for */
	char **variant_names;
	uint32_t *variant_materials;
	/* colors is NULL and each range's colour is its material's
	 * (mesh_material_vertex_color), set per draw: a variant's base colour
	 * factor changes with the variant, which vertex colours could not. */
	bool colors_by_material;
	/* flat[v] 1: the loader split vertex v's primitive at its faces for
	 * flat normals (no NORMAL, or [scene] normals = flat), so the level of
	 * detail keeps its simplified triangles flat (lod.c); NULL when no
	 * primitive was split. flat_count: the vertices it covers (lod.c reads
	 * vertices appended after it as not flat) */
	uint8_t *flat;
	uint32_t flat_count;
	/* The named nodes (inline: a copy of the struct copies them). */
	uint32_t node_count;
	struct mesh_node nodes[MESH_NODES];
};

int mesh_alloc(struct mesh *m, uint32_t vertex_count, uint32_t index_count, bool with_uvs);
/* Adds (uninitialised) tangent storage to an allocated mesh. */
int mesh_alloc_tangents(struct mesh *m);
/* Adds (uninitialised) colour storage to an allocated mesh. */
int mesh_alloc_colors(struct mesh *m);
/* Adds second-UV storage to an allocated mesh: a copy of `from`'s
 * vertex_count pairs, or uninitialised (from NULL). */
int mesh_alloc_uv1(struct mesh *m, const float *from);
/* Frees the arrays and the materials' images. */
void mesh_release(struct mesh *m);
/* Allocates n ranges and k default materials (replacing any). */
int mesh_alloc_ranges(struct mesh *m, uint32_t n, uint32_t k);
/* Each range's center from the positions of the triangles it draws. */
void mesh_range_centers(struct mesh *m);
void mesh_material_release(struct mesh_material *mat);
/* Whether the material holds a decoded image (any of its maps). */
bool mesh_material_decoded(const struct mesh_material *mat);
/* to's materials, colour facts (has_colors, vertex_color), fit and named
 * nodes from
 * from's, their images left out (to's own materials array is not freed
 * first). Returns 0 or -ENOMEM. */
int mesh_copy_factors(struct mesh *to, const struct mesh *from);
/* The material with every field at the glTF default and no image. */
void mesh_material_default(struct mesh_material *mat);
/* Material k, or for a mesh without materials (built in, made by a
 * test) the glTF default: what its one draw reads. */
const struct mesh_material *mesh_material_at(const struct mesh *m, uint32_t k);
/* Whether any of the mesh's materials answers yes: the whole model's
 * questions (does some part read a base map?) asked of materials[]. */
bool mesh_materials_any(const struct mesh *m, bool (*pred)(const struct mesh_material *));
/* The first material the file names (present), else the default: the
 * model's colour where one colour stands for the whole (the lit grey). */
const struct mesh_material *mesh_material_first(const struct mesh *m);
/* The images the loader decoded over every material. */
unsigned mesh_images_decoded(const struct mesh *m);
/* What a range of this material reads as its vertex colour when the mesh
 * has colors_by_material: rgb its base colour factor, a 1 (as struct mesh
 * colors without COLOR_0). */
void mesh_material_vertex_color(const struct mesh_material *mat, float rgba[4]);
/* Whether s is a name a struct mesh_node keeps: non-empty, valid UTF-8
 * without control characters, shorter than MESH_NODE_NAME bytes. */
bool mesh_node_name_ok(const char *s);
/* The node called name, or NULL. */
const struct mesh_node *mesh_node_find(const struct mesh *m, const char *name);
/* The index of the variant named `name` (exact), or -1. */
int mesh_variant_find(const struct mesh *m, const char *name);
/* The material range r draws with in variant v (-1: the file's default). */
uint32_t mesh_range_material(const struct mesh *m, int v, uint32_t r);
/* Frees the variants' names and table (variant_count 0 after). */
void mesh_variants_release(struct mesh *m);
/* to takes from's variants (to's own released first; from has none after). */
void mesh_variants_move(struct mesh *to, struct mesh *from);

/* rep[i] = the lowest-numbered vertex with exactly the position of vertex
 * i (by value, so -0.0 and 0.0 are one): seams and poles split vertices
 * that must still move, and shade, as one. */
int mesh_weld(const float *positions, uint32_t count, uint32_t *rep);

/* Centre world-space positions (computed in double, so a model placed far
 * from the origin or at an extreme scale keeps its precision) and scale
 * them into the unit sphere. A degenerate extent leaves the scale at 1. */
void mesh_fit_positions(const double *world, uint32_t count, float *out);
/* The centre (fit[0..2]) and scale (fit[3]) mesh_fit_positions uses. */
void mesh_fit_of(const double *world, uint32_t count, double fit[4]);
/* The box (lo xyz, hi xyz) of count positions, and with a centre the
 * squared distance of the farthest from it (*r2; 0 without). */
void mesh_box(const double *world, uint32_t count, const double *center, double box[6], double *r2);
/* positions = (world - center) * scale: the fit of mesh_fit_positions with
 * its centre and scale given (an animated model fitted once for its
 * whole clip). */
void mesh_fit_to(const double *world, uint32_t count, const double center[3], double scale,
		 float *out);

/* Area-weighted smooth normals for the triangles idx[0..index_count) over
 * vertices [first, first + count): vertices at the same position share one
 * normal, so split UV seams shade smoothly. Degenerate areas get +Z. */
int mesh_generate_normals(const float *positions, const uint32_t *idx, uint32_t index_count,
			  uint32_t first, uint32_t count, float *normals);

/* [scene] normals: what a primitive is drawn with. FILE: the file's
 * normals where it gives them, flat ones where not (glTF requires flat
 * normals, tangents ignored, for a primitive without NORMAL); FLAT: flat
 * everywhere (low-poly, CAD); SMOOTH: the file's where given, else
 * averaged (mesh_generate_normals: a scan without normals). */
enum mesh_normals { MESH_NORMALS_FILE, MESH_NORMALS_FLAT, MESH_NORMALS_SMOOTH };

/* The unit normal of triangle a b c (counter-clockwise front), computed in
 * double; +Z for a degenerate one. */
void mesh_face_normal(const float *a, const float *b, const float *c, float out[3]);
/* Each triangle's face normal written to its three corners: flat shading
 * for triangles that share no vertex (the loader splits them so). */
void mesh_flat_normals(const float *positions, const uint32_t *idx, uint32_t index_count,
		       float *normals);

/* The built-in models, already in the unit sphere. */
int mesh_torus_knot(struct mesh *m, int tubular, int radial);
int mesh_uv_sphere(struct mesh *m, int slices, int stacks);

#ifdef __cplusplus
}
#endif

#endif
