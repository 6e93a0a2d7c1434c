/* A mesh that plays its animation: posed on the CPU, its float32
 * positions and normals replaced a frame (renderer_set_mesh_live); or
 * skinned on the GPU (renderer_set_mesh_skinned): its vertices' four
 * bones and weights in two arrays of their own, and the palette's rows
 * set on every program that skins (its morph targets: render_morph.c). A model without animation
 * keeps today's programs (no SKIN_BONES), arrays and uniforms. */
#include "render/render.h"
#include "render/render_priv.h"
#include "scene/anim_palette.h"
#include "util/log.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int renderer_set_mesh_live(struct renderer *r, const struct mesh *m)
{
	struct mesh_packed packed;
	int ret = mesh_pack(m, VERTEX_FLOAT32, &packed);

	/* Its gather (16-bit chunks) is kept: each pose is gathered alike. */
	r->live_next = true;
	if (!ret)
		ret = render_variants_take(r, m);
	if (!ret)
		ret = renderer_set_packed(r, &packed);
	mesh_packed_release(&packed);
	return ret;
}

/* One float32 array of xyz per vertex into its buffer, gathered as it was
 * uploaded. */
static void replace_xyz(struct renderer *r, int a, const float *src)
{
	const struct draw_list *l = &r->list;
	size_t count = l->gather ? l->gather_count : (size_t)r->attr_bytes[a] / 12;
	float *g = l->gather ? r->live_scratch : NULL;

	for (size_t i = 0; g && i < count; i++)
		memcpy(g + i * 3, src + (size_t)l->gather[i] * 3, 12);
	r->gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo[a]);
	r->gl->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)(count * 12), g ? g : src);
}

void renderer_set_vertices(struct renderer *r, const float *positions, const float *normals)
{
	if (!r->live || r->drawn != VERTEX_FLOAT32)
		return;
	replace_xyz(r, SHADER_ATTR_POSITION, positions);
	replace_xyz(r, SHADER_ATTR_NORMAL, normals);
}

static void drop_palettes(struct renderer *r)
{
	free(r->palette_first);
	free(r->palette_count);
	free(r->palette_bones);
	free(r->palette_rows);
	r->palette_first = r->palette_count = NULL;
	r->palette_bones = NULL;
	r->palette_rows = NULL;
	r->range_count = 0;
}

int render_skin_set(struct renderer *r)
{
	uint32_t bones = r->bones_next;
	bool same_morphs = render_morph_set(r);

	drop_palettes(r); /* a split's are set after its mesh */
	r->bones_next = 0;
	if (bones == r->bones && same_morphs)
		return 0;
	r->bones = bones;
	if (!bones) {
		r->gl->DisableVertexAttribArray(SHADER_ATTR_JOINTS);
		r->gl->DisableVertexAttribArray(SHADER_ATTR_WEIGHTS);
	}
	render_drop_programs(r);
	return r->mode_set ? renderer_set_mode(r, r->mode, r->ortho) : 0;
}

unsigned renderer_mesh_serial(const struct renderer *r)
{
	return r->mesh_serial;
}

void render_live_free(struct renderer *r)
{
	r->gl->DeleteBuffers(2, r->skin_vbo);
	free(r->bone_rows);
	free(r->live_scratch);
	drop_palettes(r);
	render_morph_free(r);
}

void render_skin_source(const struct renderer *r, struct shader_source *src)
{
	if (!r->bones)
		return;
	src->bones = (int)r->bones;
	src->attributes[SHADER_ATTR_JOINTS] = "a_joints";
	src->attributes[SHADER_ATTR_WEIGHTS] = "a_weights";
	render_morph_source(r, src);
}

uint32_t renderer_bone_palette(const struct renderer *r)
{
	return r->bone_limit;
}

void renderer_set_bone_limit(struct renderer *r, uint32_t bones)
{
	uint32_t gpu =
	    anim_palette_size(r->gl->caps.max_vertex_uniform_vectors, RENDER_SKIN_RESERVED);

	r->bone_limit = bones < gpu ? bones : gpu;
}

/* One array of 4 floats a vertex, gathered into 16-bit chunks as the
 * mesh's were. */
static int upload_vec4(struct renderer *r, GLuint vbo, const float *src, uint32_t count)
{
	const struct draw_list *l = &r->list;
	size_t n = l->gather ? l->gather_count : count;
	float *g = l->gather ? malloc(n * 16 + 1) : NULL;

	if (l->gather && !g)
		return -ENOMEM;
	for (size_t i = 0; g && i < n; i++)
		memcpy(g + i * 4, src + (size_t)l->gather[i] * 4, 16);
	r->gl->BindBuffer(GL_ARRAY_BUFFER, vbo);
	r->gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * 16), g ? g : src, GL_STATIC_DRAW);
	free(g);
	return 0;
}

