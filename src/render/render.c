#include "render/render.h"
#include "render/render_priv.h"
#include "util/log.h"
#include "render/draw_list.h"
#include "render/shader.h"
#include "scene/anim/anim_palette.h"
#include "scene/mesh/texture.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct renderer *renderer_new(const struct gl *gl, const char *shader_dir)
{
	struct renderer *r = calloc(1, sizeof(*r));

	if (!r)
		return NULL;
	r->gl = gl;
	r->shader_dir = shader_dir;
	r->stop = -1;
	r->look = -1;
	/* A CPU rasteriser emulates 16-bit mediump with conversions: there
	 * highp is faster as well as exact (the mediump rows of
	 * tests/bench/report/speed-error.md: about twice as slow). A GPU runs
	 * mediump natively. */
	r->highp = gl->caps.software;
	r->format = r->drawn = VERTEX_COMPACT;
	r->position_scale = 1.0f;
	/* tests/bench/report/speed-error.md measures the three filters
	 * against a supersampled reference, large and small on screen. */
	r->matcap_filter = MATCAP_FILTER_AUTO;
	gl->GenBuffers(SHADER_ATTR_COUNT, r->vbo);
	gl->GenBuffers(2, r->skin_vbo);
	r->bone_limit =
	    anim_palette_size(gl->caps.max_vertex_uniform_vectors, RENDER_SKIN_RESERVED);
	gl->GenBuffers(1, &r->ibo);
	gl->GenTextures(1, &r->matcap);
	return r;
}

void render_drop_programs(struct renderer *r)
{
	struct program *p = &r->programs[0][0][0][0];

	for (size_t i = 0; i < sizeof(r->programs) / sizeof(*p); i++)
		if (p[i].id)
			r->gl->DeleteProgram(p[i].id);
	memset(r->programs, 0, sizeof(r->programs));
	memset(r->variants, 0, sizeof(r->variants));
	r->current = r->beside = NULL;
}

static void drop_surfaces(struct renderer *r);
static void prepare_variants(struct renderer *r);

static void drop_texture(const struct gl *gl, GLuint *tex)
{
	if (*tex)
		gl->DeleteTextures(1, tex);
	*tex = 0;
}

void renderer_free(struct renderer *r)
{
	if (!r)
		return;
	render_drop_programs(r);
	r->gl->DeleteBuffers(SHADER_ATTR_COUNT, r->vbo);
	render_skin_free(r);
	r->gl->DeleteBuffers(1, &r->ibo);
	r->gl->DeleteTextures(1, &r->matcap);
	drop_texture(r->gl, &r->detail);
	drop_texture(r->gl, &r->ramp);
	drop_surfaces(r);
	render_variants_drop(r);
	draw_list_release(&r->list);
	background_free(r->background);
	caption_gl_free(r->caption);
	for (int i = 0; i < CAPTION_STOPS; i++)
		caption_gl_free(r->stop_caption[i]);
	hotspot_gl_free(r->hotspot_gl);
	free(r);
}

static void drop_surfaces(struct renderer *r)
{
	for (uint32_t k = 0; r->base_maps && k < r->surface_count; k++)
		drop_texture(r->gl, &r->base_maps[k]);
	for (uint32_t k = 0; r->emissive_maps && k < r->surface_count; k++)
		drop_texture(r->gl, &r->emissive_maps[k]);
	for (uint32_t k = 0; r->detail_maps && k < r->surface_count; k++)
		drop_texture(r->gl, &r->detail_maps[k]);
	free(r->base_maps);
	free(r->detail_maps);
	free(r->emissive_maps);
	free(r->surfaces);
	r->base_maps = r->detail_maps = r->emissive_maps = NULL;
	r->surfaces = NULL;
	r->surface_count = 0;
}

/* Core GLES2 indexes with 16 bits; 32-bit indices need an extension that
 * some SBC GPUs lack, and then the draw list cuts the ranges into 16-bit
 * chunks, each drawn from its own first vertex. */
static int upload_indices(struct renderer *r, const struct mesh_packed *m)
{
	const struct gl *gl = r->gl;
	struct draw_list *l = &r->list;
	int ret;

	draw_list_release(l);
	ret = draw_list_build(l, m->ranges, m->range_count, m->indices, m->index_count,
			      m->vertex_count, r->surfaces, r->surface_count,
			      gl->caps.element_index_uint);
	if (ret)
		return ret;
	memset(r->variant_used, 0, sizeof(r->variant_used));
	for (uint32_t i = 0; i < l->count; i++)
		r->variant_used[draw_item_variant(&l->items[i])] = true;
	render_variants_mark(r);
	gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
	gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)l->index_count * (l->wide ? 4 : 2),
		       l->wide ? (const void *)l->indices32 : (const void *)l->indices16,
		       GL_STATIC_DRAW);
	r->index_type = l->wide ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT;
	/* Uploaded: only the draws are kept. */
	free(l->indices16);
	l->indices16 = NULL;
	l->indices32 = NULL;
	return 0;
}

