#include "render/render.h"
#include "render/background.h"
#include "util/log.h"
#include "render/shader.h"
#include "scene/texture.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The lit mode's light, fixed to the camera, from where the shipped
 * matcaps' key light is (src/render/bake.c), so that the two read alike. */
static const float light_dir[3] = {-0.5499f, 0.6198f, 0.5599f};

enum { UNIT_MATCAP, UNIT_DETAIL, UNIT_RAMP, UNIT_BASE };

struct program {
	GLuint id;
	GLint modelview, projection, normal_matrix, matcap, detail, ramp, base_map, base_transform;
	GLint iridescence, hsv, light, base_color, shininess;
};

struct renderer {
	const struct gl *gl;
	const char *shader_dir;
	struct program programs[SHADING_MODE_COUNT][2][2]; /* [mode][ortho][lit] */
	struct program *current; /* the matcap program, or the lit one alone */
	struct program *beside;	 /* lit = beside: the lit program, drawn right */
	enum shading_mode mode;
	bool ortho, mode_set;
	bool highp;	     /* every float highp (PRECISION_HIGHP): see renderer_new */
	struct material mat; /* the features and their numbers; no images */
	GLuint vbo[SHADER_ATTR_COUNT], ibo, matcap, detail, ramp, base_map;
	GLuint matcap_override; /* another's texture as the matcap (the camera's); 0: none */
	long attr_bytes[SHADER_ATTR_COUNT]; /* 0: not uploaded */
	GLenum index_type;
	GLsizei draw_count;
	bool indexed;
	enum vertex_format format; /* for the next renderer_set_mesh */
	enum vertex_format drawn;  /* of the arrays uploaded */
	float position_scale;	   /* int16 positions: the model units of 1.0 */
	enum matcap_filter matcap_filter;
	bool matcap_mippable;	       /* the image texture's size can have a chain */
	bool matcap_has_mips;	       /* it has its mipmap chain */
	int matcap_side;	       /* its shorter side, texels */
	bool matcap_mipmapped;	       /* its minifying filter now reads the chain */
	struct background *background; /* NULL: the view's clear colour */
};

struct renderer *renderer_new(const struct gl *gl, const char *shader_dir)
{
	struct renderer *r = calloc(1, sizeof(*r));

	if (!r)
		return NULL;
	r->gl = gl;
	r->shader_dir = shader_dir;
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
	gl->GenBuffers(1, &r->ibo);
	gl->GenTextures(1, &r->matcap);
	return r;
}

static void drop_programs(struct renderer *r)
{
	struct program *p = &r->programs[0][0][0];

	for (size_t i = 0; i < sizeof(r->programs) / sizeof(*p); i++)
		if (p[i].id)
			r->gl->DeleteProgram(p[i].id);
	memset(r->programs, 0, sizeof(r->programs));
	r->current = r->beside = NULL;
}

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
	drop_programs(r);
	r->gl->DeleteBuffers(SHADER_ATTR_COUNT, r->vbo);
	r->gl->DeleteBuffers(1, &r->ibo);
	r->gl->DeleteTextures(1, &r->matcap);
	drop_texture(r->gl, &r->detail);
	drop_texture(r->gl, &r->ramp);
	drop_texture(r->gl, &r->base_map);
	background_free(r->background);
	free(r);
}

/* Core GLES2 indexes with 16 bits; 32-bit indices need an extension that
 * some SBC GPUs lack, and then the mesh is drawn unindexed. */
static int upload_indices(struct renderer *r, const struct mesh_packed *m)
{
	const struct gl *gl = r->gl;

	r->indexed = true;
	r->draw_count = (GLsizei)m->index_count;
	gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
	if (m->vertex_count <= 65536) {
		uint16_t *idx16 = malloc((size_t)m->index_count * 2 + 1);

		if (!idx16)
			return -ENOMEM;
		for (uint32_t i = 0; i < m->index_count; i++)
			idx16[i] = (uint16_t)m->indices[i];
		gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)m->index_count * 2, idx16,
			       GL_STATIC_DRAW);
		free(idx16);
		r->index_type = GL_UNSIGNED_SHORT;
		return 0;
	}
	if (gl->caps.element_index_uint) {
		gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)m->index_count * 4, m->indices,
			       GL_STATIC_DRAW);
		r->index_type = GL_UNSIGNED_INT;
		return 0;
	}
	r->indexed = false;
	return 0;
}

/* One attribute array: as it is when indexed, else one entry per index. */
static int upload_attribute(struct renderer *r, const struct mesh_packed *m, int a)
{
	const struct gl *gl = r->gl;
	size_t stride = mesh_array_stride(m->format, (enum mesh_array)a);
	size_t count = r->indexed ? m->vertex_count : m->index_count;
	const char *src = m->arrays[a];
	char *flat = NULL;

	if (!r->indexed) {
		flat = malloc(count * stride + 1);
		if (!flat)
			return -ENOMEM;
		for (uint32_t i = 0; i < m->index_count; i++)
			memcpy(flat + i * stride, src + (size_t)m->indices[i] * stride, stride);
	}
	r->attr_bytes[a] = (long)(count * stride);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo[a]);
	gl->BufferData(GL_ARRAY_BUFFER, r->attr_bytes[a], flat ? (const void *)flat : src,
		       GL_STATIC_DRAW);
	free(flat);
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
	bool used[SHADER_ATTR_COUNT] = {true, true, uvs, tangents, colors};
	int ret = upload_indices(r, m);

	r->drawn = m->format;
	r->position_scale = m->position_scale;
	/* Colours without an array are one constant (material vertex_color). */
	if ((uvs && !m->arrays[MESH_UVS]) || (tangents && !m->arrays[MESH_TANGENTS]))
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