/* A split's palettes, copied: each range's bones among the total. */
static int set_palettes(struct renderer *r, const struct skin_palettes *sp)
{
	size_t n = 0;

	for (uint32_t i = 0; i < sp->range_count; i++)
		n = sp->first[i] + sp->count[i] > n ? sp->first[i] + sp->count[i] : n;
	r->palette_first = malloc((size_t)sp->range_count * 4 + 4);
	r->palette_count = malloc((size_t)sp->range_count * 4 + 4);
	r->palette_bones = malloc(n * 2 + 2);
	r->palette_rows = malloc((size_t)r->bones * 48 + 4);
	if (!r->palette_first || !r->palette_count || !r->palette_bones || !r->palette_rows) {
		drop_palettes(r);
		return -ENOMEM;
	}
	memcpy(r->palette_first, sp->first, (size_t)sp->range_count * 4);
	memcpy(r->palette_count, sp->count, (size_t)sp->range_count * 4);
	memcpy(r->palette_bones, sp->bones, n * 2);
	r->range_count = sp->range_count;
	return 0;
}

int renderer_set_mesh_skinned(struct renderer *r, const struct mesh *m, const float *joints,
			      const float *weights, uint32_t bones,
			      const struct skin_palettes *split, const struct skin_morphs *morphs)
{
	struct mesh_packed packed;
	uint32_t total = split ? split->total : bones;
	float *rows = calloc((size_t)total * 12 + 1, sizeof(float));
	int ret = rows && bones ? mesh_pack(m, VERTEX_FLOAT32, &packed) : -ENOMEM;

	if (ret) {
		free(rows);
		return ret;
	}
	free(r->bone_rows);
	r->bone_rows = rows;
	r->bone_total = total;
	for (uint32_t b = 0; b < total; b++) /* the identity until posed */
		rows[b * 12] = rows[b * 12 + 5] = rows[b * 12 + 10] = 1.0f;
	r->live_next = true;
	r->bones_next = bones;
	r->morph_next = morphs ? morphs->targets : 0;
	r->morph_normals_next = morphs && morphs->targets && morphs->normals;
	/* Its variants' table, as a still's (a split's is over its draws). */
	ret = render_variants_take(r, m);
	if (!ret)
		ret = renderer_set_packed(r, &packed);
	mesh_packed_release(&packed);
	if (!ret)
		ret = upload_vec4(r, r->skin_vbo[0], joints, m->vertex_count);
	if (!ret)
		ret = upload_vec4(r, r->skin_vbo[1], weights, m->vertex_count);
	if (!ret && split)
		ret = set_palettes(r, split);
	if (!ret && r->morph_targets)
		ret = render_morph_upload(r, morphs, m->vertex_count);
	return ret;
}

void renderer_set_bones(struct renderer *r, const float *rows)
{
	if (r->bones)
		memcpy(r->bone_rows, rows, (size_t)r->bone_total * 12 * sizeof(float));
}

void render_skin_bind(const struct renderer *r, uint32_t base)
{
	if (!r->bones)
		return;
	for (int a = 0; a < 2; a++) {
		GLuint at = a ? SHADER_ATTR_WEIGHTS : SHADER_ATTR_JOINTS;

		r->gl->BindBuffer(GL_ARRAY_BUFFER, r->skin_vbo[a]);
		r->gl->VertexAttribPointer(at, 4, GL_FLOAT, GL_FALSE, 0,
					   (const void *)(uintptr_t)(base * 16u));
		r->gl->EnableVertexAttribArray(at);
	}
	render_morph_bind(r, base);
}

void render_skin_uniforms(const struct renderer *r, const struct program *p)
{
	/* A split palette's rows are set per draw (render_skin_palette). */
	if (p->bones >= 0 && r->bones && !r->range_count)
		r->gl->Uniform4fv(p->bones, (GLsizei)r->bones * 3, r->bone_rows);
	render_morph_uniforms(r, p);
}

void render_skin_palette(struct renderer *r, const struct program *p, uint32_t range,
			 uint32_t *shown)
{
	uint32_t n;

	if (!r->range_count || p->bones < 0 || range == *shown || range >= r->range_count)
		return;
	n = r->palette_count[range];
	for (uint32_t i = 0; i < n; i++)
		memcpy(r->palette_rows + (size_t)i * 12,
		       r->bone_rows + (size_t)r->palette_bones[r->palette_first[range] + i] * 12,
		       48);
	r->gl->Uniform4fv(p->bones, (GLsizei)n * 3, r->palette_rows);
	*shown = range;
}
