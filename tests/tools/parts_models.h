/* The several-material test models (src/scene/mesh/mesh.h ranges): parts with
 * their own base maps, an alpha MASK label, BLEND panes in front of an
 * opaque part, a double-sided leaf, and a knot of 64 materials for the
 * bench. */
#ifndef MK_PARTS_MODELS_H
#define MK_PARTS_MODELS_H

/* Writes parts-textures.glb, parts-mask.glb, parts-blend.glb,
 * parts-leaf.glb and their PNGs into dir. Returns 0, or 1 after a message. */
int parts_models_write(const char *dir);
/* knot-64-materials.glb: a torus knot of about 100k triangles in 64
 * bands, each a material of its own (every eighth textured). */
int parts_models_write_bench(const char *dir);

#endif
