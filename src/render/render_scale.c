#include "render/render_scale.h"
#include "render/shader.h"
#include "util/log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* OpenGL ES 3.0's (and desktop GL's) names, for the multisampled buffer. */
#define GL_DEPTH24	    0x81A6 /* DEPTH_COMPONENT24(_OES) */
#define GL_RGBA8	    0x8058
#define GL_READ_FRAMEBUFFER 0x8CA8
#define GL_DRAW_FRAMEBUFFER 0x8CA9
#define GL_MAX_SAMPLES	    0x8D57

/* How the display's samples reach the scaled buffer. */
enum msaa_way {
	MSAA_NONE,
	MSAA_EXT,  /* EXT_multisampled_render_to_texture: resolved as written (tilers) */
	MSAA_BLIT, /* multisampled renderbuffers, resolved by a blit (ES 3.0, desktop GL) */
};

struct render_scale {
	const struct gl *gl;
	double want;
	const char *shader_dir;
	int samples;
	GLuint program, fbo, color, depth;
	GLuint msaa_fbo, msaa_color, msaa_depth; /* MSAA_BLIT's, resolved into fbo */
	enum msaa_way way;
	int fbo_w, fbo_h;	 /* the framebuffer object's size; 0: none */
	GLint target;		 /* the display's framebuffer, bound at begin */
	int width, height;	 /* the frame's full size */
	bool scaled;		 /* this frame draws into fbo */
	bool said, broken, told; /* logged once: the scale, a failure, the samples */
};

double render_scale_pick(double want, int width, int height, bool software, bool plane)
{
	double budget = software ? 1920.0 * 1080.0 : 2560.0 * 1440.0, pixels, s;

	if (want > 0)
		return want < RENDER_SCALE_MIN ? RENDER_SCALE_MIN : want > 1 ? 1 : want;
	pixels = (double)width * (double)height;
	if (pixels <= budget || (software && !plane))
		return 1;
	/* Steps of 0.05, rounded down: a step never draws over the budget. */
	s = floor(sqrt(budget / pixels) * 20 + 1e-9) / 20;
	return s < RENDER_SCALE_MIN ? RENDER_SCALE_MIN : s;
}

void render_scale_size(double scale, int width, int height, int *w, int *h)
{
	*w = (int)lround(width * scale);
	*h = (int)lround(height * scale);
	if (*w < 1)
		*w = 1;
	if (*h < 1)
		*h = 1;
}

struct render_scale *render_scale_new(const struct gl *gl, double want, int samples,
				      const char *shader_dir)
{
	struct render_scale *s = calloc(1, sizeof(*s));

	if (!s)
		return NULL;
	s->gl = gl;
	s->want = want;
	s->samples = samples;
	s->shader_dir = shader_dir;
	return s;
}

static void drop_fbo(struct render_scale *s)
{
	const struct gl *gl = s->gl;

	if (s->fbo)
		gl->DeleteFramebuffers(1, &s->fbo);
	if (s->depth)
		gl->DeleteRenderbuffers(1, &s->depth);
	if (s->color)
		gl->DeleteTextures(1, &s->color);
	if (s->msaa_fbo)
		gl->DeleteFramebuffers(1, &s->msaa_fbo);
	if (s->msaa_color)
		gl->DeleteRenderbuffers(1, &s->msaa_color);
	if (s->msaa_depth)
		gl->DeleteRenderbuffers(1, &s->msaa_depth);
	s->fbo = s->depth = s->color = s->msaa_fbo = s->msaa_color = s->msaa_depth = 0;
	s->fbo_w = s->fbo_h = 0;
}

void render_scale_free(struct render_scale *s)
{
	if (!s)
		return;
	drop_fbo(s);
	if (s->program)
		s->gl->DeleteProgram(s->program);
	free(s);
}

/* Whether the context can blit between framebuffers: OpenGL ES 3.0, or
 * desktop GL 3.0 or ARB_framebuffer_object (OSMesa's). */
