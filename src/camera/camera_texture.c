#include "camera/camera_texture.h"
#include "util/log.h"
#include "render/shader.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2ext.h>
#include <drm_fourcc.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Buffers a camera hands out at a time, at most (libcamera gives 4 to 8). */
#define IMPORT_SLOTS 16

static const char *const kind_defines[] = {"CAMERA_RGB", "CAMERA_SEMI", "CAMERA_PLANAR",
					   "CAMERA_PACKED"};

struct program {
	GLuint id;
	GLint crop, tex[3], clamp, scale[2], sel[4], yuv, offset, packed;
};

/* One camera buffer imported: an EGLImage and a texture per plane. The
 * textures sample the buffer itself, whatever the camera writes in it. */
struct imported {
	unsigned generation;
	int buffer; /* -1: empty */
	EGLImageKHR image[CAMERA_MAX_PLANES];
	GLuint tex[CAMERA_MAX_PLANES];
};

struct egl_import {
	EGLDisplay dpy;
	PFNEGLCREATEIMAGEKHRPROC create;
	PFNEGLDESTROYIMAGEKHRPROC destroy;
	PFNGLEGLIMAGETARGETTEXTURE2DOESPROC target;
	struct imported slots[IMPORT_SLOTS];
	unsigned refused_generation; /* the import failed for this camera session */
	bool refused;
};

struct camera_texture {
	const struct gl *gl;
	const char *shader_dir;
	int size;
	GLuint fbo, color, vbo;
	struct program programs[4]; /* by enum camera_kind */
	GLuint upload[CAMERA_MAX_PLANES];
	int upload_w[CAMERA_MAX_PLANES], upload_h[CAMERA_MAX_PLANES];
	GLenum upload_format[CAMERA_MAX_PLANES];
	struct egl_import *import; /* NULL: the context cannot import */
	struct camera_view view;
	enum camera_path path, logged_path;
	bool drawn, said_shrunk;
};

static void find_locations(const struct gl *gl, struct program *p)
{
	char name[32];

	p->crop = gl->GetUniformLocation(p->id, "u_crop");
	for (int i = 0; i < 3; i++) {
		snprintf(name, sizeof(name), "u_tex%d", i);
		p->tex[i] = gl->GetUniformLocation(p->id, name);
	}
	for (int i = 0; i < 4; i++) {
		snprintf(name, sizeof(name), "u_sel%d", i);
		p->sel[i] = gl->GetUniformLocation(p->id, name);
	}
	p->scale[0] = gl->GetUniformLocation(p->id, "u_scale0");
	p->scale[1] = gl->GetUniformLocation(p->id, "u_scale1");
	p->clamp = gl->GetUniformLocation(p->id, "u_clamp");
	p->yuv = gl->GetUniformLocation(p->id, "u_yuv");
	p->offset = gl->GetUniformLocation(p->id, "u_offset");
	p->packed = gl->GetUniformLocation(p->id, "u_packed");
}

static struct program *program_get(struct camera_texture *t, enum camera_kind kind)
{
	struct program *p = &t->programs[kind];
	/* highp where the GPU has it: the packed formats compute pixel
	 * columns, which mediump cannot count past 2048. */
	struct shader_source src = {.dir = t->shader_dir,
				    .precision = "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
						 "precision highp float;\n#else\n"
						 "precision mediump float;\n#endif\n",
				    .vertex = {"camera.vert"},
				    .fragment = {"camera.frag"},
				    .attributes = {"a_position"}};
	GLuint id;

	if (p->id)
		return p;
	if (shader_source_define(&src, kind_defines[kind]) ||
	    shader_program_build(t->gl, &src, &id))
		return NULL;
	p->id = id;
	find_locations(t->gl, p);
	return p;
}

/* The import needs an EGL context (not OSMesa's), the dmabuf import
 * extension and GL_OES_EGL_image. */
static struct egl_import *import_new(const struct gl *gl)
{
	const struct gl_caps *caps = &gl->caps;
	struct egl_import *im;

