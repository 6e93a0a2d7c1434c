/* A feature that is off costs nothing: for each mix of the material
 * features, build the renderer's programs through OSMesa and check what
 * the linked program reads (its active attributes and uniforms), which
 * vertex arrays were uploaded and which textures are bound. Exits 0 when
 * every scene holds exactly what its features need, else 1 (the
 * differences on stderr). Not a unit test: Mesa's own allocations would
 * trip the unit tests' LeakSanitizer. */
#include "display/display.h"
#include "scene/mesh/lod.h"
#include "util/log.h"
#include "scene/mesh/material.h"
#include "scene/mesh/mesh.h"
#include "render/render.h"
#include "scene/mesh/tangent.h"

#include <stdio.h>
#include <string.h>

struct scene_case {
	const char *name;
	unsigned features;
	int lit;
	enum shading_mode mode;
};

static const struct scene_case cases[] = {
    {"plain matcap", 0, LIT_OFF, SHADING_VIEW},
    {"displacement (CPU only)", MATERIAL_DISPLACEMENT, LIT_OFF, SHADING_VIEW},
    {"iridescence", MATERIAL_IRIDESCENCE, LIT_OFF, SHADING_VIEW},
    {"iridescence, sem-vertex", MATERIAL_IRIDESCENCE, LIT_OFF, SHADING_SEM_VERTEX},
    {"iridescence ramp", MATERIAL_IRIDESCENCE | MATERIAL_RAMP, LIT_OFF, SHADING_NORMAL},
    {"occlusion map", MATERIAL_DETAIL, LIT_OFF, SHADING_SEM_VERTEX},
    {"detail map", MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL, LIT_OFF, SHADING_SEM_FRAGMENT},
    {"lit", 0, LIT_ON, SHADING_VIEW},
    {"lit beside, everything",
     MATERIAL_IRIDESCENCE | MATERIAL_RAMP | MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL, LIT_BESIDE,
     SHADING_VIEW},
    {"base colour (COLOR_0)", MATERIAL_BASE_COLOR, LIT_OFF, SHADING_SEM_VERTEX},
    {"base colour and map", MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP, LIT_OFF, SHADING_VIEW},
    {"lit beside, base map", MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP, LIT_BESIDE, SHADING_NORMAL},
    {"lit, base map (not read)", MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP, LIT_ON, SHADING_VIEW},
};

/* Every name a feature brings, and whether this program should have it. */
static int check_program(const struct gl *gl, GLuint prog, unsigned f, bool lit, const char *name)
{
	const struct {
		const char *name;
		bool attribute, expected;
	} want[] = {
	    {"a_position", true, true},
	    {"a_normal", true, true},
	    {"a_uv", true, (f & MATERIAL_DETAIL) || ((f & MATERIAL_BASE_MAP) && !lit)},
	    {"a_color", true, (f & MATERIAL_BASE_COLOR) && !lit},
	    {"u_base_map", false, (f & MATERIAL_BASE_MAP) && !lit},
	    {"u_base_transform", false, (f & MATERIAL_BASE_MAP) && !lit},
	    {"a_tangent", true, (f & MATERIAL_DETAIL_NORMAL) != 0},
	    {"u_matcap", false, !lit},
	    {"u_detail", false, (f & MATERIAL_DETAIL) != 0},
	    {"u_iridescence", false, (f & MATERIAL_IRIDESCENCE) != 0},
	    {"u_ramp", false, (f & MATERIAL_RAMP) != 0},
	    {"u_hsv", false, (f & MATERIAL_IRIDESCENCE) && !(f & MATERIAL_RAMP)},
	    {"u_light", false, lit},
	    {"u_base_color", false, lit},
	    {"u_shininess", false, lit},
	};
	GLint attributes = 0, uniforms = 0;
	int expected_attributes = 0, bad = 0;

	for (size_t i = 0; i < sizeof(want) / sizeof(want[0]); i++) {
		GLint loc = want[i].attribute ? gl->GetAttribLocation(prog, want[i].name)
					      : gl->GetUniformLocation(prog, want[i].name);

		expected_attributes += want[i].attribute && want[i].expected;
		if ((loc >= 0) != want[i].expected) {
			fprintf(stderr, "%s: %s program %s %s\n", name, lit ? "lit" : "matcap",
				loc >= 0 ? "has" : "lacks", want[i].name);
			bad = 1;
		}
	}
	gl->GetProgramiv(prog, GL_ACTIVE_ATTRIBUTES, &attributes);
	gl->GetProgramiv(prog, GL_ACTIVE_UNIFORMS, &uniforms);
	if (attributes != expected_attributes) {
		fprintf(stderr, "%s: %d active attributes, expected %d\n", name, attributes,
			expected_attributes);
		bad = 1;
	}
	printf("  %s program: %d attributes, %d uniforms\n", lit ? "lit" : "matcap", attributes,
	       uniforms);
	return bad;
}

