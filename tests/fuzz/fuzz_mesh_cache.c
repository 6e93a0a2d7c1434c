/* libFuzzer: the prepared-mesh cache's check (src/scene/mesh_cache.c) on
 * any bytes, as a damaged, truncated or planted entry would hand them
 * over: refused, or every index inside the arrays it describes. */
#include "scene/mesh_cache.h"
#include "util/log.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	log_set_level((enum log_level)0);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	/* Aligned as a mapping is: the arrays are read in place. */
	uint64_t *copy = malloc(size + 8);
	struct mesh_packed m;
	struct mesh_material mat;
	unsigned sum = 0;

	if (!copy)
		return 0;
	memcpy(copy, data, size);
	if (mesh_cache_parse(copy, size, NULL, &m, &mat, NULL) == 0) {
		/* Touch every byte of every array it accepted. */
		for (int a = 0; a < MESH_ARRAYS; a++)
			for (size_t i = 0;
			     m.arrays[a] &&
			     i < m.vertex_count * mesh_array_stride(m.format, (enum mesh_array)a);
			     i++)
				sum += ((const uint8_t *)m.arrays[a])[i];
		for (uint32_t i = 0; i < m.index_count; i++)
			if (m.indices[i] >= m.vertex_count)
				abort();
	}
	free(copy);
	return (int)(sum & 0);
}