	if (!caps->egl_display) {
		log_debug("camera: no EGL context, so no dmabuf import");
		return NULL;
	}
	/* A software rasterizer reads the frame on the CPU either way, and
	 * Mesa's kms_swrast takes an import it cannot map (the kernel does
	 * not map imported buffers for it): llvmpipe then reads through a
	 * null pointer. */
	if (caps->software) {
		log_debug("camera: software rendering (%s): frames are uploaded, not imported",
			  (const char *)gl->GetString(GL_RENDERER));
		return NULL;
	}
	if (!caps->dmabuf_import || !caps->egl_image) {
		log_debug("camera: EGL_EXT_image_dma_buf_import or GL_OES_EGL_image missing");
		return NULL;
	}
	im = calloc(1, sizeof(*im));
	if (!im)
		return NULL;
	im->dpy = caps->egl_display;
	im->create = (PFNEGLCREATEIMAGEKHRPROC)eglGetProcAddress("eglCreateImageKHR");
	im->destroy = (PFNEGLDESTROYIMAGEKHRPROC)eglGetProcAddress("eglDestroyImageKHR");
	im->target =
	    (PFNGLEGLIMAGETARGETTEXTURE2DOESPROC)eglGetProcAddress("glEGLImageTargetTexture2DOES");
	for (int i = 0; i < IMPORT_SLOTS; i++)
		im->slots[i].buffer = -1;
	if (!im->create || !im->destroy || !im->target) {
		free(im);
		return NULL;
	}
	return im;
}

static void import_drop(const struct gl *gl, struct egl_import *im, struct imported *s)
{
	for (int p = 0; p < CAMERA_MAX_PLANES; p++) {
		if (s->tex[p])
			gl->DeleteTextures(1, &s->tex[p]);
		if (s->image[p] != EGL_NO_IMAGE_KHR)
			im->destroy(im->dpy, s->image[p]);
	}
	memset(s, 0, sizeof(*s));
	s->buffer = -1;
}

