/* What a caller may ask of the glTF loader (the material textures to
 * decode, the scene to show): the C API (gltf.h) takes it, and the mesh
 * builder (gltf_mesh.cc) and material reader (gltf_material.cc) honour
 * it, without including the API. */
#ifndef MK_GLTF_TEXTURE_H
#define MK_GLTF_TEXTURE_H

#include <stdbool.h>
#include <stddef.h>

/* The most a material map is drawn at (scene/material.c brings each to a
 * power of two at most this: every GLES2 GPU takes 2048, so no GL query
 * is needed): a larger texture is made smaller as it is decoded, so that
 * its full size is never held. */
#define GLTF_TEXTURE_SIDE 2048

/* The material textures a caller may ask to have decoded. */
enum gltf_texture {
	GLTF_TEXTURE_NORMAL = 1u << 0,	  /* normalTexture */
	GLTF_TEXTURE_OCCLUSION = 1u << 1, /* occlusionTexture */
	GLTF_TEXTURE_THICKNESS = 1u << 2, /* KHR_materials_iridescence thickness */
	/* baseColorTexture, and with it the base colour itself: per vertex
	 * baseColorFactor x COLOR_0 (struct mesh colors), or one colour for
	 * the whole model (mesh.vertex_color) */
	GLTF_TEXTURE_BASE_COLOR = 1u << 3,
};

struct mesh_anim;

/* What to load beyond the geometry. */
struct gltf_options {
	unsigned textures; /* enum gltf_texture bits */
	/* Bytes the decoded textures may take, shared among them (a texture
	 * over its share is halved until it fits); 0: no limit. */
	size_t texture_memory;
	/* The scene to show: an index ("1") or a scene's name; NULL or "" for
	 * the file's `scene`, else the first. A file without scenes shows
	 * every tree of nodes. */
	const char *scene;
	/* How a refusal of `scene` names where it came from, e.g. "[scene]
	 * model_scene"; NULL: not named. */
	const char *scene_setting;
	/* Set: the file's animations into *anim (scene/anim.h; NULL when it
	 * has none or they are malformed, which is a warning: the still
	 * model loads). NULL: animations are not read. */
	struct mesh_anim **anim;
	/* Set: what live playback needs beside the mesh into *play
	 * (scene/anim_play.h), for a pose fitted over its clip; NULL when
	 * the model cannot play (the journal says why). */
	struct anim_play **play;
	/* pose: the model posed as the clips `animation` names ("auto" or
	 * NULL: the first; "off": none; "all": every one; a name or an
	 * index) show it `time` seconds after they start, played at `speed`
	 * (0: 1) with `loop` (enum anim_loop); a name the file lacks is an
	 * error naming `animation_setting`. false: the rest pose. */
	bool pose;
	/* A clip the file lacks is a warning and the rest pose (the live
	 * kiosk: a folder's other models may have it), not an error. */
	bool animation_optional;
	const char *animation, *animation_setting;
	double time, speed;
	int loop;
	/* [scene] normals: enum mesh_normals (scene/mesh.h); 0: the file's,
	 * flat where it gives none. */
	int normals;
};

#endif
