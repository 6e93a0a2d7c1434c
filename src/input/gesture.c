#include "input/gesture.h"

#include <math.h>
#include <string.h>

#define MS 1000000ull

void gesture_config_defaults(struct gesture_config *cfg)
{
	*cfg = (struct gesture_config){
	    .tap_ns = 250 * MS, .double_tap_ns = 350 * MS, .long_ns = 700 * MS, .slop = 0.02};
}

void gesture_init(struct gesture_state *g, const struct gesture_config *cfg)
{
	memset(g, 0, sizeof(*g));
	g->cfg = *cfg;
	g->last_tap_ns = CLOCK_NEVER;
}

static const struct gesture_point *find(const struct gesture_point *pts, int n, int id)
{
	for (int i = 0; i < n; i++)
		if (pts[i].id == id)
			return &pts[i];
	return NULL;
}

static double distance(const struct gesture_point *a, const struct gesture_point *b)
{
	return hypot(a->x - b->x, a->y - b->y);
}

/* Lifting the last finger: a tap, a double tap, the end of a drag, or
 * nothing (after a long press). */
static int touch_end(struct gesture_state *g, uint64_t t, struct gesture *out)
{
	bool tap = !g->moved && !g->multi && !g->long_fired && t - g->start_ns <= g->cfg.tap_ns;

	if (g->moved || g->multi) {
		g->last_tap_ns = CLOCK_NEVER;
		*out = (struct gesture){.kind = GESTURE_END, .time_ns = t};
		return 1;
	}
	if (!tap)
		return 0;
	if (g->last_tap_ns != CLOCK_NEVER && g->start_ns - g->last_tap_ns <= g->cfg.double_tap_ns) {
		g->last_tap_ns = CLOCK_NEVER;
		*out = (struct gesture){.kind = GESTURE_DOUBLE_TAP, .time_ns = t};
		return 1;
	}
	g->last_tap_ns = t;
	*out =
	    (struct gesture){.kind = GESTURE_TAP, .time_ns = t, .x = g->start_x, .y = g->start_y};
	return 1;
}

static void touch_start(struct gesture_state *g, uint64_t t, const struct gesture_point *p)
{
	g->start_ns = t;
	g->start_x = p->x;
	g->start_y = p->y;
	g->moved = g->multi = g->long_fired = false;
}

/* One finger: a drag once it left the slop, from then on every movement. */
static int one_finger(struct gesture_state *g, uint64_t t, const struct gesture_point *p,
		      struct gesture *out)
{
	const struct gesture_point *before = find(g->prev, g->prev_n, p->id);

	if (!g->moved && hypot(p->x - g->start_x, p->y - g->start_y) > g->cfg.slop)
		g->moved = true;
	/* After a pinch the staying finger drags on, without a jump. */
	if (!g->moved || !before || (p->x == before->x && p->y == before->y))
		return 0;
	*out = (struct gesture){
	    .kind = GESTURE_DRAG, .time_ns = t, .dx = p->x - before->x, .dy = p->y - before->y};
	return 1;
}

/* Two fingers (the first two down): the change of their distance. */
static int two_fingers(struct gesture_state *g, uint64_t t, const struct gesture_point *pts,
		       struct gesture *out)
{
	const struct gesture_point *a = find(g->prev, g->prev_n, pts[0].id);
	const struct gesture_point *b = find(g->prev, g->prev_n, pts[1].id);
	double now = distance(&pts[0], &pts[1]), before;

	g->multi = true;
	if (!a || !b)
		return 0;
	before = distance(a, b);
	/* Fingers on one spot have no distance to scale. */
	if (before < 1e-6 || now < 1e-6 || now == before)
		return 0;
	*out = (struct gesture){.kind = GESTURE_PINCH, .time_ns = t, .scale = now / before};
	return 1;
}

int gesture_frame(struct gesture_state *g, uint64_t time_ns, const struct gesture_point *pts, int n,
		  struct gesture *out)
{
	int count = 0;

	if (n > GESTURE_MAX_POINTS)
		n = GESTURE_MAX_POINTS;
	if (n < 0)
		n = 0;
	if (g->prev_n == 0 && n > 0)
		touch_start(g, time_ns, &pts[0]);
	if (n == 1)
		count = one_finger(g, time_ns, &pts[0], out);
	else if (n >= 2)
		count = two_fingers(g, time_ns, pts, out);
	else if (g->prev_n > 0)
		count = touch_end(g, time_ns, out);
	memcpy(g->prev, pts, (size_t)n * sizeof(*pts));
	g->prev_n = n;
	return count;
}

uint64_t gesture_deadline(const struct gesture_state *g)
{
	if (g->prev_n != 1 || g->moved || g->multi || g->long_fired)
		return CLOCK_NEVER;
	return g->start_ns + g->cfg.long_ns;
}

int gesture_timeout(struct gesture_state *g, uint64_t now_ns, struct gesture *out)
{
	uint64_t due = gesture_deadline(g);

	if (due == CLOCK_NEVER || now_ns < due)
		return 0;
	g->long_fired = true;
	g->last_tap_ns = CLOCK_NEVER;
	*out = (struct gesture){.kind = GESTURE_LONG_PRESS, .time_ns = now_ns};
	return 1;
}

static double fraction(int raw, const int range[2])
{
	double f;

	if (range[1] <= range[0])
		return 0.5;
	f = (double)(raw - range[0]) / (double)(range[1] - range[0]);
	return f < 0 ? 0 : f > 1 ? 1 : f;
}

void gesture_map(int raw_x, int raw_y, const int range_x[2], const int range_y[2], int rotation,
		 double *x, double *y)
{
	/* The renderer turns the picture counter-clockwise by rotation on
	 * the panel: turn the touch back, about the centre, with y up. */
	static const int c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
	int k = ((rotation / 90) % 4 + 4) % 4;
	double px = 2 * fraction(raw_x, range_x) - 1, py = 1 - 2 * fraction(raw_y, range_y);
	double u = c[k] * px + s[k] * py, v = -s[k] * px + c[k] * py;

	*x = (u + 1) / 2;
	*y = (1 - v) / 2;
}