static void fill(struct image *img, int w, int h)
{
	image_alloc(img, w, h);
	memset(img->rgba, 200, (size_t)w * (size_t)h * 4);
}

static int check_case(struct display *d, const struct scene_case *c, const struct mesh *mesh,
		      const struct image *matcap)
{
	struct material_surface surface = {.alpha = 1.0f, .base_transform = {1, 0, 0, 1, 0, 0}};
	struct material mat = {.features = c->features,
			       .lit = c->lit,
			       .opacity = 0.5f,
			       .shininess = 32,
			       .surface_count = 1,
			       .surfaces = &surface};
	struct renderer *r = renderer_new(&d->gl, NULL);
	struct renderer_stats st;
	struct view v = {.orientation = quat_identity()};
	unsigned base =
	    c->lit == LIT_ON ? 0 : c->features & (MATERIAL_BASE_COLOR | MATERIAL_BASE_MAP);
	bool uvs = (c->features & MATERIAL_DETAIL) || (base & MATERIAL_BASE_MAP),
	     tangents = c->features & MATERIAL_DETAIL_NORMAL, colors = base & MATERIAL_BASE_COLOR;
	/* The default vertex format: int16 positions and normals, float UVs,
	 * int16 tangents, uint8 colours (src/render/render.c). The mesh has
	 * colours always: uploaded only for the base colour. */
	long bytes =
	    (long)mesh->vertex_count * (12 + (uvs ? 8 : 0) + (tangents ? 8 : 0) + (colors ? 4 : 0));
	int textures = (c->lit != LIT_ON) + ((c->features & MATERIAL_DETAIL) != 0) +
		       ((c->features & MATERIAL_RAMP) != 0) + ((base & MATERIAL_BASE_MAP) != 0);
	int bad = 0;

	printf("%s\n", c->name);
	fill(&mat.detail, 4, 4);
	fill(&mat.ramp, 8, 1);
	fill(&surface.base_map, 4, 4);
	if (!r || renderer_set_material(r, &mat) || renderer_set_mesh(r, mesh) ||
	    renderer_set_matcap(r, matcap) || renderer_set_mode(r, c->mode, false)) {
		fprintf(stderr, "%s: the renderer failed\n", c->name);
		bad = 1;
		goto out;
	}
	renderer_get_stats(r, &st);
	/* A model of one material: one draw with one program, as before it
	 * had ranges. */
	if (st.attributes != 2 + uvs + tangents + colors || st.vertex_bytes != bytes ||
	    st.textures != textures || st.draws != 1 || st.program_count != 1 ||
	    st.drawn[0].program != st.program) {
		fprintf(stderr,
			"%s: %d arrays of %ld bytes and %d textures, expected %d, %ld, %d\n",
			c->name, st.attributes, st.vertex_bytes, st.textures,
			2 + uvs + tangents + colors, bytes, textures);
		bad = 1;
	}
	bad |= check_program(&d->gl, st.program, c->features, c->lit == LIT_ON, c->name);
	if (c->lit == LIT_BESIDE)
		bad |= check_program(&d->gl, st.lit_program, c->features, true, c->name);
	d->begin_frame(d);
	renderer_draw(r, &v, d->width, d->height);
	d->present(d);
	if (d->gl.GetError() != GL_NO_ERROR) {
		fprintf(stderr, "%s: GL error while drawing\n", c->name);
		bad = 1;
	}
out:
	renderer_free(r);
	image_release(&mat.detail);
	image_release(&mat.ramp);
	image_release(&surface.base_map);
	return bad;
}

/* Two materials, a detail map on one and a film on the other: each range
 * draws with a program of its own material's features only (the one
 * without a detail map samples none). */
