#include "shading.h"

#include <errno.h>
#include <math.h>
#include <string.h>

static const char *const mode_names[SHADING_MODE_COUNT] = {"normal", "view", "sem-vertex",
							   "sem-fragment"};
static const char *const mode_defines[SHADING_MODE_COUNT] = {
    "#define MODE_NORMAL 1\n", "#define MODE_VIEW 1\n", "#define MODE_SEM_VERTEX 1\n",
    "#define MODE_SEM_FRAGMENT 1\n"};

const char *shading_mode_name(enum shading_mode mode)
{
	return mode < SHADING_MODE_COUNT ? mode_names[mode] : "?";
}

const char *shading_mode_define(enum shading_mode mode)
{
	return mode < SHADING_MODE_COUNT ? mode_defines[mode] : "";
}

int shading_mode_parse(const char *name, enum shading_mode *out)
{
	for (int i = 0; i < SHADING_MODE_COUNT; i++)
		if (strcmp(name, mode_names[i]) == 0) {
			*out = (enum shading_mode)i;
			return 0;
		}
	return -EINVAL;
}

void shading_uv_normal(const double n[3], double uv[2])
{
	uv[0] = n[0] * 0.5 + 0.5;
	uv[1] = -n[1] * 0.5 + 0.5;
}

void shading_uv_view(const double n[3], const double e[3], double uv[2])
{
	double v[3] = {-e[0], -e[1], -e[2]};
	double h2 = v[2] * v[2] + v[0] * v[0];
	double x[3] = {1.0, 0.0, 0.0}, y[3];

	if (h2 > 1.0e-4) {
		double s = 1.0 / sqrt(h2);

		x[0] = v[2] * s;
		x[1] = 0.0;
		x[2] = -v[0] * s;
	}
	y[0] = v[1] * x[2] - v[2] * x[1];
	y[1] = v[2] * x[0] - v[0] * x[2];
	y[2] = v[0] * x[1] - v[1] * x[0];
	uv[0] = (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]) * 0.495 + 0.5;
	uv[1] = -(y[0] * n[0] + y[1] * n[1] + y[2] * n[2]) * 0.495 + 0.5;
}

void shading_uv_sem(const double n[3], const double e[3], double uv[2])
{
	double d = n[0] * e[0] + n[1] * e[1] + n[2] * e[2];
	double h[3] = {e[0] - 2.0 * d * n[0], e[1] - 2.0 * d * n[1], e[2] - 2.0 * d * n[2] + 1.0};
	double l2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];

	if (l2 > 1.0e-6) {
		double s = 1.0 / sqrt(l2);

		for (int k = 0; k < 3; k++)
			h[k] *= s;
	} else {
		for (int k = 0; k < 3; k++)
			h[k] = n[k];
	}
	uv[0] = h[0] * 0.5 + 0.5;
	uv[1] = -h[1] * 0.5 + 0.5;
}
