#include "display/display.h"
#include "oracle/oracle.h"
#include "render/render.h"
#include "render/shader.h"
#include "scene/mesh/mesh.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static void mode_names_round_trip(void **state)
{
	enum shading_mode m;

	(void)state;
	for (int i = 0; i < SHADING_MODE_COUNT; i++) {
		assert_int_equal(shading_mode_parse(shading_mode_name((enum shading_mode)i), &m),
				 0);
		assert_int_equal(m, i);
	}
	assert_int_equal(shading_mode_parse("lambert", &m), -EINVAL);
}

static void normal_mode_maps_the_disk(void **state)
{
	double uv[2];
	double up[3] = {0, 1, 0}, right[3] = {1, 0, 0}, front[3] = {0, 0, 1};

	(void)state;
	shading_uv_normal(front, uv);
	assert_true(uv[0] == 0.5 && uv[1] == 0.5);
	shading_uv_normal(up, uv);
	assert_true(uv[0] == 0.5 && uv[1] == 0.0); /* top row of the image */
	shading_uv_normal(right, uv);
	assert_true(uv[0] == 1.0 && uv[1] == 0.5);
}

static double radius(const double uv[2])
{
	return hypot(uv[0] - 0.5, uv[1] - 0.5);
}

/* r = reflect(e, n) = (0,0,-1) makes m = 0: a surface seen exactly edge-on
 * at the centre of the screen. The result must stay finite and on the
 * disk, and approach the rim continuously. */
static void sem_is_safe_at_the_singularity(void **state)
{
	double e[3] = {0, 0, -1}, uv[2];

	(void)state;
	for (int k = 0; k <= 40; k++) {
		double eps = k == 40 ? 0.0 : pow(10.0, -k / 4.0);
		double n[3] = {1, 0, eps}, len = hypot(1, eps);

		n[0] /= len;
		n[2] /= len;
		shading_uv_sem(n, e, uv);
		assert_true(isfinite(uv[0]) && isfinite(uv[1]));
		/* The exact value is 1 / (2 sqrt(1 + eps^2)): the rim, less eps^2/4. */
		assert_true(radius(uv) <= 0.5 + 1e-12);
		assert_true(fabs(radius(uv) - 0.5) <= 0.25 * eps * eps + 1e-9);
	}
}

static void sem_facing_viewer_is_centre(void **state)
{
	double e[3] = {0, 0, -1}, n[3] = {0, 0, 1}, uv[2];

	(void)state;
	shading_uv_sem(n, e, uv);
	assert_true(fabs(uv[0] - 0.5) < 1e-12 && fabs(uv[1] - 0.5) < 1e-12);
}

static void view_mode_stays_inside_the_disk(void **state)
{
	double uv[2];

	(void)state;
	for (int i = 0; i < 1000; i++) {
		double a = i * 0.7, b = i * 0.13;
		double n[3] = {cos(a) * sin(b), sin(a) * sin(b), cos(b)};
		double e[3] = {0.3 * sin(a), 0.2 * cos(b), -1};
		double el = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);

		for (int k = 0; k < 3; k++)
			e[k] /= el;
		shading_uv_view(n, e, uv);
		assert_true(radius(uv) <= 0.495 + 1e-9);
	}
}

/* The shader builder on a real GL (OSMesa), through a copy of the GL table
 * that counts the shaders and programs made and deleted: a build that
 * fails must delete each exactly once, leave no GL error and return
 * nothing. */
#define MAX_OBJECTS 64

struct tally {
	struct gl real;
	GLuint live[MAX_OBJECTS]; /* shaders and programs not deleted yet */
	int made, bad_deletes;
};

static struct tally tally; /* the wrappers below have no user pointer */

static void tally_add(GLuint id)
{
	tally.made++;
	for (int i = 0; i < MAX_OBJECTS; i++)
		if (!tally.live[i]) {
			tally.live[i] = id;
			return;
		}
}