static void matcap_choose_filter(struct renderer *r, const int vp[4])
{
	bool mip = r->matcap_mippable &&
		   matcap_filter_mipmaps(r->matcap_filter, r->matcap_side, vp[2], vp[3]);

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
	drop_programs(r);
	return r->mode_set ? renderer_set_mode(r, r->mode, r->ortho) : 0;
}

int renderer_set_material(struct renderer *r, const struct material *m)
{
	bool changed = m->features != r->mat.features || m->lit != r->mat.lit;
	int ret = 0;

	r->mat = *m;
	memset(&r->mat.detail, 0, sizeof(r->mat.detail));
	memset(&r->mat.ramp, 0, sizeof(r->mat.ramp));
	memset(&r->mat.height, 0, sizeof(r->mat.height));
	memset(&r->mat.base_map, 0, sizeof(r->mat.base_map));
	if (m->features & MATERIAL_DETAIL)
		ret = upload_texture(r->gl, &r->detail, &m->detail, true, true);
	else
		drop_texture(r->gl, &r->detail);
	if (!ret && (m->features & MATERIAL_RAMP))
		ret = upload_texture(r->gl, &r->ramp, &m->ramp, false, false);
	else if (!ret)
		drop_texture(r->gl, &r->ramp);
	if (!ret && (drawn_features(m) & MATERIAL_BASE_MAP))
		ret = upload_texture(r->gl, &r->base_map, &m->base_map, true, true);
	else if (!ret)
		drop_texture(r->gl, &r->base_map);
	if (ret)
		log_err("render: cannot upload the material's textures");
	if (!ret && changed) {
		drop_programs(r);
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
	p->iridescence = gl->GetUniformLocation(p->id, "u_iridescence");
	p->hsv = gl->GetUniformLocation(p->id, "u_hsv");
	p->light = gl->GetUniformLocation(p->id, "u_light");
	p->base_color = gl->GetUniformLocation(p->id, "u_base_color");
	p->shininess = gl->GetUniformLocation(p->id, "u_shininess");
}

/* Lit programs do not depend on the mapping mode: one per camera. A
 * program that fails to build is not kept, so the next call tries again
 * and the one in use stays. */
static struct program *program_get(struct renderer *r, enum shading_mode mode, bool ortho, bool lit)
{
	struct program *p = &r->programs[lit ? SHADING_VIEW : mode][ortho][lit];
	struct shader_source src;
	GLuint id;

	if (p->id)
		return p;
	if (shader_source_matcap(&src, r->shader_dir, r->mat.features, mode, ortho, lit,
				 r->highp) ||
	    shader_program_build(r->gl, &src, &id))
		return NULL;
	p->id = id;
	find_uniforms(r->gl, p);
	return p;
}

int renderer_set_mode(struct renderer *r, enum shading_mode mode, bool ortho)
{
	struct program *first = NULL, *second = NULL;
	int lit = r->mat.lit;

	if (lit != LIT_ON && !(first = program_get(r, mode, ortho, false)))
		return -EINVAL;
	if (lit != LIT_OFF &&
	    !(*(lit == LIT_ON ? &first : &second) = program_get(r, mode, ortho, true)))
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
	return 0;
}

void render_matrices(const struct view *v, int width, int height, float modelview[16],
		     float projection[16])
{
	bool quarter = v->rotation == 90 || v->rotation == 270;
	float rot[16], move[16], proj[16], panel[16];
	struct sphere_fit fit;

	sphere_fit_init(&fit, quarter ? (double)height / width : (double)width / height);
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
	/* A portrait panel turns the picture, not the scanout, so it works
	 * with every driver and plane. */
	mat4_rotate_z(panel, v->rotation);
	mat4_multiply(projection, panel, proj);
}

static void bind_texture(const struct gl *gl, GLint uniform, int unit, GLuint tex)
{
	if (uniform < 0)
		return;
	gl->ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
	gl->BindTexture(GL_TEXTURE_2D, tex);
	gl->Uniform1i(uniform, unit);
}

static void set_uniforms(const struct renderer *r, const struct program *p)
{
	const struct gl *gl = r->gl;
	const struct material *m = &r->mat;

	bind_texture(gl, p->matcap, UNIT_MATCAP,
		     r->matcap_override ? r->matcap_override : r->matcap);
	bind_texture(gl, p->detail, UNIT_DETAIL, r->detail);
	bind_texture(gl, p->ramp, UNIT_RAMP, r->ramp);
	bind_texture(gl, p->base_map, UNIT_BASE, r->base_map);
	if (p->base_transform >= 0) {
		const float *t = m->base_transform;
		const float m3[9] = {t[0], t[1], 0, t[2], t[3], 0, t[4], t[5], 1};

		gl->UniformMatrix3fv(p->base_transform, 1, GL_FALSE, m3);
	}
	if (p->iridescence >= 0)
		gl->Uniform4f(p->iridescence, m->hue_range, m->hue_average, m->hue_shift,
			      m->opacity);
	if (p->hsv >= 0)
		gl->Uniform2f(p->hsv, m->saturation, m->value);
	if (p->light >= 0)
		gl->Uniform3f(p->light, light_dir[0], light_dir[1], light_dir[2]);
	if (p->base_color >= 0)
		gl->Uniform3f(p->base_color, m->base_color[0], m->base_color[1], m->base_color[2]);
	if (p->shininess >= 0)
		gl->Uniform1f(p->shininess, m->shininess);
}

static const GLenum gl_types[] = {
    [MESH_FLOAT32] = GL_FLOAT, [MESH_SNORM16] = GL_SHORT, [MESH_UNORM8] = GL_UNSIGNED_BYTE};

static void draw_with(struct renderer *r, const struct program *p, const struct view *v,
		      const int vp[4])
{
	const struct gl *gl = r->gl;
	float mv[16], proj[16], nm[9];

	gl->Viewport(vp[0], vp[1], vp[2], vp[3]);
	matcap_choose_filter(r, vp);
	render_matrices(v, vp[2], vp[3], mv, proj);
	/* The model-view is a rotation and a translation: its upper 3x3 is
	 * already the inverse transpose. Scales and mirrors were baked into
	 * the mesh in double precision at load time. */
	mat3_from_mat4(nm, mv);
	/* int16 positions are in units of the mesh's largest coordinate:
	 * the model-view scales them back (the normals' matrix stays). */
	for (int i = 0; i < 12; i++)
		mv[i] *= r->position_scale;
	gl->UseProgram(p->id);
	gl->UniformMatrix4fv(p->modelview, 1, GL_FALSE, mv);
	gl->UniformMatrix4fv(p->projection, 1, GL_FALSE, proj);
	gl->UniformMatrix3fv(p->normal_matrix, 1, GL_FALSE, nm);
	set_uniforms(r, p);
	for (int a = 0; a < SHADER_ATTR_COUNT; a++) {
		enum mesh_component c = mesh_array_component(r->drawn, (enum mesh_array)a);

		if (!r->attr_bytes[a]) {
			/* A disabled array reads the constant: a model of one
			 * colour needs no colour per vertex. */
			gl->DisableVertexAttribArray((GLuint)a);
			if (a == SHADER_ATTR_COLOR)
				gl->VertexAttrib4fv((GLuint)a, r->mat.vertex_color);
			continue;
		}
		gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo[a]);
		gl->VertexAttribPointer((GLuint)a, mesh_array_components((enum mesh_array)a),
					gl_types[c], c != MESH_FLOAT32 ? GL_TRUE : GL_FALSE, 0,
					NULL);
		gl->EnableVertexAttribArray((GLuint)a);
	}
	if (r->indexed) {
		gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
		gl->DrawElements(GL_TRIANGLES, r->draw_count, r->index_type, NULL);
	} else {
		gl->DrawArrays(GL_TRIANGLES, 0, r->draw_count);
	}
}

