#include "render/gl.h"
#include "util/log.h"

#include <errno.h>
#include <string.h>

bool gl_extension_listed(const char *list, const char *name)
{
	size_t n = strlen(name);

	while (list && *list) {
		const char *end = strchr(list, ' ');
		size_t len = end ? (size_t)(end - list) : strlen(list);

		if (len == n && memcmp(list, name, n) == 0)
			return true;
		list = end ? end + 1 : NULL;
	}
	return false;
}

static void read_caps(const struct gl *gl, struct gl_caps *caps)
{
	const char *name = (const char *)gl->GetString(GL_RENDERER);
	const char *ext = (const char *)gl->GetString(GL_EXTENSIONS);

	caps->software = name && (strstr(name, "llvmpipe") || strstr(name, "softpipe") ||
				  strstr(name, "swrast"));
	caps->element_index_uint = gl_extension_listed(ext, "GL_OES_element_index_uint");
	caps->depth24 = gl_extension_listed(ext, "GL_OES_depth24");
	caps->egl_image = gl_extension_listed(ext, "GL_OES_EGL_image");
	/* A desktop context without ES2 compatibility knows only the
	 * components (GL_MAX_VERTEX_UNIFORM_COMPONENTS); GLES2's floor else. */
	caps->max_vertex_uniform_vectors = 0;
	for (int i = 0; i < 8 && gl->GetError() != GL_NO_ERROR; i++)
		;
	gl->GetIntegerv(GL_MAX_VERTEX_UNIFORM_VECTORS, &caps->max_vertex_uniform_vectors);
	if (gl->GetError() != GL_NO_ERROR || caps->max_vertex_uniform_vectors <= 0) {
		GLint components = 0;

		gl->GetIntegerv(0x8B4A, &components);
		caps->max_vertex_uniform_vectors =
		    gl->GetError() == GL_NO_ERROR && components > 0 ? components / 4 : 128;
	}
	caps->max_vertex_attribs = 0;
	gl->GetIntegerv(GL_MAX_VERTEX_ATTRIBS, &caps->max_vertex_attribs);
	if (gl->GetError() != GL_NO_ERROR || caps->max_vertex_attribs < 8)
		caps->max_vertex_attribs = 8;
}

int gl_load(struct gl *gl, gl_get_proc_fn get_proc, void *ctx)
{
	void *p;

	memset(gl, 0, sizeof(*gl));
#define GL_LOAD(type, name)                                                                        \
	p = get_proc(ctx, "gl" #name);                                                             \
	if (!p) {                                                                                  \
		log_err("GL driver lacks gl" #name);                                               \
		return -ENOSYS;                                                                    \
	}                                                                                          \
	memcpy(&gl->name, &p, sizeof(p));
	GL_FUNCS(GL_LOAD)
#undef GL_LOAD
#define GL_LOAD_OPTIONAL(type, name)                                                               \
	p = get_proc(ctx, "gl" #name);                                                             \
	memcpy(&gl->name, &p, sizeof(p));
	GL_OPTIONAL_FUNCS(GL_LOAD_OPTIONAL)
#undef GL_LOAD_OPTIONAL
	read_caps(gl, &gl->caps);
	return 0;
}

GLuint gl_texture_picture(const struct gl *gl, int width, int height, const void *rgba)
{
	GLuint tex = 0;

	gl->GenTextures(1, &tex);
	gl->BindTexture(GL_TEXTURE_2D, tex);
	gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
		       rgba);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	return tex;
}

void gl_draw_quad(const struct gl *gl, GLuint attr, const float corners[8])
{
	gl->BindBuffer(GL_ARRAY_BUFFER, 0);
	gl->EnableVertexAttribArray(attr);
	gl->VertexAttribPointer(attr, 2, GL_FLOAT, GL_FALSE, 0, corners);
	gl->DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
	gl->DisableVertexAttribArray(attr);
}