static bool can_blit(const struct gl *gl)
{
	const char *v = (const char *)gl->GetString(GL_VERSION);
	const char *ext = (const char *)gl->GetString(GL_EXTENSIONS);
	int major = 0;

	if (!gl->BlitFramebuffer || !gl->RenderbufferStorageMultisample || !v)
		return false;
	if (sscanf(v, "OpenGL ES %d", &major) == 1)
		return major >= 3;
	return (sscanf(v, "%d", &major) == 1 && major >= 3) ||
	       gl_extension_listed(ext, "GL_ARB_framebuffer_object");
}

/* The display's samples, as many as the context allows; the way, once. */
static int choose_msaa(struct render_scale *s)
{
	const struct gl *gl = s->gl;
	const char *ext = (const char *)gl->GetString(GL_EXTENSIONS);
	GLint max = 0;

	if (!s->samples)
		return 0;
	if (gl_extension_listed(ext, "GL_EXT_multisampled_render_to_texture") &&
	    gl->FramebufferTexture2DMultisampleEXT && gl->RenderbufferStorageMultisampleEXT)
		s->way = MSAA_EXT;
	else if (can_blit(gl))
		s->way = MSAA_BLIT;
	gl->GetIntegerv(GL_MAX_SAMPLES, &max);
	if (gl->GetError() != GL_NO_ERROR || max < 1)
		s->way = MSAA_NONE;
	if (s->way == MSAA_NONE && !s->told) {
		s->told = true;
		log_warn("render_scale: this context has no multisampled framebuffers: the scaled "
			 "scene is drawn without the display's %d samples",
			 s->samples);
	}
	return s->way == MSAA_NONE ? 0 : s->samples < max ? s->samples : max;
}

/* MSAA_BLIT: multisampled colour and depth, resolved into fbo at the end. */
static GLenum make_msaa_fbo(struct render_scale *s, int w, int h, int samples)
{
	const struct gl *gl = s->gl;

	gl->GenRenderbuffers(1, &s->msaa_color);
	gl->BindRenderbuffer(GL_RENDERBUFFER, s->msaa_color);
	gl->RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
	gl->GenRenderbuffers(1, &s->msaa_depth);
	gl->BindRenderbuffer(GL_RENDERBUFFER, s->msaa_depth);
	gl->RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24, w, h);
	gl->GenFramebuffers(1, &s->msaa_fbo);
	gl->BindFramebuffer(GL_FRAMEBUFFER, s->msaa_fbo);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
				    s->msaa_color);
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
				    s->msaa_depth);
	return gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
}

/* The scaled colour (a texture the pass samples, linear and clamped) and
 * a depth buffer (24 bits where offered, as the display's), multisampled
 * as the display is where the context can. */
static int make_fbo(struct render_scale *s, int w, int h)
{
	const struct gl *gl = s->gl;
	int samples = choose_msaa(s);
	GLenum depth = gl->caps.depth24 ? GL_DEPTH24 : GL_DEPTH_COMPONENT16, status;

	drop_fbo(s);
	gl->GenTextures(1, &s->color);
	gl->BindTexture(GL_TEXTURE_2D, s->color);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	gl->GenRenderbuffers(1, &s->depth);
	gl->BindRenderbuffer(GL_RENDERBUFFER, s->depth);
	gl->GenFramebuffers(1, &s->fbo);
	gl->BindFramebuffer(GL_FRAMEBUFFER, s->fbo);
	if (samples && s->way == MSAA_EXT) {
		gl->RenderbufferStorageMultisampleEXT(GL_RENDERBUFFER, samples, depth, w, h);
		gl->FramebufferTexture2DMultisampleEXT(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
						       GL_TEXTURE_2D, s->color, 0, samples);
	} else {
		gl->RenderbufferStorage(GL_RENDERBUFFER, depth, w, h);
		gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
					 s->color, 0);
	}
	gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, s->depth);
	status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
	if (status == GL_FRAMEBUFFER_COMPLETE && samples && s->way == MSAA_BLIT)
		status = make_msaa_fbo(s, w, h, samples);
	if (status != GL_FRAMEBUFFER_COMPLETE) {
		log_err("render_scale: a %dx%d framebuffer (%d samples) is incomplete (0x%x): "
			"drawing full size",
			w, h, samples, status);
		gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)s->target);
		drop_fbo(s);
		return -1;
	}
	s->fbo_w = w;
	s->fbo_h = h;
	return 0;
}

