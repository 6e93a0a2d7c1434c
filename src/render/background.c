#include "render/background.h"
#include "render/shader.h"
#include "scene/mesh/texture.h"
#include "util/log.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

struct background {
	const struct gl *gl;
	struct background_spec spec;
	GLuint program, texture;
	GLint turn, scale, slice, top, bottom, image;
	int image_width, image_height;
};

void background_spec_default(struct background_spec *out)
{
	/* The dark grey the kiosk has always cleared to. */
	*out = (struct background_spec){
	    BACKGROUND_COLOR, {0.06f, 0.06f, 0.07f}, {0.06f, 0.06f, 0.07f}, NULL};
}

static int hex_digit(char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	c = (char)tolower((unsigned char)c);
	return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/* "#rrggbb" (with blanks around it), exactly. */
static int parse_color(const char *s, size_t len, float out[3], char *err, size_t n)
{
	while (len && isspace((unsigned char)*s))
		s++, len--;
	while (len && isspace((unsigned char)s[len - 1]))
		len--;
	if (len != 7 || s[0] != '#') {
		snprintf(err, n, "'%.*s' is not a colour; expected #rrggbb (six hex digits)",
			 (int)len, s);
		return -EINVAL;
	}
	for (int i = 0; i < 3; i++) {
		int hi = hex_digit(s[1 + 2 * i]), lo = hex_digit(s[2 + 2 * i]);

		if (hi < 0 || lo < 0) {
			snprintf(err, n, "'%.7s' has a digit that is not hex; expected #rrggbb", s);
			return -EINVAL;
		}
		out[i] = (float)(hi * 16 + lo) / 255.0f;
	}
	return 0;
}

bool background_names_image(const char *s)
{
	const char *dot = strrchr(s, '.');

	return dot && (!strcasecmp(dot, ".png") || !strcasecmp(dot, ".jpg") ||
		       !strcasecmp(dot, ".jpeg") || !strcasecmp(dot, ".webp"));
}

int background_parse(const char *text, struct background_spec *out, char *err, size_t n)
{
	const char *comma;
	int ret;

	background_spec_default(out);
	while (text && isspace((unsigned char)*text))
		text++;
	if (!text || !*text)
		return 0;
	if (text[0] != '#') {
		if (!background_names_image(text)) {
			snprintf(err, n,
				 "'%s' is neither a colour nor a .png/.jpg/.jpeg/.webp file", text);
			return -EINVAL;
		}
		out->kind = BACKGROUND_IMAGE;
		out->path = text;
		return 0;
	}
	comma = strchr(text, ',');
	if (comma && strchr(comma + 1, ',')) {
		snprintf(err, n, "a gradient has two colours, top and bottom, not more");
		return -EINVAL;
	}
	ret = parse_color(text, comma ? (size_t)(comma - text) : strlen(text), out->top, err, n);
	if (!ret && comma)
		ret = parse_color(comma + 1, strlen(comma + 1), out->bottom, err, n);
	else if (!ret)
		memcpy(out->bottom, out->top, sizeof(out->top));
	if (!ret && comma)
		out->kind = BACKGROUND_GRADIENT;
	return ret;
}

void background_clear_color(const struct background_spec *s, float out[3])
{
	for (int i = 0; i < 3; i++)
		out[i] = (s->top[i] + s->bottom[i]) / 2;
}

/* A photo larger than the GPU's textures: scaled down into small. */
static const struct image *fit_texture(const struct gl *gl, const struct image *img,
				       struct image *small)
{
	GLint max = 0;
	double s;

	gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
	if (max <= 0 || (img->width <= max && img->height <= max))
		return img;
	s = fmin((double)max / img->width, (double)max / img->height);
	log_info("background: %dx%d is larger than this GPU's textures (%d): scaled down",
		 img->width, img->height, max);
	if (texture_resample(img, (int)(img->width * s), (int)(img->height * s), small))
		return NULL;
	return small;
}

static int upload(struct background *b, const struct image *img)
{
	const struct gl *gl = b->gl;
	struct image small = {0};
	const struct image *up = fit_texture(gl, img, &small);

	if (!up)
		return -ENOMEM;
	b->texture = gl_texture_picture(gl, up->width, up->height, up->rgba);
	b->image_width = img->width;
	b->image_height = img->height;
	image_release(&small);
	return 0;
}

static int build(struct background *b)
{
	struct shader_source src = {.precision = "precision mediump float;\n",
				    .vertex = {"background.vert"},
				    .fragment = {"background.frag"},
				    .attributes = {[SHADER_ATTR_POSITION] = "a_position"}};
	const struct gl *gl = b->gl;
	int ret = 0;

	if (b->spec.kind == BACKGROUND_IMAGE)
		ret = shader_source_define(&src, "BACKGROUND_IMAGE");
	if (!ret)
		ret = shader_program_build(gl, &src, &b->program);
	if (ret)
		return ret;
	b->turn = gl->GetUniformLocation(b->program, "u_turn");
	b->scale = gl->GetUniformLocation(b->program, "u_scale");
	b->slice = gl->GetUniformLocation(b->program, "u_slice");
	b->top = gl->GetUniformLocation(b->program, "u_top");
	b->bottom = gl->GetUniformLocation(b->program, "u_bottom");
	b->image = gl->GetUniformLocation(b->program, "u_image");
	return 0;
}

struct background *background_new(const struct gl *gl, const struct background_spec *s,
				  const struct image *img)
{
	struct background *b = calloc(1, sizeof(*b));
	int ret = b ? 0 : -ENOMEM;

	if (!b)
		return NULL;
	b->gl = gl;
	b->spec = *s;
	b->spec.path = NULL; /* the text it pointed into is the caller's */
	if (s->kind == BACKGROUND_IMAGE && (!img || !img->rgba)) {
		log_err("background: the image was not decoded");
		ret = -EINVAL;
	}
	if (!ret && s->kind == BACKGROUND_IMAGE)
		ret = upload(b, img);
	if (!ret && s->kind != BACKGROUND_COLOR)
		ret = build(b);
	if (ret) {
		background_free(b);
		return NULL;
	}
	return b;
}

void background_free(struct background *b)
{
	if (!b)
		return;
	if (b->program)
		b->gl->DeleteProgram(b->program);
	if (b->texture)
		b->gl->DeleteTextures(1, &b->texture);
	free(b);
}

/* The image's texture coordinates over the screen: it covers the panel
 * (as the viewer sees it, turned a quarter on a portrait panel; a wall's
 * whole picture, screen the wall's aspect) and keeps its shape, so the
 * longer axis is cropped about its centre. */
static void cover_scale(const struct background *b, double screen, float out[2])
{
	double image = (double)b->image_width / b->image_height;

	out[0] = (float)(image > screen ? screen / image : 1.0);
	out[1] = (float)(image > screen ? 1.0 : image / screen);
}

void background_draw(const struct background *b, int width, int height, int rotation)
{
	struct wall_slice whole;

	wall_slice_turned(&(struct wall_layout){0}, rotation, width, height, &whole);
	background_draw_slice(b, &whole, rotation);
}

void background_draw_slice(const struct background *b, const struct wall_slice *s, int rotation)
{
	static const float quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
	/* The panel's quarter turn, as poster.c and the renderer turn. */
	static const float c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
	int k = ((rotation / 90) % 4 + 4) % 4;
	const struct gl *gl = b->gl;
	float clear[3], scale[2] = {1, 1};

	background_clear_color(&b->spec, clear);
	gl->ClearColor(clear[0], clear[1], clear[2], 1.0f);
	gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	if (!b->program)
		return; /* a plain colour: the clear is all of it */
	if (b->texture)
		cover_scale(b, s->aspect, scale);
	gl->Disable(GL_DEPTH_TEST);
	gl->Disable(GL_CULL_FACE);
	gl->UseProgram(b->program);
	gl->Uniform4f(b->turn, c[k], sn[k], -sn[k], c[k]);
	gl->Uniform2f(b->scale, scale[0], scale[1]);
	/* This screen's part of the wall: its centre and half sizes. */
	gl->Uniform4f(b->slice, (float)((s->rect[0] + s->rect[2]) / 2),
		      (float)((s->rect[1] + s->rect[3]) / 2),
		      (float)((s->rect[2] - s->rect[0]) / 2),
		      (float)((s->rect[3] - s->rect[1]) / 2));
	gl->Uniform3f(b->top, b->spec.top[0], b->spec.top[1], b->spec.top[2]);
	gl->Uniform3f(b->bottom, b->spec.bottom[0], b->spec.bottom[1], b->spec.bottom[2]);
	if (b->texture) {
		gl->ActiveTexture(GL_TEXTURE0);
		gl->BindTexture(GL_TEXTURE_2D, b->texture);
		gl->Uniform1i(b->image, 0);
	}
	gl_draw_quad(gl, SHADER_ATTR_POSITION, quad);
}
