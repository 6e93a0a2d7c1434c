/* What the loader does with each part of glTF 2.0 that a model's author
 * might look for: used (shown as glTF says) or ignored (read past, with
 * why). One table: the loader takes its list of extensions it understands
 * from it, `mkman gltf-features` prints it, and tests/e2e/feature_claims.sh
 * fails a document that calls a used feature ignored. */
#ifndef MK_GLTF_FEATURES_H
#define MK_GLTF_FEATURES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

struct gltf_feature {
	const char *name;      /* as a document names it */
	const char *extension; /* its glTF extension, or NULL for the core */
	bool used;
	/* An extended regular expression (lower case, POSIX awk's: no \\b)
	 * for the words a document uses for it. */
	const char *words;
};

/* The table, *count rows. */
const struct gltf_feature *gltf_features(size_t *count);

/* true when the loader understands the extension (a file that requires
 * any other is refused). */
bool gltf_extension_known(const char *name);

/* "used|ignored<TAB>name<TAB>words<TAB>extension (- for the core)", a
 * row a line. */
void gltf_features_print(FILE *out);

#ifdef __cplusplus
}
#endif

#endif
