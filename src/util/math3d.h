/* Small column-major matrix and quaternion helpers, as GL expects them. */
#ifndef MK_MATH3D_H
#define MK_MATH3D_H

#include <stdbool.h>

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

/* Small double-precision vector helpers, for the mesh code. */
double vec3_dot(const double a[3], const double b[3]);
void vec3_cross(const double a[3], const double b[3], double out[3]);
/* false (and v unchanged) when v is too short or not finite. */
bool vec3_normalize(double v[3]);

struct quat quat_identity(void);
struct quat quat_from_axis_angle(double x, double y, double z, double radians);
struct quat quat_multiply(struct quat a, struct quat b);
struct quat quat_normalize(struct quat q);

#endif
