#include "scene/mesh/material.h"
#include "scene/gltf/gltf.h"
#include "util/log.h"
#include "util/math3d.h"
#include "scene/mesh/subdivide.h"
#include "scene/mesh/tangent.h"
#include "scene/mesh/texture.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The iridescence defaults: a beetle's green turning blue-violet. */
#define DEFAULT_HUE_AVERAGE 0.33
#define DEFAULT_HUE_RANGE   0.4
#define DEFAULT_HUE_SHIFT   0.2
#define DEFAULT_OPACITY	    0.6
#define DEFAULT_SATURATION  0.7
#define DEFAULT_VALUE	    0.8
/* The wavelength one turn of the hue circle stands for (green). */
#define FILM_LAMBDA_NM 550.0
/* Detail maps are mipmapped and repeat: GLES2 needs power-of-two sides,
 * and every GLES2 GPU takes 2048. */
#define DETAIL_MAX_SIDE 2048
#define LIT_GREY	0.8f

void material_config_defaults(struct material_config *cfg)
{
	memset(cfg, 0, sizeof(*cfg));
	cfg->iridescence = MATERIAL_AUTO;
	cfg->hue_range = cfg->hue_average = cfg->hue_shift = NAN;
	cfg->opacity = cfg->saturation = cfg->value = NAN;
	cfg->detail = MATERIAL_AUTO;
	cfg->displacement_scale = 0.05;
	cfg->displacement_pixels = 3.0;
	cfg->displacement_triangles = 1000000;
	cfg->lit = LIT_OFF;
	cfg->shininess = 48.0;
}

void material_config_release(struct material_config *cfg)
{
	free(cfg->ramp);
	free(cfg->detail_map);
	free(cfg->height_map);
	cfg->ramp = cfg->detail_map = cfg->height_map = NULL;
}

unsigned material_gltf_textures(const struct material_config *cfg)
{
	unsigned t = 0;

	/* A detail map named in the settings replaces the model's maps. */
	if (cfg->detail != MATERIAL_OFF && !cfg->detail_map) {
		t |= GLTF_TEXTURE_NORMAL | GLTF_TEXTURE_OCCLUSION;
		if (cfg->iridescence != MATERIAL_OFF)
			t |= GLTF_TEXTURE_THICKNESS;
	}
	if (cfg->base_color != MATERIAL_OFF)
		t |= GLTF_TEXTURE_BASE_COLOR;
	return t;
}

static float pick(double setting, double otherwise)
{
	return (float)(isnan(setting) ? otherwise : setting);
}

/* KHR_materials_iridescence to the hue formula of shaders/material.glsl.
 * The film's colour turns once round the hue circle each time its
 * optical path 2 eta d cos(theta_t) grows by a wavelength. With cos(theta_t) ~ 1 - sin^2(theta)
 * / (2 eta^2) and sin^2(theta) = 1 - (n.e)^2:
 *   hue = 2 eta d / lambda - d / (eta lambda) * (1 - (n.e)^2),
 * the shader's form, with average and range from the thickest film, and a
 * thinner one (thickness map -> 0 at the minimum) shifting the hue. */
static void iridescence_from_gltf(const struct mesh_material *g, struct material *m)
{
	double eta = g->iridescence_ior > 1.0f ? g->iridescence_ior : 1.3;
	double dmax = g->thickness_max, dmin = g->has_thickness_map ? g->thickness_min : dmax;

	m->hue_average = (float)(2.0 * eta * dmax / FILM_LAMBDA_NM);
	m->hue_range = (float)(-dmax / (eta * FILM_LAMBDA_NM));
	m->hue_shift = (float)(2.0 * eta * (dmax - dmin) / FILM_LAMBDA_NM);
	m->opacity = (float)(DEFAULT_OPACITY * fmin(fmax(g->iridescence_factor, 0.0), 1.0));
}

/* One material's iridescence: on as the settings say or, auto, where its
 * glTF material has it; the settings' numbers over the material's. */
static void surface_iridescence(const struct material_config *cfg, const struct mesh_material *g,
				struct material_surface *s)
{
	struct material film;
	bool from_gltf = g->iridescence && g->iridescence_factor > 0.0f;

