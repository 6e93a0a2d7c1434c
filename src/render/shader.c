#include "render/shader.h"
#include "util/log.h"
#include "render/shader_files.h"
#include "scene/mesh/material.h"

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

int shader_source_define(struct shader_source *s, const char *name)
{
	if (s->define_count >= SHADER_MAX_DEFINES)
		return -ENOSPC;
	s->defines[s->define_count++] = name;
	return 0;
}

int shader_source_matcap(struct shader_source *s, const char *dir, unsigned features,
			 enum shading_mode mode, bool ortho, bool lit, bool highp)
{
	static const struct {
		unsigned feature;
		const char *name;
	} feature_defines[] = {
	    {MATERIAL_IRIDESCENCE, "IRIDESCENCE"},   {MATERIAL_RAMP, "IRIDESCENCE_RAMP"},
	    {MATERIAL_DETAIL, "DETAIL_MAP"},	     {MATERIAL_DETAIL_NORMAL, "DETAIL_NORMAL"},
	    {MATERIAL_BASE_COLOR, "BASE_COLOR"},     {MATERIAL_BASE_MAP, "BASE_MAP"},
	    {MATERIAL_ALPHA_MASK, "ALPHA_MASK"},     {MATERIAL_ALPHA_BLEND, "ALPHA_BLEND"},
	    {MATERIAL_DOUBLE_SIDED, "DOUBLE_SIDED"}, {MATERIAL_EMISSIVE, "EMISSIVE"},
	    {MATERIAL_EMISSIVE_MAP, "EMISSIVE_MAP"}, {MATERIAL_EMISSIVE_UV1, "EMISSIVE_UV1"},
	    {MATERIAL_UNLIT, "UNLIT"}};
	int ret;

	/* The lit mode compares shapes: it keeps its own grey, and shades
	 * every part (its emission still added). */
	if (lit)
		features &= ~(unsigned)(MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP | MATERIAL_UNLIT);
	*s = (struct shader_source){.dir = dir,
				    .precision = "precision mediump float;\n",
				    .vertex = {"mapping.glsl", "matcap.vert"},
				    .fragment = {"mapping.glsl", "material.glsl", "matcap.frag"},
				    .attributes = {[SHADER_ATTR_POSITION] = "a_position",
						   [SHADER_ATTR_NORMAL] = "a_normal",
						   [SHADER_ATTR_UV] = "a_uv",
						   [SHADER_ATTR_TANGENT] = "a_tangent",
						   [SHADER_ATTR_COLOR] = "a_color"}};
	/* Bound only where a program reads it: the others keep the location free. */
	if (features & MATERIAL_EMISSIVE_UV1)
		s->attributes[SHADER_ATTR_UV1] = "a_uv1";
	/* These read the normal per fragment, which sem-vertex has not. */
	if (mode == SHADING_SEM_VERTEX &&
	    (lit ||
	     (features & (MATERIAL_IRIDESCENCE | MATERIAL_DETAIL_NORMAL | MATERIAL_DOUBLE_SIDED))))
		mode = SHADING_SEM_FRAGMENT;
	ret = shader_source_define(s, shading_mode_macro(mode));
	if (!ret && ortho)
		ret = shader_source_define(s, "CAMERA_ORTHO");
	for (size_t i = 0; i < sizeof(feature_defines) / sizeof(feature_defines[0]); i++)
		if (!ret && (features & feature_defines[i].feature))
			ret = shader_source_define(s, feature_defines[i].name);
	if (!ret && lit)
		ret = shader_source_define(s, "LIT");
	if (!ret && highp)
		ret = shader_source_define(s, "PRECISION_HIGHP");
	return ret;
}

static const char *const *stage_files(const struct shader_source *s, bool fragment)
{
	return fragment ? s->fragment : s->vertex;
}

/* The stage's own file: its last, after what it shares. */
static const char *main_file(const char *const *files)
{
	int i = 0;

	while (i + 1 < SHADER_MAX_FILES && files[i + 1])
		i++;
	return files[i];
}