static void set_sampling(const struct gl *gl, GLenum filter)
{
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/* Texels that hold two pixels are read exactly. */
static GLenum plane_filter(const struct camera_frame *f)
{
	return f->layout.kind == CAMERA_KIND_PACKED ? GL_NEAREST : GL_LINEAR;
}

/* What each plane is imported as: RGB formats as themselves (the driver
 * then samples true red, green, blue), the others byte for byte. */
static uint32_t import_fourcc(const struct camera_frame *f, int plane)
{
	switch (f->layout.kind) {
	case CAMERA_KIND_RGB:
		return f->layout.fourcc;
	case CAMERA_KIND_PACKED:
		return DRM_FORMAT_ABGR8888; /* bytes 0..3 in r, g, b, a */
	case CAMERA_KIND_SEMI:
		return plane == 0 ? DRM_FORMAT_R8 : DRM_FORMAT_GR88;
	default:
		return DRM_FORMAT_R8;
	}
}

static int import_plane(const struct gl *gl, struct egl_import *im, const struct camera_frame *f,
			int p, struct imported *s)
{
	const struct camera_plane_layout *pl = &f->layout.plane[p];
	EGLint attrs[] = {EGL_WIDTH,
			  pl->width,
			  EGL_HEIGHT,
			  pl->height,
			  EGL_LINUX_DRM_FOURCC_EXT,
			  (EGLint)import_fourcc(f, p),
			  EGL_DMA_BUF_PLANE0_FD_EXT,
			  f->plane[p].fd,
			  EGL_DMA_BUF_PLANE0_OFFSET_EXT,
			  (EGLint)f->plane[p].offset,
			  EGL_DMA_BUF_PLANE0_PITCH_EXT,
			  (EGLint)pl->stride,
			  EGL_NONE};

	s->image[p] = im->create(im->dpy, EGL_NO_CONTEXT, EGL_LINUX_DMA_BUF_EXT, NULL, attrs);
	if (s->image[p] == EGL_NO_IMAGE_KHR) {
		log_info("camera: the driver refuses to import the frames' dmabufs (%#x); "
			 "uploading them instead",
			 eglGetError());
		return -ENOTSUP;
	}
	gl->GenTextures(1, &s->tex[p]);
	gl->BindTexture(GL_TEXTURE_2D, s->tex[p]);
	im->target(GL_TEXTURE_2D, (GLeglImageOES)s->image[p]);
	set_sampling(gl, plane_filter(f));
	if (gl->GetError() != GL_NO_ERROR) {
		log_info("camera: GL cannot sample the imported frames; uploading them instead");
		return -ENOTSUP;
	}
	return 0;
}

/* The buffer's textures, imported on its first frame and kept. NULL
 * when this camera session's buffers do not import. */
static struct imported *import_frame(struct camera_texture *t, const struct camera_frame *f)
{
	struct egl_import *im = t->import;
	struct imported *s;

	if (!im || (im->refused && im->refused_generation == f->generation) || f->buffer < 0 ||
	    f->buffer >= IMPORT_SLOTS)
		return NULL;
	s = &im->slots[f->buffer];
	if (s->buffer == f->buffer && s->generation == f->generation)
		return s;
	/* A new camera session: its buffers are new, drop the old ones. */
	for (int i = 0; i < IMPORT_SLOTS; i++)
		if (im->slots[i].buffer >= 0 && im->slots[i].generation != f->generation)
			import_drop(t->gl, im, &im->slots[i]);
	import_drop(t->gl, im, s);
	for (int p = 0; p < f->layout.planes; p++) {
		if (import_plane(t->gl, im, f, p, s)) {
			import_drop(t->gl, im, s);
			im->refused = true;
			im->refused_generation = f->generation;
			return NULL;
		}
	}
	s->buffer = f->buffer;
	s->generation = f->generation;
	return s;
}

static void upload_plane(struct camera_texture *t, const struct camera_frame *f, int p)
{
	const struct gl *gl = t->gl;
	const struct camera_plane_layout *pl = &f->layout.plane[p];
	static const GLenum formats[5] = {0, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RGB, GL_RGBA};
	GLenum format = formats[pl->bytes_per_texel];
	struct camera_upload up;
	int rows = 0;

	camera_upload_plan(pl, &up);
	if (!t->upload[p])
		gl->GenTextures(1, &t->upload[p]);
	gl->BindTexture(GL_TEXTURE_2D, t->upload[p]);
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, up.alignment);
	if (t->upload_w[p] != up.texture_width || t->upload_h[p] != pl->height ||
	    t->upload_format[p] != format)
		gl->TexImage2D(GL_TEXTURE_2D, 0, (GLint)format, up.texture_width, pl->height, 0,
			       format, GL_UNSIGNED_BYTE, NULL);
	/* A wide upload would read the last row's padding too, which a
	 * tightly allocated buffer does not have: that row goes alone. */
	if (up.mode == CAMERA_UPLOAD_ALIGNED)
		rows = pl->height;
	else if (up.mode == CAMERA_UPLOAD_WIDE)
		rows = pl->height - 1;
	if (rows)
		gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, up.texture_width, rows, format,
				  GL_UNSIGNED_BYTE, f->plane[p].data);
	for (int y = rows; y < pl->height; y++)
		gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, y, pl->width, 1, format, GL_UNSIGNED_BYTE,
				  f->plane[p].data + (size_t)y * pl->stride);
	t->upload_w[p] = up.texture_width;
	t->upload_h[p] = pl->height;
	t->upload_format[p] = format;
	set_sampling(gl, plane_filter(f));
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

/* A unit vector that picks byte b of a texel out of what the sampler
 * returns: LUMINANCE_ALPHA gives byte 0 in r, g, b and byte 1 in a;
 * RGB(A) and the imported R8/GR88/ABGR8888 give byte i in component i. */
static void byte_selector(int bytes_per_texel, bool imported, int b, float out[4])
{
	memset(out, 0, 4 * sizeof(float));
	out[!imported && bytes_per_texel == 2 && b == 1 ? 3 : b] = 1.0f;
}

static void set_selectors(const struct camera_texture *t, const struct program *p,
			  const struct camera_frame *f, bool imported)
{
	const struct camera_layout *l = &f->layout;
	int bytes = l->kind == CAMERA_KIND_SEMI ? 2 : l->plane[0].bytes_per_texel;
	float sel[4];

	for (int i = 0; i < 4; i++) {
		/* An imported RGB format is sampled as true RGB already. */
		int b = l->kind == CAMERA_KIND_RGB && imported ? i : l->order[i];

		byte_selector(bytes, imported, b, sel);
		if (p->sel[i] >= 0)
			t->gl->Uniform4f(p->sel[i], sel[0], sel[1], sel[2], sel[3]);
	}
}