/* One attribute array: as it is, or each 16-bit chunk's vertices
 * gathered (struct draw_list). */
static int upload_attribute(struct renderer *r, const struct mesh_packed *m, int a)
{
	const struct gl *gl = r->gl;
	const struct draw_list *l = &r->list;
	size_t stride = mesh_array_stride(m->format, (enum mesh_array)a);
	size_t count = l->gather ? l->gather_count : m->vertex_count;
	const char *src = m->arrays[a];
	char *gathered = NULL;

	if (l->gather) {
		gathered = malloc(count * stride + 1);
		if (!gathered)
			return -ENOMEM;
		for (size_t i = 0; i < count; i++)
			memcpy(gathered + i * stride, src + (size_t)l->gather[i] * stride, stride);
	}
	r->attr_bytes[a] = (long)(count * stride);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo[a]);
	gl->BufferData(GL_ARRAY_BUFFER, r->attr_bytes[a], gathered ? gathered : src,
		       GL_STATIC_DRAW);
	free(gathered);
	return 0;
}

void renderer_set_vertex_format(struct renderer *r, enum vertex_format format)
{
	r->format = format;
}

/* The features the programs drawn read: the lit mode alone keeps its own
 * grey (render/shader.c), so the base colour is no feature of it. */
static unsigned drawn_features(const struct material *m)
{
	unsigned base = MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP;

	return m->lit == LIT_ON ? m->features & ~base : m->features;
}

int renderer_set_packed(struct renderer *r, const struct mesh_packed *m)
{
	unsigned f = drawn_features(&r->mat);
	bool uvs = material_needs_uvs(f);
	bool tangents = material_needs_tangents(f);
	bool colors = material_needs_colors(f);
	bool used[SHADER_ATTR_COUNT] = {true, true, uvs, tangents, colors, material_needs_uv1(f)};
	bool live = r->live_next;
	int ret = upload_indices(r, m);

	r->live_next = r->live = false;
	r->mesh_serial++;
	r->drawn = m->format;
	r->position_scale = m->position_scale;
	/* Skinned or morphed otherwise than the last mesh: other programs. */
	if (!ret && render_skin_set(r)) {
		render_drop_programs(r);
		ret = r->mode_set ? renderer_set_mode(r, r->mode, r->ortho) : 0;
	}
	if (!ret && r->mode_set)
		prepare_variants(r);
	/* Colours without an array are one constant (material vertex_color). */
	if ((uvs && !m->arrays[MESH_UVS]) || (tangents && !m->arrays[MESH_TANGENTS]) ||
	    (material_needs_uv1(f) && !m->arrays[MESH_UV1]))
		log_warn("render: the mesh lacks the UVs or tangents its material needs");
	for (int a = 0; a < SHADER_ATTR_COUNT && !ret; a++) {
		if (used[a] && m->arrays[a]) {
			ret = upload_attribute(r, m, a);
		} else if (r->attr_bytes[a]) {
			/* A feature no longer used gives its memory back. */
			r->gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo[a]);
			r->gl->BufferData(GL_ARRAY_BUFFER, 0, NULL, GL_STATIC_DRAW);
			r->attr_bytes[a] = 0;
		}
	}
	/* Uploaded: only the draws are kept (a live mesh keeps its gather and
	 * room for a pose gathered). */
	free(r->live_scratch);
	r->live_scratch = NULL;
	if (live && r->list.gather &&
	    !(r->live_scratch = malloc((size_t)r->list.gather_count * 12 + 1)))
		ret = -ENOMEM;
	if (!live) {
		free(r->list.gather);
		r->list.gather = NULL;
	}
	r->live = live && !ret;
	if (!ret && r->gl->GetError() == GL_OUT_OF_MEMORY) {
		log_err("render: out of GPU memory for %u vertices", m->vertex_count);
		ret = -ENOMEM;
	}
	return ret;
}

