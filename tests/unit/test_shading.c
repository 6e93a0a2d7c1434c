#include "oracle/oracle.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
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

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(mode_names_round_trip),
	    cmocka_unit_test(normal_mode_maps_the_disk),
	    cmocka_unit_test(sem_is_safe_at_the_singularity),
	    cmocka_unit_test(sem_facing_viewer_is_centre),
	    cmocka_unit_test(view_mode_stays_inside_the_disk),
	};
	return cmocka_run_group_tests_name("shading", tests, NULL, NULL);
}