	if (cfg->iridescence == MATERIAL_OFF || (cfg->iridescence == MATERIAL_AUTO && !from_gltf))
		return;
	film.hue_average = DEFAULT_HUE_AVERAGE;
	film.hue_range = DEFAULT_HUE_RANGE;
	film.hue_shift = DEFAULT_HUE_SHIFT;
	film.opacity = DEFAULT_OPACITY;
	if (from_gltf)
		iridescence_from_gltf(g, &film);
	s->features |= MATERIAL_IRIDESCENCE;
	s->hue_average = pick(cfg->hue_average, film.hue_average);
	s->hue_range = pick(cfg->hue_range, film.hue_range);
	s->hue_shift = pick(cfg->hue_shift, film.hue_shift);
	s->opacity = pick(cfg->opacity, film.opacity);
}

/* Iridescence per material; the model's numbers are its first
 * iridescent material's. */
static void resolve_iridescence(const struct material_config *cfg, const struct mesh *mesh,
				struct material *m)
{
	for (uint32_t k = m->surface_count; k-- > 0;) {
		struct material_surface *s = &m->surfaces[k];

		surface_iridescence(cfg, mesh_material_at(mesh, k), s);
		if (!(s->features & MATERIAL_IRIDESCENCE))
			continue;
		m->features |= MATERIAL_IRIDESCENCE;
		m->hue_average = s->hue_average;
		m->hue_range = s->hue_range;
		m->hue_shift = s->hue_shift;
		m->opacity = s->opacity;
	}
	if (!(m->features & MATERIAL_IRIDESCENCE))
		return;
	m->saturation = pick(cfg->saturation, DEFAULT_SATURATION);
	m->value = pick(cfg->value, DEFAULT_VALUE);
}

/* A file the settings name: an error when strict, else a warning and the
 * feature stays off (the image is left empty). */
static int load_named(const char *path, const char *feature, bool strict, struct image *img)
{
	int ret = image_load(path, img);

	if (ret && !strict) {
		log_warn("%s: %s is off", path, feature);
		ret = 0;
	}
	return ret;
}

/* glTF's normal, occlusion and thickness textures into one packed map,
 * sampled at the largest one's size (rounded to a power of two). The
 * normal is scaled as glTF says and stored as xy: the shader rebuilds z,
 * exact for unit normals, which a fixed z = 1 would not be. */
static void pack_texel(const struct mesh_material *g, const struct image *shift, double u, double v,
		       uint8_t *out)
{
	double t[4], n[3] = {0, 0, 1}, len;

	if (g->normal_map.width) {
		texture_sample(&g->normal_map, u, v, t);
		for (int k = 0; k < 3; k++)
			n[k] = (t[k] * 2.0 - 1.0) * (k < 2 ? g->normal_scale : 1.0);
	}
	len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	if (!(len > 1e-6) || n[2] < 0.0)
		n[0] = n[1] = 0.0, len = 1.0;
	out[0] = (uint8_t)lround((n[0] / len * 0.5 + 0.5) * 255.0);
	out[1] = (uint8_t)lround((n[1] / len * 0.5 + 0.5) * 255.0);
	out[2] = 255;
	if (g->occlusion_map.width) {
		texture_sample(&g->occlusion_map, u, v, t);
		out[2] = (uint8_t)lround(
		    fmin(fmax(1.0 + g->occlusion_strength * (t[0] - 1.0), 0.0), 1.0) * 255.0);
	}
	out[3] = 255;
	if (shift) {
		texture_sample(shift, u, v, t);
		out[3] = (uint8_t)lround(t[1] * 255.0);
	}
}

static int pack_gltf(const struct mesh_material *g, bool with_shift, struct image *out)
{
	const struct image *shift = with_shift && g->thickness_map.width ? &g->thickness_map : NULL;
	const struct image *maps[3] = {&g->normal_map, &g->occlusion_map, shift};
	int w = 0, h = 0, ret;

	for (int i = 0; i < 3; i++)
		if (maps[i] && maps[i]->width) {
			w = maps[i]->width > w ? maps[i]->width : w;
			h = maps[i]->height > h ? maps[i]->height : h;
		}
	if (!w)
		return -ENOENT;
	ret = image_alloc(out, texture_pot(w, DETAIL_MAX_SIDE), texture_pot(h, DETAIL_MAX_SIDE));
	for (int y = 0; !ret && y < out->height; y++)
		for (int x = 0; x < out->width; x++)
			pack_texel(g, shift, (x + 0.5) / out->width, (y + 0.5) / out->height,
				   out->rgba + ((size_t)y * (size_t)out->width + (size_t)x) * 4);
	return ret;
}