int renderer_set_mesh(struct renderer *r, const struct mesh *m)
{
	struct mesh_packed packed;
	int ret = mesh_pack(m, r->format, &packed);

	if (!ret)
		ret = render_variants_take(r, m);
	if (!ret)
		ret = renderer_set_packed(r, &packed);
	mesh_packed_release(&packed);
	return ret;
}

/* repeat: the detail map tiles (glTF's default) and is mipmapped, so a
 * far, dense map does not shimmer; it has power-of-two sides for that.
 * The ramp is read by angle: clamped, no mipmaps, so any size is legal in
 * GLES2. The matcap is clamped; which minifying filter reads it is chosen
 * per draw, and its mipmap chain built on the first draw that reads one
 * (matcap_choose_filter). */
static int upload_texture(const struct gl *gl, GLuint *tex, const struct image *img, bool repeat,
			  bool mipmaps)
{
	if (!*tex)
		gl->GenTextures(1, tex);
	gl->BindTexture(GL_TEXTURE_2D, *tex);
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, img->width, img->height, 0, GL_RGBA,
		       GL_UNSIGNED_BYTE, img->rgba);
	if (mipmaps)
		gl->GenerateMipmap(GL_TEXTURE_2D);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
			  mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE);
	return gl->GetError() == GL_NO_ERROR ? 0 : -EIO;
}

static bool is_pot(int n)
{
	return n > 0 && !(n & (n - 1));
}

/* GLES2 mipmaps only power-of-two textures: another size is resampled to
 * the nearest one first (the shipped matcaps are 256 x 256 already). */
int renderer_set_matcap(struct renderer *r, const struct image *img)
{
	bool pot_size = is_pot(img->width) && is_pot(img->height);
	bool forced = r->matcap_filter == MATCAP_FILTER_MIPMAP;
	struct image pot = {0};
	int ret;

	/* Under AUTO the chain is built on the first draw that reads it
	 * (matcap_choose_filter): llvmpipe compiles a blit shader for
	 * glGenerateMipmap, 40 ms of a start that a full-screen kiosk, which
	 * never reads the chain, should not pay. */
	if (!forced || pot_size) {
		ret = upload_texture(r->gl, &r->matcap, img, false, forced);
	} else {
		ret = texture_resample(img, texture_pot(img->width, 4096),
				       texture_pot(img->height, 4096), &pot);
		if (!ret)
			ret = upload_texture(r->gl, &r->matcap, &pot, false, true);
	}
	r->matcap_mippable =
	    !ret && r->matcap_filter != MATCAP_FILTER_LINEAR && (forced || pot_size);
	r->matcap_has_mips = !ret && forced;
	r->matcap_mipmapped = r->matcap_has_mips;
	r->matcap_side = pot.width ? (pot.width < pot.height ? pot.width : pot.height)
				   : (img->width < img->height ? img->width : img->height);
	image_release(&pot);
	return ret;
}

int renderer_set_background(struct renderer *r, const struct background_spec *s,
			    const struct image *img)
{
	struct background *b = background_new(r->gl, s, img);

	if (!b)
		return -EINVAL;
	background_free(r->background);
	r->background = b;
	return 0;
}

void renderer_set_matcap_filter(struct renderer *r, enum matcap_filter filter)
{
	r->matcap_filter = filter;
}

/* The unit sphere the model is fitted to spans at most twice the pixels
 * per unit at its front; the matcap's side maps onto that disc. Switching
 * the filter is one texture parameter, set only when it changes. Measured
 * in tests/bench/report/speed-error.md: at 1280x720 (disc 847 px, matcap
 * 256) linear is 2 dB closer to the reference, at 128 px (disc 151 px)
 * the mipmaps are 1-1.4 dB closer. */
bool matcap_filter_mipmaps(enum matcap_filter filter, int side, int width, int height)
{
	if (filter != MATCAP_FILTER_AUTO)
		return filter == MATCAP_FILTER_MIPMAP;
	return 2.0 * sphere_fit_pixels_per_unit(width, height) <= (double)side;
}

void render_matcap_choose_filter(struct renderer *r, const struct view *v, const int vp[4])
{
	int w, h; /* a wall's screen shows the model as large as the wall does */
	bool mip;

	wall_pixels(&v->wall, v->rotation, vp[2], vp[3], &w, &h);
	mip = r->matcap_mippable && matcap_filter_mipmaps(r->matcap_filter, r->matcap_side, w, h);

	if (mip == r->matcap_mipmapped || r->matcap_override)
		return;
	r->gl->BindTexture(GL_TEXTURE_2D, r->matcap);
	if (mip && !r->matcap_has_mips) {
		r->gl->GenerateMipmap(GL_TEXTURE_2D);
		r->matcap_has_mips = true;
	}
	r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
			     mip ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
	r->matcap_mipmapped = mip;
}

