/* Writes the KHR_materials_variants test model: a cube of two primitives
 * (three faces each) and two materials, "red" (the default of both) and
 * "blue" (used only by a variant), and two variants, "red" and "blue",
 * each mapping both primitives to its material. */
#ifndef MK_TEST_GLTF_VARIANTS_H
#define MK_TEST_GLTF_VARIANTS_H

enum gltf_variants_fault {
	VARIANTS_OK,
	VARIANTS_MISSING_MATERIAL, /* a mapping names material 7 (there are 2) */
	VARIANTS_MISSING_VARIANT,  /* a mapping names variant 5 (there are 2) */
	VARIANTS_SPLIT,		   /* "blue" maps the second primitive only */
	VARIANTS_TOO_MANY,	   /* 257 variants (at most 256) */
};

/* A .gltf with its buffer in a data: URI. Returns 0 or -1. */
int gltf_write_variants(const char *path, enum gltf_variants_fault fault);
/* The same cube skinned: its first three faces on joint 0, the others on
 * joint 1 (JOINTS_0/WEIGHTS_0), a clip of 1 s holding both still, so that
 * live playback skins it on the GPU (split into a draw a joint where the
 * palette holds one bone). */
int gltf_write_variants_skinned(const char *path, enum gltf_variants_fault fault);

#endif
