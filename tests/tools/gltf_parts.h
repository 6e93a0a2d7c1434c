/* Writes a GLB of several primitives, each with a material of its own: the
 * several-material test models (parts with their own base maps, alpha
 * MASK and BLEND, double-sided). */
#ifndef MK_GLTF_PARTS_H
#define MK_GLTF_PARTS_H

#include "scene/mesh/mesh.h"

struct gltf_part {
	const struct mesh *mesh; /* positions, normals, uvs (required), indices */
	double factor[4];	 /* baseColorFactor */
	const char *png;	 /* baseColorTexture, embedded; NULL: none */
	/* More members of the material, e.g. "\"alphaMode\":\"MASK\"" (NULL: none). */
	const char *material;
	/* Members of the primitive's baseColorTexture besides index (e.g. a
	 * KHR_texture_transform's "extensions"); NULL: none. */
	const char *texture_info;
	int own_material;	/* 0: the part shares the previous part's material */
	const char *normal_png; /* normalTexture, embedded; NULL: none */
};

/* More of a part, where asked (gltf_write_parts_more). */
struct gltf_part_more {
	const char *emissive_png;  /* emissiveTexture, embedded; NULL: none */
	const char *emissive_info; /* its members besides index; NULL: none */
	int uv_set;		   /* the UVs written as TEXCOORD_<uv_set> */
	/* factor and png written as KHR_materials_pbrSpecularGlossiness's
	 * diffuseFactor and diffuseTexture, not pbrMetallicRoughness's. */
	int spec_gloss;
	/* A second UV set, one pair per vertex of the part's mesh, written as
	 * TEXCOORD_<uv1_set> beside the first; NULL: none. */
	const float *uv1;
	int uv1_set;
};

/* One node, one mesh of n primitives. Returns 0 or -1. */
int gltf_write_parts(const char *path, const struct gltf_part *parts, int n);
/* The same, with more[k] for part k (more NULL: none). */
int gltf_write_parts_more(const char *path, const struct gltf_part *parts,
			  const struct gltf_part_more *more, int n);

#endif
