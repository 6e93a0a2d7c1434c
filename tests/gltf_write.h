/* Writes small glTF files for the tests: valid ones in every variant the
 * loader must accept, and broken ones it must refuse with a clear error. */
#ifndef MK_GLTF_WRITE_H
#define MK_GLTF_WRITE_H

#include "mesh.h"

enum gltf_container { GLTF_GLB, GLTF_EXTERNAL_BIN, GLTF_DATA_URI };

struct gltf_write_opts {
	enum gltf_container container;
	int index_bytes;       /* 1, 2 or 4; 0 for a primitive without indices */
	int with_normals;      /* write the NORMAL attribute */
	const char *node;      /* extra JSON members of the mesh's node, e.g. "\"scale\":[-1,1,1]" */
	const char *parent;    /* set: a root node with these members holds the mesh's node */
	const char *bin_uri;   /* override the external buffer's URI */
	long position_count;   /* override POSITION's count (0: the real one) */
	long bad_index;        /* >= 0: write this value as the first index */
	int byte_stride;       /* byteStride of the POSITION view (0: tight) */
	long truncate_to;      /* > 0: cut the written file to this many bytes */
};

/* Writes path (and, for GLTF_EXTERNAL_BIN, path with .bin for .gltf).
 * Returns 0 or -1. */
int gltf_write(const char *path, const struct mesh *m, const struct gltf_write_opts *o);

#endif