void renderer_use_matcap_texture(struct renderer *r, GLuint tex)
{
	r->matcap_override = tex;
}

int renderer_set_precision(struct renderer *r, bool highp)
{
	if (highp == r->highp)
		return 0;
	r->highp = highp;
	render_drop_programs(r);
	return r->mode_set ? renderer_set_mode(r, r->mode, r->ortho) : 0;
}

/* A material's map with its sampler's wrap (upload_texture leaves it bound). */
static int upload_wrapped(struct renderer *r, GLuint *tex, const struct image *img,
			  const int wrap[2], bool no_mipmaps)
{
	static const GLint modes[] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT};
	int ret = upload_texture(r->gl, tex, img, true, !no_mipmaps);

	r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, modes[wrap[0]]);
	r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, modes[wrap[1]]);
	return ret;
}

/* One material's maps: its base map (where the programs drawn read it),
 * its emissive map (every mode adds its light) and its own detail map. */
static int upload_surface(struct renderer *r, const struct material *m, uint32_t k)
{
	const struct material_surface *s = &m->surfaces[k];
	int ret = 0;

	if ((drawn_features(m) & MATERIAL_BASE_MAP) && s->base_map.width)
		ret = upload_wrapped(r, &r->base_maps[k], &s->base_map, s->wrap, s->no_mipmaps);
	if (!ret && (s->features & MATERIAL_EMISSIVE_MAP) && s->emissive_map.width)
		ret = upload_wrapped(r, &r->emissive_maps[k], &s->emissive_map, s->emissive_wrap,
				     s->emissive_no_mipmaps);
	if (!ret && (s->features & MATERIAL_DETAIL) && s->detail.width)
		ret = upload_texture(r->gl, &r->detail_maps[k], &s->detail, true, true);
	return ret;
}

/* Each material's sides, alpha, features and maps. A material made by
 * no mesh (surface_count 0) has the model's features. */
static int set_surfaces(struct renderer *r, const struct material *m)
{
	uint32_t n = m->surface_count ? m->surface_count : 1;
	int ret = 0;

	drop_surfaces(r);
	r->surfaces = calloc(n, sizeof(*r->surfaces));
	r->base_maps = calloc(n, sizeof(*r->base_maps));
	r->detail_maps = calloc(n, sizeof(*r->detail_maps));
	r->emissive_maps = calloc(n, sizeof(*r->emissive_maps));
	if (!r->surfaces || !r->base_maps || !r->detail_maps || !r->emissive_maps)
		return -ENOMEM;
	r->surface_count = n;
	for (uint32_t k = 0; k < n; k++) {
		struct material_surface *s = &r->surfaces[k];

		if (!m->surface_count) {
			*s = (struct material_surface){.alpha = 1.0f, .features = m->features};
			s->base_transform[0] = s->base_transform[3] = 1.0f;
			continue;
		}
		*s = m->surfaces[k];
		memset(&s->base_map, 0, sizeof(struct image));
		memset(&s->detail, 0, sizeof(struct image));
		memset(&s->emissive_map, 0, sizeof(struct image));
		if (!ret)
			ret = upload_surface(r, m, k);
	}
	return ret;
}

int renderer_set_material(struct renderer *r, const struct material *m)
{
	bool changed = m->features != r->mat.features || m->lit != r->mat.lit;
	int ret = 0;

	r->mat = *m;
	memset(&r->mat.detail, 0, sizeof(r->mat.detail));
	memset(&r->mat.ramp, 0, sizeof(r->mat.ramp));
	memset(&r->mat.height, 0, sizeof(r->mat.height));
	r->mat.surfaces = NULL;
	r->mat.surface_count = 0;
	ret = set_surfaces(r, m);
	if (!ret && (m->features & MATERIAL_DETAIL) && m->detail.width)
		ret = upload_texture(r->gl, &r->detail, &m->detail, true, true);
	else
		drop_texture(r->gl, &r->detail);
	if (!ret && (m->features & MATERIAL_RAMP))
		ret = upload_texture(r->gl, &r->ramp, &m->ramp, false, false);
	else if (!ret)
		drop_texture(r->gl, &r->ramp);
	if (ret)
		log_err("render: cannot upload the material's textures");
	if (!ret && changed) {
		render_drop_programs(r);
		if (r->mode_set)
			ret = renderer_set_mode(r, r->mode, r->ortho);
	}
	return ret;
}

