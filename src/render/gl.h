/* One table of GL entry points, filled from the active backend.
 *
 * libOSMesa and libGLESv2 both export the gl* symbols, so the program links
 * neither: every call goes through this table, filled by the backend from
 * OSMesaGetProcAddress or eglGetProcAddress, and the renderer never knows
 * which one filled it. */
#ifndef MK_GL_H
#define MK_GL_H

#include <GLES2/gl2.h>
#include <stdbool.h>

#define GL_FUNCS(X)                                                                                \
	X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                   \
	X(PFNGLATTACHSHADERPROC, AttachShader)                                                     \
	X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)                                         \
	X(PFNGLBINDBUFFERPROC, BindBuffer)                                                         \
	X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                               \
	X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                             \
	X(PFNGLBINDTEXTUREPROC, BindTexture)                                                       \
	X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                                           \
	X(PFNGLBUFFERDATAPROC, BufferData)                                                         \
	X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                                   \
	X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                 \
	X(PFNGLCLEARPROC, Clear)                                                                   \
	X(PFNGLCLEARCOLORPROC, ClearColor)                                                         \
	X(PFNGLCOMPILESHADERPROC, CompileShader)                                                   \
	X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                   \
	X(PFNGLCREATESHADERPROC, CreateShader)                                                     \
	X(PFNGLCULLFACEPROC, CullFace)                                                             \
	X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                   \
	X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                         \
	X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                   \
	X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                                       \
	X(PFNGLDELETESHADERPROC, DeleteShader)                                                     \
	X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                 \
	X(PFNGLDEPTHMASKPROC, DepthMask)                                                           \
	X(PFNGLDISABLEPROC, Disable)                                                               \
	X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)                             \
	X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                         \
	X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                     \
	X(PFNGLENABLEPROC, Enable)                                                                 \
	X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                               \
	X(PFNGLFINISHPROC, Finish)                                                                 \
	X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                               \
	X(PFNGLFRONTFACEPROC, FrontFace)                                                           \
	X(PFNGLGENBUFFERSPROC, GenBuffers)                                                         \
	X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                               \
	X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                             \
	X(PFNGLGENTEXTURESPROC, GenTextures)                                                       \
	X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                                                 \
	X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                                           \
	X(PFNGLGETERRORPROC, GetError)                                                             \
	X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                       \
	X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                           \
	X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                     \
	X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                             \
	X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                       \
	X(PFNGLGETSTRINGPROC, GetString)                                                           \
	X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                         \
	X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                       \
	X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                       \
	X(PFNGLREADPIXELSPROC, ReadPixels)                                                         \
	X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                                       \
	X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                     \
	X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                         \
	X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                   \
	X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                                   \
	X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                     \
	X(PFNGLUNIFORM1FPROC, Uniform1f)                                                           \
	X(PFNGLUNIFORM1IPROC, Uniform1i)                                                           \
	X(PFNGLUNIFORM2FPROC, Uniform2f)                                                           \
	X(PFNGLUNIFORM3FPROC, Uniform3f)                                                           \
	X(PFNGLUNIFORM4FPROC, Uniform4f)                                                           \
	X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                         \
	X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                                             \
	X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                             \
	X(PFNGLUSEPROGRAMPROC, UseProgram)                                                         \
	X(PFNGLVERTEXATTRIB4FVPROC, VertexAttrib4fv)                                               \
	X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                       \
	X(PFNGLVIEWPORTPROC, Viewport)

/* Multisampled framebuffers, where the context has them (OpenGL ES 3.0,
 * desktop GL's ARB_framebuffer_object, EXT_multisampled_render_to_texture):
 * loaded without being required, NULL where the driver has none. A
 * driver may hand out an entry its context cannot use: check the version
 * or the extension first. */
typedef void (*gl_storage_multisample_fn)(GLenum, GLsizei, GLenum, GLsizei, GLsizei);
typedef void (*gl_blit_fn)(GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield,
			   GLenum);
typedef void (*gl_texture_multisample_fn)(GLenum, GLenum, GLenum, GLuint, GLint, GLsizei);
#define GL_OPTIONAL_FUNCS(X)                                                                       \
	X(gl_blit_fn, BlitFramebuffer)                                                             \
	X(gl_storage_multisample_fn, RenderbufferStorageMultisample)                               \
	X(gl_storage_multisample_fn, RenderbufferStorageMultisampleEXT)                            \
	X(gl_texture_multisample_fn, FramebufferTexture2DMultisampleEXT)

/* What the context can do, read once when it is made: the renderer and
 * the camera pass look here, never at extension strings, renderer names
 * or which display backend made the context. */
struct gl_caps {
	/* A CPU rasteriser (llvmpipe, softpipe, swrast): it emulates mediump,
	 * and reads imported buffers on the CPU anyway. */
	bool software;
	bool element_index_uint; /* GL_OES_element_index_uint: 32-bit indices */
	bool depth24;		 /* GL_OES_depth24 renderbuffers */
	bool egl_image;		 /* GL_OES_EGL_image: a texture from an EGLImage */
	/* Set by the EGL backends only: the context's EGLDisplay (NULL: not
	 * an EGL context, as with OSMesa), and whether it imports dmabufs
	 * (EGL_EXT_image_dma_buf_import). */
	void *egl_display;
	bool dmabuf_import;
	/* GL_MAX_VERTEX_UNIFORM_VECTORS (at least 128 in GLES2): the bone
	 * palette of a model skinned on the GPU is sized from it. */
	int max_vertex_uniform_vectors;
	/* GL_MAX_VERTEX_ATTRIBS (at least 8 in GLES2): what the model's
	 * program leaves of them carries its morph targets on the GPU. */
	int max_vertex_attribs;
};

struct gl {
#define GL_MEMBER(type, name) type name;
	GL_FUNCS(GL_MEMBER)
	GL_OPTIONAL_FUNCS(GL_MEMBER)
#undef GL_MEMBER
	struct gl_caps caps;
};

typedef void *(*gl_get_proc_fn)(void *ctx, const char *name);

/* Fill every entry through get_proc("gl" + name), then the GL side of
 * caps (the context must be current). Returns 0, or -ENOSYS after
 * logging the first entry point the driver does not provide. */
int gl_load(struct gl *gl, gl_get_proc_fn get_proc, void *ctx);

/* Whether name is one of the space-separated names in list (GL's or
 * EGL's extension string); a NULL list has none. */
bool gl_extension_listed(const char *list, const char *name);

/* A picture drawn once over the frame (the poster, a background image):
 * RGBA bytes, one level, linear, clamped. Returns the texture, bound. */
GLuint gl_texture_picture(const struct gl *gl, int width, int height, const void *rgba);

/* A quad of four corners (xy each, a triangle strip) from client memory,
 * the attribute attr fed from it: what the pictures over the frame draw
 * (the poster, the background, the caption, the render-scale pass). */
void gl_draw_quad(const struct gl *gl, GLuint attr, const float corners[8]);

#endif
