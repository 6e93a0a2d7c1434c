/* The skinning state inside the renderer (render_priv.h): the palette's
 * bones and rows, a split palette's ranges, the programs' source, arrays
 * and uniforms for them (the morph targets': render_morph.c). render.c
 * and render_draw.c call these, render_live.c sets a skinned mesh through
 * them; nothing here calls those back (render_skin_set says when the
 * programs must be built again, render.c builds them). */
#include "render/render.h"
#include "render/render_priv.h"
#include "scene/anim/anim_palette.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

bool render_skin_set(struct renderer *r)
{
	uint32_t bones = r->bones_next;
	bool same_morphs = render_morph_set(r);

	drop_palettes(r); /* a split's are set after its mesh */
	r->bones_next = 0;
	if (bones == r->bones && same_morphs)
		return false;
	r->bones = bones;
	if (!bones) {
		r->gl->DisableVertexAttribArray(SHADER_ATTR_JOINTS);
		r->gl->DisableVertexAttribArray(SHADER_ATTR_WEIGHTS);
	}
	return true;
}

void render_skin_free(struct renderer *r)
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

/* A split's palettes, copied: each range's bones among the total. */
int render_skin_set_palettes(struct renderer *r, const struct skin_palettes *sp)
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
