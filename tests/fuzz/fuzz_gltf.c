/* libFuzzer: the glTF loader on any bytes, as a model file would hand them
 * over (.gltf JSON, or GLB by its magic). tinygltf's parser is compiled in
 * with the same sanitizers (tests/fuzz/tinygltf_impl.cc). External buffer
 * URIs resolve beside the seeds, in tests/fuzz/corpus/gltf (or the folder
 * FUZZ_GLTF_DIR names), so the fuzzer reaches the file path too. A mesh that loads must be one
 * every consumer can read blindly: whole triangles, every index in range, every position finite and
 * inside the unit sphere it was fitted to. */
#include "scene/gltf/gltf.h"
#include "util/log.h"
#include "scene/mesh/mesh.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define GLTF_DIR "tests/fuzz/corpus/gltf"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	log_set_level((enum log_level)0); /* one error line per input: too slow */
	return 0;
}

static void check_mesh(const struct mesh *m)
{
	if (m->index_count % 3 || !m->vertex_count || !m->positions || !m->normals || !m->indices)
		abort();
	for (uint32_t i = 0; i < m->index_count; i++)
		if (m->indices[i] >= m->vertex_count)
			abort();
	for (uint32_t v = 0; v < m->vertex_count; v++) {
		const float *p = m->positions + (size_t)v * 3;

		if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) ||
		    p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 1.01f)
			abort();
	}
	for (size_t i = 0; m->colors && i < (size_t)m->vertex_count * 4; i++)
		if (!(m->colors[i] >= 0.0f && m->colors[i] <= 1.0f))
			abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *dir = getenv("FUZZ_GLTF_DIR");
	struct mesh m;

	/* With the base colour: COLOR_0, the factors and the map's transform. */
	if (gltf_load_memory_textures("fuzz.gltf", data, size, dir ? dir : GLTF_DIR,
				      GLTF_TEXTURE_BASE_COLOR, &m) == 0) {
		check_mesh(&m);
		mesh_release(&m);
	}
	return 0;
}
