#include "util/math3d.h"

#include <math.h>
#include <string.h>

void mat4_identity(float m[16])
{
	memset(m, 0, 16 * sizeof(float));
	m[0] = m[5] = m[10] = m[15] = 1.0f;
}

void mat4_multiply(float out[16], const float a[16], const float b[16])
{
	float r[16];

	for (int c = 0; c < 4; c++)
		for (int row = 0; row < 4; row++) {
			double s = 0.0;

			for (int k = 0; k < 4; k++)
				s += (double)a[k * 4 + row] * (double)b[c * 4 + k];
			r[c * 4 + row] = (float)s;
		}
	memcpy(out, r, sizeof(r));
}

void mat4_perspective(float m[16], double fovy_rad, double aspect, double znear, double zfar)
{
	double f = 1.0 / tan(fovy_rad / 2.0);

	memset(m, 0, 16 * sizeof(float));
	m[0] = (float)(f / aspect);
	m[5] = (float)f;
	m[10] = (float)((zfar + znear) / (znear - zfar));
	m[11] = -1.0f;
	m[14] = (float)(2.0 * zfar * znear / (znear - zfar));
}

void mat4_ortho(float m[16], double l, double r, double b, double t, double n, double f)
{
	mat4_identity(m);
	m[0] = (float)(2.0 / (r - l));
	m[5] = (float)(2.0 / (t - b));
	m[10] = (float)(-2.0 / (f - n));
	m[12] = (float)(-(r + l) / (r - l));
	m[13] = (float)(-(t + b) / (t - b));
	m[14] = (float)(-(f + n) / (f - n));
}

#define FOV_Y_DEGREES 30.0
#define FIT_MARGIN    1.08

void sphere_fit_init(struct sphere_fit *f, double aspect)
{
	f->aspect = aspect;
	f->half_fov = FOV_Y_DEGREES / 2.0 * M_PI / 180.0;
	f->half_min = fmin(f->half_fov, atan(tan(f->half_fov) * aspect));
	f->distance = FIT_MARGIN / sin(f->half_min);
}

void sphere_fit_projection(const struct sphere_fit *f, bool ortho, float m[16])
{
	double a = f->aspect, dist = f->distance;

	if (ortho) {
		double sx = a > 1 ? a : 1, sy = a > 1 ? 1 : 1 / a;

		mat4_ortho(m, -sx, sx, -sy, sy, dist - 1.5, dist + 1.5);
	} else {
		mat4_perspective(m, 2.0 * f->half_fov, a, dist - 1.5, dist + 1.5);
	}
}

double sphere_fit_pixels_per_unit(int width, int height)
{
	double short_side = width < height ? width : height;
	struct sphere_fit f;

	sphere_fit_init(&f, (double)width / height);
	/* The short side spans 2 z tan(half_min) model units at depth z; the
	 * nearest point of the unit sphere is at distance - 1. */
	return short_side / 2.0 / ((f.distance - 1.0) * tan(f.half_min));
}

void mat4_translate(float m[16], double x, double y, double z)
{
	mat4_identity(m);
	m[12] = (float)x;
	m[13] = (float)y;
	m[14] = (float)z;
}

void mat4_from_quat(float m[16], struct quat q)
{
	double w = q.w, x = q.x, y = q.y, z = q.z;

	mat4_identity(m);
	m[0] = (float)(1 - 2 * (y * y + z * z));
	m[1] = (float)(2 * (x * y + w * z));
	m[2] = (float)(2 * (x * z - w * y));
	m[4] = (float)(2 * (x * y - w * z));
	m[5] = (float)(1 - 2 * (x * x + z * z));
	m[6] = (float)(2 * (y * z + w * x));
	m[8] = (float)(2 * (x * z + w * y));
	m[9] = (float)(2 * (y * z - w * x));
	m[10] = (float)(1 - 2 * (x * x + y * y));
}

void mat4_rotate_z(float m[16], int degrees)
{
	/* Exact for the quarter turns a portrait panel needs. */
	static const float c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
	int k = ((degrees / 90) % 4 + 4) % 4;

	mat4_identity(m);
	m[0] = c[k];
	m[1] = s[k];
	m[4] = -s[k];
	m[5] = c[k];
}

void mat3_from_mat4(float out[9], const float m[16])
{
	for (int c = 0; c < 3; c++)
		for (int r = 0; r < 3; r++)
			out[c * 3 + r] = m[c * 4 + r];
}

double vec3_dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void vec3_cross(const double a[3], const double b[3], double out[3])
{
	out[0] = a[1] * b[2] - a[2] * b[1];
	out[1] = a[2] * b[0] - a[0] * b[2];
	out[2] = a[0] * b[1] - a[1] * b[0];
}

bool vec3_normalize(double v[3])
{
	double l = sqrt(vec3_dot(v, v));

	if (!(l > 1e-12) || !isfinite(l))
		return false;
	for (int k = 0; k < 3; k++)
		v[k] /= l;
	return true;
}

struct quat quat_identity(void)
{
	return (struct quat){1, 0, 0, 0};
}

struct quat quat_from_axis_angle(double x, double y, double z, double radians)
{
	double len = sqrt(x * x + y * y + z * z);
	double s = sin(radians / 2.0);

	if (len == 0.0)
		return quat_identity();
	return (struct quat){cos(radians / 2.0), x / len * s, y / len * s, z / len * s};
}

struct quat quat_multiply(struct quat a, struct quat b)
{
	return (struct quat){
	    a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
	    a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
	    a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
	    a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
	};
}

struct quat quat_normalize(struct quat q)
{
	double len = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);

	if (!(len > 0.0) || !isfinite(len))
		return quat_identity();
	return (struct quat){q.w / len, q.x / len, q.y / len, q.z / len};
}

double mat4_normal_matrix(const double m[16], double n[9])
{
	double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6],
	       i = m[10];
	double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
	/* Cofactors C(row, col), stored column by column. */
	double cof[9] = {e * i - f * h,	   -(b * i - c * h), b * f - c * e,
			 -(d * i - f * g), a * i - c * g,    -(a * f - c * d),
			 d * h - e * g,	   -(a * h - b * g), a * e - b * d};

	for (int k = 0; k < 9; k++)
		n[k] = det < 0 ? -cof[k] : cof[k];
	return det;
}