static void set_uniforms(struct camera_texture *t, const struct program *p,
			 const struct camera_frame *f, const GLuint tex[3], const double scale[2],
			 const struct camera_crop *crop)
{
	const struct gl *gl = t->gl;
	const struct camera_layout *l = &f->layout;
	struct camera_yuv_matrix m;
	float cols[9];
	double tex_w = l->plane[0].width / scale[0]; /* texels: pixel pairs, packed */

	for (int i = 0; i < 3; i++) {
		if (p->tex[i] < 0)
			continue;
		gl->ActiveTexture(GL_TEXTURE0 + (GLenum)i);
		gl->BindTexture(GL_TEXTURE_2D, tex[i]);
		gl->Uniform1i(p->tex[i], i);
	}
	gl->Uniform4f(p->crop, (float)crop->u0, (float)crop->v0, (float)crop->du, (float)crop->dv);
	gl->Uniform4f(p->clamp, 0.5f / l->width, 0.5f / l->height, 1.0f - 0.5f / l->width,
		      1.0f - 0.5f / l->height);
	gl->Uniform2f(p->scale[0], (float)scale[0], 1.0f);
	if (p->scale[1] >= 0)
		gl->Uniform2f(p->scale[1], (float)scale[1], 1.0f);
	if (p->packed >= 0)
		gl->Uniform2f(p->packed, (float)l->width, (float)tex_w);
	if (p->yuv >= 0) {
		camera_yuv_matrix_make(f->encoding, f->range, &m);
		for (int c = 0; c < 3; c++)
			for (int r = 0; r < 3; r++)
				cols[c * 3 + r] = m.m[r][c]; /* GL wants columns */
		gl->UniformMatrix3fv(p->yuv, 1, GL_FALSE, cols);
		gl->Uniform3f(p->offset, m.offset[0], m.offset[1], m.offset[2]);
	}
}

static void draw_pass(struct camera_texture *t)
{
	const struct gl *gl = t->gl;
	GLint fbo = 0, vp[4];

	gl->GetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
	gl->GetIntegerv(GL_VIEWPORT, vp);
	gl->BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
	gl->Viewport(0, 0, t->size, t->size);
	gl->Disable(GL_DEPTH_TEST);
	gl->Disable(GL_CULL_FACE);
	gl->BindBuffer(GL_ARRAY_BUFFER, t->vbo);
	gl->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
	gl->EnableVertexAttribArray(0);
	gl->DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
	gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
	gl->Viewport(vp[0], vp[1], vp[2], vp[3]);
	gl->ActiveTexture(GL_TEXTURE0);
}

/* The textures of the frame's planes, uploaded or imported, in the order
 * the shader reads them (luma first; Cb, Cr for the planar formats). */
static int frame_textures(struct camera_texture *t, const struct camera_frame *f, GLuint tex[3],
			  double scale[2], bool *imported)
{
	const struct camera_layout *l = &f->layout;
	struct imported *s = import_frame(t, f);
	struct camera_upload up;
	int order[3] = {0, 1, 2};

	if (l->kind == CAMERA_KIND_PLANAR) {
		order[1] = l->order[0];
		order[2] = l->order[1];
	}
	*imported = s != NULL;
	scale[0] = scale[1] = 1.0;
	if (s) {
		for (int i = 0; i < l->planes; i++)
			tex[i] = s->tex[order[i]];
		return 0;
	}
	for (int p = 0; p < l->planes; p++)
		if (!f->plane[p].data) {
			log_err("camera: the frames can neither be imported nor mapped");
			return -EIO;
		}
	camera_frame_cpu_access(f, true);
	for (int p = 0; p < l->planes; p++)
		upload_plane(t, f, p);
	camera_frame_cpu_access(f, false);
	for (int i = 0; i < l->planes; i++)
		tex[i] = t->upload[order[i]];
	camera_upload_plan(&l->plane[0], &up);
	scale[0] = up.u_scale;
	if (l->planes > 1) {
		camera_upload_plan(&l->plane[1], &up);
		scale[1] = up.u_scale;
	}
	return 0;
}