/* A map read as is, brought to power-of-two sides. */
static int to_pot(struct image *img)
{
	struct image pot;
	int w = texture_pot(img->width, DETAIL_MAX_SIDE),
	    h = texture_pot(img->height, DETAIL_MAX_SIDE);
	int ret;

	if (w == img->width && h == img->height)
		return 0;
	ret = texture_resample(img, w, h, &pot);
	image_release(img);
	*img = pot;
	return ret;
}

/* Each material's own normal and occlusion maps (and, where it is
 * iridescent, its film thickness) packed into its own detail map. */
static int pack_surfaces(const struct material_config *cfg, const struct mesh *mesh,
			 struct material *m)
{
	int ret = 0;

	for (uint32_t k = 0; k < m->surface_count && !ret; k++) {
		const struct mesh_material *g = mesh_material_at(mesh, k);
		struct material_surface *s = &m->surfaces[k];

		ret = pack_gltf(g, (s->features & MATERIAL_IRIDESCENCE) != 0, &s->detail);
		if (ret == -ENOENT) {
			ret = 0;
			continue;
		}
		if (!ret)
			s->features |=
			    MATERIAL_DETAIL | (g->normal_map.width ? MATERIAL_DETAIL_NORMAL : 0);
		m->features |= s->features & (MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL);
	}
	if (!ret && !(m->features & MATERIAL_DETAIL) && cfg->detail == MATERIAL_ON)
		log_warn("detail = on, but no detail_map is set and no material of the model "
			 "has a normal or occlusion texture: the detail map is off");
	return ret;
}

static int resolve_detail(const struct material_config *cfg, const struct mesh *mesh, bool strict,
			  struct material *m)
{
	int ret = 0;

	if (cfg->detail == MATERIAL_OFF)
		return 0;
	if (!mesh->uvs && (cfg->detail_map || cfg->detail == MATERIAL_ON)) {
		log_msg(strict ? LOG_ERR : LOG_WARN,
			"%s: the model has no TEXCOORD_0 to place it: the detail map is off",
			cfg->detail_map ? cfg->detail_map : "detail = on");
		return strict ? -EINVAL : 0;
	}
	if (!cfg->detail_map)
		return pack_surfaces(cfg, mesh, m);
	/* The settings' map covers every part, in place of their own. */
	ret = load_named(cfg->detail_map, "the detail map", strict, &m->detail);
	if (!ret && m->detail.width)
		ret = to_pot(&m->detail);
	if (!ret && m->detail.width) {
		m->features |= MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL;
		for (uint32_t k = 0; k < m->surface_count; k++)
			m->surfaces[k].features |= MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL;
	}
	return ret;
}

static int resolve_displacement(const struct material_config *cfg, const struct mesh *mesh,
				bool strict, struct material *m)
{
	int ret;

	if (!cfg->height_map)
		return 0;
	if (!mesh->uvs) {
		log_msg(strict ? LOG_ERR : LOG_WARN,
			"%s: the model has no TEXCOORD_0 to place it: displacement is off",
			cfg->height_map);
		return strict ? -EINVAL : 0;
	}
	ret = load_named(cfg->height_map, "displacement", strict, &m->height);
	if (!ret && m->height.width)
		m->features |= MATERIAL_DISPLACEMENT;
	m->displacement_scale = (float)cfg->displacement_scale;
	m->displacement_pixels = (float)cfg->displacement_pixels;
	m->displacement_triangles = (uint32_t)cfg->displacement_triangles;
	return ret;
}

/* One material's base map, brought to power-of-two sides to repeat. */
static int copy_base_map(const struct image *from, struct image *to)
{
	int ret = image_alloc(to, from->width, from->height);

	if (!ret)
		memcpy(to->rgba, from->rgba, (size_t)from->width * (size_t)from->height * 4);
	return ret ? ret : to_pot(to);
}

/* Every material's sides and, when base colour is drawn, its alpha and
 * base map (placed by the mesh's UVs). */
