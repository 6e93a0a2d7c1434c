#include "render.h"
#include "log.h"
#include "shader.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FOV_Y_DEGREES 30.0
#define FIT_MARGIN    1.08

struct program {
	GLuint id;
	GLint modelview, projection, normal_matrix, matcap;
};

struct renderer {
	const struct gl *gl;
	const char *shader_dir;
	struct program programs[SHADING_MODE_COUNT][2]; /* [mode][ortho] */
	struct program *current;
	GLuint vbo_position, vbo_normal, ibo, matcap;
	GLenum index_type;
	GLsizei draw_count;
	bool indexed;
};

struct renderer *renderer_new(const struct gl *gl, const char *shader_dir)
{
	struct renderer *r = calloc(1, sizeof(*r));

	if (!r)
		return NULL;
	r->gl = gl;
	r->shader_dir = shader_dir;
	gl->GenBuffers(1, &r->vbo_position);
	gl->GenBuffers(1, &r->vbo_normal);
	gl->GenBuffers(1, &r->ibo);
	gl->GenTextures(1, &r->matcap);
	return r;
}

void renderer_free(struct renderer *r)
{
	if (!r)
		return;
	for (int m = 0; m < SHADING_MODE_COUNT; m++)
		for (int o = 0; o < 2; o++)
			if (r->programs[m][o].id)
				r->gl->DeleteProgram(r->programs[m][o].id);
	r->gl->DeleteBuffers(1, &r->vbo_position);
	r->gl->DeleteBuffers(1, &r->vbo_normal);
	r->gl->DeleteBuffers(1, &r->ibo);
	r->gl->DeleteTextures(1, &r->matcap);
	free(r);
}

static bool has_gl_extension(const struct gl *gl, const char *name)
{
	const char *ext = (const char *)gl->GetString(GL_EXTENSIONS);
	size_t n = strlen(name);

	for (const char *p = ext; p && (p = strstr(p, name)); p += n)
		if ((p == ext || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
			return true;
	return false;
}

/* Core GLES2 indexes with 16 bits; 32-bit indices need an extension that
 * some SBC GPUs lack, and then the mesh is drawn unindexed. */
static int upload_indices(struct renderer *r, const struct mesh *m, float **flat_pos,
			  float **flat_nrm)
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
	if (has_gl_extension(gl, "GL_OES_element_index_uint")) {
		gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)m->index_count * 4, m->indices,
			       GL_STATIC_DRAW);
		r->index_type = GL_UNSIGNED_INT;
		return 0;
	}
	r->indexed = false;
	*flat_pos = malloc((size_t)m->index_count * 3 * sizeof(float) + 1);
	*flat_nrm = malloc((size_t)m->index_count * 3 * sizeof(float) + 1);
	if (!*flat_pos || !*flat_nrm)
		return -ENOMEM;
	for (uint32_t i = 0; i < m->index_count; i++) {
		memcpy(*flat_pos + i * 3, m->positions + (size_t)m->indices[i] * 3, 12);
		memcpy(*flat_nrm + i * 3, m->normals + (size_t)m->indices[i] * 3, 12);
	}
	return 0;
}

int renderer_set_mesh(struct renderer *r, const struct mesh *m)
{
	const struct gl *gl = r->gl;
	float *flat_pos = NULL, *flat_nrm = NULL;
	GLsizeiptr n = (GLsizeiptr)m->vertex_count * 12;
	int ret = upload_indices(r, m, &flat_pos, &flat_nrm);

	if (ret)
		goto out;
	if (!r->indexed)
		n = (GLsizeiptr)m->index_count * 12;
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_position);
	gl->BufferData(GL_ARRAY_BUFFER, n, r->indexed ? m->positions : flat_pos, GL_STATIC_DRAW);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_normal);
	gl->BufferData(GL_ARRAY_BUFFER, n, r->indexed ? m->normals : flat_nrm, GL_STATIC_DRAW);
	if (gl->GetError() == GL_OUT_OF_MEMORY) {
		log_err("render: out of GPU memory for %u vertices", m->vertex_count);
		ret = -ENOMEM;
	}
out:
	free(flat_pos);
	free(flat_nrm);
	return ret;
}

