/* The model's name, for [caption] text = auto: what a glTF says it is,
 * read from its JSON alone (a GLB's first chunk; no buffer, no image). */
#ifndef MK_GLTF_NAME_H
#define MK_GLTF_NAME_H

#ifdef __cplusplus
extern "C" {
#endif

/* asset.extras.title (Sketchfab's and other exporters' title), else the
 * name of the scene shown (scene: [scene] model_scene, an index or a
 * name; NULL: the file's default scene, else its first). Malloc'd, or
 * NULL when the file names none or does not read as glTF. */
char *gltf_model_name(const char *path, const char *scene);

#ifdef __cplusplus
}
#endif

#endif
