/* The table of src/scene/gltf/gltf_features.h. */
#include "scene/gltf/gltf_features.h"

#include <string.h>

static const struct gltf_feature features[] = {
    /* The core: geometry, material and motion. */
    {"animations", NULL, true, "animation"},
    {"skins", NULL, true, "skin"},
    {"morph targets", NULL, true, "morph"},
    {"node transforms", NULL, true, "node transform"},
    {"sparse accessors", NULL, true, "sparse"},
    {"base colour", NULL, true, "base colou?r"},
    {"vertex colours", NULL, true, "vertex colou?r|color_0"},
    {"alpha", NULL, true, "alpha|blended|cut out"},
    {"double-sided materials", NULL, true, "double.sided|double sides"},
    {"normal maps", NULL, true, "normal ?maps?|normaltexture"},
    {"occlusion maps", NULL, true, "occlusion"},
    {"emission", NULL, true, "emissi"},
    {"cameras", NULL, false, "camera"},
    {"metallic and roughness", NULL, false, "metallic|roughness"},
    /* Extensions the loader understands. */
    {"quantized attributes", "KHR_mesh_quantization", true, "quantiz"},
    {"meshopt compression", "EXT_meshopt_compression", true, "meshopt"},
    {"Draco compression", "KHR_draco_mesh_compression", true, "draco"},
    {"iridescence", "KHR_materials_iridescence", true, "iridescen"},
    {"texture transforms", "KHR_texture_transform", true, "texture.transform"},
    {"unlit materials", "KHR_materials_unlit", true, "unlit"},
    {"emissive strength", "KHR_materials_emissive_strength", true, "emissive.strength"},
    /* Its diffuse colour and texture are the base colour; specular and
     * glossiness are not needed by a matcap, which holds its own light. */
    {"specular-glossiness's diffuse", "KHR_materials_pbrSpecularGlossiness", true, "diffuse"},
    {"WebP textures", "EXT_texture_webp", true, "webp"},
    {"product variants", "KHR_materials_variants", true, "variant"},
    /* Read past: a matcap is the light and the material. */
    {"lights", "KHR_lights_punctual", false, "light"},
    {"specular and glossiness", NULL, false, "specular|glossiness"},
};

const struct gltf_feature *gltf_features(size_t *count)
{
	*count = sizeof(features) / sizeof(features[0]);
	return features;
}

bool gltf_extension_known(const char *name)
{
	for (size_t i = 0; i < sizeof(features) / sizeof(features[0]); i++)
		if (features[i].used && features[i].extension &&
		    !strcmp(features[i].extension, name))
			return true;
	return false;
}

void gltf_features_print(FILE *out)
{
	for (size_t i = 0; i < sizeof(features) / sizeof(features[0]); i++)
		fprintf(out, "%s\t%s\t%s\t%s\n", features[i].used ? "used" : "ignored",
			features[i].name, features[i].words,
			features[i].extension ? features[i].extension : "-");
}
