#include "render/caption.h"
#include "render/shader.h"
#include "util/log.h"

#include <stdlib.h>

struct caption_gl {
	const struct gl *gl;
	GLuint tex, program;
	GLint rect, turn, image;
	int width, height;
	struct caption_config place; /* position, padding, drift; no strings */
};

struct caption_gl *caption_gl_new(const struct gl *gl, const struct image *img,
				  const struct caption_config *c)
{
	struct shader_source src = {.precision = "precision mediump float;\n",
				    .vertex = {"caption.vert"},
				    .fragment = {"caption.frag"},
				    .attributes = {[SHADER_ATTR_POSITION] = "a_position"}};
	struct caption_gl *cap = calloc(1, sizeof(*cap));

	if (!cap || shader_program_build(gl, &src, &cap->program)) {
		log_err("caption: cannot build its program");
		free(cap);
		return NULL;
	}
	cap->gl = gl;
	cap->width = img->width;
	cap->height = img->height;
	cap->place = (struct caption_config){
	    .padding = c->padding, .position = c->position, .drift = c->drift};
	cap->rect = gl->GetUniformLocation(cap->program, "u_rect");
	cap->turn = gl->GetUniformLocation(cap->program, "u_turn");
	cap->image = gl->GetUniformLocation(cap->program, "u_image");
	cap->tex = gl_texture_picture(gl, img->width, img->height, img->rgba);
	/* Texel for pixel: no filter should mix them. */
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	if (gl->GetError() != GL_NO_ERROR) {
		log_err("caption: cannot upload its %dx%d picture", img->width, img->height);
		caption_gl_free(cap);
		return NULL;
	}
	return cap;
}

void caption_gl_free(struct caption_gl *cap)
{
	if (!cap)
		return;
	cap->gl->DeleteTextures(1, &cap->tex);
	cap->gl->DeleteProgram(cap->program);
	free(cap);
}

void caption_gl_at(const struct caption_gl *cap, double seconds, int width, int height,
		   int rotation, int out[2])
{
	int sw = rotation % 180 ? height : width, sh = rotation % 180 ? width : height;

	caption_place(&cap->place, cap->width, cap->height, sw, sh, seconds, out);
}

void caption_gl_size(const struct caption_gl *cap, int size[2])
{
	size[0] = cap->width;
	size[1] = cap->height;
}

void caption_gl_draw(const struct caption_gl *cap, double seconds, int width, int height,
		     int rotation)
{
	int at[2];

	caption_gl_at(cap, seconds, width, height, rotation, at);
	caption_gl_draw_at(cap, at, width, height, rotation);
}

void caption_gl_draw_at(const struct caption_gl *cap, const int at[2], int width, int height,
			int rotation)
{
	static const float quad[8] = {0, 0, 1, 0, 0, 1, 1, 1};
	/* The panel's quarter turn, as poster.c turns the poster. */
	static const float c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
	const struct gl *gl = cap->gl;
	int k = ((rotation / 90) % 4 + 4) % 4;
	float sw = (float)(rotation % 180 ? height : width);
	float sh = (float)(rotation % 180 ? width : height);

	gl->Viewport(0, 0, width, height);
	gl->Disable(GL_DEPTH_TEST);
	gl->Disable(GL_CULL_FACE);
	gl->Enable(GL_BLEND);
	gl->BlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
	gl->UseProgram(cap->program);
	gl->Uniform4f(cap->rect, 2.0f * at[0] / sw - 1, 1 - 2.0f * at[1] / sh,
		      2.0f * cap->width / sw, -2.0f * cap->height / sh);
	gl->Uniform4f(cap->turn, c[k], sn[k], -sn[k], c[k]);
	gl->Uniform1i(cap->image, 0);
	gl->ActiveTexture(GL_TEXTURE0);
	gl->BindTexture(GL_TEXTURE_2D, cap->tex);
	gl_draw_quad(gl, SHADER_ATTR_POSITION, quad);
	gl->UseProgram(0);
	gl->Disable(GL_BLEND);
}
