#include "render/shader.h"
#include "util/log.h"
#include "render/shader_files.h"

#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SHADER_MAX_FILE (256u << 10)

static char *read_text(const char *path)
{
	FILE *f = fopen(path, "rb");
	char *text = NULL;
	size_t n;

	if (!f) {
		log_err("%s: cannot open shader: %s", path, strerror(errno));
		return NULL;
	}
	text = malloc(SHADER_MAX_FILE + 1);
	if (text) {
		n = fread(text, 1, SHADER_MAX_FILE, f);
		text[n] = '\0';
	}
	fclose(f);
	return text;
}

char *shader_read(const char *dir, const char *name)
{
	char path[4096];

	if (dir) {
		snprintf(path, sizeof(path), "%s/%s", dir, name);
		return read_text(path);
	}
	for (const struct shader_file *f = shader_files; f->name; f++)
		if (strcmp(f->name, name) == 0)
			return strdup(f->text);
	log_err("shader %s is not built in", name);
	return NULL;
}

/* #line gives mapping.glsl the source number 1, the stage's file 2 and
 * material.glsl (fragment stage only) 3, so the driver's "1:12" or "2:40"
 * can be read back to a file and a line. */
static void log_failure(const struct gl *gl, GLuint obj, bool is_program, const char *dir,
			const char *file)
{
	char log[4096] = "";

	if (is_program)
		gl->GetProgramInfoLog(obj, sizeof(log), NULL, log);
	else
		gl->GetShaderInfoLog(obj, sizeof(log), NULL, log);
	for (char *p = log; *p; p++)
		if (*p == '\n' && p[1])
			*p = ' ';
	log_err("%s/%s: %s failed (source 1 is mapping.glsl, 2 is %s, 3 is material.glsl): %s",
		dir ? dir : "shaders", file, is_program ? "link" : "compile", file, log);
}

static int compile(const struct gl *gl, GLenum type, const char *dir, const char *defines,
		   const char *file, GLuint *out)
{
	bool fragment = type == GL_FRAGMENT_SHADER;
	const char *precision = fragment ? "precision mediump float;\n" : "";
	char header[1024];
	char *mapping = shader_read(dir, "mapping.glsl");
	char *material = fragment ? shader_read(dir, "material.glsl") : NULL;
	char *body = shader_read(dir, file);
	const char *parts[6];
	int n = 0;
	GLint ok = 0;
	int ret = -EINVAL;

	if (!mapping || !body || (fragment && !material))
		goto out;
	snprintf(header, sizeof(header), "#version 100\n%s%s#line 1 1\n", precision, defines);
	parts[n++] = header;
	parts[n++] = mapping;
	if (fragment) {
		parts[n++] = "#line 1 3\n";
		parts[n++] = material;
	}
	parts[n++] = "#line 1 2\n";
	parts[n++] = body;
	*out = gl->CreateShader(type);
	gl->ShaderSource(*out, n, parts, NULL);
	gl->CompileShader(*out);
	gl->GetShaderiv(*out, GL_COMPILE_STATUS, &ok);
	if (!ok) {
		log_failure(gl, *out, false, dir, file);
		gl->DeleteShader(*out);
		goto out;
	}
	ret = 0;
out:
	free(mapping);
	free(material);
	free(body);
	return ret;
}

int shader_build(const struct gl *gl, const char *dir, const char *defines, GLuint *program)
{
	GLuint vs = 0, fs = 0;
	GLint ok = 0;
	int ret = -EINVAL;

	if (compile(gl, GL_VERTEX_SHADER, dir, defines, "matcap.vert", &vs) ||
	    compile(gl, GL_FRAGMENT_SHADER, dir, defines, "matcap.frag", &fs))
		goto out;
	*program = gl->CreateProgram();
	gl->AttachShader(*program, vs);
	gl->AttachShader(*program, fs);
	/* Fixed locations: the renderer enables only what a program reads. */
	gl->BindAttribLocation(*program, SHADER_ATTR_POSITION, "a_position");
	gl->BindAttribLocation(*program, SHADER_ATTR_NORMAL, "a_normal");
	gl->BindAttribLocation(*program, SHADER_ATTR_UV, "a_uv");
	gl->BindAttribLocation(*program, SHADER_ATTR_TANGENT, "a_tangent");
	gl->LinkProgram(*program);
	gl->GetProgramiv(*program, GL_LINK_STATUS, &ok);
	if (!ok) {
		log_failure(gl, *program, true, dir, "matcap.vert+matcap.frag");
		gl->DeleteProgram(*program);
		goto out;
	}
	ret = 0;
out:
	if (vs)
		gl->DeleteShader(vs);
	if (fs)
		gl->DeleteShader(fs);
	return ret;
}
