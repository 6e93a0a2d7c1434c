/* The one table of what a cache entry keeps of a material and of a draw
 * range: every field of struct mesh_material and struct mesh_range is
 * either stored (and checked when read back) or named as not stored, with
 * why. tests/unit/test_mesh_cache.c fails when a field of either struct
 * is in neither: a field added to the data model cannot be forgotten by
 * the cache. */
#include "scene/mesh/mesh_cache.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define FIELD(s, f, type, kind, max)                                                               \
	{                                                                                          \
#f, offsetof(struct s, f), sizeof(((struct s *)0)->f), _Alignof(type), kind, max   \
	}

static const struct mesh_cache_field material_fields[] = {
    FIELD(mesh_material, present, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, base_color, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, base_alpha, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, alpha_mode, int, MESH_FIELD_INT, MESH_ALPHA_BLEND),
    FIELD(mesh_material, alpha_cutoff, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, double_sided, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, iridescence, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, iridescence_factor, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, iridescence_ior, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, thickness_min, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, thickness_max, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, has_normal_map, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, has_occlusion_map, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, has_thickness_map, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, normal_scale, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, occlusion_strength, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, has_base_map, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, images_decoded, unsigned, MESH_FIELD_U32, 0),
    FIELD(mesh_material, base_transform, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, base_wrap, int, MESH_FIELD_INT, MESH_WRAP_MIRROR),
    FIELD(mesh_material, base_no_mipmaps, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, unlit, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, emissive, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, has_emissive_map, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, emissive_transform, float, MESH_FIELD_FLOAT, 0),
    FIELD(mesh_material, emissive_wrap, int, MESH_FIELD_INT, MESH_WRAP_MIRROR),
    FIELD(mesh_material, emissive_no_mipmaps, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh_material, emissive_uv1, bool, MESH_FIELD_BOOL, 1),
    /* Images are not stored: an entry is written only for a scene that
     * decodes none (src/app/content.c), and read back with none. */
    FIELD(mesh_material, normal_map, struct image, MESH_FIELD_NONE, 0),
    FIELD(mesh_material, occlusion_map, struct image, MESH_FIELD_NONE, 0),
    FIELD(mesh_material, thickness_map, struct image, MESH_FIELD_NONE, 0),
    FIELD(mesh_material, base_map, struct image, MESH_FIELD_NONE, 0),
    FIELD(mesh_material, emissive_map, struct image, MESH_FIELD_NONE, 0),
};

/* The model's colour facts, which no material holds: the rest of struct
 * mesh is the entry's arrays, ranges and materials. */
static const struct mesh_cache_field color_fields[] = {
    FIELD(mesh, has_colors, bool, MESH_FIELD_BOOL, 1),
    FIELD(mesh, vertex_color, float, MESH_FIELD_FLOAT, 0),
};

static const struct mesh_cache_field range_fields[] = {
    FIELD(mesh_range, first_index, uint32_t, MESH_FIELD_U32, 0),
    FIELD(mesh_range, index_count, uint32_t, MESH_FIELD_U32, 0),
    FIELD(mesh_range, material, uint32_t, MESH_FIELD_U32, 0),
    FIELD(mesh_range, center, float, MESH_FIELD_FLOAT, 0),
};

const struct mesh_cache_field *mesh_cache_fields(enum mesh_cache_table t, size_t *count)
{
	if (t == MESH_CACHE_RANGE) {
		*count = sizeof(range_fields) / sizeof(range_fields[0]);
		return range_fields;
	}
	if (t == MESH_CACHE_COLORS) {
		*count = sizeof(color_fields) / sizeof(color_fields[0]);
		return color_fields;
	}
	*count = sizeof(material_fields) / sizeof(material_fields[0]);
	return material_fields;
}

static size_t element_size(const struct mesh_cache_field *f)
{
	return f->kind == MESH_FIELD_BOOL ? sizeof(bool) : 4;
}

size_t mesh_cache_record_words(enum mesh_cache_table t)
{
	size_t n, words = 0;
	const struct mesh_cache_field *f = mesh_cache_fields(t, &n);

	for (size_t i = 0; i < n; i++)
		if (f[i].kind != MESH_FIELD_NONE)
			words += f[i].size / element_size(&f[i]);
	return words;
}

void mesh_cache_record_write(enum mesh_cache_table t, const void *obj, uint32_t *out)
{
	size_t n;
	const struct mesh_cache_field *f = mesh_cache_fields(t, &n);
	const char *base = obj;

	for (size_t i = 0; i < n; i++)
		for (size_t e = 0;
		     f[i].kind != MESH_FIELD_NONE && e < f[i].size / element_size(&f[i]); e++) {
			const char *p = base + f[i].offset + e * element_size(&f[i]);

			if (f[i].kind == MESH_FIELD_BOOL)
				*out++ = *(const bool *)(const void *)p;
			else
				memcpy(out++, p, 4);
		}
}

/* One word into its field: a bool 0 or 1, an enum up to its max, a float
 * finite; anything else is damage. */
static bool read_word(const struct mesh_cache_field *f, uint32_t w, char *p)
{
	float x;

	switch (f->kind) {
	case MESH_FIELD_BOOL:
		*(bool *)(void *)p = w != 0;
		return w <= 1;
	case MESH_FIELD_INT:
		memcpy(p, &w, 4);
		return w <= f->max;
	case MESH_FIELD_FLOAT:
		memcpy(&x, &w, 4);
		memcpy(p, &w, 4);
		return isfinite(x);
	default:
		memcpy(p, &w, 4);
		return true;
	}
}

bool mesh_cache_record_read(enum mesh_cache_table t, const uint32_t *in, void *obj)
{
	size_t n;
	const struct mesh_cache_field *f = mesh_cache_fields(t, &n);
	char *base = obj;
	bool ok = true;

	for (size_t i = 0; i < n; i++)
		for (size_t e = 0;
		     f[i].kind != MESH_FIELD_NONE && e < f[i].size / element_size(&f[i]); e++)
			ok &= read_word(&f[i], *in++, base + f[i].offset + e * element_size(&f[i]));
	return ok;
}
