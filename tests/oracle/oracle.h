/* The C mirror of the shader math: the reference that the accuracy and
 * stability tests and the bench compare against. The program links none
 * of it.
 *
 * The mirror (shading_mirror.h) follows shaders/mapping.glsl,
 * material.glsl, matcap.vert and matcap.frag line for line. It is built
 * twice: in double (these names), exact enough to be the reference, and
 * in float (the same names with _f), where every operation rounds as a
 * GPU's does: to binary32, or to binary16 for the values the shaders
 * leave at mediump on a GPU that runs mediump in 16 bits (enum
 * shading_fp). */
#ifndef MK_ORACLE_H
#define MK_ORACLE_H

#include "render/shading.h"

#include <stdbool.h>

/* How a GPU rounds the fragment shader's floats. The vertex stage is
 * binary32 on every GLES2 GPU (the vertex language requires highp). */
enum shading_fp {
	SHADING_FP32,	    /* every float binary32: llvmpipe, VideoCore IV and VI */
	SHADING_FP16_HIGHP, /* mediump binary16, highp binary32: Mali T/G, Adreno */
	SHADING_FP16,	    /* no GL_FRAGMENT_PRECISION_HIGH: all binary16 (Mali-400) */
	SHADING_FP_COUNT
};
const char *shading_fp_name(enum shading_fp fp);

/* A texture read as the renderer sets it up (bilinear; clamped for the
 * matcap and the ramp, repeated for the detail map), v = 0 the top row. */
typedef void (*shading_sampler)(const void *texture, double u, double v, double rgba[4]);

/* One fragment: the program's #defines, the varyings as the rasteriser
 * interpolated them, the uniforms and the textures. */
struct shading_fragment {
	enum shading_mode mode; /* as compiled: sem-vertex only without the features below */
	bool iridescence, ramp, detail_map, detail_normal, lit;
	double normal[3], eye[3];		   /* v_normal, v_eye */
	double matcap_uv[2];			   /* v_matcap_uv (sem-vertex) */
	double uv[2], tangent[4];		   /* v_uv, v_tangent */
	double iridescence_uniform[4], hsv[2];	   /* u_iridescence, u_hsv */
	double light[3], base_color[3], shininess; /* u_light, u_base_color, u_shininess */
	shading_sampler sample;
	const void *matcap_texture, *detail_texture, *ramp_texture;
};

/* The mirror in double. n is a unit view-space normal, e the unit
 * direction from the eye to the point (as safe_normalize gives them). */
void shading_safe_normalize(const double v[3], double out[3]);
void shading_uv_normal(const double n[3], double uv[2]);
void shading_uv_view(const double n[3], const double e[3], double uv[2]);
void shading_uv_sem(const double n[3], const double e[3], double uv[2]);
/* Iridescence: hue = (1 - (n.e)^2) range + average - shift (1 - map_a), in
 * turns of the colour circle; the same for n.e and -n.e. */
double shading_iridescence_hue(double n_dot_e, double range, double average, double shift,
			       double map_a);
void shading_hsv_to_rgb(double h, double s, double v, double rgb[3]);
/* The packed detail map's normal (rg = its red and green, in [0, 1]) in
 * the frame of the unit normal n and tangent (xyz, w the handedness). */
void shading_detail_normal(const double n[3], const double tangent[4], const double rg[2],
			   double out[3]);
/* The lit mode: l the unit direction to the light, e from the eye. */
void shading_blinn_phong(const double n[3], const double e[3], const double l[3],
			 const double base[3], double shininess, double rgb[3]);
/* matcap.vert: a vertex (model space) to the varyings; the matrices are
 * column-major, as GL takes them. */
void shading_vertex(const double modelview[16], const double normal_matrix[9], bool ortho,
		    const double position[3], const double normal[3], double eye[3],
		    double view_normal[3], double matcap_uv[2]);
/* matcap.frag: gl_FragColor's rgb. */
void shading_fragment(const struct shading_fragment *in, double rgb[3]);

/* The same in float, rounded as fp says. The arguments are read as the
 * shader reads them: a fragment function's inputs are rounded to its
 * precision first. */
void shading_safe_normalize_f(enum shading_fp fp, const double v[3], double out[3]);
void shading_uv_normal_f(enum shading_fp fp, const double n[3], double uv[2]);
void shading_uv_view_f(enum shading_fp fp, const double n[3], const double e[3], double uv[2]);
void shading_uv_sem_f(enum shading_fp fp, const double n[3], const double e[3], double uv[2]);
double shading_iridescence_hue_f(enum shading_fp fp, double n_dot_e, double range, double average,
				 double shift, double map_a);
void shading_hsv_to_rgb_f(enum shading_fp fp, double h, double s, double v, double rgb[3]);
void shading_detail_normal_f(enum shading_fp fp, const double n[3], const double tangent[4],
			     const double rg[2], double out[3]);
void shading_blinn_phong_f(enum shading_fp fp, const double n[3], const double e[3],
			   const double l[3], const double base[3], double shininess,
			   double rgb[3]);
void shading_vertex_f(enum shading_fp fp, const double modelview[16], const double normal_matrix[9],
		      bool ortho, const double position[3], const double normal[3], double eye[3],
		      double view_normal[3], double matcap_uv[2]);
void shading_fragment_f(enum shading_fp fp, const struct shading_fragment *in, double rgb[3]);

#endif