static void tally_remove(GLuint id)
{
	for (int i = 0; i < MAX_OBJECTS; i++)
		if (id && tally.live[i] == id) {
			tally.live[i] = 0;
			return;
		}
	tally.bad_deletes++;
}

static int tally_live(void)
{
	int n = 0;

	for (int i = 0; i < MAX_OBJECTS; i++)
		n += tally.live[i] != 0;
	return n;
}

/* Shaders and programs share GL's name space: programs are tagged here,
 * so that deleting one as the other counts as a bad delete. */
static GLuint GL_APIENTRY counted_create_shader(GLenum type)
{
	GLuint id = tally.real.CreateShader(type);

	tally_add(id);
	return id;
}

static void GL_APIENTRY counted_delete_shader(GLuint id)
{
	tally_remove(id);
	tally.real.DeleteShader(id);
}

static GLuint GL_APIENTRY counted_create_program(void)
{
	GLuint id = tally.real.CreateProgram();

	tally_add(id | 0x80000000u);
	return id;
}

static void GL_APIENTRY counted_delete_program(GLuint id)
{
	tally_remove(id | 0x80000000u);
	tally.real.DeleteProgram(id);
}

struct builder_fixture {
	struct display *d;
	struct gl gl; /* the display's, with the counting wrappers */
	char dir[64];
};

static void write_file(const char *dir, const char *name, const char *text)
{
	char path[128];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

/* The built-in matcap sources, so one of them can be broken. */
static void copy_builtin(const char *dir, const char *name)
{
	char *text = shader_read(NULL, name);

	assert_non_null(text);
	write_file(dir, name, text);
	free(text);
}

static int builder_setup(void **state)
{
	static const char *const files[] = {"mapping.glsl", "material.glsl", "matcap.vert",
					    "matcap.frag"};
	struct display_config cfg = {.width = 16, .height = 16};
	struct builder_fixture *f = calloc(1, sizeof(*f));

	if (!f)
		return -1;
	f->d = display_osmesa_new(&cfg);
	if (!f->d || f->d->begin_frame(f->d))
		return -1;
	memset(&tally, 0, sizeof(tally));
	tally.real = f->d->gl;
	f->gl = f->d->gl;
	f->gl.CreateShader = counted_create_shader;
	f->gl.DeleteShader = counted_delete_shader;
	f->gl.CreateProgram = counted_create_program;
	f->gl.DeleteProgram = counted_delete_program;
	strcpy(f->dir, "/tmp/mk-shader-XXXXXX");
	if (!mkdtemp(f->dir))
		return -1;
	for (size_t i = 0; i < sizeof(files) / sizeof(files[0]); i++)
		copy_builtin(f->dir, files[i]);
	write_file(f->dir, "plain.vert",
		   "attribute vec4 a_position;\nvoid main() { gl_Position = a_position; }\n");
	write_file(f->dir, "plain.frag", "void main() { gl_FragColor = vec4(VALUE); }\n");
	write_file(f->dir, "typo.frag", "void main() { gl_FragColor = vec4(1.0) }\n");
	/* Compiles, but a program needs a main in each stage: the link fails. */
	write_file(f->dir, "no_main.frag", "vec4 colour() { return vec4(1.0); }\n");
	*state = f;
	return 0;
}

/* OSMesa leaks a fixed few hundred bytes per process; see
 * tests/unit/test_camera_texture.c. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
	return "leak:libOSMesa\nleak:libLLVM\nleak:display_osmesa_new\n";
}

static int builder_teardown(void **state)
{
	struct builder_fixture *f = *state;
	char cmd[96];

	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", f->dir);
	if (system(cmd) != 0)
		return -1;
	/* The display is left open: see __lsan_default_suppressions. */
	free(f);
	return 0;
}

static struct shader_source plain_source(const char *dir, const char *fragment)
{
	struct shader_source src = {.dir = dir,
				    .precision = "precision mediump float;\n",
				    .vertex = {"plain.vert"},
				    .fragment = {fragment},
				    .attributes = {"a_position"}};