static int check_parts(struct display *d, struct mesh *mesh, const struct image *matcap)
{
	struct material_surface surfaces[2] = {
	    {.features = MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL,
	     .alpha = 1.0f,
	     .base_transform = {1, 0, 0, 1, 0, 0}},
	    {.features = MATERIAL_IRIDESCENCE,
	     .opacity = 0.5f,
	     .alpha = 1.0f,
	     .base_transform = {1, 0, 0, 1, 0, 0}}};
	struct material mat = {.features =
				   MATERIAL_DETAIL | MATERIAL_DETAIL_NORMAL | MATERIAL_IRIDESCENCE,
			       .surface_count = 2,
			       .surfaces = surfaces};
	uint32_t half = mesh->index_count / 6 * 3;
	struct renderer *r = renderer_new(&d->gl, NULL);
	struct renderer_stats st;
	struct view v = {.orientation = quat_identity()};
	int bad = 1;

	printf("two materials, a detail map and a film\n");
	fill(&surfaces[0].detail, 4, 4);
	if (!r || mesh_alloc_ranges(mesh, 2, 2))
		goto out;
	mesh->ranges[0] = (struct mesh_range){0, half, 0, {0, 0, 0}};
	mesh->ranges[1] = (struct mesh_range){half, mesh->index_count - half, 1, {0, 0, 0}};
	if (renderer_set_material(r, &mat) || renderer_set_mesh(r, mesh) ||
	    renderer_set_matcap(r, matcap) || renderer_set_mode(r, SHADING_VIEW, false)) {
		fprintf(stderr, "two materials: the renderer failed\n");
		goto out;
	}
	renderer_get_stats(r, &st);
	bad = st.draws != 2 || st.program_count != 2;
	if (bad)
		fprintf(stderr, "two materials: %u draws with %u programs, expected 2 and 2\n",
			st.draws, st.program_count);
	for (uint32_t k = 0; !bad && k < 2; k++)
		bad |= check_program(&d->gl, st.drawn[k].program,
				     surfaces[st.drawn[k].surface].features, false,
				     st.drawn[k].surface ? "the film's part" : "the detailed part");
	d->begin_frame(d);
	renderer_draw(r, &v, d->width, d->height);
	d->present(d);
	if (d->gl.GetError() != GL_NO_ERROR) {
		fprintf(stderr, "two materials: GL error while drawing\n");
		bad = 1;
	}
out:
	renderer_free(r);
	image_release(&surfaces[0].detail);
	return bad;
}

/* Only what the display shows reaches the GPU: a mesh simplified for
 * this display (src/scene/mesh/lod.c) uploads its own vertices, no more. */
static int check_lod(struct display *d, const struct image *matcap)
{
	struct material mat = {0};
	struct renderer *r = renderer_new(&d->gl, NULL);
	struct renderer_stats st;
	struct lod_result lod;
	struct mesh m;
	int bad = 1;

	printf("level of detail\n");
	if (!r || mesh_uv_sphere(&m, 64, 32))
		goto out;
	if (lod_prepare_mesh(&m, 2.0, d->width, d->height, &lod) ||
	    renderer_set_material(r, &mat) || renderer_set_mesh(r, &m) ||
	    renderer_set_matcap(r, matcap) || renderer_set_mode(r, SHADING_VIEW, false)) {
		fprintf(stderr, "level of detail: the renderer failed\n");
		goto release;
	}
	renderer_get_stats(r, &st);
	printf("  %u of %u vertices, %ld bytes uploaded\n", lod.vertices_after, lod.vertices_before,
	       st.vertex_bytes);
	bad = !(lod.vertices_after < lod.vertices_before && st.attributes == 2 &&
		st.vertex_bytes == (long)lod.vertices_after * 12);
	if (bad)
		fprintf(stderr, "level of detail: %d arrays of %ld bytes for %u vertices\n",
			st.attributes, st.vertex_bytes, lod.vertices_after);
release:
	mesh_release(&m);
out:
	renderer_free(r);
	return bad;
}

int main(void)
{
	struct display_config cfg = {.width = 64, .height = 64};
	struct display *d;
	struct mesh mesh;
	struct image matcap;
	int bad = 0;

	log_set_level(LOG_WARN);
#ifdef MK_HAVE_OSMESA
	d = display_osmesa_new(&cfg);
#else /* Mesa without OSMesa: the same renders through EGL */
	d = display_egl_new(&cfg);
#endif
	if (!d || mesh_uv_sphere(&mesh, 16, 8) || tangent_generate(&mesh) ||
	    mesh_alloc_colors(&mesh))
		return 1;
	for (size_t i = 0; i < (size_t)mesh.vertex_count * 4; i++)
		mesh.colors[i] = 0.5f;
	fill(&matcap, 8, 8);
	d->begin_frame(d);
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++)
		bad |= check_case(d, &cases[i], &mesh, &matcap);
	bad |= check_parts(d, &mesh, &matcap);
	bad |= check_lod(d, &matcap);
	image_release(&matcap);
	mesh_release(&mesh);
	display_free(d);
	printf("%s\n", bad ? "FAILED" : "every program holds only what its features need");
	return bad;
}
