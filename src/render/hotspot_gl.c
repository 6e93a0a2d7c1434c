/* Hotspots on the GL path (render/hotspot_gl.h): the projection, the fade
 * and the label's place on the CPU, one quad a hotspot on the GPU. */
#include "render/hotspot_gl.h"
#include "render/shader.h"
#include "util/log.h"

#include <math.h>
#include <stdlib.h>

struct hotspot_gl {
	const struct gl *gl;
	GLuint program, digits;
	GLint centre, size, turn, color, fade, digit, pixels, image;
};

/* The digits 0-9 in 3x5 cells, a row a byte (bit 2: the left column). */
static const unsigned char glyphs[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 3, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 2, 2, 2}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
};

/* 40x5 RGBA: glyph d's cells at x = 4 d .. 4 d + 2; alpha is the ink. */
static GLuint digits_texture(const struct gl *gl)
{
	unsigned char px[5][40][4] = {{{0}}};

	for (int d = 0; d < 10; d++)
		for (int y = 0; y < 5; y++)
			for (int x = 0; x < 3; x++)
				px[y][4 * d + x][3] = glyphs[d][y] >> (2 - x) & 1 ? 255 : 0;
	return gl_texture_picture(gl, 40, 5, px);
}

struct hotspot_gl *hotspot_gl_new(const struct gl *gl)
{
	struct shader_source src = {.precision = "precision mediump float;\n",
				    .vertex = {"hotspot.vert"},
				    .fragment = {"hotspot.frag"},
				    .attributes = {[SHADER_ATTR_POSITION] = "a_position"}};
	struct hotspot_gl *g = calloc(1, sizeof(*g));

	if (!g || shader_program_build(gl, &src, &g->program)) {
		log_err("hotspots: cannot build their program; the model is shown without them");
		free(g);
		return NULL;
	}
	g->gl = gl;
	g->centre = gl->GetUniformLocation(g->program, "u_centre");
	g->size = gl->GetUniformLocation(g->program, "u_size");
	g->turn = gl->GetUniformLocation(g->program, "u_turn");
	g->color = gl->GetUniformLocation(g->program, "u_color");
	g->fade = gl->GetUniformLocation(g->program, "u_fade");
	g->digit = gl->GetUniformLocation(g->program, "u_digit");
	g->pixels = gl->GetUniformLocation(g->program, "u_pixels");
	g->image = gl->GetUniformLocation(g->program, "u_digits");
	g->digits = digits_texture(gl);
	/* Texel for cell: the digit's strokes stay crisp at any size. */
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	return g;
}

void hotspot_gl_free(struct hotspot_gl *g)
{
	if (!g)
		return;
	g->gl->DeleteTextures(1, &g->digits);
	g->gl->DeleteProgram(g->program);
	free(g);
}

static void transform(const float m[16], const double in[4], double out[4])
{
	for (int r = 0; r < 4; r++)
		out[r] = m[r] * in[0] + m[4 + r] * in[1] + m[8 + r] * in[2] + m[12 + r] * in[3];
}

/* Edge-on below cos = 0.1 (84 degrees), whole above 0.35 (70 degrees):
 * a badge at the rim reads as leaving rather than blinking out. */
double hotspot_fade(const double normal[3], const double to_eye[3])
{
	double c = normal[0] * to_eye[0] + normal[1] * to_eye[1] + normal[2] * to_eye[2];
	double t = (c - 0.1) / (0.35 - 0.1);

	if (t <= 0)
		return 0;
	return t >= 1 ? 1 : t * t * (3 - 2 * t);
}

static double place_fade(const struct render_hotspot *h, const float mv[16], const double eye[4],
			 bool ortho)
{
	double n[4] = {h->normal[0], h->normal[1], h->normal[2], 0}, nv[4], to_eye[3] = {0, 0, 1};
	double len = sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);

	if (!h->has_normal)
		return 1;
	transform(mv, n, nv);
	if (!ortho && len > 0)
		for (int k = 0; k < 3; k++)
			to_eye[k] = -eye[k] / len;
	return hotspot_fade(nv, to_eye);
}

void hotspot_project(const struct render_hotspot *h, const float modelview[16],
		     const float projection[16], bool ortho, int width, int height,
		     struct hotspot_place *out)
{
	double p[4] = {h->point[0], h->point[1], h->point[2], 1}, eye[4], clip[4], near[4];

