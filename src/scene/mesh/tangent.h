/* Per-vertex tangent frames for tangent-space maps (the packed detail map,
 * glTF normalTexture), in the glTF convention: tangent along +u, bitangent
 * = cross(normal, tangent) * w pointing to the image's top (v decreasing).
 * Every tangent written is finite, unit length and normal to its vertex's
 * normal, whatever the mesh holds (zero-area triangles, collapsed UVs). */
#ifndef MK_TANGENT_H
#define MK_TANGENT_H

#include "scene/mesh/mesh.h"

/* Generate m->tangents from the UVs. A vertex shared by triangles whose
 * UVs are mirrored against each other (a mirror seam) is split in two, one
 * per handedness, so the frame never averages to nothing: vertex_count
 * may grow and indices change. Returns 0, -EINVAL (no UVs) or -ENOMEM. */
int tangent_generate(struct mesh *m);

/* Make given tangents (glTF's TANGENT, or interpolated ones) unit length
 * and normal to the current normals again, keeping their handedness. */
void tangent_orthonormalize(struct mesh *m);

#endif
