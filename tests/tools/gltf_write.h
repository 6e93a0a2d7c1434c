/* Writes small glTF files for the tests: valid ones in every variant the
 * loader must accept, and broken ones it must refuse with a clear error. */
#ifndef MK_GLTF_WRITE_H
#define MK_GLTF_WRITE_H

#include "scene/mesh/mesh.h"

enum gltf_container { GLTF_GLB, GLTF_EXTERNAL_BIN, GLTF_DATA_URI };

struct gltf_write_opts {
	enum gltf_container container;
	int index_bytes;     /* 1, 2 or 4; 0 for a primitive without indices */
	int with_normals;    /* write the NORMAL attribute */
	const char *node;    /* extra JSON members of the mesh's node, e.g. "\"scale\":[-1,1,1]" */
	const char *parent;  /* set: a root node with these members holds the mesh's node */
	const char *bin_uri; /* override the external buffer's URI */
	long position_count; /* override POSITION's count (0: the real one) */
	long bad_index;	     /* >= 0: write this value as the first index */
	int byte_stride;     /* byteStride of the POSITION view (0: tight) */
	long truncate_to;    /* > 0: cut the written file to this many bytes */
	int with_uvs;	     /* TEXCOORD_0 from the mesh's uvs */
	int uv_set;	     /* ... written as TEXCOORD_<uv_set> */
	int with_tangents;   /* TANGENT from the mesh's tangents */
	/* A material, written when one of these is set. The PNG files become
	 * its normalTexture, occlusionTexture and KHR_materials_iridescence
	 * thickness texture: copied into the buffer (embed_images), else
	 * named by URI (their file names: they must lie beside the model). */
	const char *normal_png, *occlusion_png, *thickness_png;
	int embed_images;
	const char *image_uri;	   /* override every image's URI */
	double iridescence_factor; /* > 0: KHR_materials_iridescence */
	double thickness_range[2]; /* its thickness minimum and maximum, nm */
	/* Base colour: baseColorTexture from this PNG (as the others), with
	 * these members in its KHR_texture_transform (NULL: none); the factor
	 * (NULL: 0.8 0.7 0.6 1); COLOR_0 from the mesh's colors, as 5126
	 * (float), 5121 or 5123 (normalized), with 3 or 4 components. */
	const char *base_color_png;
	const char *texture_transform;
	const double *base_factor;
	int color_type, color_components;
	/* More nodes after the mesh's (JSON members of the array), and the
	 * scenes in place of the one scene (JSON: the array's members). */
	const char *extra_nodes, *scenes;
	/* A skin of these joints (JSON: node indices, two of them), with
	 * JOINTS_0 and WEIGHTS_0 that blend from the first joint at x = -1 to
	 * the second at x = 1; the mesh's node names it in node. */
	const char *skin_joints;
	/* An animation that turns this node (an index) about z, LINEAR: 0 at
	 * 0 s, 45 degrees at 1 s, 0 at 2 s; its keys in a second buffer (a
	 * data: URI). */
	int anim_node;
	int with_anim;
	int anim_step; /* its keys STEP instead of LINEAR */
};

/* Writes path (and, for GLTF_EXTERNAL_BIN, path with .bin for .gltf).
 * Returns 0 or -1. */
int gltf_write(const char *path, const struct mesh *m, const struct gltf_write_opts *o);

/* A cube of side 1 about the origin as an STL conversion has it: its 8
 * corners shared by its 12 triangles, no normals (zeros), no UVs. Returns
 * 0 or -1. */
int gltf_test_cube(struct mesh *m);

#endif