	return src;
}

static void builder_makes_a_program(void **state)
{
	struct builder_fixture *f = *state;
	struct shader_source src = plain_source(f->dir, "plain.frag");
	GLuint prog = 0;
	GLint linked = 0;

	assert_int_equal(shader_source_define(&src, "VALUE"), 0);
	assert_int_equal(shader_program_build(&f->gl, &src, &prog), 0);
	assert_true(prog != 0);
	f->gl.GetProgramiv(prog, GL_LINK_STATUS, &linked);
	assert_true(linked);
	/* The two shaders went with the build; the program is the caller's. */
	assert_int_equal(tally.made, 3);
	assert_int_equal(tally_live(), 1);
	f->gl.DeleteProgram(prog);
	assert_int_equal(tally_live(), 0);
	assert_int_equal(tally.bad_deletes, 0);
	assert_int_equal(f->gl.GetError(), GL_NO_ERROR);
}

static void check_failed_build(struct builder_fixture *f, const char *fragment, int made)
{
	struct shader_source src = plain_source(f->dir, fragment);
	GLuint prog = 12345;

	tally.made = 0;
	assert_int_equal(shader_program_build(&f->gl, &src, &prog), -EINVAL);
	assert_int_equal(prog, 12345);
	assert_int_equal(tally.made, made);
	assert_int_equal(tally_live(), 0);
	assert_int_equal(tally.bad_deletes, 0);
	assert_int_equal(f->gl.GetError(), GL_NO_ERROR);
}

static void builder_frees_a_failed_build_once(void **state)
{
	struct builder_fixture *f = *state;

	check_failed_build(f, "typo.frag", 2);	  /* the fragment stage fails */
	check_failed_build(f, "no_main.frag", 3); /* both compile, the link fails */
	check_failed_build(f, "missing.frag", 1); /* the file is not there */
}

/* A variant that fails to build leaves the one in use drawing, and is not
 * remembered: asked again, the renderer tries again. */
static void renderer_keeps_its_program_when_a_build_fails(void **state)
{
	struct builder_fixture *f = *state;
	struct renderer *r = renderer_new(&f->gl, f->dir);
	struct material mat = {0};
	struct renderer_stats st;
	struct mesh m;
	GLuint first;
	GLint linked = 0;

	assert_non_null(r);
	assert_int_equal(mesh_uv_sphere(&m, 8, 4), 0);
	assert_int_equal(renderer_set_material(r, &mat), 0);
	assert_int_equal(renderer_set_mesh(r, &m), 0);
	assert_int_equal(renderer_set_mode(r, SHADING_VIEW, false), 0);
	renderer_get_stats(r, &st);
	first = st.program;
	write_file(f->dir, "matcap.frag", "vec4 colour() { return vec4(1.0); }\n");
	for (int i = 0; i < 2; i++) {
		assert_int_equal(renderer_set_mode(r, SHADING_NORMAL, false), -EINVAL);
		renderer_get_stats(r, &st);
		assert_int_equal(st.program, first);
	}
	write_file(f->dir, "matcap.frag", "void main() { gl_FragColor = vec4(1.0) }\n");
	assert_int_equal(renderer_set_mode(r, SHADING_NORMAL, true), -EINVAL);
	f->gl.GetProgramiv(first, GL_LINK_STATUS, &linked);
	assert_true(linked);
	f->d->begin_frame(f->d);
	renderer_draw(r, &(struct view){.orientation = quat_identity()}, 16, 16);
	assert_int_equal(f->gl.GetError(), GL_NO_ERROR);
	copy_builtin(f->dir, "matcap.frag");
	assert_int_equal(renderer_set_mode(r, SHADING_NORMAL, false), 0);
	renderer_get_stats(r, &st);
	assert_true(st.program != 0 && st.program != first);
	renderer_free(r);
	mesh_release(&m);
	assert_int_equal(tally_live(), 0);
	assert_int_equal(tally.bad_deletes, 0);
	assert_int_equal(f->gl.GetError(), GL_NO_ERROR);
}

