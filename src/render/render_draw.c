/* The draws of a frame: one per range of the draw list (render/draw_list.c),
 * with the GL state set only where it changes. */
#include "render/render.h"
#include "render/render_priv.h"

#include <stdint.h>

/* The lit mode's light, fixed to the camera, from where the shipped
 * matcaps' key light is (src/render/bake.c), so that the two read alike. */
static const float light_dir[3] = {-0.5499f, 0.6198f, 0.5599f};

static void bind_texture(const struct gl *gl, GLint uniform, int unit, GLuint tex)
{
	if (uniform < 0)
		return;
	gl->ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
	gl->BindTexture(GL_TEXTURE_2D, tex);
	gl->Uniform1i(uniform, unit);
}

/* What every range of a program shares: the matcap, the ramp and the
 * material's numbers. */
static void set_uniforms(const struct renderer *r, const struct program *p)
{
	const struct gl *gl = r->gl;
	const struct material *m = &r->mat;

	bind_texture(gl, p->matcap, UNIT_MATCAP,
		     r->matcap_override ? r->matcap_override : r->matcap);
	bind_texture(gl, p->ramp, UNIT_RAMP, r->ramp);
	if (p->hsv >= 0)
		gl->Uniform2f(p->hsv, m->saturation, m->value);
	if (p->light >= 0)
		gl->Uniform3f(p->light, light_dir[0], light_dir[1], light_dir[2]);
	if (p->base_color >= 0)
		gl->Uniform3f(p->base_color, m->base_color[0], m->base_color[1], m->base_color[2]);
	if (p->shininess >= 0)
		gl->Uniform1f(p->shininess, m->shininess);
}

/* A map's KHR_texture_transform (mesh_material.base_transform) as a mat3. */
static void set_transform(const struct gl *gl, GLint uniform, const float t[6])
{
	const float m3[9] = {t[0], t[1], 0, t[2], t[3], 0, t[4], t[5], 1};

	if (uniform >= 0)
		gl->UniformMatrix3fv(uniform, 1, GL_FALSE, m3);
}

/* What one material changes: its base map, its transform and its alpha,
 * its detail map (else the model's) and its iridescence (where its
 * program has them). A material without a base map leaves the last one
 * bound and says so (u_reads_base_map 0): its draw reads none of it. */
static void set_surface(const struct renderer *r, const struct program *p, uint32_t k)
{
	const struct gl *gl = r->gl;
	const struct material_surface *s = &r->surfaces[k];

	if (r->base_maps[k] || !k)
		bind_texture(gl, p->base_map, UNIT_BASE, r->base_maps[k]);
	bind_texture(gl, p->detail, UNIT_DETAIL, r->detail_maps[k] ? r->detail_maps[k] : r->detail);
	if (p->iridescence >= 0 && (s->features & MATERIAL_IRIDESCENCE))
		gl->Uniform4f(p->iridescence, s->hue_range, s->hue_average, s->hue_shift,
			      s->opacity);
	else if (p->iridescence >= 0)
		gl->Uniform4f(p->iridescence, r->mat.hue_range, r->mat.hue_average,
			      r->mat.hue_shift, r->mat.opacity);
	set_transform(gl, p->base_transform, s->base_transform);
	if (p->reads_base_map >= 0)
		gl->Uniform1f(p->reads_base_map, r->base_maps[k] ? 1.0f : 0.0f);
	if (p->alpha >= 0)
		gl->Uniform2f(p->alpha, s->alpha, s->alpha_cutoff);
	if (p->emissive >= 0)
		gl->Uniform3f(p->emissive, s->emissive[0], s->emissive[1], s->emissive[2]);
	bind_texture(gl, p->emissive_map, UNIT_EMISSIVE, r->emissive_maps[k]);
	set_transform(gl, p->emissive_transform, s->emissive_transform);
}

static const GLenum gl_types[] = {
    [MESH_FLOAT32] = GL_FLOAT, [MESH_SNORM16] = GL_SHORT, [MESH_UNORM8] = GL_UNSIGNED_BYTE};

/* The arrays from vertex `base` on (a 16-bit chunk's first vertex). */
static void bind_arrays(const struct renderer *r, uint32_t base)
{
	const struct gl *gl = r->gl;

	for (int a = 0; a < SHADER_ATTR_COUNT; a++) {
		enum mesh_component c = mesh_array_component(r->drawn, (enum mesh_array)a);
		size_t stride = mesh_array_stride(r->drawn, (enum mesh_array)a);

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
					(const void *)(uintptr_t)(base * stride));
		gl->EnableVertexAttribArray((GLuint)a);
	}
	render_skin_bind(r, base);
}

/* The GL state the draws of one frame pass through, set only where it
 * changes: a model of one opaque material draws as it always did. */
struct draw_state {
	const struct program *program;
	uint32_t surface, base;
	uint32_t palette; /* the range whose split palette is set; UINT32_MAX: none */
	bool culled, blending;
	const float *mv, *proj, *nm;
};

