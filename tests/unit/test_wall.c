/* [wall] (render/wall.h): each screen's slice of one frustum. The
 * arithmetic alone (a 1x1 wall is the whole picture, the slices and the
 * bezels' gaps tile the wall exactly, a position outside refused), and
 * the renderer's camera: a point of the model lands where the whole wall's
 * camera puts it, seen through the slice (render_matrices). */
#include "render/render.h"
#include "render/wall.h"
#include "util/math3d.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define EPS 1e-12

static struct wall_layout layout(int columns, int rows, int column, int row)
{
	return (struct wall_layout){.columns = columns, .rows = rows, .column = column, .row = row};
}

static void one_by_one_is_whole(void **state)
{
	struct wall_layout none = {0}, one = layout(1, 1, 1, 1);
	struct wall_slice s;
	char why[200];

	(void)state;
	assert_int_equal(wall_slice(&one, 800, 480, &s, why, sizeof(why)), 0);
	assert_true(s.whole);
	assert_true(fabs(s.aspect - 800.0 / 480) < EPS);
	assert_true(s.rect[0] == -1 && s.rect[1] == -1 && s.rect[2] == 1 && s.rect[3] == 1);
	assert_int_equal(wall_slice(&none, 800, 480, &s, why, sizeof(why)), 0);
	assert_true(s.whole);
	assert_false(wall_active(&none));
	assert_false(wall_active(&one));
}

static void two_by_one_halves(void **state)
{
	struct wall_layout left = layout(2, 1, 1, 1), right = layout(2, 1, 2, 1);
	struct wall_slice a, b;
	char why[200];

	(void)state;
	assert_int_equal(wall_slice(&left, 640, 480, &a, why, sizeof(why)), 0);
	assert_int_equal(wall_slice(&right, 640, 480, &b, why, sizeof(why)), 0);
	assert_false(a.whole);
	assert_true(fabs(a.aspect - 1280.0 / 480) < EPS);
	assert_true(fabs(a.rect[0] + 1) < EPS && fabs(a.rect[2]) < EPS);
	assert_true(fabs(b.rect[0]) < EPS && fabs(b.rect[2] - 1) < EPS);
	for (int i = 0; i < 2; i++) /* one row: the full height */
		assert_true(fabs(a.rect[2 * i + 1] - (i ? 1 : -1)) < EPS);
}

/* A bezel of 20 mm on screens of 400 mm across 800 px: a gap of 40 px
 * between the pictures, which no screen shows. */
static void bezel_gap_excluded(void **state)
{
	struct wall_layout w = layout(2, 2, 1, 1);
	struct wall_slice s[2][2];
	char why[200];

	(void)state;
	w.bezel = 20;
	w.screen_w = 400;
	w.screen_h = 240;
	for (int c = 0; c < 2; c++)
		for (int r = 0; r < 2; r++) {
			w.column = c + 1;
			w.row = r + 1;
			assert_int_equal(wall_slice(&w, 800, 480, &s[c][r], why, sizeof(why)), 0);
		}
	assert_true(fabs(s[0][0].width - (2 * 800 + 40)) < EPS);
	assert_true(fabs(s[0][0].height - (2 * 480 + 40)) < EPS);
	/* Across: the left slice ends 40 px (2 * 40 / 1640 of NDC) before the right begins. */
	assert_true(fabs(s[1][0].rect[0] - s[0][0].rect[2] - 2.0 * 40 / 1640) < EPS);
	/* Down: row 1 is the top one, above row 2 by the gap. */
	assert_true(s[0][0].rect[1] > s[0][1].rect[3]);
	assert_true(fabs(s[0][0].rect[1] - s[0][1].rect[3] - 2.0 * 40 / 1000) < EPS);
	/* Without the screen's size millimetres mean nothing: no gap. */
	w.screen_w = w.screen_h = 0;
	w.column = 2;
	assert_int_equal(wall_slice(&w, 800, 480, &s[1][1], why, sizeof(why)), 0);
	assert_true(fabs(s[1][1].rect[0]) < EPS);
}

/* Every slice of a 5x3 wall with a bezel: the widths plus the gaps are the
 * wall's 2 of NDC, each screen's share the same, no overlap. */
