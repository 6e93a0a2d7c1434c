/* How deep a glTF's JSON nests, counted before any parser sees it.
 * tinygltf (and the JSON library under it) parse by recursion, one call
 * chain per level: a file nested 30,000 deep overflowed an 8 MiB stack
 * and killed the process, however the error paths around it were written.
 * A real glTF nests a handful of levels (the deepest file in the test
 * corpora: tests/unit/test_gltf.c), so a bound far above that refuses
 * only what no exporter writes. Plain C, one pass, no allocation. */
#ifndef MK_GLTF_JSON_DEPTH_H
#define MK_GLTF_JSON_DEPTH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The deepest nesting of objects and arrays a model may have: eight times
 * the deepest file of the test corpora and Debian's assimp-testmodels
 * (8 levels: tests/corpus/blender/cube-textured.glb). Extras (free-form, any depth an exporter
 * likes) are the only place a real file nests further. The stack a parse of this depth takes is
 * measured in tests/unit/test_gltf.c and far below the worker's (content/worker.h). */
#define GLTF_JSON_MAX_DEPTH 64

/* Where the JSON nested too deep. */
struct gltf_json_depth {
	unsigned depth; /* the deepest nesting seen (up to max + 1, where it stopped) */
	size_t offset;	/* the byte of the first bracket past max, in the file */
	size_t line;	/* ... and its line in the JSON text, from 1 */
	bool glb;	/* the JSON was a GLB's first chunk */
};

/* The depth of `{` and `[` in text (outside strings, whose `\"` escapes are
 * skipped) stays within max: true. Otherwise false, with where the first
 * bracket past max lies (offset from text). */
bool gltf_json_depth_within(const char *text, size_t size, unsigned max,
			    struct gltf_json_depth *out);

/* The same for a model file as it is read: a .gltf's whole text, or a GLB's
 * JSON chunk (as much of it as the file holds); offset counts from the
 * file's first byte. A GLB without a JSON chunk is within (its parser
 * refuses it without parsing anything). */
bool gltf_json_depth_file_within(const uint8_t *data, size_t size, unsigned max,
				 struct gltf_json_depth *out);

#ifdef __cplusplus
}
#endif

#endif