static void find_uniforms(const struct gl *gl, struct program *p)
{
	p->modelview = gl->GetUniformLocation(p->id, "u_modelview");
	p->projection = gl->GetUniformLocation(p->id, "u_projection");
	p->normal_matrix = gl->GetUniformLocation(p->id, "u_normal_matrix");
	p->matcap = gl->GetUniformLocation(p->id, "u_matcap");
	p->detail = gl->GetUniformLocation(p->id, "u_detail");
	p->ramp = gl->GetUniformLocation(p->id, "u_ramp");
	p->base_map = gl->GetUniformLocation(p->id, "u_base_map");
	p->base_transform = gl->GetUniformLocation(p->id, "u_base_transform");
	p->reads_base_map = gl->GetUniformLocation(p->id, "u_reads_base_map");
	p->iridescence = gl->GetUniformLocation(p->id, "u_iridescence");
	p->hsv = gl->GetUniformLocation(p->id, "u_hsv");
	p->light = gl->GetUniformLocation(p->id, "u_light");
	p->base_color = gl->GetUniformLocation(p->id, "u_base_color");
	p->shininess = gl->GetUniformLocation(p->id, "u_shininess");
	p->alpha = gl->GetUniformLocation(p->id, "u_alpha");
	p->emissive = gl->GetUniformLocation(p->id, "u_emissive");
	p->emissive_map = gl->GetUniformLocation(p->id, "u_emissive_map");
	p->emissive_transform = gl->GetUniformLocation(p->id, "u_emissive_transform");
	p->bones = gl->GetUniformLocation(p->id, "u_bones");
	p->morph_weights = gl->GetUniformLocation(p->id, "u_morph_weights");
}

/* A range's program variant by its alphaMode (enum mesh_alpha) and sides;
 * + 6 x what its material lacks (draw_variant_missing). */
static const unsigned variant_features[DRAW_SIDES_VARIANTS] = {
    0,
    MATERIAL_ALPHA_MASK,
    MATERIAL_ALPHA_BLEND,
    MATERIAL_DOUBLE_SIDED,
    MATERIAL_DOUBLE_SIDED | MATERIAL_ALPHA_MASK,
    MATERIAL_DOUBLE_SIDED | MATERIAL_ALPHA_BLEND};

/* Lit programs do not depend on the mapping mode: one per camera. A
 * program that fails to build is not kept, so the next call tries again
 * and the one in use stays. */
static struct program *program_get(struct renderer *r, enum shading_mode mode, bool ortho, bool lit,
				   int variant)
{
	struct program *p = &r->programs[lit ? SHADING_VIEW : mode][ortho][lit][variant];
	unsigned features =
	    (r->mat.features & ~(draw_variant_missing(variant) | MATERIAL_PER_RANGE)) |
	    variant_features[variant % DRAW_SIDES_VARIANTS] | draw_variant_adds(variant);
	struct shader_source src;
	GLuint id;

	if (p->id)
		return p;
	if (shader_source_matcap(&src, r->shader_dir, features, mode, ortho, lit, r->highp))
		return NULL;
	render_skin_source(r, &src); /* a model skinned on the GPU (render_skin.c) */
	if (shader_program_build(r->gl, &src, &id))
		return NULL;
	p->id = id;
	p->features = features;
	find_uniforms(r->gl, p);
	return p;
}

/* The masked and blended programs the ranges need, built with the opaque
 * one (never on a frame). The lit mode keeps its own grey and no alpha:
 * its ranges all draw opaque. One that fails to build: its ranges draw
 * with the opaque program. */
static void prepare_variants(struct renderer *r)
{
	const struct program *p[2] = {r->current, r->beside};

	for (int side = 0; side < 2; side++) {
		bool lit = p[side] && (side == 1 || r->mat.lit == LIT_ON);
		bool alpha = p[side] && !lit && (r->mat.features & MATERIAL_BASE_COLOR);

		for (int v = 0; v < VARIANTS; v++) {
			/* The lit mode has no alpha: its sides only. */
			int sides = v % DRAW_SIDES_VARIANTS;
			int want = v - sides + (alpha ? sides : sides / 3 * 3);
			struct program *q = NULL;

			if (want && p[side] && r->variant_used[v])
				q = program_get(r, r->mode, r->ortho, lit, want);
			r->variants[side][v] = q ? q : (struct program *)p[side];
		}
	}
}