static void use_program(const struct renderer *r, struct draw_state *st, const struct program *p)
{
	const struct gl *gl = r->gl;

	gl->UseProgram(p->id);
	gl->UniformMatrix4fv(p->modelview, 1, GL_FALSE, st->mv);
	gl->UniformMatrix4fv(p->projection, 1, GL_FALSE, st->proj);
	gl->UniformMatrix3fv(p->normal_matrix, 1, GL_FALSE, st->nm);
	render_skin_uniforms(r, p);
	set_uniforms(r, p);
	st->program = p;
	st->surface = UINT32_MAX;
	st->palette = UINT32_MAX;
}

static void draw_item(struct renderer *r, struct draw_state *st, int side,
		      const struct draw_item *it)
{
	const struct gl *gl = r->gl;
	const struct program *p = r->variants[side][draw_item_variant(it)];
	bool blend = (p->features & MATERIAL_ALPHA_BLEND) != 0;

	if (p != st->program)
		use_program(r, st, p);
	render_skin_palette(r, p, it->range, &st->palette);
	bool recolour = it->surface != st->surface || it->base_vertex != st->base;
	const float *colour = render_variant_color(r, it->surface);

	if (it->surface != st->surface) {
		set_surface(r, p, it->surface);
		st->surface = it->surface;
	}
	if (it->base_vertex != st->base) {
		bind_arrays(r, it->base_vertex);
		st->base = it->base_vertex;
	}
	/* Colours by material (a model with variants): the constant colour
	 * attribute is this range's material's, as its variant has it. */
	if (recolour && colour && !r->attr_bytes[SHADER_ATTR_COLOR])
		gl->VertexAttrib4fv(SHADER_ATTR_COLOR, colour);
	if (it->double_sided == st->culled) {
		st->culled = !it->double_sided;
		(st->culled ? gl->Enable : gl->Disable)(GL_CULL_FACE);
	}
	if (blend != st->blending) {
		/* Blended parts over what is drawn, behind each other, and
		 * hiding nothing: no depth writes. The frame's alpha stays 1. */
		(blend ? gl->Enable : gl->Disable)(GL_BLEND);
		gl->BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
		gl->DepthMask(blend ? GL_FALSE : GL_TRUE);
		st->blending = blend;
	}
	gl->DrawElements(
	    GL_TRIANGLES, (GLsizei)it->count, r->index_type,
	    (const void *)(uintptr_t)(it->first * (r->index_type == GL_UNSIGNED_INT ? 4u : 2u)));
}

static void draw_with(struct renderer *r, int side, const struct view *v, const int vp[4])
{
	const struct gl *gl = r->gl;
	float mv[16], proj[16], nm[9];
	struct draw_state st = {.culled = true, .mv = mv, .proj = proj, .nm = nm};

	gl->Viewport(vp[0], vp[1], vp[2], vp[3]);
	render_matcap_choose_filter(r, v, vp);
	render_matrices(v, vp[2], vp[3], mv, proj);
	draw_list_sort_blended(&r->list, mv);
	/* The model-view is a rotation and a translation: its upper 3x3 is
	 * already the inverse transpose. Scales and mirrors were baked into
	 * the mesh in double precision at load time. */
	mat3_from_mat4(nm, mv);
	/* int16 positions are in units of the mesh's largest coordinate:
	 * the model-view scales them back (the normals' matrix stays). */
	for (int i = 0; i < 12; i++)
		mv[i] *= r->position_scale;
	use_program(r, &st, r->variants[side][0]);
	bind_arrays(r, 0);
	gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
	for (uint32_t i = 0; i < r->list.count; i++)
		draw_item(r, &st, side, &r->list.items[i]);
	if (st.blending) {
		gl->Disable(GL_BLEND);
		gl->DepthMask(GL_TRUE);
	}
	if (!st.culled)
		gl->Enable(GL_CULL_FACE);
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

	if (r->background && !v->plain_background) {
		struct wall_slice s;

		wall_slice_turned(&v->wall, v->rotation, width, height, &s);
		background_draw_slice(r->background, &s, v->rotation);
	} else {
		gl->ClearColor(v->background[0], v->background[1], v->background[2], 1.0f);
		gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	}
	if (!r->current || !r->list.count)
		return;
	gl->Enable(GL_DEPTH_TEST);
	gl->Enable(GL_CULL_FACE);
	gl->CullFace(GL_BACK);
	gl->FrontFace(GL_CCW);
	if (r->beside) {
		half_viewport(v->rotation, width, height, true, vp);
		draw_with(r, 0, v, vp);
		half_viewport(v->rotation, width, height, false, vp);
		draw_with(r, 1, v, vp);
		gl->Viewport(0, 0, width, height);
	} else {
		draw_with(r, 0, v, vp);
		render_draw_hotspots(r, v, width, height);
	}
}