int camera_texture_update(struct camera_texture *t, const struct camera_frame *f)
{
	const struct camera_view *v = &t->view;
	struct program *p;
	struct camera_crop crop;
	GLuint tex[3] = {0, 0, 0};
	double scale[2];
	bool imported;
	int ret;

	ret = camera_crop_make(f->layout.width, f->layout.height, v->cx, v->cy, v->radius,
			       v->mirror, &crop);
	if (ret) {
		log_err("camera: the crop circle (%g, %g) radius %g is outside the %dx%d frame",
			v->cx, v->cy, v->radius, f->layout.width, f->layout.height);
		return ret;
	}
	if (crop.shrunk && !t->said_shrunk)
		log_warn("camera: the crop circle (%g, %g) radius %g does not fit in the %dx%d "
			 "frame; using a smaller radius",
			 v->cx, v->cy, v->radius, f->layout.width, f->layout.height);
	t->said_shrunk |= crop.shrunk;
	ret = frame_textures(t, f, tex, scale, &imported);
	if (ret)
		return ret;
	p = program_get(t, f->layout.kind);
	if (!p)
		return -EINVAL;
	t->gl->UseProgram(p->id);
	set_selectors(t, p, f, imported);
	set_uniforms(t, p, f, tex, scale, &crop);
	draw_pass(t);
	t->path = imported ? CAMERA_PATH_IMPORT : CAMERA_PATH_UPLOAD;
	if (t->path != t->logged_path)
		log_info("camera: frames reach the GPU by %s", camera_path_name(t->path));
	t->logged_path = t->path;
	t->drawn = true;
	return 0;
}

struct camera_texture *camera_texture_new(const struct gl *gl, const char *shader_dir, int size,
					  bool allow_import)
{
	static const float quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
	struct camera_texture *t = calloc(1, sizeof(*t));
	GLint fbo = 0;

	if (!t)
		return NULL;
	t->gl = gl;
	t->shader_dir = shader_dir;
	t->size = size;
	t->view = (struct camera_view){0.5, 0.5, 0.5, false};
	t->import = allow_import ? import_new(gl) : NULL;
	gl->GenBuffers(1, &t->vbo);
	gl->BindBuffer(GL_ARRAY_BUFFER, t->vbo);
	gl->BufferData(GL_ARRAY_BUFFER, sizeof(quad), quad, GL_STATIC_DRAW);
	gl->GenTextures(1, &t->color);
	gl->BindTexture(GL_TEXTURE_2D, t->color);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
	set_sampling(gl, GL_LINEAR);
	gl->GetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
	gl->GenFramebuffers(1, &t->fbo);
	gl->BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
	gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->color, 0);
	if (gl->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
		log_err("camera: a %dx%d framebuffer for the camera matcap is incomplete", size,
			size);
		gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
		camera_texture_free(t);
		return NULL;
	}
	gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
	return t;
}

void camera_texture_free(struct camera_texture *t)
{
	const struct gl *gl;

	if (!t)
		return;
	gl = t->gl;
	if (t->import) {
		for (int i = 0; i < IMPORT_SLOTS; i++)
			import_drop(gl, t->import, &t->import->slots[i]);
		free(t->import);
	}
	for (int i = 0; i < 4; i++)
		if (t->programs[i].id)
			gl->DeleteProgram(t->programs[i].id);
	for (int p = 0; p < CAMERA_MAX_PLANES; p++)
		if (t->upload[p])
			gl->DeleteTextures(1, &t->upload[p]);
	if (t->fbo)
		gl->DeleteFramebuffers(1, &t->fbo);
	gl->DeleteTextures(1, &t->color);
	gl->DeleteBuffers(1, &t->vbo);
	free(t);
}

void camera_texture_set_view(struct camera_texture *t, const struct camera_view *v)
{
	t->view = *v;
	t->said_shrunk = false;
}

GLuint camera_texture_id(const struct camera_texture *t)
{
	return t->drawn ? t->color : 0;
}

enum camera_path camera_texture_path(const struct camera_texture *t)
{
	return t->path;
}

const char *camera_path_name(enum camera_path p)
{
	static const char *const names[] = {"none", "dmabuf import (zero copy)",
					    "upload from the mapped buffer"};

	return names[p];
}

int camera_texture_read(struct camera_texture *t, struct image *out)
{
	const struct gl *gl = t->gl;
	GLint fbo = 0;
	int ret = image_alloc(out, t->size, t->size);

	if (ret)
		return ret;
	gl->GetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
	gl->BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
	gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
	gl->ReadPixels(0, 0, t->size, t->size, GL_RGBA, GL_UNSIGNED_BYTE, out->rgba);
	gl->BindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
	return gl->GetError() == GL_NO_ERROR ? 0 : -EIO;
}