int renderer_set_matcap(struct renderer *r, const struct image *img)
{
	const struct gl *gl = r->gl;

	gl->BindTexture(GL_TEXTURE_2D, r->matcap);
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, img->width, img->height, 0, GL_RGBA,
		       GL_UNSIGNED_BYTE, img->rgba);
	/* No mipmaps: a matcap is looked up by normal, and at silhouettes the
	 * derivatives would pick a blurred level for the sharpest part. NPOT
	 * sizes are then legal in GLES2 too. */
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	return gl->GetError() == GL_NO_ERROR ? 0 : -EIO;
}

int renderer_set_mode(struct renderer *r, enum shading_mode mode, bool ortho)
{
	struct program *p = &r->programs[mode][ortho];
	char defines[256];

	if (!p->id) {
		snprintf(defines, sizeof(defines), "%s%s", shading_mode_define(mode),
			 ortho ? "#define CAMERA_ORTHO 1\n" : "");
		if (shader_build(r->gl, r->shader_dir, defines, &p->id))
			return -EINVAL;
		p->modelview = r->gl->GetUniformLocation(p->id, "u_modelview");
		p->projection = r->gl->GetUniformLocation(p->id, "u_projection");
		p->normal_matrix = r->gl->GetUniformLocation(p->id, "u_normal_matrix");
		p->matcap = r->gl->GetUniformLocation(p->id, "u_matcap");
	}
	r->current = p;
	return 0;
}

void render_matrices(const struct view *v, int width, int height, float modelview[16],
		     float projection[16])
{
	bool quarter = v->rotation == 90 || v->rotation == 270;
	double aspect = quarter ? (double)height / width : (double)width / height;
	double half = FOV_Y_DEGREES / 2.0 * M_PI / 180.0;
	double half_min = fmin(half, atan(tan(half) * aspect));
	double dist = FIT_MARGIN / sin(half_min);
	float rot[16], move[16], proj[16], panel[16];

	mat4_from_quat(rot, v->orientation);
	mat4_translate(move, 0, 0, -dist);
	mat4_multiply(modelview, move, rot);
	if (v->ortho) {
		double sx = aspect > 1 ? aspect : 1, sy = aspect > 1 ? 1 : 1 / aspect;

		mat4_ortho(proj, -sx, sx, -sy, sy, dist - 1.5, dist + 1.5);
	} else {
		mat4_perspective(proj, 2.0 * half, aspect, dist - 1.5, dist + 1.5);
	}
	/* A portrait panel turns the picture, not the scanout, so it works
	 * with every driver and plane. */
	mat4_rotate_z(panel, v->rotation);
	mat4_multiply(projection, panel, proj);
}

void renderer_draw(struct renderer *r, const struct view *v, int width, int height)
{
	const struct gl *gl = r->gl;
	struct program *p = r->current;
	float mv[16], proj[16], nm[9];

	gl->ClearColor(v->background[0], v->background[1], v->background[2], 1.0f);
	gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	if (!p || !r->draw_count)
		return;
	render_matrices(v, width, height, mv, proj);
	/* The model-view is a rotation and a translation: its upper 3x3 is
	 * already the inverse transpose. Scales and mirrors were baked into
	 * the mesh in double precision at load time. */
	mat3_from_mat4(nm, mv);
	gl->Enable(GL_DEPTH_TEST);
	gl->Enable(GL_CULL_FACE);
	gl->CullFace(GL_BACK);
	gl->FrontFace(GL_CCW);
	gl->UseProgram(p->id);
	gl->UniformMatrix4fv(p->modelview, 1, GL_FALSE, mv);
	gl->UniformMatrix4fv(p->projection, 1, GL_FALSE, proj);
	gl->UniformMatrix3fv(p->normal_matrix, 1, GL_FALSE, nm);
	gl->ActiveTexture(GL_TEXTURE0);
	gl->BindTexture(GL_TEXTURE_2D, r->matcap);
	gl->Uniform1i(p->matcap, 0);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_position);
	gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	gl->EnableVertexAttribArray(0);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_normal);
	gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	gl->EnableVertexAttribArray(1);
	if (r->indexed) {
		gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo);
		gl->DrawElements(GL_TRIANGLES, r->draw_count, r->index_type, NULL);
	} else {
		gl->DrawArrays(GL_TRIANGLES, 0, r->draw_count);
	}
}
