/* A mesh that plays its animation: posed on the CPU, its float32
 * positions and normals replaced a frame (renderer_set_mesh_live); or
 * skinned on the GPU (renderer_set_mesh_skinned): its vertices' four
 * bones and weights in two arrays of their own, and the palette's rows
 * set on every program that skins (the skinning state: render_skin.c; its
 * morph targets: render_morph.c). A model without animation keeps today's
 * programs (no SKIN_BONES), arrays and uniforms. */
#include "render/render.h"
#include "render/render_priv.h"
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

unsigned renderer_mesh_serial(const struct renderer *r)
{
	return r->mesh_serial;
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
		ret = render_skin_set_palettes(r, split);
	if (!ret && r->morph_targets)
		ret = render_morph_upload(r, morphs, m->vertex_count);
	return ret;
}