static int resolve_surfaces(const struct mesh *mesh, bool base, struct material *m)
{
	bool unplaced = false;
	int ret = 0;

	for (uint32_t k = 0; k < m->surface_count && !ret; k++) {
		const struct mesh_material *g = mesh_material_at(mesh, k);
		struct material_surface *s = &m->surfaces[k];

		s->double_sided = g->double_sided;
		s->alpha = 1.0f;
		s->base_transform[0] = s->base_transform[3] = 1.0f;
		if (!base)
			continue;
		memcpy(s->base_transform, g->base_transform, sizeof(s->base_transform));
		memcpy(s->wrap, g->base_wrap, sizeof(s->wrap));
		s->no_mipmaps = g->base_no_mipmaps;
		s->alpha_mode = g->alpha_mode;
		s->alpha = g->base_alpha;
		s->alpha_cutoff = g->alpha_cutoff;
		unplaced |= g->base_map.width && !mesh->uvs;
		if (g->base_map.width && mesh->uvs)
			ret = copy_base_map(&g->base_map, &s->base_map);
		if (!ret && s->base_map.width)
			m->features |= MATERIAL_BASE_MAP;
	}
	if (unplaced)
		log_warn("the model's baseColorTexture has no TEXCOORD_0 to place it: not used");
	return ret;
}

/* One material's emission (its factor and, placed by the mesh's UVs, its
 * map) and whether it is shown unlit. A black factor emits nothing: its
 * ranges keep the program without emission. */
static int surface_light(const struct material_config *cfg, const struct mesh *mesh,
			 const struct mesh_material *g, struct material_surface *s)
{
	bool placed;
	int ret = 0;

	if (g->unlit && cfg->unlit == UNLIT_FILE)
		s->features |= MATERIAL_UNLIT;
	if (!(g->emissive[0] > 0.0f || g->emissive[1] > 0.0f || g->emissive[2] > 0.0f))
		return 0;
	s->features |= MATERIAL_EMISSIVE;
	memcpy(s->emissive, g->emissive, sizeof(s->emissive));
	memcpy(s->emissive_transform, g->emissive_transform, sizeof(s->emissive_transform));
	memcpy(s->emissive_wrap, g->emissive_wrap, sizeof(s->emissive_wrap));
	s->emissive_no_mipmaps = g->emissive_no_mipmaps;
	/* Its UVs: the mesh's second set where it reads another than the base map. */
	placed = g->emissive_uv1 ? mesh->uv1 != NULL : mesh->uvs != NULL;
	if (g->emissive_map.width && placed)
		ret = copy_base_map(&g->emissive_map, &s->emissive_map);
	if (!ret && s->emissive_map.width)
		s->features |=
		    MATERIAL_EMISSIVE_MAP | (g->emissive_uv1 ? MATERIAL_EMISSIVE_UV1 : 0);
	else if (g->emissive_map.width)
		log_warn("the model's emissiveTexture has no %s to place it: its "
			 "emissiveFactor alone is drawn",
			 g->emissive_uv1 ? "second TEXCOORD_n" : "TEXCOORD_0");
	return ret;
}

/* The model's base colour, when the loader gave it (mesh colors): each
 * material's map needs the UVs it is placed by. Emission and unlit are
 * the file's colours too: off with the base colour. */
static int resolve_base_color(const struct material_config *cfg, const struct mesh *mesh,
			      struct material *m)
{
	bool colour = cfg->base_color != MATERIAL_OFF;
	bool base = colour && (mesh->colors || mesh->has_colors);
	int ret;

	if (base) {
		m->features |= MATERIAL_BASE_COLOR;
		memcpy(m->vertex_color, mesh->vertex_color, sizeof(m->vertex_color));
	}
	ret = resolve_surfaces(mesh, base, m);
	for (uint32_t k = 0; colour && !ret && k < m->surface_count; k++) {
		ret = surface_light(cfg, mesh, mesh_material_at(mesh, k), &m->surfaces[k]);
		m->features |= m->surfaces[k].features & MATERIAL_PER_RANGE;
	}
	return ret;
}

int material_load(struct material *out, const struct material_config *cfg, const struct mesh *mesh,
		  bool strict)
{
	const struct mesh_material *g = mesh_material_first(mesh);
	int ret = 0;

	memset(out, 0, sizeof(*out));
	out->surface_count = mesh->material_count ? mesh->material_count : 1;
	out->surfaces = calloc(out->surface_count, sizeof(*out->surfaces));
	if (!out->surfaces)
		return -ENOMEM;
	out->lit = cfg->lit;
	out->shininess = (float)cfg->shininess;
	for (int k = 0; k < 3; k++)
		out->base_color[k] = g->present ? g->base_color[k] : LIT_GREY;
	resolve_iridescence(cfg, mesh, out);
	if ((out->features & MATERIAL_IRIDESCENCE) && cfg->ramp) {
		ret =
		    load_named(cfg->ramp, "the iridescence ramp (HSV is used)", strict, &out->ramp);
		if (!ret && out->ramp.width)
			out->features |= MATERIAL_RAMP;
	}
	if (!ret)
		ret = resolve_detail(cfg, mesh, strict, out);
	if (!ret)
		ret = resolve_displacement(cfg, mesh, strict, out);
	if (!ret)
		ret = resolve_base_color(cfg, mesh, out);
	if (ret)
		material_release(out);
	return ret;
}

