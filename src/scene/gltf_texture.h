/* The material textures a caller may ask the glTF loader to decode: the
 * C API (gltf.h) takes them, and the material reader (gltf_material.cc)
 * honours them, without either including the other. */
#ifndef MK_GLTF_TEXTURE_H
#define MK_GLTF_TEXTURE_H

/* The material textures a caller may ask to have decoded. */
enum gltf_texture {
	GLTF_TEXTURE_NORMAL = 1u << 0,	  /* normalTexture */
	GLTF_TEXTURE_OCCLUSION = 1u << 1, /* occlusionTexture */
	GLTF_TEXTURE_THICKNESS = 1u << 2, /* KHR_materials_iridescence thickness */
	/* baseColorTexture, and with it the base colour itself: per vertex
	 * baseColorFactor x COLOR_0 (struct mesh colors) */
	GLTF_TEXTURE_BASE_COLOR = 1u << 3,
};

#endif
