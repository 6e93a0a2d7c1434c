/* Small column-major matrix and quaternion helpers, as GL expects them. */
#ifndef MK_MATH3D_H
#define MK_MATH3D_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

struct quat {
	double w, x, y, z;
};

void mat4_identity(float m[16]);
void mat4_multiply(float out[16], const float a[16], const float b[16]);
void mat4_perspective(float m[16], double fovy_rad, double aspect, double znear, double zfar);
void mat4_ortho(float m[16], double l, double r, double b, double t, double n, double f);
void mat4_translate(float m[16], double x, double y, double z);
void mat4_from_quat(float m[16], struct quat q);
void mat4_rotate_z(float m[16], int degrees);
/* The upper 3x3 of an orthonormal transform is its own normal matrix. */
void mat3_from_mat4(float out[9], const float m[16]);

/* How the kiosk's camera frames the unit sphere in a frame of this
 * aspect (width over height): a 30 degree vertical field of view,
 * narrowed to the horizontal one on a portrait frame, from the distance
 * at which the sphere, with a margin, just fills the short side. The
 * renderer's projection and the mesh code's pixel density both come
 * from here, so the two cannot disagree. */
struct sphere_fit {
	double aspect;
	double half_fov; /* vertical, radians */
	double half_min; /* across the short side, radians */
	double distance; /* from the eye to the sphere's centre */
};

void sphere_fit_init(struct sphere_fit *f, double aspect);
/* The outline centre's x in NDC shrinks as the frame widens (x / (tan *
 * aspect) in perspective; ortho, past a square). Kept times this unit it
 * is the same on a frame of any aspect, so a display plugged in after the
 * start (framed for 1920x1080 until then) still centres the model. */
static inline double sphere_fit_x_unit(bool ortho, double aspect)
{
	return ortho ? (aspect > 1 ? aspect : 1) : aspect;
}

/* Perspective, or orthographic where the unit sphere fills the short
 * side; depth from just before the sphere to just behind it. */
void sphere_fit_projection(const struct sphere_fit *f, bool ortho, float m[16]);
/* Pixels per model unit at the front of the unit sphere in a width x
 * height frame: the most any part of a fitted model is magnified (by the
 * perspective camera; the orthographic one magnifies less). A mesh's
 * density is judged by it. */
double sphere_fit_pixels_per_unit(int width, int height);

/* Small double-precision vector helpers, for the mesh code. */
double vec3_dot(const double a[3], const double b[3]);
void vec3_cross(const double a[3], const double b[3], double out[3]);
/* false (and v unchanged) when v is too short or not finite. */
bool vec3_normalize(double v[3]);

struct quat quat_identity(void);
struct quat quat_from_axis_angle(double x, double y, double z, double radians);
struct quat quat_multiply(struct quat a, struct quat b);
struct quat quat_normalize(struct quat q);

/* The normal matrix of m's 3x3 (column-major, 9 of n) up to a scale:
 * its cofactor matrix, negated where m mirrors (directions are
 * normalised later, so only the determinant's sign counts). Returns the
 * determinant: negative, the winding flips too. The loader's bake and
 * live playback's CPU pose share it, so that they agree to the bit. */
double mat4_normal_matrix(const double m[16], double n[9]);

#ifdef __cplusplus
}
#endif

#endif