void material_release(struct material *m)
{
	image_release(&m->detail);
	image_release(&m->ramp);
	image_release(&m->height);
	for (uint32_t k = 0; m->surfaces && k < m->surface_count; k++) {
		image_release(&m->surfaces[k].base_map);
		image_release(&m->surfaces[k].detail);
		image_release(&m->surfaces[k].emissive_map);
	}
	free(m->surfaces);
	memset(m, 0, sizeof(*m));
}

static void refit(struct mesh *mesh)
{
	double *world = malloc((size_t)mesh->vertex_count * 3 * sizeof(double) + 1), again[4];

	if (!world)
		return; /* it still draws, only a little larger */
	for (size_t i = 0; i < (size_t)mesh->vertex_count * 3; i++)
		world[i] = mesh->positions[i];
	mesh_fit_of(world, mesh->vertex_count, again);
	mesh_fit_to(world, mesh->vertex_count, again, again[3], mesh->positions);
	/* The file's points follow: (world - c1) s1 - c2) s2. */
	if (mesh->fit[3] > 0) {
		for (int k = 0; k < 3; k++)
			mesh->fit[k] += again[k] / mesh->fit[3];
		mesh->fit[3] *= again[3];
	}
	free(world);
}

static int displace(const struct material *m, struct mesh *mesh, int width, int height)
{
	int n = subdivide_segments(mesh, sphere_fit_pixels_per_unit(width, height),
				   m->displacement_pixels, &m->height, m->displacement_triangles);
	int ret = 0;

	if (n > 1) {
		struct mesh fine;

		ret = subdivide_mesh(mesh, n, &fine);
		if (ret)
			return ret;
		/* Triangle t became n x n triangles at t n n: each range
		 * keeps its material over its own, n n times as many. */
		fine.has_colors = mesh->has_colors;
		memcpy(fine.vertex_color, mesh->vertex_color, sizeof(fine.vertex_color));
		fine.ranges = mesh->ranges, fine.range_count = mesh->range_count;
		fine.materials = mesh->materials, fine.material_count = mesh->material_count;
		for (uint32_t r = 0; r < fine.range_count; r++) {
			fine.ranges[r].first_index *= (uint32_t)(n * n);
			fine.ranges[r].index_count *= (uint32_t)(n * n);
		}
		mesh->ranges = NULL, mesh->range_count = 0;
		mesh->materials = NULL, mesh->material_count = 0;
		mesh_variants_move(&fine, mesh);
		mesh_release(mesh);
		*mesh = fine;
	}
	ret = displace_mesh(mesh, &m->height, m->displacement_scale);
	if (ret)
		return ret;
	refit(mesh);
	mesh_range_centers(mesh);
	/* The surface has moved: its tangents are made again from the UVs. */
	free(mesh->tangents);
	mesh->tangents = NULL;
	log_info("displacement: %d segments per edge, %u triangles", n, mesh->index_count / 3);
	return 0;
}

int material_prepare_mesh(const struct material *m, struct mesh *mesh, int width, int height)
{
	int ret = 0;

	if (m->features & MATERIAL_DISPLACEMENT)
		ret = displace(m, mesh, width, height);
	if (!ret && (m->features & MATERIAL_DETAIL_NORMAL)) {
		if (mesh->tangents)
			tangent_orthonormalize(mesh);
		else
			ret = tangent_generate(mesh);
	}
	if (ret)
		log_err("material: cannot prepare the mesh: %s", strerror(-ret));
	return ret;
}

bool material_needs_uvs(unsigned features)
{
	return (features & (MATERIAL_DETAIL | MATERIAL_BASE_MAP | MATERIAL_EMISSIVE_MAP)) != 0;
}

bool material_needs_uv1(unsigned features)
{
	return (features & MATERIAL_EMISSIVE_UV1) != 0;
}

bool material_needs_tangents(unsigned features)
{
	return (features & MATERIAL_DETAIL_NORMAL) != 0;
}

bool material_needs_colors(unsigned features)
{
	return (features & MATERIAL_BASE_COLOR) != 0;
}