	transform(modelview, p, eye);
	transform(projection, eye, clip);
	out->ahead = clip[3] > 1e-9;
	if (!out->ahead) {
		*out = (struct hotspot_place){0};
		return;
	}
	out->x = (clip[0] / clip[3] + 1) * 0.5 * width;
	out->y = (1 - clip[1] / clip[3]) * 0.5 * height;
	/* The eye looks down -z: towards it is +z. */
	eye[2] += HOTSPOT_DEPTH_BIAS;
	transform(projection, eye, near);
	out->depth = near[3] > 1e-9 ? (near[2] / near[3] + 1) * 0.5 : 0;
	eye[2] -= HOTSPOT_DEPTH_BIAS;
	out->fade = place_fade(h, modelview, eye, ortho);
}

double hotspot_radius(bool badge, int short_side)
{
	/* 8 and 12 pixels at 480; never so small that a badge's digit (3x5
	 * cells in two thirds of it) cannot be read. */
	double r = (badge ? 12.0 : 8.0) * short_side / 480.0, least = badge ? 9 : 5;

	return r < least ? least : r;
}

static int clamp_int(int v, int lo, int hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* Right of the badge, else left, else below, else above: the first
 * that fits the screen across (beside) or down (below, above), moved in
 * along the other axis; none fits: right, moved in both ways. */
void hotspot_label_place(double x, double y, double r, int w, int h, int width, int height,
			 int margin, int out[2])
{
	int gap = (int)ceil(r) + margin, cx = (int)lround(x), cy = (int)lround(y);
	const int xs[4] = {cx + gap, cx - gap - w, cx - w / 2, cx - w / 2};
	const int ys[4] = {cy - h / 2, cy - h / 2, cy + gap, cy - gap - h};
	int k = 0;

	while (k < 4 && !(k < 2 ? xs[k] >= margin && xs[k] + w + margin <= width
				: ys[k] >= margin && ys[k] + h + margin <= height))
		k++;
	k = k < 4 ? k : 0;
	/* A label larger than the screen keeps its start on it. */
	out[0] =
	    clamp_int(xs[k], margin, width - w - margin > margin ? width - w - margin : margin);
	out[1] =
	    clamp_int(ys[k], margin, height - h - margin > margin ? height - h - margin : margin);
}

static void draw_one(const struct hotspot_gl *g, const struct render_hotspot *h,
		     const struct hotspot_place *at, int width, int height, int short_side)
{
	const struct gl *gl = g->gl;
	double r = hotspot_radius(h->badge, short_side);
	static const float quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};

	gl->Uniform3f(g->centre, (float)(2 * at->x / width - 1), (float)(1 - 2 * at->y / height),
		      (float)(2 * at->depth - 1));
	gl->Uniform2f(g->size, (float)(2 * r / width), (float)(2 * r / height));
	gl->Uniform4f(g->color, h->color[0], h->color[1], h->color[2], h->color[3]);
	gl->Uniform1f(g->fade, (float)at->fade);
	gl->Uniform1f(g->digit, h->badge ? (float)(h->number % 10) : -1.0f);
	gl->Uniform1f(g->pixels, (float)r);
	gl_draw_quad(gl, SHADER_ATTR_POSITION, quad);
}

void hotspot_gl_draw(const struct hotspot_gl *g, const struct render_hotspot *hs, int count,
		     const float modelview[16], const float projection[16], bool ortho,
		     int rotation, int width, int height)
{
	/* The panel's quarter turn, as the caption turns its quad. */
	static const float c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
	const struct gl *gl = g->gl;
	int k = ((rotation / 90) % 4 + 4) % 4;

	gl->Enable(GL_DEPTH_TEST);
	gl->DepthMask(GL_FALSE);
	gl->Disable(GL_CULL_FACE);
	gl->Enable(GL_BLEND);
	gl->BlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
	gl->UseProgram(g->program);
	gl->Uniform4f(g->turn, c[k], sn[k], -sn[k], c[k]);
	gl->Uniform1i(g->image, 0);
	gl->ActiveTexture(GL_TEXTURE0);
	gl->BindTexture(GL_TEXTURE_2D, g->digits);
	for (int i = 0; i < count; i++) {
		struct hotspot_place at;

		hotspot_project(&hs[i], modelview, projection, ortho, width, height, &at);
		if (at.ahead && at.fade > 0)
			draw_one(g, &hs[i], &at, width, height, width < height ? width : height);
	}
	gl->UseProgram(0);
	gl->Disable(GL_BLEND);
	gl->DepthMask(GL_TRUE);
}