int renderer_set_mode(struct renderer *r, enum shading_mode mode, bool ortho)
{
	struct program *first = NULL, *second = NULL;
	int lit = r->mat.lit;

	if (lit != LIT_ON && !(first = program_get(r, mode, ortho, false, 0)))
		return -EINVAL;
	if (lit != LIT_OFF &&
	    !(*(lit == LIT_ON ? &first : &second) = program_get(r, mode, ortho, true, 0)))
		return -EINVAL;
	if (mode == SHADING_SEM_VERTEX && lit != LIT_ON &&
	    (r->mat.features & (MATERIAL_IRIDESCENCE | MATERIAL_DETAIL_NORMAL)))
		log_info(
		    "render: sem-vertex is drawn per fragment, where the material's normal is");
	r->current = first;
	r->beside = second;
	r->mode = mode;
	r->ortho = ortho;
	r->mode_set = true;
	prepare_variants(r);
	return 0;
}

void render_matrices(const struct view *v, int width, int height, float modelview[16],
		     float projection[16])
{
	float rot[16], move[16], proj[16], panel[16], crop[16];
	struct wall_slice slice;
	struct sphere_fit fit;

	/* The camera frames the whole wall (one screen when there is none). */
	wall_slice_turned(&v->wall, v->rotation, width, height, &slice);
	sphere_fit_init(&fit, slice.aspect);
	mat4_from_quat(rot, v->orientation);
	mat4_translate(move, 0, 0, -fit.distance);
	mat4_multiply(modelview, move, rot);
	sphere_fit_projection(&fit, v->ortho, proj);
	/* Zoom scales the picture in clip space, so perspective, depth and
	 * the fit stay as they are. */
	if (v->zoom > 0 && v->zoom != 1)
		for (int i = 0; i < 4; i++) {
			proj[4 * i] *= v->zoom;
			proj[4 * i + 1] *= v->zoom;
		}
	/* The outline's centre, zoomed, to the room's centre: a shift in
	 * clip space (x += s w), so the zoom is about that centre; its x is
	 * kept in sphere_fit_x_unit, this frame's aspect divided out. */
	for (int i = 0; i < 4; i++) {
		float z = v->zoom > 0 ? v->zoom : 1;
		double ox = v->outline[0] / sphere_fit_x_unit(v->ortho, fit.aspect);

		proj[4 * i] += (float)(v->room[0] - z * ox) * proj[4 * i + 3];
		proj[4 * i + 1] += (v->room[1] - z * v->outline[1]) * proj[4 * i + 3];
	}
	/* A wall's screen shows its slice of that one frustum: off-axis. */
	if (!slice.whole) {
		wall_crop(&slice, crop);
		mat4_multiply(proj, crop, proj);
	}
	/* A portrait panel turns the picture, not the scanout, so it works
	 * with every driver and plane. */
	mat4_rotate_z(panel, v->rotation);
	mat4_multiply(projection, panel, proj);
}

void renderer_get_stats(const struct renderer *r, struct renderer_stats *out)
{
	const struct program *p[2] = {r->current, r->beside};
	bool matcap = false, detail = false, ramp = false, base = false;

	memset(out, 0, sizeof(*out));
	for (int a = 0; a < SHADER_ATTR_COUNT; a++) {
		out->attributes += r->attr_bytes[a] > 0;
		out->vertex_bytes += r->attr_bytes[a];
	}
	for (int i = 0; i < 2; i++)
		if (p[i]) {
			matcap |= p[i]->matcap >= 0;
			detail |= p[i]->detail >= 0;
			ramp |= p[i]->ramp >= 0;
			base |= p[i]->base_map >= 0;
		}
	out->textures = matcap + detail + ramp + base;
	out->program = p[0] ? p[0]->id : 0;
	out->lit_program = p[1] ? p[1]->id : 0;
	out->highp = r->highp;
	out->matcap_filter = r->matcap_filter;
	out->matcap_mipmapped = r->matcap_mipmapped;
	out->format = r->drawn;
	out->draws = r->list.count;
	for (uint32_t i = 0; r->current && i < r->list.count; i++) {
		const struct program *q = r->variants[0][draw_item_variant(&r->list.items[i])];
		uint32_t k = 0, n = out->program_count < 4 ? out->program_count : 4;

		while (k < n && out->drawn[k].program != q->id)
			k++;
		if (k < n)
			continue;
		if (out->program_count++ < 4) {
			out->drawn[k].program = q->id;
			out->drawn[k].surface = r->list.items[i].surface;
		}
	}
}