static void slices_tile_the_wall(void **state)
{
	struct wall_layout w = layout(5, 3, 1, 1);
	struct wall_slice s;
	char why[200];

	(void)state;
	w.bezel = 7.5;
	w.screen_w = 527;
	w.screen_h = 296;
	for (int r = 1; r <= 3; r++) {
		double sum = 0, gaps = 0, last = -1;

		for (int c = 1; c <= 5; c++) {
			w.column = c;
			w.row = r;
			assert_int_equal(wall_slice(&w, 1920, 1080, &s, why, sizeof(why)), 0);
			sum += s.rect[2] - s.rect[0];
			gaps += s.rect[0] - last;
			assert_true(s.rect[0] >= last - EPS);
			last = s.rect[2];
			/* The slice keeps the screen's own aspect in the wall. */
			assert_true(fabs((s.rect[2] - s.rect[0]) * s.width /
					     ((s.rect[3] - s.rect[1]) * s.height) -
					 1920.0 / 1080) < 1e-9);
		}
		gaps += 1 - last;
		assert_true(fabs(sum + gaps - 2) < EPS);
		assert_true(fabs(gaps - 4 * 2 * (7.5 * 1920 / 527) / s.width) < 1e-9);
	}
}

static void position_outside_refused(void **state)
{
	const struct wall_layout bad[] = {layout(2, 1, 3, 1), layout(2, 2, 1, 3),
					  layout(2, 1, 0, 1), layout(17, 1, 1, 1),
					  layout(1, 1, 2, 1), layout(-1, 1, 1, 1)};
	struct wall_slice s;
	char why[200];

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		assert_int_equal(wall_slice(&bad[i], 640, 480, &s, why, sizeof(why)), -EINVAL);
		assert_true(s.whole); /* the whole picture instead */
		assert_true(strstr(why, "expected") != NULL);
	}
	assert_non_null(strstr((wall_slice(&bad[0], 640, 480, &s, why, sizeof(why)), why),
			       "outside the wall of 2 columns and 1 rows"));
	/* A bezel the settings would refuse, were they bypassed: no NaN
	 * reaches the projection. */
	for (int i = 0; i < 3; i++) {
		struct wall_layout w = layout(2, 1, 1, 1);

		w.bezel = i == 0 ? NAN : i == 1 ? INFINITY : -1;
		w.screen_w = w.screen_h = 100;
		assert_int_equal(wall_slice(&w, 640, 480, &s, why, sizeof(why)), -EINVAL);
		assert_true(s.whole && s.aspect == 640.0 / 480);
	}
}

/* A point through render_matrices: in the whole wall's picture (2W x H,
 * no wall) and in the right slice (W x H): the same spot of the wall. */
static void clip_of(const struct view *v, int w, int h, const double p[3], double out[2])
{
	float mv[16], proj[16], m[16];
	double c[4];

	render_matrices(v, w, h, mv, proj);
	mat4_multiply(m, proj, mv);
	for (int i = 0; i < 4; i++)
		c[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i];
	out[0] = c[0] / c[3];
	out[1] = c[1] / c[3];
}

static void camera_sees_the_slice(void **state)
{
	struct view whole = {.orientation = quat_from_axis_angle(0, 1, 0, 0.4), .zoom = 0.8};
	struct view right = whole;
	const double p[3] = {0.3, -0.2, 0.5};
	double a[2], b[2];

	(void)state;
	whole.outline[0] = 0.1f;
	right.outline[0] = 0.1f;
	right.wall = layout(2, 1, 2, 1);
	for (int ortho = 0; ortho < 2; ortho++) {
		whole.ortho = right.ortho = ortho;
		clip_of(&whole, 1280, 480, p, a);
		clip_of(&right, 640, 480, p, b);
		/* The right half of the wall: x in [0, 1] there is [-1, 1] here. */
		assert_true(fabs(b[0] - (2 * a[0] - 1)) < 1e-5);
		assert_true(fabs(b[1] - a[1]) < 1e-5);
	}
	/* A portrait panel turned a quarter: the slice is the turned frame's. */
	whole.rotation = right.rotation = 90;
	whole.ortho = right.ortho = false;
	clip_of(&whole, 480, 1280, p, a);
	clip_of(&right, 480, 640, p, b);
	/* The panel maps the viewer's (x, y) to the buffer's (-y, x): the
	 * right half of the wall is the buffer's top half. */
	assert_true(fabs(b[0] - a[0]) < 1e-5);
	assert_true(fabs(b[1] - (2 * a[1] - 1)) < 1e-5);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(one_by_one_is_whole),	cmocka_unit_test(two_by_one_halves),
	    cmocka_unit_test(bezel_gap_excluded),	cmocka_unit_test(slices_tile_the_wall),
	    cmocka_unit_test(position_outside_refused), cmocka_unit_test(camera_sees_the_slice),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
