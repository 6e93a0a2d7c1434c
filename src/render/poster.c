#include "render/poster.h"
#include "render/background.h"
#include "render/shader.h"
#include "scene/mesh/texture.h"
#include "util/log.h"

#include <errno.h>
#include <math.h>

/* The image's share of the screen: it fills one axis and keeps its
 * shape; on a panel turned a quarter, the screen's axes swap. */
static void fit(const struct image *img, int width, int height, int rotation, float out[2])
{
	double sw = rotation % 180 ? height : width, sh = rotation % 180 ? width : height;
	double s = fmin(sw / img->width, sh / img->height);

	out[0] = (float)(img->width * s / sw);
	out[1] = (float)(img->height * s / sh);
}

static void draw_image(const struct gl *gl, GLuint program, const struct image *img, int width,
		       int height, int rotation)
{
	static const float quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
	/* The panel's quarter turn, exact, as the renderer turns the model
	 * (mat4_rotate_z): a column-major 2x2. */
	static const float c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
	int k = ((rotation / 90) % 4 + 4) % 4;
	float turn[4] = {c[k], sn[k], -sn[k], c[k]};
	float f[2];
	GLuint tex = gl_texture_picture(gl, img->width, img->height, img->rgba);

	fit(img, width, height, rotation, f);
	gl->UseProgram(program);
	gl->Uniform2f(gl->GetUniformLocation(program, "u_fit"), f[0], f[1]);
	gl->Uniform4f(gl->GetUniformLocation(program, "u_turn"), turn[0], turn[1], turn[2],
		      turn[3]);
	gl->Uniform1i(gl->GetUniformLocation(program, "u_image"), 0);
	gl_draw_quad(gl, SHADER_ATTR_POSITION, quad);
	gl->UseProgram(0);
	gl->DeleteTextures(1, &tex);
}

/* A photo larger than the GPU's textures (2048 on a Pi 3, 4096 on a Pi 4)
 * would upload nothing and show black: scaled down to fit, into small. */
static int fit_texture_size(const struct gl *gl, const struct image **img, struct image *small)
{
	GLint max = 0;
	double s;
	int ret;

	gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
	if (max <= 0 || ((*img)->width <= max && (*img)->height <= max))
		return 0;
	s = fmin((double)max / (*img)->width, (double)max / (*img)->height);
	log_info("poster: %dx%d is larger than this GPU's textures (%d): drawn scaled down",
		 (*img)->width, (*img)->height, max);
	ret = texture_resample(*img, (int)((*img)->width * s), (int)((*img)->height * s), small);
	if (!ret)
		*img = small;
	return ret;
}

int poster_draw(const struct gl *gl, const struct image *img, int width, int height, int rotation,
		const struct background *bg)
{
	struct shader_source src = {.precision = "precision mediump float;\n",
				    .vertex = {"poster.vert"},
				    .fragment = {"poster.frag"},
				    .attributes = {[SHADER_ATTR_POSITION] = "a_position"}};
	struct image small = {0};
	GLuint program = 0;
	int ret = 0;

	gl->Viewport(0, 0, width, height);
	background_draw(bg, width, height, rotation);
	if (!img)
		return 0;
	gl->Disable(GL_DEPTH_TEST);
	gl->Disable(GL_CULL_FACE);
	ret = fit_texture_size(gl, &img, &small);
	if (!ret)
		ret = shader_program_build(gl, &src, &program);
	if (!ret)
		draw_image(gl, program, img, width, height, rotation);
	if (!ret && gl->GetError() != GL_NO_ERROR)
		ret = -EIO;
	if (program)
		gl->DeleteProgram(program);
	image_release(&small);
	return ret;
}
