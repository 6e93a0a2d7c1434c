/* Morph targets on the GPU (render.h renderer_set_mesh_skinned): each
 * target's deltas an attribute at a location the model's program leaves
 * free (the mesh's arrays its material reads and the skin's two keep
 * theirs), all in one buffer gathered into 16-bit chunks as the mesh's
 * arrays are, and the pose's weights a uniform set a frame. A mesh
 * without targets on the GPU builds programs without MORPH_TARGETS and
 * binds no array of them. */
#include "render/render.h"
#include "render/render_priv.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char *const morph_names[2][8] = {
    {"a_morph_p0", "a_morph_p1", "a_morph_p2", "a_morph_p3", "a_morph_p4", "a_morph_p5",
     "a_morph_p6", "a_morph_p7"},
    {"a_morph_n0", "a_morph_n1", "a_morph_n2", "a_morph_n3", "a_morph_n4", "a_morph_n5",
     "a_morph_n6", "a_morph_n7"}};

static uint32_t attribute_limit(const struct renderer *r)
{
	uint32_t gpu = (uint32_t)r->gl->caps.max_vertex_attribs;

	if (gpu > SHADER_MAX_ATTRIBUTES)
		gpu = SHADER_MAX_ATTRIBUTES;
	return r->attribute_limit && r->attribute_limit < gpu ? r->attribute_limit : gpu;
}

/* The locations a skinning program of this material reads. */
static void used_locations(const struct renderer *r, bool used[SHADER_MAX_ATTRIBUTES])
{
	unsigned f = r->mat.features;

	memset(used, 0, SHADER_MAX_ATTRIBUTES * sizeof(*used));
	used[SHADER_ATTR_POSITION] = used[SHADER_ATTR_NORMAL] = true;
	used[SHADER_ATTR_UV] = material_needs_uvs(f);
	used[SHADER_ATTR_TANGENT] = material_needs_tangents(f);
	used[SHADER_ATTR_COLOR] = material_needs_colors(f);
	used[SHADER_ATTR_UV1] = material_needs_uv1(f);
	used[SHADER_ATTR_JOINTS] = used[SHADER_ATTR_WEIGHTS] = true;
}

uint32_t renderer_morph_room(const struct renderer *r)
{
	bool used[SHADER_MAX_ATTRIBUTES];
	uint32_t limit = attribute_limit(r), room = 0;

	used_locations(r, used);
	for (uint32_t a = 0; a < limit; a++)
		room += !used[a];
	return room;
}

void renderer_set_attribute_limit(struct renderer *r, uint32_t attributes)
{
	r->attribute_limit = attributes;
}

static uint32_t arrays(uint32_t targets, bool normals)
{
	return targets * (normals ? 2 : 1);
}

bool render_morph_set(struct renderer *r)
{
	bool used[SHADER_MAX_ATTRIBUTES];
	uint32_t n = arrays(r->morph_next, r->morph_normals_next), k = 0;

	if (r->morph_next == r->morph_targets && r->morph_normals_next == r->morph_normals) {
		r->morph_next = 0;
		r->morph_normals_next = false;
		return true;
	}
	/* The old arrays' locations may be another program's, unused. */
	for (uint32_t i = 0; i < arrays(r->morph_targets, r->morph_normals); i++)
		r->gl->DisableVertexAttribArray(r->morph_location[i]);
	used_locations(r, used);
	for (uint32_t a = 0; a < SHADER_MAX_ATTRIBUTES && k < n; a++)
		if (!used[a])
			r->morph_location[k++] = a;
	r->morph_targets = r->morph_next;
	r->morph_normals = r->morph_normals_next;
	r->morph_next = 0;
	r->morph_normals_next = false;
	if (!r->morph_targets)
		render_morph_free(r); /* its memory back */
	return false;
}

void render_morph_source(const struct renderer *r, struct shader_source *src)
{
	if (!r->morph_targets)
		return;
	src->morph_targets = (int)r->morph_targets;
	src->morph_normals = r->morph_normals;
	src->vertex[2] = src->vertex[1]; /* morph.glsl before matcap.vert */
	src->vertex[1] = "morph.glsl";
	for (uint32_t i = 0; i < arrays(r->morph_targets, r->morph_normals); i++)
		src->attributes[r->morph_location[i]] =
		    morph_names[i >= r->morph_targets][i % r->morph_targets];
}

void render_morph_bind(const struct renderer *r, uint32_t base)
{
	if (!r->morph_targets)
		return;
	r->gl->BindBuffer(GL_ARRAY_BUFFER, r->morph_vbo);
	for (uint32_t i = 0; i < arrays(r->morph_targets, r->morph_normals); i++) {
		GLuint at = r->morph_location[i];

		r->gl->VertexAttribPointer(
		    at, 3, GL_FLOAT, GL_FALSE, 0,
		    (const void *)(uintptr_t)(i * r->morph_array + base * 12u));
		r->gl->EnableVertexAttribArray(at);
	}
}

void render_morph_uniforms(const struct renderer *r, const struct program *p)
{
	if (p->morph_weights >= 0 && r->morph_targets)
		r->gl->Uniform4fv(p->morph_weights, 2, r->morph_weights);
}

void renderer_set_morph_weights(struct renderer *r, const float *weights)
{
	memcpy(r->morph_weights, weights, sizeof(r->morph_weights));
}

/* The deltas, each array gathered into 16-bit chunks as the mesh's. */
int render_morph_upload(struct renderer *r, const struct skin_morphs *m, uint32_t vertex_count)
{
	const struct draw_list *l = &r->list;
	size_t n = l->gather ? l->gather_count : vertex_count;
	uint32_t count = arrays(m->targets, m->normals);
	float *g = malloc(n * 12 * count + 4);

	if (!g)
		return -ENOMEM;
	for (uint32_t a = 0; a < count; a++) {
		const float *from = m->deltas + (size_t)a * vertex_count * 3;

		for (size_t i = 0; i < n; i++)
			memcpy(g + (a * n + i) * 3,
			       from + (size_t)(l->gather ? l->gather[i] : i) * 3, 12);
	}
	if (!r->morph_vbo)
		r->gl->GenBuffers(1, &r->morph_vbo);
	r->gl->BindBuffer(GL_ARRAY_BUFFER, r->morph_vbo);
	r->gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * 12 * count), g, GL_STATIC_DRAW);
	r->morph_array = n * 12;
	memset(r->morph_weights, 0, sizeof(r->morph_weights));
	free(g);
	return 0;
}

void render_morph_free(struct renderer *r)
{
	if (r->morph_vbo)
		r->gl->DeleteBuffers(1, &r->morph_vbo);
	r->morph_vbo = 0;
}
