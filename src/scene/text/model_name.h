/* The name [caption] text = auto shows: a file's own name unless it is
 * one an exporter gives every file ("Scene", "RootNode", ...), else the
 * file's name made readable. Pure string work, any thread. */
#ifndef MK_MODEL_NAME_H
#define MK_MODEL_NAME_H

#include <stdbool.h>

/* Whether name is one exporters give every file: Blender's "Scene" (and
 * "Scene.001"), "Root", "RootNode", Sketchfab's "Sketchfab_Scene",
 * "Sketchfab_model", "RootNode.fbx", "GLTF_SceneRootNode", "AuxScene",
 * ..., in any case; an empty or blank name too. */
bool model_name_generic(const char *name);
/* The file name of path made readable: no folder, no extension, '_' and
 * '-' as blanks (one at a time), the first letter upper case:
 * "old_radio-v2.glb" -> "Old radio v2". Malloc'd; NULL when nothing is
 * left (or no memory). */
char *model_name_from_file(const char *path);

#endif