/* Whether the last draw read the matcap's mipmaps, drawing a w x h frame
 * with a side x side matcap under the given filter. */
static bool draws_mipmapped(struct builder_fixture *f, enum matcap_filter filter, int side, int w,
			    int h)
{
	struct renderer *r = renderer_new(&f->gl, f->dir);
	struct material mat = {0};
	struct renderer_stats st;
	struct image img = {0};
	struct mesh m;

	assert_non_null(r);
	assert_int_equal(image_alloc(&img, side, side), 0);
	assert_int_equal(mesh_uv_sphere(&m, 8, 4), 0);
	renderer_set_matcap_filter(r, filter);
	assert_int_equal(renderer_set_material(r, &mat), 0);
	assert_int_equal(renderer_set_mesh(r, &m), 0);
	assert_int_equal(renderer_set_matcap(r, &img), 0);
	copy_builtin(f->dir, "matcap.frag");
	assert_int_equal(renderer_set_mode(r, SHADING_VIEW, false), 0);
	f->d->begin_frame(f->d);
	renderer_draw(r, &(struct view){.orientation = quat_identity()}, w, h);
	assert_int_equal(f->gl.GetError(), GL_NO_ERROR);
	renderer_get_stats(r, &st);
	assert_int_equal(st.matcap_filter, filter);
	renderer_free(r);
	mesh_release(&m);
	image_release(&img);
	return st.matcap_mipmapped;
}

/* auto: mipmaps only where the model's disc (at most 2 x the pixels per
 * unit: 151 px in 128x128, 282 px in 320x240, 847 px in 1280x720) is no
 * wider than the matcap; the forced filters whatever the size; a matcap
 * whose size GLES2 cannot mipmap stays linear under auto. */
static void matcap_filter_follows_the_size_on_screen(void **state)
{
	struct builder_fixture *f = *state;

	assert_true(draws_mipmapped(f, MATCAP_FILTER_AUTO, 256, 64, 64));
	assert_true(draws_mipmapped(f, MATCAP_FILTER_AUTO, 256, 128, 128));
	assert_false(draws_mipmapped(f, MATCAP_FILTER_AUTO, 256, 320, 240));
	assert_false(draws_mipmapped(f, MATCAP_FILTER_AUTO, 256, 1280, 720));
	assert_true(draws_mipmapped(f, MATCAP_FILTER_AUTO, 1024, 1280, 720));
	assert_false(draws_mipmapped(f, MATCAP_FILTER_AUTO, 201, 64, 64));
	assert_true(draws_mipmapped(f, MATCAP_FILTER_MIPMAP, 256, 1280, 720));
	assert_true(draws_mipmapped(f, MATCAP_FILTER_MIPMAP, 201, 1280, 720));
	assert_false(draws_mipmapped(f, MATCAP_FILTER_LINEAR, 256, 64, 64));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(mode_names_round_trip),
	    cmocka_unit_test(normal_mode_maps_the_disk),
	    cmocka_unit_test(sem_is_safe_at_the_singularity),
	    cmocka_unit_test(sem_facing_viewer_is_centre),
	    cmocka_unit_test(view_mode_stays_inside_the_disk),
	};
	const struct CMUnitTest builder[] = {
	    cmocka_unit_test(builder_makes_a_program),
	    cmocka_unit_test(builder_frees_a_failed_build_once),
	    cmocka_unit_test(renderer_keeps_its_program_when_a_build_fails),
	    cmocka_unit_test(matcap_filter_follows_the_size_on_screen),
	};
	int failed = cmocka_run_group_tests_name("shading", tests, NULL, NULL);

	return failed + cmocka_run_group_tests_name("shader builder", builder, builder_setup,
						    builder_teardown);
}