/* One stage's text, as struct shader_source says. NULL after logging. */
static char *stage_text(const struct shader_source *s, bool fragment)
{
	const char *const *files = stage_files(s, fragment);
	char *text = NULL, *body;
	size_t size = 0;
	FILE *f = open_memstream(&text, &size);
	bool ok = true;

	if (!f) {
		log_err("shader: no memory for %s", main_file(files));
		return NULL;
	}
	fputs("#version 100\n", f);
	if (fragment && s->precision)
		fputs(s->precision, f);
	for (int i = 0; i < s->define_count; i++)
		fprintf(f, "#define %s 1\n", s->defines[i]);
	if (s->bones > 0)
		fprintf(f, "#define SKIN_BONES %d\n", s->bones);
	if (s->morph_targets > 0)
		fprintf(f, "#define MORPH_TARGETS %d\n%s", s->morph_targets,
			s->morph_normals ? "#define MORPH_NORMALS 1\n" : "");
	for (int i = 0; ok && i < SHADER_MAX_FILES && files[i]; i++) {
		body = shader_read(s->dir, files[i]);
		if (body)
			fprintf(f, "#line 1 %d\n%s", i + 1, body);
		ok = body != NULL;
		free(body);
	}
	ok = fclose(f) == 0 && ok;
	if (!ok) {
		free(text);
		text = NULL;
	}
	return text;
}

/* The driver's log goes on one line of the journal. */
static void one_line(char *log)
{
	for (char *p = log; *p; p++)
		if (*p == '\n')
			*p = p[1] ? ' ' : '\0';
}

static void log_compile_failure(const struct gl *gl, GLuint shader, const struct shader_source *s,
				bool fragment)
{
	const char *const *files = stage_files(s, fragment);
	char log[4096] = "", names[256] = "";
	size_t n = 0;

	gl->GetShaderInfoLog(shader, sizeof(log), NULL, log);
	one_line(log);
	for (int i = 0; i < SHADER_MAX_FILES && files[i] && n < sizeof(names); i++)
		n += (size_t)snprintf(names + n, sizeof(names) - n, "%s%d is %s", i ? ", " : "",
				      i + 1, files[i]);
	log_err("%s/%s: compile failed (source %s): %s", s->dir ? s->dir : "shaders",
		main_file(files), names, log);
}

static void log_link_failure(const struct gl *gl, GLuint program, const struct shader_source *s)
{
	char log[4096] = "";

	gl->GetProgramInfoLog(program, sizeof(log), NULL, log);
	one_line(log);
	log_err("%s/%s+%s: link failed: %s", s->dir ? s->dir : "shaders", main_file(s->vertex),
		main_file(s->fragment), log);
}

/* *out is the shader made, even when it failed: the caller deletes it. */
static int compile_stage(const struct gl *gl, const struct shader_source *s, bool fragment,
			 GLuint *out)
{
	char *text = stage_text(s, fragment);
	const char *parts[1] = {text};
	GLint ok = 0;

	if (!text)
		return -EINVAL;
	*out = gl->CreateShader(fragment ? GL_FRAGMENT_SHADER : GL_VERTEX_SHADER);
	gl->ShaderSource(*out, 1, parts, NULL);
	gl->CompileShader(*out);
	gl->GetShaderiv(*out, GL_COMPILE_STATUS, &ok);
	free(text);
	if (!ok)
		log_compile_failure(gl, *out, s, fragment);
	return ok ? 0 : -EINVAL;
}

/* *out is the program made, even when it failed: the caller deletes it. */
static int link_program(const struct gl *gl, const struct shader_source *s, GLuint vs, GLuint fs,
			GLuint *out)
{
	GLint ok = 0;

	*out = gl->CreateProgram();
	gl->AttachShader(*out, vs);
	gl->AttachShader(*out, fs);
	for (int i = 0; i < SHADER_MAX_ATTRIBUTES; i++)
		if (s->attributes[i])
			gl->BindAttribLocation(*out, (GLuint)i, s->attributes[i]);
	gl->LinkProgram(*out);
	gl->GetProgramiv(*out, GL_LINK_STATUS, &ok);
	if (!ok)
		log_link_failure(gl, *out, s);
	return ok ? 0 : -EINVAL;
}

int shader_program_build(const struct gl *gl, const struct shader_source *s, GLuint *program)
{
	GLuint vs = 0, fs = 0, prog = 0;
	int ret = compile_stage(gl, s, false, &vs);

	if (!ret)
		ret = compile_stage(gl, s, true, &fs);
	if (!ret)
		ret = link_program(gl, s, vs, fs, &prog);
	/* The program keeps what it needs of its shaders. */
	if (vs)
		gl->DeleteShader(vs);
	if (fs)
		gl->DeleteShader(fs);
	if (ret && prog)
		gl->DeleteProgram(prog);
	if (!ret)
		*program = prog;
	return ret;
}
