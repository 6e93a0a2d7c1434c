#include "input/button.h"

static int emit(struct app_event *out, int n, uint64_t t, enum app_action a, bool pressed)
{
	if (a == ACTION_NONE)
		return n;
	out[n] = (struct app_event){.time_ns = t, .action = a, .pressed = pressed};
	return n + 1;
}

static bool repeats(const struct button_config *c)
{
	return c->repeat_ns && c->long_press == ACTION_NONE && c->press != ACTION_NONE &&
	       !app_action_is_turn(c->press);
}

void button_init(struct button *b, const struct button_config *cfg, bool down)
{
	*b = (struct button){.cfg = *cfg, .raw = down, .down = down, .hold_ns = CLOCK_NEVER};
	/* A button already down at start-up may be stuck or leaned on: it
	 * does nothing until it has been released. */
	b->spent = down;
}

/* When the line has been quiet for the window on a level other than the
 * reported one. */
static uint64_t settle_at(const struct button *b)
{
	if (!b->seen_edge || b->raw == b->down)
		return CLOCK_NEVER;
	return b->edge_ns + b->cfg.debounce_ns;
}

uint64_t button_deadline(const struct button *b)
{
	uint64_t s = settle_at(b), h = b->down ? b->hold_ns : CLOCK_NEVER;

	return s < h ? s : h;
}

static int transition(struct button *b, bool down, uint64_t t, struct app_event *out)
{
	const struct button_config *c = &b->cfg;
	bool spent = b->spent;
	int n = 0;

	b->down = down;
	b->hold_ns = CLOCK_NEVER;
	b->spent = false;
	if (down) {
		/* With a long action the press must wait to learn which it is;
		 * without one it acts at once. */
		if (c->long_press != ACTION_NONE || repeats(c))
			b->hold_ns = t + c->long_ns;
		if (c->long_press == ACTION_NONE)
			n = emit(out, n, t, c->press, true);
		return n;
	}
	if (spent)
		return 0;
	if (c->long_press != ACTION_NONE) /* short: a tap of the press action */
		n = emit(out, n, t, c->press, true);
	return emit(out, n, t, c->press, false);
}

static int hold(struct button *b, uint64_t now, struct app_event *out)
{
	const struct button_config *c = &b->cfg;
	uint64_t t = b->hold_ns;

	if (c->long_press != ACTION_NONE) {
		b->spent = true;
		b->hold_ns = CLOCK_NEVER;
		return emit(out, emit(out, 0, t, c->long_press, true), t, c->long_press, false);
	}
	/* A loop that fell behind repeats once, not in a burst. */
	b->hold_ns = t + c->repeat_ns > now ? t + c->repeat_ns : now + c->repeat_ns;
	return emit(out, 0, t, c->press, true);
}

int button_timeout(struct button *b, uint64_t now_ns, struct app_event *out)
{
	int n = 0;

	/* In time order: a settle can start a hold that is due as well. */
	for (;;) {
		uint64_t s = settle_at(b), h = b->down ? b->hold_ns : CLOCK_NEVER;

		if (s <= now_ns && s <= h)
			n += transition(b, b->raw, s, out + n);
		else if (h <= now_ns)
			n += hold(b, now_ns, out + n);
		else
			return n;
	}
}

int button_edge(struct button *b, uint64_t time_ns, bool down, struct app_event *out)
{
	uint64_t t = b->seen_edge && time_ns < b->edge_ns ? b->edge_ns : time_ns;
	int n = button_timeout(b, t, out);
	bool bounce = b->seen_edge && t - b->edge_ns < b->cfg.debounce_ns;

	b->raw = down;
	b->edge_ns = t;
	b->seen_edge = true;
	if (!bounce && down != b->down)
		n += transition(b, down, t, out + n);
	return n;
}

int button_lost(struct button *b, uint64_t now_ns, struct app_event *out)
{
	int n = 0;

	if (b->down && !b->spent && b->cfg.long_press == ACTION_NONE)
		n = emit(out, n, now_ns, b->cfg.press, false);
	b->raw = b->down = false;
	b->hold_ns = CLOCK_NEVER;
	return n;
}