/* lit = beside: the matcap on the panel's left half, the lit mode on its
 * right. The picture is turned by the panel's rotation, so the panel's
 * left is the frame's left (0), bottom (90), right (180) or top (270). */
static void half_viewport(int rotation, int w, int h, bool left, int vp[4])
{
	bool low = (rotation == 0 || rotation == 90) == left;

	if (rotation == 90 || rotation == 270) {
		vp[0] = 0, vp[2] = w;
		vp[1] = low ? 0 : h / 2, vp[3] = low ? h / 2 : h - h / 2;
	} else {
		vp[1] = 0, vp[3] = h;
		vp[0] = low ? 0 : w / 2, vp[2] = low ? w / 2 : w - w / 2;
	}
}

void renderer_draw(struct renderer *r, const struct view *v, int width, int height)
{
	const struct gl *gl = r->gl;
	int vp[4] = {0, 0, width, height};

	if (r->background) {
		background_draw(r->background, width, height, v->rotation);
	} else {
		gl->ClearColor(v->background[0], v->background[1], v->background[2], 1.0f);
		gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	}
	if (!r->current || !r->draw_count)
		return;
	gl->Enable(GL_DEPTH_TEST);
	gl->Enable(GL_CULL_FACE);
	gl->CullFace(GL_BACK);
	gl->FrontFace(GL_CCW);
	if (r->beside) {
		half_viewport(v->rotation, width, height, true, vp);
		draw_with(r, r->current, v, vp);
		half_viewport(v->rotation, width, height, false, vp);
		draw_with(r, r->beside, v, vp);
		gl->Viewport(0, 0, width, height);
	} else {
		draw_with(r, r->current, v, vp);
	}
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
}