static int make_program(struct render_scale *s)
{
	struct shader_source src = {.dir = s->shader_dir,
				    .precision = "precision mediump float;\n",
				    .vertex = {"scale.vert"},
				    .fragment = {"scale.frag"},
				    .attributes = {[SHADER_ATTR_POSITION] = "a_position"}};

	return s->program ? 0 : shader_program_build(s->gl, &src, &s->program);
}

/* Said once: the scale, the sizes and the samples. */
static void say(struct render_scale *s, double scale, int w, int h)
{
	static const char *const ways[] = {"", ", multisampled as written",
					   ", multisampled and resolved by a blit"};

	if (s->said)
		return;
	s->said = true;
	log_info("render_scale %s%.2f: the scene drawn at %dx%d%s, scaled up to %dx%d by a GL pass",
		 s->want > 0 ? "" : "auto: ", scale, w, h,
		 s->msaa_fbo || s->way == MSAA_EXT ? ways[s->way] : "", s->width, s->height);
}

void render_scale_begin(struct render_scale *s, bool plane, int width, int height, int *w, int *h)
{
	const struct gl *gl = s->gl;
	double scale =
	    plane ? 1 : render_scale_pick(s->want, width, height, gl->caps.software, false);

	*w = width;
	*h = height;
	s->width = width;
	s->height = height;
	s->scaled = false;
	render_scale_size(scale, width, height, w, h);
	if (s->broken || (*w == width && *h == height)) {
		*w = width;
		*h = height;
		return;
	}
	gl->GetIntegerv(GL_FRAMEBUFFER_BINDING, &s->target);
	if ((s->fbo_w != *w || s->fbo_h != *h) && make_fbo(s, *w, *h))
		s->broken = true;
	if (!s->broken && make_program(s))
		s->broken = true;
	if (s->broken) {
		*w = width;
		*h = height;
		return;
	}
	say(s, scale, *w, *h);
	gl->BindFramebuffer(GL_FRAMEBUFFER, s->msaa_fbo ? s->msaa_fbo : s->fbo);
	gl->Viewport(0, 0, *w, *h);
	s->scaled = true;
}

void render_scale_end(struct render_scale *s)
{
	static const float quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
	const struct gl *gl = s->gl;

	if (!s->scaled)
		return;
	if (s->msaa_fbo) {
		gl->BindFramebuffer(GL_READ_FRAMEBUFFER, s->msaa_fbo);
		gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, s->fbo);
		gl->BlitFramebuffer(0, 0, s->fbo_w, s->fbo_h, 0, 0, s->fbo_w, s->fbo_h,
				    GL_COLOR_BUFFER_BIT, GL_NEAREST);
	}
	gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)s->target);
	gl->Viewport(0, 0, s->width, s->height);
	/* Every pixel is written: no clear, no depth, no blending. */
	gl->Disable(GL_DEPTH_TEST);
	gl->Disable(GL_CULL_FACE);
	gl->Disable(GL_BLEND);
	gl->UseProgram(s->program);
	gl->ActiveTexture(GL_TEXTURE0);
	gl->BindTexture(GL_TEXTURE_2D, s->color);
	gl->Uniform1i(gl->GetUniformLocation(s->program, "u_image"), 0);
	gl_draw_quad(gl, SHADER_ATTR_POSITION, quad);
	gl->UseProgram(0);
	s->scaled = false;
}
